// The search policy: the one interface between the generic stages and a
// filter. The stages (check/Collision_checker.h, search/Divide_and_conquer.h,
// search/Null_object_test.h) run on a kernel and call these members at the
// few places where a filtered run differs from a plain one; they catch no
// exception, keep no trail and call no callback of their own. No_filter is
// the policy of every run that decides its own signs (rational, double): it
// does nothing, and compiles away. The filtered exact kernel's policies are
// in exact/ (Interval_filter.h: the interval run; Earliest_replay.h: a
// rational run straight to the interval run's t*; Exact_line_filter.h: rational
// lines that try intervals first).
//
// A policy P provides:
//   Collision_checker, per sub-span of a pair (in time order):
//     template <class K, class FT> bool enters_span(k, goal, span)
//                                      whether the span could hold a better
//                                      point (Search_goal::can_improve at its
//                                      start; spans come in time order, so
//                                      false stops the pair)
//     bool skips_span(index)           the span is known to hold no collision
//     template <class Decide> std::optional<Verdict> convex_stage(decide)
//                                      a convex pair's linear programs
//                                      (search/Convex_pair.h): decide() gives
//                                      the verdict; a filter failing in it
//                                      may stop the pair instead (nothing;
//                                      stops_after then says so)
//   Convex_pair:
//     template <class Stage, class Predicate> auto convex_certain(stage, p)
//                                      p(stage): one sign of the programs,
//                                      whose arguments are guesses (the same
//                                      in every kernel), certain; a filter
//                                      that cannot tell (p throws, or gives
//                                      an indeterminate CGAL::Uncertain)
//                                      asks p of its exact kernel's stage on
//                                      the same sub-span
//     template <class K, class Stage, class FT>
//       bool convex_improves(k, stage, goal, B, t)   whether the stage's
//                                      point at time t (the vertex of the
//                                      four rows *B, when not null) could
//                                      improve the goal
//                                      (Search_goal::can_improve)
//     template <class Stage> void convex_found(stage)   the stage recorded
//                                      a collision (stage.found() says how)
//     template <class M, class Stage, class Run>
//       void region_stage(a, b, index, A, B, stage, run)   the S-bounds and
//                                      region: run() makes them here; a
//                                      filter may make them elsewhere and
//                                      set A's and B's emptied bounds
//     bool keeps_doubtful_bounds()     run() keeps S-bounds the kernel cannot
//                                      decide (Region_stage::doubtful): the
//                                      policy then takes only a stage that
//                                      prunes the span
//     void search_span(a, b, index, frame_of_a)   the span about to be searched
//     void found_in_span(index)        a (better) point inside was found there
//     bool stops_after(index)          after a span: stop the pair (the
//                                      span found nothing, or the policy
//                                      stopped the search: takes_child and
//                                      decides_here false from then on)
//     bool witness_certified()         the point found may become the witness
//     bool witness_answers(goal)       a witness made from goal could be the
//                                      answer's (a filter whose closed
//                                      witness must be its exact numbers
//                                      declines a contact time it only
//                                      encloses: the witness comes from
//                                      elsewhere, at no cost of a making)
//     template <class F> void attempt(F make)   make the witness; a filter
//                                      failing on the way leaves it unmade
//   Divide_and_conquer:
//     template <class FT> const std::vector<Hyperplane4<FT>>*
//       plane_keys_on_doubt()          plane_keys (below), made now if need
//                                      be: a box simplification is open
//     void uncertain_simplification()  a box simplification was not decided
//                                      (the leaf was kept: regularised-
//                                      semantics item 4)
//     bool takes_child(depth, child)   whether to search this sub-region
//     template <class K, class FT> bool can_enter(k, goal, region)
//                                      whether the region could hold a
//                                      better point (Search_goal::can_improve
//                                      at its lower time)
//     bool decides_here(depth, conquers)  a region decides (folds to inside,
//                                      or is conquered): whether to go on
//     template <class FT> void found_at(path, on_line, region, formula)
//                                      the first point inside was found in
//                                      the region at this division path,
//                                      with the formula simplified there
//     template <class FT> bool jumps_to(region, formula, on_line, path)
//                                      the region that decides is known
//                                      (with its formula, whether it
//                                      conquers, its path): go there directly
//   Null_object_test:
//     const std::array<std::size_t, 3>* replay_line()  go straight to it
//     void replayed(found)             what going straight there gave
//     template <class G> void test_line(G& g, f, i, j, m, goal)
//                                      decide one line (g.test_line)
//     template <class K, class G, class FT, class Fourth>
//       bool improves(k, g, goal, t, line, fourth)   whether a point of
//                                      line (three plane indices of g's
//                                      layout) at time t, where plane
//                                      fourth() cuts it (npos: unknown),
//                                      could improve the goal
//                                      (Search_goal::can_improve)
//     template <class K, class G, class FT> CGAL::Sign
//       compare_cuts(k, g, a, pa, b, pb, line)   the order of cuts a and b
//                                      (by planes pa and pb of g's layout,
//                                      or npos) of line (three plane
//                                      indices): k.compare(a, b)
//     template <class K, class G> bool zero_on_line(k, g, line, p, along)
//                                      a zero k left open: whether plane p
//                                      of g's layout is parallel to line
//                                      (along), or contains it; false: the
//                                      kernel's own sign is asked later
//     int same_plane(k, h, g, entry_h, face_h, entry_g, face_g, region)
//                                      +1/-1/0 as geometry/Hyperplane4.h's
//                                      proportional
//     template <class V, class Inside> std::optional<bool>
//       verdict_first(l, normals, inside, tested)   only a verdict is wanted:
//                                      decide the neighbourhood another way
//                                      first (nothing: classify it here);
//                                      also asked, on a keyed line, with the
//                                      keys of the planes through the point
//     template <class V, class Inside> std::optional<bool>
//       verdict_around(keys, inside, tested)   the same for a closed touch
//                                      point's neighbourhood, on the keys
//     template <class FT> const std::vector<Vector4<FT>>* normal_keys()
//                                      per table entry, a nonzero multiple of
//                                      its normal in numbers this kernel
//                                      computes with exactly (small integers),
//                                      or nothing: zeros certified on them are
//                                      written (Null_object_test)
//     template <class FT> const std::vector<Hyperplane4<FT>>* plane_keys()
//                                      the same for whole planes (normal and
//                                      offset): a plane parallel to a line
//                                      whose key is a combination of the
//                                      line's planes' keys contains it
#ifndef CLASH4D_SEARCH_NO_FILTER_H
#define CLASH4D_SEARCH_NO_FILTER_H

