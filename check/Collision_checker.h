// The cascade of §4 for one pair of objects, sub-span by sub-span: the
// region from the S-bounds (§4.3, search/Span_region.h), the pair's
// extrusion (model/Extrusion.h), divide-and-conquer (§4.1) with
// generate-and-test (§4.2), and the witness (search/Witness.h) checked
// against the scene; in either semantics (search/Semantics.h).
#ifndef CLASH4D_CHECK_COLLISION_CHECKER_H
#define CLASH4D_CHECK_COLLISION_CHECKER_H

#include "model/Extrusion.h"
#include "model/Point_classifier.h"
#include "numbers/Number_ops.h"
#include "search/Convex_pair.h"
#include "search/Divide_and_conquer.h"
#include "search/Span_region.h"
#include "search/Witness.h"
#include "search/No_filter.h"
#include "search/Stage_clock.h"
#include <optional>
#include <stdexcept>
#include <vector>

namespace clash4d {

template <class FT>
struct Pair_result {
  int a = -1, b = -1;
  bool collide = false;
  Vector4<FT> witness = shared_zeros<FT, 4>();   // (x, y, z, t), generic, strictly inside both
  bool has_witness = false;       // false: found, the witness is for another kernel to make
  bool witness_verified = false;  // checked with strict signs against the scene
  bool earliest = false;          // t_star and contact are set (--earliest)
  FT t_star = zero_value<FT>();  // inf of the collision times (§5); closed: the first contact time
  Vector4<FT> contact = shared_zeros<FT, 4>();   // (x*, t*) in the closure of the collision region
  // What makes the answer checkable (check/Check_answer.h, Pair_answer):
  // closed, generic points inside a and inside b whose cells' closures hold
  // the witness; earliest, the same for the contact point (regularised: one
  // point inside both, twice).
  // Each empty until set, then one point per object: a pair that needs
  // none (regularised, not earliest; no collision) makes no numbers.
  Semantics semantics = Semantics::regularised;
  std::vector<Vector4<FT>> witness_cells;
  std::vector<Vector4<FT>> contact_cells;

  Pair_result() = default;
  Pair_result(const Pair_result&) = default;
  Pair_result(Pair_result&&) = default;
  Pair_result& operator=(const Pair_result&) = default;
  // By exchange: a defaulted one copies every rational (CGAL's Gmpq has no
  // move; numbers/Number_ops.h, swap_numbers), and a pair's answer is moved
  // into its slot on every query.
  Pair_result& operator=(Pair_result&& o) noexcept
  {
    swap(o);
    return *this;
  }
  // Every member: a new one goes here too (test_numbers,
  // swapped_rationals_and_moved_pair_results_keep_every_member).
  void swap(Pair_result& o) noexcept
  {
    std::swap(a, o.a);
    std::swap(b, o.b);
    std::swap(collide, o.collide);
    swap_numbers(witness, o.witness);
    std::swap(has_witness, o.has_witness);
    std::swap(witness_verified, o.witness_verified);
    std::swap(earliest, o.earliest);
    swap_numbers(t_star, o.t_star);
    swap_numbers(contact, o.contact);
    std::swap(semantics, o.semantics);
    witness_cells.swap(o.witness_cells);
    contact_cells.swap(o.contact_cells);
  }
};

// K: the kernel; Policy: search/No_filter.h (a filtered run's is in exact/).
template <class K, class Policy = No_filter>
class Collision_checker {
public:
  using FT = typename K::FT;
  using H = Hyperplane4<FT>;
  using Box4 = Box<FT, 4>;
  using V4 = Vector4<FT>;
  using Bounds = typename S_bounds<K>::Bounds;

  Collision_checker(const K& k, const Scene_model<K>& model, const std::vector<Bounds>& settled, Check_stats& stats,
                    bool use_sbounds = true, Policy* policy = nullptr)
    : k_(k), model_(model), stats_(stats), use_sbounds_(use_sbounds), settled_(settled),
      policy_(policy ? *policy : own_policy_.emplace()) {}
  Collision_checker(const Collision_checker&) = delete;
  Collision_checker& operator=(const Collision_checker&) = delete;

