// The cascade of §4 for one pair of objects, sub-span by sub-span: the
// region from the S-bounds (§4.3, search/Span_region.h), the pair's
// extrusion (model/Extrusion.h), divide-and-conquer (§4.1) with
// generate-and-test (§4.2), and the witness (search/Witness.h) checked
// against the scene.
#ifndef CLASH4D_CHECK_COLLISION_CHECKER_H
#define CLASH4D_CHECK_COLLISION_CHECKER_H

#include "model/Extrusion.h"
#include "model/Point_classifier.h"
#include "search/Divide_and_conquer.h"
#include "search/Span_region.h"
#include "search/Witness.h"
#include <chrono>
#include <functional>

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

  using Bounds = typename S_bounds<K>::Bounds;

  Collision_checker(const K& k, const Scene_model<K>& model, const std::vector<Bounds>& settled, Check_stats& stats,
                    bool use_sbounds = true)
    : k_(k), model_(model), stats_(stats), use_sbounds_(use_sbounds), settled_(settled) {}

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

  // The plane table of check_span (Extrusion::pair_table) for a sub-span and frame.
  std::vector<H> span_table(int a, int b, std::size_t span_index, const std::array<bool, 3>& frame_of_a,
                            Motion_groups<FT>& groups) const
  {
    const Time_span<FT> span = model_.sub_spans({a, b}).at(span_index);
    Moving A = moving(a, span), B = moving(b, span);
    Vector3<FT> shear;
    for (int q = 0; q < 3; ++q) shear[q] = !use_sbounds_ ? FT(0) : frame_of_a[q] ? A.v[q] : B.v[q];
    return Extrusion<K>::pair_table(A, B, shear, frame_of_a, use_sbounds_, groups);
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

private:
  const K& k_;
  const Scene_model<K>& model_;
  Check_stats& stats_;
  bool use_sbounds_;
  const std::vector<Bounds>& settled_;
  Search_trail* trail_ = nullptr;
  std::size_t span_index_ = 0;
  std::array<bool, 3> frame_of_a_{};       // this span's frame choice per axis
  bool certified_witness_only_ = false;
  Exact_lines exact_lines_;
  Exact_proportional exact_proportional_;

  bool replaying() const { return trail_ && trail_->replaying(); }

  using Moving = Moving_object<FT>;

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
    Span_region<K> bounds(k_, stats_);
    bool alive = use_sbounds_ ? bounds.four_d_bounds(A, B, tl, th) : true;
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
    Box4 region = use_sbounds_ ? bounds.fitted(A, B, tl, th, shear, frame_of_a_) : bounds.original(A, B, span.lo, span.hi, shear);
    for (int q = 0; q < 4; ++q) ss.region += std::string(q ? " x " : "") + interval_text(region.lo[q], region.hi[q]);
    if (has_no_interior(k_, region)) {
      ss.narrowed = "empty";
      stats_.spans.push_back(ss);
      return;
    }
    if (use_sbounds_) region = bounds.on_grid(region, span.lo, span.hi);
    for (int q = 0; q < 3; ++q) ss.frame += std::string(q ? " " : "") + k_.to_text(shear[q]);
    Motion_groups<FT> groups;
    std::vector<H> table = Extrusion<K>::pair_table(A, B, shear, frame_of_a_, use_sbounds_, groups);
    Formula formula = Extrusion<K>::pair_formula(A, B);
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
    r.witness = Witness<K>(k_).make(goal.inside, shear, A, B, span.lo, span.hi);
    r.witness_verified = verify(r.witness, r.a, r.b);
    r.has_witness = true;
    r.t_star = goal.t_star;
    r.contact = goal.contact;
    for (int q = 0; q < 3; ++q) r.contact[q] += shear[q] * r.contact[3];
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

  bool verify(const V4& w, int a, int b) const { return is_valid_witness(k_, model_, a, b, w); }
};

} // namespace clash4d

#endif
