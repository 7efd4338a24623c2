// The cascade of §4 for one pair of objects: S-bounds per constant-velocity
// sub-span (§4.3), divide-and-conquer (§4.1) on the region chosen by
// Appendix B's optimal fitting, generate-and-test (§4.2), and a witness
// stepped off every hyperplane and checked against the scene.
#ifndef CLASH4D_CHECK_COLLISION_CHECKER_H
#define CLASH4D_CHECK_COLLISION_CHECKER_H

#include "search/Divide_and_conquer.h"
#include "model/Point_classifier.h"
#include "search/S_bounds.h"
#include "model/Scene_model.h"
#include "scene/Input_error.h"
#include <chrono>
#include <functional>
#include <map>

namespace clash4d {

template <class FT>
struct Pair_result {
  int a = -1, b = -1;
  bool collide = false;
  Vector4<FT> witness{};          // (x, y, z, t), generic, strictly inside both
  bool has_witness = false;       // false: found, the witness is for another kernel to make
  bool witness_verified = false;  // checked with strict signs against the scene
  bool earliest = false;          // t_star and contact are set (--earliest)
  FT t_star{};                    // inf of the collision times (§5)
  Vector4<FT> contact{};          // (x*, t*) in the closure of the collision region
};

template <class K>
class Collision_checker {
public:
  using FT = typename K::FT;
  using H = Hyperplane4<FT>;
  using Box3 = Box<FT, 3>;
  using Box4 = Box<FT, 4>;
  using V4 = Vector4<FT>;

  static constexpr int max_sbound_passes = 16;

  using Bounds = typename S_bounds<K>::Bounds;

  // The 3D S-bounds of every object on its own (§4.3.1), computed once and
  // shared by every pair: §6's per-partner arrays start from these, and each
  // pair narrows its own copies (the j-th element for partner j).
  static std::vector<Bounds> settle_all(const K& k, const Scene_model<K>& model, Check_stats& stats, bool use_sbounds)
  {
    auto start = std::chrono::steady_clock::now();
    std::vector<Bounds> settled;
    for (const auto& o : model.objects) settled.push_back(settle_one(k, o.csg, stats, use_sbounds));
    stats.seconds_sbounds += seconds_since(start);
    return settled;
  }

  static Bounds settle_one(const K& k, const Csg_model<FT>& csg, Check_stats& stats, bool use_sbounds)
  {
    S_bounds<K> sb(k);
    Bounds b = sb.initial(csg);
    stats.sbound_passes += use_sbounds ? sb.settle(csg, b, max_sbound_passes) : 0;
    return b;
  }

  Collision_checker(const K& k, const Scene_model<K>& model, const std::vector<Bounds>& settled, Check_stats& stats,
                    bool use_sbounds = true)
    : k_(k), model_(model), stats_(stats), sb_(k), use_sbounds_(use_sbounds), settled_(settled) {}

  // Any-witness searches only: record where the first point inside is
  // found, or replay such a record (search/Search_trail.h).
  void follow(Search_trail* trail) { trail_ = trail; }

  // For an approximate run whose answers must be the exact run's
  // (exact/Filtered_runner.h): make the witness only when this run's path is
  // certified to be the exact run's (an any-witness search, its trail not
  // approximate, its point its own) and every sign and rounding on the way
  // is certain, otherwise report the verdict only; hand the lines it cannot
  // decide to `exact` (Exact_lines, as Generate_and_test::Exact_lines with
  // the pair, the sub-span's index and the frame), and let `same` say
  // whether two table entries are one plane when it cannot tell
  // (Exact_proportional, geometry/Hyperplane4.h's proportional).
  using Exact_lines = std::function<typename Generate_and_test<K>::Line_decider(
      int a, int b, std::size_t span, const std::array<bool, 3>& frame_of_a, const Plane_layout&, const Box4& region)>;
  using Exact_proportional =
      std::function<int(int a, int b, std::size_t span, const std::array<bool, 3>& frame_of_a, long entry_h, int face_h,
                        long entry_g, int face_g, const Box4& region)>;
  void as_filter(Exact_lines exact, Exact_proportional same)
  {
    certified_witness_only_ = true;
    exact_lines_ = std::move(exact);
    exact_proportional_ = std::move(same);
  }