  // Convex pairs are decided by linear programs first (search/Convex_pair.h,
  // beyond the paper); off, every pair goes through the paper's cascade.
  void use_convex_lp(bool on) { convex_lp_ = on; }
  // The witness checks take their plane sides from `sides` (the same signs,
  // decided another way: model/Point_classifier.h); none, the kernel's.
  void check_points_with(const Sides_at<FT>* sides) { sides_ = sides; }
  // Convex pairs take their objects' guides from `guides`, which keeps
  // them across pairs and queries (search/Convex_guide.h); none, each pair
  // makes its own.
  void use_guides(const Guide_source* guides) { guides_ = guides; }

  // earliest: find t* (§5) rather than stopping at the first witness;
  // ceiling: in that mode, ignore collisions that start at or after it.
  Pair_result<FT> check_pair(int a, int b, bool earliest = false, const FT* ceiling = nullptr,
                             Semantics semantics = Semantics::regularised)
  {
    Pair_result<FT> r;
    spans(a, b, earliest, ceiling, semantics, r, false);
    return r;
  }

  // The same answer when the linear programs decide every sub-span it
  // needs (the model's S-bounds are not read); nothing when a sub-span is
  // left to the cascade or the pair is not convex.
  std::optional<Pair_result<FT>> check_convex_pair(int a, int b, bool earliest, const FT* ceiling, Semantics semantics)
  {
    Pair_result<FT> r;
    if (!convex_lp_ || !Convex_pair<K>::applies(model_, a, b) || !spans(a, b, earliest, ceiling, semantics, r, true))
      return std::nullopt;
    return r;
  }

  using Moving = Moving_object<FT>;

  // The witness (regularised: generic, strictly inside both; closed: the
  // point found, with a generic point inside each object whose cell's
  // closure holds it) and, earliest, the contact point with the same; each
  // checked against the scene. Found on `span`, where A and B move as
  // given, in the frame x' = x - shear t. None (r.has_witness false) where
  // the kernel cannot tell a sign a point depends on (search/Witness.h).
  // cells: closed, the generic points near_in_space makes, if made already
  // (a filter's, exact/Filtered_runner.h); they are checked the same.
  // world: the sub-span's world planes (Witness::world_planes), when the
  // stage made them already; values: theirs at goal.inside, when known
  // (Convex_pair::values_inside; shear zero).
  void make_witness(const Search_goal<FT>& goal, const Vector3<FT>& shear, const Moving& A, const Moving& B,
                    const Time_span<FT>& span, Pair_result<FT>& r, const std::array<V4, 2>* cells = nullptr,
                    const std::vector<H>* world = nullptr, const std::vector<FT>* values = nullptr) const
  {
    Witness<K> w(k_);
    V4 contact = goal.contact;
    for (int q = 0; q < 3; ++q) contact[q] += shear[q] * contact[3];
    if (goal.closed() && goal.convex) {
      // The point lies in both objects (the programs proved every row <= 0
      // there) and each cell point strictly inside its object at its time
      // (Convex_pair::cell): only the cell points are left to check.
      r.witness = contact;
      r.witness_cells = {goal.convex->cell_a, goal.convex->cell_b};
      r.witness_verified = is_generic_inside(k_, model_, r.a, goal.convex->cell_a, sides_) &&
                           is_generic_inside(k_, model_, r.b, goal.convex->cell_b, sides_);
      r.contact_cells = r.witness_cells;
    } else if (goal.closed()) {
      std::optional<V4> ga = cells ? (*cells)[0] : w.near_in_space(goal.contact, goal.toward_a, shear, A),
                        gb = !ga ? std::nullopt
                             : cells ? (*cells)[1] : w.near_in_space(goal.contact, goal.toward_b, shear, B);
      if (!gb) return unmade();
      r.witness = contact;
      r.witness_cells = {*ga, *gb};
      r.witness_verified =
          is_valid_touch(k_, model_, r.a, r.b, r.witness, r.witness_cells[0], r.witness_cells[1], sides_);
      r.contact_cells = r.witness_cells;
    } else {
      std::optional<V4> in =
          world ? w.make_on(goal.inside, shear, *world, values) : w.make(goal.inside, shear, A, B, span.lo, span.hi);
      if (!in) return unmade();
      r.witness = *in;
      r.witness_verified = is_valid_witness(k_, model_, r.a, r.b, r.witness, sides_);
      if (goal.earliest && goal.convex) {
        // A convex pair's region is one cell, whose closure holds the
        // contact point (it lies in P, proven row by row): the witness is
        // the generic point near it.
        r.contact_cells = {r.witness, r.witness};
      } else if (goal.earliest) {
        std::optional<V4> g = w.near(goal.contact, goal.inside, shear, A, B, span.lo, span.hi);
        if (!g) return unmade();
        r.contact_cells = {*g, *g};
        r.witness_verified = r.witness_verified && is_valid_contact_cell(k_, model_, r.a, r.b, contact, *g, sides_);
      }
    }
    r.has_witness = true;
    r.t_star = goal.t_star;
    r.contact = contact;
  }

private:
  // A witness a kernel could not make: a filter's enclosures leave it to
  // another kernel; an exact kernel tells every sign.
  static void unmade()
  {
    if (K::is_exact) throw std::logic_error("internal error: an exact kernel made no witness; please report this scene");
  }

