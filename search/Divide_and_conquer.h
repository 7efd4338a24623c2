// Divide-and-conquer over 4D boxes (§4.1): simplify the formula against the
// region, decide at once when it folds to a constant, conquer with
// generate-and-test when it is small (fewer leaves than kappa(d) = 2d + 6),
// otherwise bisect every axis into 16 sub-regions. Depth-first, so memory is
// proportional to the depth; stops at the first region found inside.
// Closed semantics (search/Semantics.h) simplifies strictly, so that a
// half-space touching the closed region only on its boundary stays: a
// contact there is a closed collision.
#ifndef CLASH4D_SEARCH_DIVIDE_AND_CONQUER_H
#define CLASH4D_SEARCH_DIVIDE_AND_CONQUER_H

#include "search/Null_object_test.h"
#include "search/No_filter.h"
#include <CGAL/Uncertain.h>
#include <optional>

namespace clash4d {

template <class K, class Policy = No_filter>
class Divide_and_conquer {
public:
  using FT = typename K::FT;
  using H = Hyperplane4<FT>;
  using Box4 = Box<FT, 4>;

  // Past this depth the region is conquered whatever its size: a depth limit
  // costs time, never a wrong answer.
  static constexpr std::size_t max_depth = 8;

  // Holds a reference into itself (its own policy when none is given).
  Divide_and_conquer(const Divide_and_conquer&) = delete;
  Divide_and_conquer& operator=(const Divide_and_conquer&) = delete;

  // groups: which table planes move together (model/Motion_groups.h), if
  // known. policy: search/No_filter.h.
  Divide_and_conquer(const K& k, const std::vector<H>& table, Check_stats& stats,
                     const Motion_groups<FT>* groups = nullptr, Policy* policy = nullptr)
    : k_(k), table_(table), stats_(stats), policy_(policy ? *policy : own_policy_.emplace()),
      conquer_(k, table, stats, groups, &policy_) {}

  static std::size_t kappa(std::size_t d) { return 2 * d + 6; }

  // Depth-first, earliest times first; the goal says when to stop.
  void search(const Box4& region, const Pair_formula& formula, Search_goal<FT>& goal, std::size_t depth = 0)
  {
    if (!policy_.can_enter(k_, goal, region)) return;
    Work_budget::check();
    if (depth == 0 && jumped(goal)) return;
    stats_.visit(depth);
    bool strict = goal.closed();
    Pair_formula f = formula.simplified([&](std::uint32_t h) { return leaf_status(h, region, strict); });
    if (f.value() == Truth::False) return;
    if (f.value() == Truth::True) {
      if (!policy_.decides_here(depth, false)) return;
      fold(region, f, goal);
      return;
    }
    std::size_t leaves = f.leaf_count();
    if (leaves < kappa(depth) || depth >= max_depth) {
      if (!policy_.decides_here(depth, true)) return;
      conquer(region, f, goal);
      return;
    }
    // Sixteen sub-regions, earliest in time first.
    for (int child = 0; child < 16 && !goal.done(); ++child) {
      if (!policy_.takes_child(depth, child)) continue;
      path_.push_back(child);
      search(sub_region(region, child), f, goal, depth + 1);
      path_.pop_back();
    }
  }

  // Every interior point is inside (closed: every point of the closed
  // region, strict signs); the earliest is on the face t = lo.
  void fold(const Box4& region, const Pair_formula& f, Search_goal<FT>& goal)
  {
    Vector4<FT> c = centre(region), low = c;
    low[3] = region.lo[3];
    Vector4<FT> none{FT(0), FT(0), FT(0), FT(0)};
    if (goal.closed()) goal.record_touch(k_, low, none, none);
    else goal.record(k_, c, low);
    policy_.found_at(path_, false, region, f);
  }

  void conquer(const Box4& region, const Pair_formula& f, Search_goal<FT>& goal)
  {
    std::size_t leaves = f.leaf_count();
    ++stats_.conquers;
    conquered_ = join(conquered_, region);
    stats_.leaves_at_conquer += leaves;
    stats_.max_leaves_at_conquer = std::max(stats_.max_leaves_at_conquer, leaves);
    conquer_.run(f, region, goal);
    if (goal.found) policy_.found_at(path_, true, region, f);
  }

  // A replay that knows the region deciding and its formula goes there
  // directly (exact/Earliest_replay.h), instead of simplifying down the path.
  bool jumped(Search_goal<FT>& goal)
  {
    Box4 at;
    Pair_formula f;
    bool on_line = false;
    if (!policy_.jumps_to(at, f, on_line, path_)) return false;
    if (on_line) conquer(at, f, goal);
    else fold(at, f, goal);
    return true;
  }