  // The plane table of check_span (plane_table) for a sub-span and frame.
  std::vector<H> span_table(int a, int b, std::size_t span_index, const std::array<bool, 3>& frame_of_a,
                            Motion_groups<FT>& groups) const
  {
    const Time_span<FT> span = model_.sub_spans({a, b}).at(span_index);
    Moving A = moving(a, span), B = moving(b, span);
    Vector3<FT> shear;
    for (int q = 0; q < 3; ++q) shear[q] = !use_sbounds_ ? FT(0) : frame_of_a[q] ? A.v[q] : B.v[q];
    return plane_table(A, B, shear, frame_of_a, groups);
  }

  // earliest: find t* (§5) rather than stopping at the first witness;
  // ceiling: in that mode, ignore collisions that start at or after it.
  Pair_result<FT> check_pair(int a, int b, bool earliest = false, const FT* ceiling = nullptr)
  {
    ++stats_.pairs;
    Pair_result<FT> r;
    r.a = a;
    r.b = b;
    Search_goal<FT> goal;
    goal.earliest = earliest;
    if (ceiling) { goal.has_ceiling = true; goal.ceiling = *ceiling; }
    std::size_t index = 0;
    for (const auto& span : model_.sub_spans({a, b})) {
      span_index_ = index++;
      if (!goal.can_improve(span.lo)) break;   // spans come in time order
      if (replaying() && span_index_ < trail_->span) continue;   // proven free of collisions
      ++stats_.sub_spans;
      check_span(a, b, span, r, goal);
      if (goal.done()) break;
      if (replaying()) { trail_->diverged = true; break; }      // the trail's span must hold it
    }
    r.earliest = earliest && r.collide;
    return r;
  }

  using Segment = std::array<V4, 2>;

  // §5 skeleton: every edge of the boundary of the pair's regularised
  // collision region, in world coordinates, collinear pieces merged. The
  // full, non-terminating search. Each sub-span is searched in its S-bound
  // region, but with the formula of the whole extrusions (every motion
  // segment with its time slab, §3), so that edges on a velocity change are
  // classified with both segments and the span's ends tL, tH are real faces.
  std::vector<Segment> skeleton_pair(int a, int b)
  {
    ++stats_.pairs;
    std::vector<Segment> edges;
    for (const auto& span : model_.sub_spans({a, b})) {
      ++stats_.sub_spans;
      Moving A = moving(a, span), B = moving(b, span);
      FT tl = span.lo, th = span.hi;
      if (!four_d_bounds(A, B, tl, th)) { ++stats_.sub_spans_pruned; continue; }
      Vector3<FT> shear;
      Box4 region = fitted_region(A, B, tl, th, shear);
      std::vector<H> table;
      Formula::Builder builder;
      std::size_t mark = builder.open();
      for (const H& h : {time_at_least(model_.t_lo), time_at_most(model_.t_hi)}) slab_leaf(h, table, builder);
      whole_extrusion(a, shear, table, builder);
      whole_extrusion(b, shear, table, builder);
      builder.close(Formula::Op::And, mark);
      Formula formula = builder.finish();
      std::vector<Segment> pieces;
      Divide_and_conquer<K>(k_, table, stats_).skeleton(region, formula, pieces);
      for (Segment& e : pieces)
        for (V4& p : e)
          for (int q = 0; q < 3; ++q) p[q] += shear[q] * p[3];
      edges.insert(edges.end(), pieces.begin(), pieces.end());
    }
    return merge_collinear(edges);
  }

private:
  const K& k_;
  const Scene_model<K>& model_;
  Check_stats& stats_;
  S_bounds<K> sb_;
  bool use_sbounds_;
  const std::vector<Bounds>& settled_;
  Search_trail* trail_ = nullptr;
  std::size_t span_index_ = 0;
  std::array<bool, 3> frame_of_a_{};       // this span's frame choice per axis
  bool certified_witness_only_ = false;
  Exact_lines exact_lines_;
  Exact_proportional exact_proportional_;