  const K& k_;
  const Scene_model<K>& model_;
  Check_stats& stats_;
  bool use_sbounds_, convex_lp_ = true;
  const Sides_at<FT>* sides_ = nullptr;
  const Guide_source* guides_ = nullptr;
  const std::vector<Bounds>& settled_;
  std::optional<Policy> own_policy_;   // made only when no policy is given
  Policy& policy_;

  // The pair's sub-spans in time order, until the goal is met; false when
  // convex_only and a sub-span was left to the cascade.
  bool spans(int a, int b, bool earliest, const FT* ceiling, Semantics semantics, Pair_result<FT>& r,
             bool convex_only)
  {
    ++stats_.pairs;
    r.a = a;
    r.b = b;
    r.semantics = semantics;
    Search_goal<FT> goal;
    goal.earliest = earliest;
    goal.semantics = semantics;
    if (ceiling) goal.ceiling = *ceiling;
    std::optional<Convex_pair<K, Policy>> convex;
    if (convex_lp_ && Convex_pair<K>::applies(model_, a, b))
      convex.emplace(k_, model_, a, b, &policy_, guides_ ? Convex_guides{(*guides_)(a), (*guides_)(b)} : Convex_guides{});
    std::size_t index = 0;
    for (const auto& span : model_.sub_spans({a, b})) {
      std::size_t here = index++;
      if (!policy_.enters_span(k_, goal, span)) break;   // spans come in time order
      if (policy_.skips_span(here)) continue;
      ++stats_.sub_spans;
      if (!check_span(a, b, here, span, r, goal, convex ? &*convex : nullptr, convex_only)) return false;
      if (goal.done() || policy_.stops_after(here)) break;
    }
    r.earliest = earliest && r.collide;
    return true;
  }

  // One sub-span: a convex pair's linear programs, or its region (§4.3),
  // then its extrusion searched (§4.1, §4.2); then the witness of what was
  // found. False: left to the cascade, when convex_only.
  bool check_span(int a, int b, std::size_t index, const Time_span<FT>& span, Pair_result<FT>& r,
                  Search_goal<FT>& goal, Convex_pair<K, Policy>* convex, bool convex_only)
  {
    Stage_clock clock(stats_.timed);
    Moving A = moving_on(model_, a, span, settled_[a]), B = moving_on(model_, b, span, settled_[b]);
    if (convex) {
      goal.improved = false;
      using Verdict = typename Convex_pair<K, Policy>::Verdict;
      std::optional<Verdict> decided = policy_.convex_stage([&] { return convex->decide(index, A, B, span, goal); });
      if (!decided) return true;   // the policy stopped the pair here (stops_after)
      Verdict v = *decided;
      stats_.seconds_divide += clock.lap();
      if (v == Verdict::undecided) {
        ++stats_.convex_undecided;
        if (convex_only) return false;
      } else {
        ++stats_.convex_spans;
        if (goal.improved) {
          // Regularised: the witness is made on the pair's rows, which are
          // the sub-span's world planes, mostly made by the stage already,
          // and their values at the point inside when the stage has them
          // (a closed witness reads none).
          const std::vector<H>* rows = goal.closed() ? nullptr : &convex->world_rows();
          found(index, goal, Vector3<FT>{FT(0), FT(0), FT(0)}, A, B, span, r, rows,
                rows ? convex->values_inside() : nullptr);
        }
        return true;
      }
    }
    Vector3<FT> shear;
    std::array<bool, 3> frame_of_a{};
    Span_stats ss;
    std::optional<Box4> region = span_region(a, b, index, A, B, span, goal, shear, frame_of_a, ss);
    stats_.seconds_sbounds += clock.lap();
    if (!region) {
      stats_.spans.push_back(ss);
      return true;
    }

    Motion_groups<FT> groups;
    std::vector<H> table = Extrusion<K>::pair_table(A, B, shear, frame_of_a, use_sbounds_, groups);
    std::size_t slab = goal.closed() ? Extrusion<K>::add_time_slab(table, span.lo, span.hi) : 0;
    Pair_formula formula = Extrusion<K>::pair_formula(A, B, goal.closed() ? &slab : nullptr);
    ss.leaves = formula.leaf_count();
    stats_.spans.push_back(ss);
    Divide_and_conquer<K, Policy> dc(k_, table, stats_, &groups, &policy_);
    goal.improved = false;
    policy_.search_span(a, b, index, frame_of_a);
    dc.search(*region, formula, goal);
    stats_.seconds_divide += clock.lap();
    if (!dc.conquered().empty)
      for (int q = 0; q < 4; ++q) stats_.conquered_box.push_back(range(dc.conquered().lo[q], dc.conquered().hi[q]));
    if (goal.improved) found(index, goal, shear, A, B, span, r);
    return true;
  }