  // Skeleton mode (§5): the full search, never stopping. Simplification is
  // strict here (min > 0, max < 0), so a plane touching the region's boundary
  // stays, and regions with no plane of the formula through them are skipped:
  // they hold no boundary.
  void skeleton(const Box4& region, const Formula& formula, std::vector<std::array<Vector4<FT>, 2>>& out,
                std::size_t depth = 0)
  {
    Work_budget::check();
    stats_.visit(depth);
    Formula f = formula.simplified([&](std::uint32_t h) { return leaf_status(h, region, true); });
    if (f.value() != Truth::Unknown) return;
    std::size_t leaves = f.leaf_count();
    if (leaves < kappa(depth) || depth >= max_depth) {
      ++stats_.conquers;
      stats_.leaves_at_conquer += leaves;
      conquer_.skeleton(f, region, out);
      return;
    }
    for (int child = 0; child < 16; ++child) skeleton(sub_region(region, child), f, out, depth + 1);
  }

  // Over a closed box, min h >= 0 means the leaf is empty there and max h <= 0
  // that it is everything, up to the boundary that regularisation ignores
  // (regularised-semantics.md, item 4). Strict (min > 0, max < 0) keeps the
  // planes that touch the box, which the skeleton and closed semantics need
  // (the sign is then fixed on a neighbourhood of the closed box).
  // An approximate kernel that cannot tell keeps the leaf (Unknown):
  // `doubt` says so.
  Truth status(const H& h, const Box4& b, bool strict, bool& doubt) const
  {
    FT lo = h.c, hi = h.c;
    for (int a = 0; a < 4; ++a) {
      FT x = h.n[a] * b.lo[a], y = h.n[a] * b.hi[a];
      lo += Number_ops<FT>::lower(x, y);
      hi += Number_ops<FT>::upper(x, y);
    }
    if (decided(k_.is_nonnegative(lo, strict), doubt)) return Truth::False;
    if (decided(k_.is_nonnegative(-hi, strict), doubt)) return Truth::True;
    return Truth::Unknown;
  }
  Truth status(const H& h, const Box4& b, bool strict = false) const
  {
    bool doubt = false;
    return status(h, b, strict, doubt);
  }

  // Table entry e's status over the region. When the kernel cannot tell,
  // again on the entry's key (the policy's plane_keys_on_doubt: a positive
  // multiple in small integers, so on a grid region a plane through a
  // corner is a zero intervals certify, as under rational rotations); still
  // open, the leaf is kept and the policy told.
  Truth leaf_status(std::uint32_t e, const Box4& region, bool strict)
  {
    bool doubt = false;
    Truth t = status(table_[e], region, strict, doubt);
    if (doubt)
      if (const std::vector<H>* keys = policy_.template plane_keys_on_doubt<FT>()) {
        doubt = false;
        t = status((*keys)[e], region, strict, doubt);
      }
    if (doubt) policy_.uncertain_simplification();
    return t;
  }

  // Child `child` of the 16-way bisection; bit a set: upper half of axis a.
  // t is the slowest bit, so the earliest halves come first.
  static Box4 sub_region(const Box4& region, int child)
  {
    Box4 sub = region;
    for (int a = 0; a < 4; ++a) {
      FT mid = (region.lo[a] + region.hi[a]) / FT(2);
      ((child >> a) & 1 ? sub.lo[a] : sub.hi[a]) = mid;
    }
    return sub;
  }

  // The smallest box holding every region handed to generate-and-test.
  const Box4& conquered() const { return conquered_; }

private:
  const K& k_;
  const std::vector<H>& table_;
  Box4 conquered_ = Box4::nothing();
  Check_stats& stats_;
  std::optional<Policy> own_policy_;   // made only when no policy is given
  Policy& policy_;
  Null_object_test<K, Policy> conquer_;
  std::vector<int> path_;                 // child indices from the root region to here

  static bool decided(CGAL::Uncertain<bool> u, bool& doubt)
  {
    if (CGAL::is_certain(u)) return CGAL::get_certain(u);
    doubt = true;
    return false;
  }


  static Vector4<FT> centre(const Box4& b)
  {
    Vector4<FT> c;
    for (int a = 0; a < 4; ++a) c[a] = (b.lo[a] + b.hi[a]) / FT(2);
    return c;
  }
};

} // namespace clash4d

#endif