#include "geometry/Box.h"
#include "geometry/Hyperplane4.h"
#include "model/Pair_formula.h"
#include "model/Scene_model.h"
#include "search/Search_goal.h"
#include <CGAL/Uncertain.h>
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace clash4d {

struct No_filter {
  template <class K, class FT>
  bool enters_span(const K& k, const Search_goal<FT>& goal, const Time_span<FT>& span) const
  {
    return goal.can_improve(k, span.lo);
  }
  bool skips_span(std::size_t) const { return false; }
  template <class Decide>
  auto convex_stage(Decide decide) -> std::optional<decltype(decide())>
  {
    return decide();
  }
  template <class Stage, class Predicate>
  auto convex_certain(Stage& stage, Predicate p)
  {
    return CGAL::get_certain(p(stage));   // a kernel deciding its own signs: always certain
  }
  template <class K, class Stage, class FT>
  bool convex_improves(const K& k, Stage&, const Search_goal<FT>& goal, const std::array<int, 4>*, const FT& t) const
  {
    return goal.can_improve(k, t);
  }
  template <class Stage>
  void convex_found(const Stage&) {}
  template <class M, class Stage, class Run>
  void region_stage(int, int, std::size_t, M&, M&, Stage&, Run run)
  {
    run();
  }
  static constexpr bool keeps_doubtful_bounds() { return false; }
  void search_span(int, int, std::size_t, const std::array<bool, 3>&) {}
  void found_in_span(std::size_t) {}
  bool stops_after(std::size_t) const { return false; }
  bool witness_certified() const { return true; }
  template <class FT>
  bool witness_answers(const Search_goal<FT>&) const
  {
    return true;
  }
  template <class F>
  void attempt(F make) { make(); }

  void uncertain_simplification() {}
  bool takes_child(std::size_t, int) const { return true; }
  template <class K, class FT>
  bool can_enter(const K& k, const Search_goal<FT>& goal, const Box<FT, 4>& region) const
  {
    return goal.can_improve(k, region.lo[3]);
  }
  bool decides_here(std::size_t, bool) const { return true; }
  template <class FT>
  void found_at(const std::vector<int>&, bool, const Box<FT, 4>&, const Pair_formula&) {}
  template <class FT>
  bool jumps_to(Box<FT, 4>&, Pair_formula&, bool&, std::vector<int>&) const { return false; }

  const std::array<std::size_t, 3>* replay_line() const { return nullptr; }
  void replayed(bool) {}
  template <class G, class FT>
  void test_line(G& g, const Pair_formula& f, std::size_t i, std::size_t j, std::size_t m, Search_goal<FT>& goal)
  {
    g.test_line(f, i, j, m, goal);
  }
  template <class K, class G, class FT, class Fourth>
  bool improves(const K& k, const G&, const Search_goal<FT>& goal, const FT& t, const std::array<std::size_t, 3>&,
                Fourth) const
  {
    return goal.can_improve(k, t);
  }
  template <class K, class G, class FT>
  CGAL::Sign compare_cuts(const K& k, const G&, const FT& a, std::size_t, const FT& b, std::size_t,
                          const std::array<std::size_t, 3>&) const
  {
    return k.compare(a, b);
  }
  template <class K, class G>
  bool zero_on_line(const K&, const G&, const std::array<std::size_t, 3>&, std::size_t, bool) const
  {
    return false;
  }
  template <class K, class FT>
  int same_plane(const K& k, const Hyperplane4<FT>& h, const Hyperplane4<FT>& g, long, int, long, int,
                 const Box<FT, 4>&)
  {
    return proportional(k, h, g);
  }
  template <class V, class Inside>
  std::optional<bool> verdict_first(const V&, const std::vector<V>&, Inside&, std::size_t&)
  {
    return std::nullopt;
  }
  template <class V, class Inside>
  std::optional<bool> verdict_around(const std::vector<V>&, Inside, std::size_t&)
  {
    return std::nullopt;
  }
  template <class FT>
  const std::vector<Vector4<FT>>* normal_keys() const
  {
    return nullptr;
  }
  template <class FT>
  const std::vector<Hyperplane4<FT>>* plane_keys() const
  {
    return nullptr;
  }
  template <class FT>
  const std::vector<Hyperplane4<FT>>* plane_keys_on_doubt()
  {
    return nullptr;
  }
};

} // namespace clash4d

#endif