  bool replaying() const { return trail_ && trail_->replaying(); }

  struct Moving {
    const Object_model<FT>* object;
    Vector3<FT> v, o;                        // D(t) = v t + o on the sub-span
    typename S_bounds<K>::Bounds beta;
  };

  static double seconds_since(std::chrono::steady_clock::time_point s)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - s).count();
  }

  Moving moving(int i, const Time_span<FT>& span) const
  {
    const Object_model<FT>& obj = model_.objects[i];
    std::size_t seg = model_.segment_on(i, span);
    return {&obj, obj.motion.velocity[seg], obj.motion.offset[seg], settled_[i]};
  }

  void check_span(int a, int b, const Time_span<FT>& span, Pair_result<FT>& r, Search_goal<FT>& goal)
  {
    auto start = std::chrono::steady_clock::now();
    Moving A = moving(a, span), B = moving(b, span);
    FT tl = span.lo, th = span.hi;
    frame_of_a_ = {};
    bool alive = use_sbounds_ ? four_d_bounds(A, B, tl, th) : true;
    alive = alive && goal.can_improve(tl);
    Span_stats ss;
    ss.pair = A.object->name + "/" + B.object->name;
    ss.span = interval_text(span.lo, span.hi);
    ss.narrowed = alive ? interval_text(tl, th) : "empty";
    count_pruned(A, ss);
    count_pruned(B, ss);
    if (stats_.span_before.empty()) {
      stats_.span_before = ss.span;
      stats_.span_after = ss.narrowed;
    }
    stats_.seconds_sbounds += seconds_since(start);
    if (!alive) {
      ++stats_.sub_spans_pruned;
      stats_.spans.push_back(ss);
      return;
    }

    start = std::chrono::steady_clock::now();
    Vector3<FT> shear;
    stats_.conquered_box.clear();
    Box4 region = use_sbounds_ ? fitted_region(A, B, tl, th, shear) : original_region(A, B, span, shear);
    for (int q = 0; q < 4; ++q) ss.region += std::string(q ? " x " : "") + interval_text(region.lo[q], region.hi[q]);
    if (has_no_interior(k_, region)) {
      ss.narrowed = "empty";
      stats_.spans.push_back(ss);
      return;
    }
    if (use_sbounds_) region = on_grid(region, span);
    for (int q = 0; q < 3; ++q) ss.frame += std::string(q ? " " : "") + k_.to_text(shear[q]);
    Motion_groups<FT> groups;
    std::vector<H> table = plane_table(A, B, shear, frame_of_a_, groups);
    Formula::Builder builder;
    std::size_t mark = builder.open();
    std::size_t next = 0;
    emit(A, 0, false, builder, next);
    next = 0;
    for (const auto& p : A.object->csg.primitives) next += 2 * p.planes.size();   // B's first plane
    emit(B, 0, false, builder, next);
    builder.close(Formula::Op::And, mark);
    Formula formula = builder.finish();
    ss.leaves = formula.leaf_count();
    stats_.spans.push_back(ss);
    Divide_and_conquer<K> dc(k_, table, stats_, trail_, &groups);
    if (exact_lines_)
      dc.lines_undecided_with([&](const Plane_layout& layout, const Box4& box) {
        return exact_lines_(a, b, span_index_, frame_of_a_, layout, box);
      });
    if (exact_proportional_)
      dc.proportional_undecided_with([&](long eh, int fh, long eg, int fg, const Box4& box) {
        return exact_proportional_(a, b, span_index_, frame_of_a_, eh, fh, eg, fg, box);
      });
    goal.improved = false;
    dc.search(region, formula, goal);
    if (trail_ && trail_->recording() && goal.improved) {
      trail_->span = span_index_;
    }
    stats_.seconds_divide += seconds_since(start);
    if (!dc.conquered().empty)
      for (int q = 0; q < 4; ++q)
        stats_.conquered_box += std::string(q ? " x " : "") + interval_text(dc.conquered().lo[q], dc.conquered().hi[q]);
    if (!goal.improved) return;

    // Found here (or, earliest mode, earlier than before): the witness and
    // contact point are made with this span's planes and frame.
    start = std::chrono::steady_clock::now();
    r.collide = true;
    r.has_witness = false;
    if (certified_witness_only_) {
      if (!trail_ || !trail_->recording() || trail_->approximate || !goal.inside_known) return;
      try {
        make_witness(goal, shear, A, B, span, r);
      } catch (const CGAL::Uncertain_conversion_exception&) {
        // has_witness stays false: the pair goes to the exact kernel.
      }
    } else {
      make_witness(goal, shear, A, B, span, r);
    }
    stats_.seconds_witness += seconds_since(start);
    if (K::is_exact && !r.witness_verified)
      throw std::logic_error("internal error: the exact witness failed its check; please report this scene");
  }

  void make_witness(const Search_goal<FT>& goal, const Vector3<FT>& shear, const Moving& A, const Moving& B,
                    const Time_span<FT>& span, Pair_result<FT>& r) const
  {
    r.witness = witness(goal.inside, shear, A, B, span);
    r.witness_verified = verify(r.witness, r.a, r.b);
    r.has_witness = true;
    r.t_star = goal.t_star;
    r.contact = goal.contact;
    for (int q = 0; q < 3; ++q) r.contact[q] += shear[q] * r.contact[3];
  }

  // §4.3.2: 3D Up/Down passes in each object, and the closed form of
  // Appendix B at the root, repeated until nothing shrinks.
  bool four_d_bounds(Moving& A, Moving& B, FT& tl, FT& th)
  {
    for (int pass = 0; pass < max_sbound_passes; ++pass) {
      ++stats_.sbound_passes;
      Box3 ra = A.beta[0], rb = B.beta[0];
      FT l0 = tl, h0 = th;
      typename S_bounds<K>::Moving_box ma{&A.beta[0], &A.v, &A.o}, mb{&B.beta[0], &B.v, &B.o};
      if (!sb_.meet_moving(ma, mb, tl, th)) return false;
      sb_.settle(A.object->csg, A.beta, max_sbound_passes);
      sb_.settle(B.object->csg, B.beta, max_sbound_passes);
      if (A.beta[0].empty || B.beta[0].empty) return false;
      if (same_on_grid(k_, ra, A.beta[0]) && same_on_grid(k_, rb, B.beta[0]) && k_.same_on_grid(l0, tl) &&
          k_.same_on_grid(h0, th))
        break;
    }
    return true;
  }

  void count_pruned(const Moving& m, Span_stats& ss)
  {
    const auto& nodes = m.object->csg.nodes;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (nodes[i].op == Csg_node::Op::Primitive) {
        ++stats_.primitives;
        ++ss.primitives;
        stats_.primitives_pruned += m.beta[i].empty;
        ss.primitives_alive += !m.beta[i].empty;
      }
  }

  std::string interval_text(const FT& lo, const FT& hi) const { return "[" + k_.to_text(lo) + ", " + k_.to_text(hi) + "]"; }

  // §4.1's original bound: each object's box at the span's ends (its swept box
  // under one velocity), intersected, with the span's times; no shear.
  Box4 original_region(const Moving& A, const Moving& B, const Time_span<FT>& span, Vector3<FT>& shear) const
  {
    Box3 sweep[2];
    int i = 0;
    for (const Moving* m : {&A, &B}) {
      Box3 at_lo = m->beta[0], at_hi = m->beta[0];
      for (int q = 0; q < 3; ++q) {
        FT dlo = m->v[q] * span.lo + m->o[q], dhi = m->v[q] * span.hi + m->o[q];
        at_lo.lo[q] += dlo; at_lo.hi[q] += dlo;
        at_hi.lo[q] += dhi; at_hi.hi[q] += dhi;
      }
      sweep[i++] = join(at_lo, at_hi);
    }
    Box3 both = meet(sweep[0], sweep[1]);
    Box4 region;
    for (int q = 0; q < 3; ++q) {
      if (!both.has_lo[q] || !both.has_hi[q])
        throw Input_error("", "the original bounding procedure needs bounded objects", CLASH4D_EXIT_LIMIT);
      region.set(q, both.lo[q], both.hi[q]);
      shear[q] = FT(0);
    }
    region.set(3, span.lo, span.hi);
    return region;
  }

  // Appendix B, "optimal fitting": per axis, measure q in the frame of the
  // object whose bound is narrower there (q' = q - w t with w its velocity),
  // the widths compared on the grid (Kernel_base::less_on_grid).
  Box4 fitted_region(const Moving& A, const Moving& B, const FT& tl, const FT& th, Vector3<FT>& shear)
  {
    Box4 region;
    const char* axis = "xyz";
    for (int q = 0; q < 3; ++q) {
      const Box3 &ba = A.beta[0], &bb = B.beta[0];
      bool fa = ba.has_lo[q] && ba.has_hi[q], fb = bb.has_lo[q] && bb.has_hi[q];
      if (!fa && !fb)
        throw Input_error("", std::string("both objects are unbounded along ") + axis[q] +
                              ": this version needs one of each pair bounded", CLASH4D_EXIT_LIMIT);
      bool use_a = fa && (!fb || !k_.less_on_grid(bb.hi[q] - bb.lo[q], ba.hi[q] - ba.lo[q]));
      frame_of_a_[q] = use_a;
      const Moving& m = use_a ? A : B;
      const Box3& bm = use_a ? ba : bb;
      shear[q] = m.v[q];
      region.set(q, bm.lo[q] + m.o[q], bm.hi[q] + m.o[q]);
    }
    region.set(3, tl, th);
    return region;
  }

  // Region faces moved out to the next multiples of 2^-grid_bits beyond the
  // S-bound region, which stays a bound. S-bounds are vertex coordinates, so
  // their faces pass through the objects' vertex lines: a degeneracy of the
  // bound, not of the scene, which interval arithmetic cannot certify. Grid
  // values are exact in every kernel, and so are the bisections of §4.1.
  // Time stays within the sub-span (the formula has no time slab). The
  // rounding jumps at half-grid points, not at the grid points that integer
  // and short binary bounds sit on, so an interval enclosing such a bound
  // still rounds to one grid point; the margin is at least half a step.
  Box4 on_grid(const Box4& region, const Time_span<FT>& span) const
  {
    const FT step = k_.power_of_two(-K::grid_bits);
    auto below = [&](const FT& x) { return k_.grid_point(x) - step; };
    Box4 out = region;
    for (int q = 0; q < 4; ++q) out.set(q, below(region.lo[q]), -below(-region.hi[q]));
    out.lo[3] = Number_ops<FT>::upper(out.lo[3], span.lo);
    out.hi[3] = Number_ops<FT>::lower(out.hi[3], span.hi);
    return out;
  }

  // A's planes then B's (add_planes), groups 0 and 1; per axis, the frame
  // is A's own or B's (fitted regions only).
  std::vector<H> plane_table(const Moving& A, const Moving& B, const Vector3<FT>& shear,
                             const std::array<bool, 3>& frame_of_a, Motion_groups<FT>& groups) const
  {
    std::array<bool, 3> own_a{}, own_b{};
    for (int q = 0; q < 3 && use_sbounds_; ++q) own_a[q] = frame_of_a[q], own_b[q] = !frame_of_a[q];
    std::vector<H> table;
    groups.velocity.push_back(add_planes(A, shear, own_a, table, &groups));
    groups.of.assign(table.size(), 0);
    groups.velocity.push_back(add_planes(B, shear, own_b, table, &groups));
    groups.of.resize(table.size(), 1);
    groups.still = {own_a, own_b};
    return table;
  }

  // Every plane of every primitive, extruded (eq. 4) and sheared, followed by
  // its complement: table[2i] is plane i, table[2i + 1] its complement.
  // In the frame x' = x - w t the object moves with v - w (eq. 4 with that
  // velocity). On an axis measured in the object's own frame (own[q]) that
  // is a written zero, not v - v: an interval run then gets a point zero
  // where the exact run has one, instead of an uncertain sign.
  // Returns the velocity v - w. groups: where to list the corners each entry
  // passes through (model/Motion_groups.h).
  Vector3<FT> add_planes(const Moving& m, const Vector3<FT>& shear, const std::array<bool, 3>& own,
                         std::vector<H>& table, Motion_groups<FT>* groups = nullptr) const
  {
    Vector3<FT> relative;
    for (int q = 0; q < 3; ++q) relative[q] = own[q] ? FT(0) : m.v[q] - shear[q];
    for (const auto& p : m.object->csg.primitives) {
      std::vector<std::vector<int>> through(p.planes.size());
      if (groups) {
        for (const auto& corner : p.corners) {
          for (int plane : corner) through[plane].push_back(groups->corner_count);
          ++groups->corner_count;
        }
        groups->corners.resize(table.size());
      }
      for (std::size_t i = 0; i < p.planes.size(); ++i) {
        table.push_back(extrude(p.planes[i], relative, m.o));
        table.push_back(table.back().complement());
        if (groups) groups->corners.insert(groups->corners.end(), 2, through[i]);
      }
    }
    return relative;
  }

  // The object's tree in negation normal form; pruned nodes (empty S-bound)
  // are the null set. `next` walks the table in primitive order.
  void emit(const Moving& m, int node, bool negated, Formula::Builder& b, std::size_t& next) const
  {
    const Csg_model<FT>& csg = m.object->csg;
    const Csg_node& n = csg.nodes[node];
    if (m.beta[node].empty) {
      skip_planes(csg, node, next);
      b.constant(negated);
      return;
    }
    std::size_t mark = b.open();
    switch (n.op) {
      case Csg_node::Op::Primitive:
        for (std::size_t i = 0; i < csg.primitives[n.primitive].planes.size(); ++i, next += 2)
          b.leaf(static_cast<std::uint32_t>(negated ? next + 1 : next));
        b.close(negated ? Formula::Op::Or : Formula::Op::And, mark);
        return;
      case Csg_node::Op::Union:
      case Csg_node::Op::Intersection: {
        for (int c : n.children) emit(m, c, negated, b, next);
        bool conj = (n.op == Csg_node::Op::Intersection) != negated;
        b.close(conj ? Formula::Op::And : Formula::Op::Or, mark);
        return;
      }
      case Csg_node::Op::Difference:
        // L - R1 - ... = L and not R1 and ...; its negation is not L or R1 or ...
        for (std::size_t i = 0; i < n.children.size(); ++i) emit(m, n.children[i], i == 0 ? negated : !negated, b, next);
        b.close(negated ? Formula::Op::Or : Formula::Op::And, mark);
        return;
    }
  }

  void slab_leaf(const H& h, std::vector<H>& table, Formula::Builder& b) const
  {
    b.leaf(static_cast<std::uint32_t>(table.size()));
    table.push_back(h);
    table.push_back(h.complement());
  }

  // The object over all time: the union over its motion segments of the
  // segment's tree within the segment's time slab (§3).
  void whole_extrusion(int i, const Vector3<FT>& shear, std::vector<H>& table, Formula::Builder& b) const
  {
    const Object_model<FT>& obj = model_.objects[i];
    const Motion_path<FT>& m = obj.motion;
    std::size_t mark = b.open();
    for (std::size_t s = 0; s < m.velocity.size(); ++s) {
      if (s > 0 && !(m.times[s - 1] < model_.t_hi)) continue;
      if (s < m.times.size() && !(model_.t_lo < m.times[s])) continue;
      Moving seg{&obj, m.velocity[s], m.offset[s], settled_[i]};
      std::size_t seg_mark = b.open();
      if (s > 0) slab_leaf(time_at_least(m.times[s - 1]), table, b);
      if (s < m.times.size()) slab_leaf(time_at_most(m.times[s]), table, b);
      std::size_t next = table.size();
      add_planes(seg, shear, {}, table);
      emit(seg, 0, false, b, next);
      b.close(Formula::Op::And, seg_mark);
    }
    b.close(Formula::Op::Or, mark);
  }

  // Pieces found in neighbouring regions (or split at cuts) are joined when
  // they lie on one line and overlap or meet end to end.
  std::vector<Segment> merge_collinear(const std::vector<Segment>& pieces) const
  {
    // Key: the direction scaled so its first non-zero coordinate k is 1, and
    // the line's point with coordinate k = 0; a piece is then [p_k, q_k].
    std::map<std::array<FT, 8>, std::vector<std::pair<FT, FT>>> lines;
    for (const Segment& e : pieces) {
      V4 d;
      for (int q = 0; q < 4; ++q) d[q] = e[1][q] - e[0][q];
      int k = 0;
      while (k < 4 && k_.sign(d[k]) == CGAL::ZERO) ++k;
      if (k == 4) continue;
      std::array<FT, 8> key;
      for (int q = 0; q < 4; ++q) key[q] = d[q] / d[k];
      for (int q = 0; q < 4; ++q) key[4 + q] = e[0][q] - e[0][k] * key[q];
      FT s0 = e[0][k], s1 = e[1][k];
      lines[key].emplace_back(s0 < s1 ? s0 : s1, s0 < s1 ? s1 : s0);
    }
    std::vector<Segment> out;
    for (auto& [key, spans] : lines) {
      std::sort(spans.begin(), spans.end());
      std::vector<std::pair<FT, FT>> merged;
      for (const auto& sp : spans) {
        if (!merged.empty() && !(merged.back().second < sp.first)) {
          if (merged.back().second < sp.second) merged.back().second = sp.second;
        } else merged.push_back(sp);
      }
      for (const auto& sp : merged) {
        Segment e;
        for (int q = 0; q < 4; ++q) {
          e[0][q] = key[4 + q] + sp.first * key[q];
          e[1][q] = key[4 + q] + sp.second * key[q];
        }
        out.push_back(e);
      }
    }
    return out;
  }

  void skip_planes(const Csg_model<FT>& csg, int node, std::size_t& next) const
  {
    const Csg_node& n = csg.nodes[node];
    if (n.op == Csg_node::Op::Primitive) { next += 2 * csg.primitives[n.primitive].planes.size(); return; }
    for (int c : n.children) skip_planes(csg, c, next);
  }

  // Largest step (halved) along d from p that crosses no hyperplane not
  // already through p; values[i] is planes[i] at p.
  FT safe_step(const V4& d, const std::vector<H>& planes, const std::vector<FT>& values) const
  {
    bool any = false;
    FT best(1);
    for (std::size_t i = 0; i < planes.size(); ++i) {
      FT nd = dot(planes[i].n, d);
      if (k_.sign(values[i]) == CGAL::ZERO || k_.sign(nd) == CGAL::ZERO) continue;
      FT s = Number_ops<FT>::magnitude(values[i]) / Number_ops<FT>::magnitude(nd);
      best = any ? Number_ops<FT>::lower(best, s) : s;
      any = true;
    }
    return any ? best / FT(2) : FT(1);
  }

  // regularised-semantics item 3: the point found inside the formula's cell,
  // in world coordinates, moved off every plane of the two objects (planes
  // of primitives the S-bounds pruned were not in the search) and rounded
  // (snap) to a short dyadic point.
  V4 witness(V4 p, const Vector3<FT>& shear, const Moving& A, const Moving& B, const Time_span<FT>& span) const
  {
    for (int q = 0; q < 3; ++q) p[q] += shear[q] * p[3];
    std::vector<H> world;
    for (const Moving* m : {&A, &B})
      for (const auto& prim : m->object->csg.primitives)
        for (const auto& plane : prim.planes) world.push_back(extrude(plane, m->v, m->o));
    world.push_back(time_at_least(span.lo));
    world.push_back(time_at_most(span.hi));
    std::vector<FT> values = values_at(p, world);
    if (make_generic(p, world, values)) values = values_at(p, world);
    return snap(p, world, values);
  }

  static std::vector<FT> values_at(const V4& p, const std::vector<H>& planes)
  {
    std::vector<FT> values;
    values.reserve(planes.size());
    for (const H& h : planes) values.push_back(h.value(p));
    return values;
  }

  // Steps p off the planes through it; true when it moved.
  bool make_generic(V4& p, const std::vector<H>& planes, const std::vector<FT>& values) const
  {
    std::vector<const H*> through;
    for (std::size_t i = 0; i < planes.size(); ++i)
      if (k_.sign(values[i]) == CGAL::ZERO) through.push_back(&planes[i]);
    if (through.empty()) return false;
    // d = (1, j, j^2, j^3) is orthogonal to a given normal for at most three
    // values of j, so some j <= 3 * |through| + 1 avoids all of them.
    for (int j = 1;; ++j) {
      V4 d{FT(1), FT(j), FT(j * j), FT(j * j * j)};
      bool ok = true;
      for (const H* h : through) ok = ok && k_.dot_sign(h->n, d) != CGAL::ZERO;
      if (ok) {
        p = point_along(p, safe_step(d, planes, values), d);
        return true;
      }
      if (j > 3 * static_cast<int>(through.size()) + 1) return false;   // only with a tolerance
    }
  }

  // p rounded to the coarsest grid 2^-bits that keeps it where it is. No
  // plane n.x + c changes sign within max-norm distance room of p, where
  // room = min |h(p)| / (4 max |n_j|) (as |h(q) - h(p)| <= |n|_1 |q - p|);
  // with 2^-bits <= room, rounding each coordinate to the nearest multiple
  // of 2^-bits moves p by at most room / 2, so every |h| keeps at least half
  // its value. The result is a function of the exact p alone: a kernel that
  // only encloses p (intervals) finds the same dyadic point or fails the
  // filter. And users read 1/2 rather than 1999999999/4000000000.
  // bits is taken for 13/16 of the room: the search makes distances that
  // are powers of two (grid faces, halved steps), and an enclosure of an
  // exact power of two could not say which side of it the room is on.
  V4 snap(const V4& p, const std::vector<H>& planes, const std::vector<FT>& values) const
  {
    FT least = Number_ops<FT>::magnitude(values[0]), widest = Number_ops<FT>::magnitude(planes[0].n[0]);
    for (std::size_t i = 0; i < planes.size(); ++i) {
      if (i > 0) least = Number_ops<FT>::lower(least, Number_ops<FT>::magnitude(values[i]));
      for (const FT& n : planes[i].n) widest = Number_ops<FT>::upper(widest, Number_ops<FT>::magnitude(n));
    }
    FT room = FT(13) * least / (FT(64) * widest);
    if (k_.sign(room) != CGAL::POSITIVE) return p;   // only with a tolerance: not generic
    int bits = std::max(0, k_.grid_exponent(room));
    V4 out;
    for (int q = 0; q < 4; ++q) out[q] = k_.round_to_grid(p[q], bits);
    return out;
  }

  bool verify(const V4& w, int a, int b) const { return is_valid_witness(k_, model_, a, b, w); }
};

} // namespace clash4d

#endif