  // Found on sub-span `index` (or, earliest mode, earlier than before): the
  // witness and contact point are made with this span's planes and frame.
  void found(std::size_t index, const Search_goal<FT>& goal, const Vector3<FT>& shear, const Moving& A,
             const Moving& B, const Time_span<FT>& span, Pair_result<FT>& r, const std::vector<H>* world = nullptr,
             const std::vector<FT>* values = nullptr)
  {
    policy_.found_in_span(index);
    Stage_clock clock(stats_.timed);
    r.collide = true;
    r.has_witness = false;
    if (policy_.witness_certified() && policy_.witness_answers(goal))
      policy_.attempt([&] { make_witness(goal, shear, A, B, span, r, nullptr, world, values); });
    stats_.seconds_witness += clock.seconds();
    if (K::is_exact && r.has_witness && !r.witness_verified)
      throw std::logic_error("internal error: the exact witness failed its check; please report this scene");
  }

  // The region the sub-span is searched in, in the frame x' = x - shear t
  // (search/Span_region.h), with the S-bound stage's statistics; nothing
  // when the pair cannot collide on the span. The policy may make the stage
  // in another kernel (region_stage).
  std::optional<Box4> span_region(int a, int b, std::size_t index, Moving& A, Moving& B, const Time_span<FT>& span,
                                  const Search_goal<FT>& goal, Vector3<FT>& shear, std::array<bool, 3>& frame_of_a,
                                  Span_stats& ss)
  {
    Region_stage<FT> st;
    policy_.region_stage(a, b, index, A, B, st, [&] {
      st = Span_region<K>(k_, stats_, model_.far_exponent, goal.closed(), policy_.keeps_doubtful_bounds())
               .stage(A, B, span, use_sbounds_);
    });
    bool alive = st.alive && goal.can_improve(k_, st.tl);
    ss.pair = A.object->name + "/" + B.object->name;
    ss.span = range(span.lo, span.hi);
    if (alive) ss.narrowed = range(st.tl, st.th);
    count_pruned(A, ss);
    count_pruned(B, ss);
    if (!stats_.span_before) {
      stats_.span_before = ss.span;
      stats_.span_after = ss.narrowed;
    }
    if (!alive) {
      ++stats_.sub_spans_pruned;
      return std::nullopt;
    }
    stats_.conquered_box.clear();
    for (int q = 0; q < 4; ++q) ss.region.push_back(range(st.fitted.lo[q], st.fitted.hi[q]));
    if (!st.region) {
      ss.narrowed.reset();
      return std::nullopt;
    }
    for (int q = 0; q < 3; ++q) ss.frame.push_back(k_.to_stat(st.shear[q]));
    shear = st.shear;
    frame_of_a = st.frame_of_a;
    return st.region;
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

  Stat_range range(const FT& lo, const FT& hi) const { return {k_.to_stat(lo), k_.to_stat(hi)}; }
};

} // namespace clash4d

#endif
