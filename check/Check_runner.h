// `check` over a whole scene with one kernel: every pair not ignored, in
// order, stopping at the first collision unless all pairs are asked for.
#ifndef CLASH4D_CHECK_CHECK_RUNNER_H
#define CLASH4D_CHECK_CHECK_RUNNER_H

#include "check/Check_answer.h"
#include "check/Collision_checker.h"
#include "check/Pair_skeleton.h"
#include "check/Pair_sweep.h"
#include "check/Piece_pairs.h"
#include "numbers/Number_ops.h"
#include "run/Work_budget.h"
#include <boost/container/small_vector.hpp>
#include <algorithm>
#include <atomic>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>
#include <type_traits>
#include <utility>

namespace clash4d {

// A colliding pair's result r in text (check/Check_answer.h), written into
// p, a fresh answer in place (an answer is 27 strings: no move).
template <class K>
void pair_answer(const K& k, const Scene_model<K>& model, const Pair_result<typename K::FT>& r, Pair_answer& p)
{
  p.a = model.objects[r.a].name;
  p.b = model.objects[r.b].name;
  for (int i = 0; i < 4; ++i) p.witness[i] = k.to_text(r.witness[i]);
  p.witness_verified = r.witness_verified;
  p.earliest = r.earliest;
  bool closed = r.semantics == Semantics::closed;
  if ((closed && r.witness_cells.size() != 2) || (r.earliest && r.contact_cells.size() != 2))
    throw std::logic_error("internal error: a colliding pair without the generic points of its cells");
  // x's text, or `made`, the text of `like` when x is the same number: the
  // contact and the cells often repeat the witness (closed, earliest), and
  // GMP's text is much of a small pair's answer.
  auto text = [&](const typename K::FT& x, const typename K::FT& like, const std::string& made) {
    return Number_ops<typename K::FT>::same(x, like) ? made : k.to_text(x);
  };
  for (int c = 0; c < 2; ++c)
    for (int i = 0; i < 4; ++i) {
      if (closed) p.witness_cells[c][i] = text(r.witness_cells[c][i], r.witness[i], p.witness[i]);
      if (r.earliest)
        p.contact_cells[c][i] = closed ? text(r.contact_cells[c][i], r.witness_cells[c][i], p.witness_cells[c][i])
                                       : text(r.contact_cells[c][i], r.witness[i], p.witness[i]);
    }
  if (r.earliest) {
    for (int i = 0; i < 4; ++i) p.contact[i] = text(r.contact[i], r.witness[i], p.witness[i]);
    p.t_star = text(r.t_star, r.contact[3], p.contact[3]);
    p.at_start = k.compare(r.t_star, model.t_lo) == CGAL::ZERO;
  }
}

// What run_pairs asks of a pair's result: Pair_result here; a filtered
// run's own type provides the same three (exact/Filtered_result.h).
template <class FT>
bool collides(const Pair_result<FT>& r)
{
  return r.collide;
}
// t*, asked with --earliest only.
template <class FT>
const FT& collision_time(const Pair_result<FT>& r)
{
  return r.t_star;
}
// A regularised collision with a verified witness made the closed answer
// (closed_pair): true, and r is that answer; false, r unchanged.
template <class FT>
bool close_on_witness(Pair_result<FT>& r)
{
  if (!r.collide || !r.has_witness || !r.witness_verified) return false;
  r.semantics = Semantics::closed;
  r.witness_cells = {r.witness, r.witness};
  r.contact = r.witness;
  return true;
}

// Closed semantics without --earliest: a regularised collision is a closed
// contact (regularised-semantics item 6), and its generic witness is a
// touching point inside both objects, so it serves as the point and as the
// generic point of each object's cell (item 1). The regularised search is
// the cheaper (S-bounds prune touching pairs, and its witness is a grid
// point), so it goes first; only a pair it finds apart is searched closed.
template <class Result, class Check_one>
Result closed_pair(std::size_t i, Check_one& check, Check_stats& stats)
{
  Result r = check(i, nullptr, Semantics::regularised, stats);
  if (close_on_witness(r)) return r;
  Check_stats closed_stats = stats.fresh();
  r = check(i, nullptr, Semantics::closed, closed_stats);
  stats.add(closed_stats);
  return r;
}

// Pairs are checked a chunk (Check_options::pair_chunk) at a time: a Result
// and a 700-byte Check_stats are kept per pair of the chunk, not of the
// scene (issue 59 item 5: 2,000 overlapping blocks, 2 million candidate
// pairs, took 1.76 GB), and the work budget is looked at between chunks.

// Pairs are independent, so they are checked in parallel (TBB); results are
// kept per pair and merged in pair order, so the answer is the one a single
// thread gives: the first colliding pair in order, or the smallest t* with
// the first pair in order among equals. check(i, ceiling, semantics, stats)
// decides pair i, and answer_one(r, p) writes a colliding result's text
// into p; a result is a Pair_result in K's numbers, or a filtered run's
// own (exact/Filtered_result.h: it may hold another kernel's exact numbers),
// its t* in K's numbers.
template <class K, class Check_one, class Answer_one>
class Pair_runner {
public:
  using FT = typename K::FT;
  using Result = std::decay_t<std::invoke_result_t<Check_one&, std::size_t, const FT*, Semantics, Check_stats&>>;

  Pair_runner(const K& k, const Check_options& options, Check_one& check, Answer_one& answer_one, Check_answer& answer)
    : k_(k), options_(options), check_(check), answer_one_(answer_one), answer_(answer)
  {}

  // Pairs [from, to): checked, then merged into the answer in order. False
  // when the answer is complete (any-collision mode found its pair).
  bool run_chunk(std::size_t from, std::size_t to)
  {
    // One pair (the common query) inline: no allocation for either. Each
    // pair's stats made empty in place, timed as the run (what fresh() gives,
    // without copying a 700-byte struct per pair).
    boost::container::small_vector<Result, 1> results(to - from);
    boost::container::small_vector<Check_stats, 1> stats(to - from);
    for (Check_stats& s : stats) s.timed = answer_.stats.timed;
    std::atomic<std::size_t> first_hit{to};   // any-collision mode: lowest colliding index
    auto check_one = [&](std::size_t i) {
      if (!options_.all_pairs && !options_.earliest && i > first_hit.load()) return;
      Result& r = results[i - from];
      r = decide(i, stats[i - from]);
      if (!collides(r)) return;
      if (options_.earliest) lower_best(collision_time(r));
      std::size_t seen = first_hit.load();
      while (i < seen && !first_hit.compare_exchange_weak(seen, i)) {}
    };
    // In a context of its own: a caller's cancellation (another case of a
    // fuzz batch throwing) would otherwise end this loop early and silently,
    // leaving pairs unchecked, a "no collision" nobody decided.
    // One pair (the common query) is checked here: no tasks to share.
    if (to - from == 1) {
      check_one(from);
    } else {
      tbb::task_group_context own(tbb::task_group_context::isolated);
      tbb::parallel_for(tbb::blocked_range<std::size_t>(from, to, 1),
                        [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) check_one(i);
                        },
                        own);
    }
    return merge(results, stats);
  }

  // --earliest alone: only the earliest pair is reported (others may have
  // been cut short by the ceiling), moved to the front: a copy of its texts
  // was a tenth of an --earliest query.
  void keep_earliest_only()
  {
    if (!options_.earliest || options_.all_pairs || answer_.earliest_pair < 0) return;
    auto first = static_cast<std::size_t>(answer_.earliest_pair);
    if (first > 0) std::swap(answer_.pairs.front(), answer_.pairs[first]);
    answer_.pairs.erase(answer_.pairs.begin() + 1, answer_.pairs.end());
    answer_.earliest_pair = 0;
  }

private:
  const K& k_;
  const Check_options& options_;
  Check_one& check_;
  Answer_one& answer_one_;
  Check_answer& answer_;
  std::mutex best_mutex_;
  std::optional<FT> best_;          // the least t* found so far (--earliest): a ceiling for later pairs
  std::optional<FT> merged_best_;   // the least t* merged into the answer

  Result decide(std::size_t i, Check_stats& stats)
  {
    std::optional<FT> ceiling;
    if (options_.earliest && !options_.all_pairs) {
      // An exact kernel's answer does not depend on the ceiling (ties are
      // still found: search/Search_goal.h), so the threads share theirs. A
      // float search cut at another point may end elsewhere (issue 60: a
      // double t* that changed from run to run), so a float kernel takes
      // only the earlier chunks' best, which is the same in every run.
      std::lock_guard<std::mutex> lock(best_mutex_);
      ceiling = K::is_exact ? best_ : merged_best_;
    }
    return options_.semantics == Semantics::closed && !options_.earliest
               ? closed_pair<Result>(i, check_, stats)
               : check_(i, ceiling ? &*ceiling : nullptr, options_.semantics, stats);
  }

  void lower_best(const FT& t)
  {
    std::lock_guard<std::mutex> lock(best_mutex_);
    if (!best_ || k_.less(t, *best_)) best_ = t;
  }

  template <class Results, class Stats>
  bool merge(const Results& results, const Stats& stats)
  {
    for (std::size_t i = 0; i < results.size(); ++i) {
      answer_.stats.add(stats[i]);
      const Result& r = results[i];
      if (!collides(r)) continue;
      if (!options_.all_pairs && !options_.earliest && answer_.collide) return false;
      answer_.collide = true;
      answer_one_(r, answer_.pairs.emplace_back());
      if (options_.earliest && (!merged_best_ || k_.less(collision_time(r), *merged_best_))) {
        merged_best_ = collision_time(r);
        answer_.earliest_pair = static_cast<int>(answer_.pairs.size()) - 1;
      }
    }
    return options_.all_pairs || options_.earliest || !answer_.collide;
  }
};

template <class K, class Check_one, class Answer_one>
void run_pairs(const K& k, const std::vector<std::pair<int, int>>& pairs, const Check_options& options,
               Check_one check, Answer_one answer_one, Check_answer& answer)
{
  Pair_runner<K, Check_one, Answer_one> runner(k, options, check, answer_one, answer);
  std::size_t chunk = std::max<std::size_t>(1, options.pair_chunk);
  for (std::size_t from = 0; from < pairs.size(); from += chunk) {
    if (from > 0) Work_budget::check();
    if (!runner.run_chunk(from, std::min(pairs.size(), from + chunk))) break;
  }
  runner.keep_earliest_only();
}

// Object pairs the sweep keeps (§6), written into pairs (certain: see
// Pair_sweep::candidates), with the sweep's counts and time. Each object's
// root is its settled S-bounds' first box, read in place.
template <class K>
void candidate_pairs(const K& k, const Scene_model<K>& model,
                     const std::vector<typename S_bounds<K>::Bounds>& settled, const Scene& scene,
                     Check_stats& stats, Semantics semantics, std::vector<std::pair<int, int>>& pairs,
                     std::vector<char>* certain = nullptr)
{
  Stage_clock clock(stats.timed);
  Pair_sweep<K>(k, semantics == Semantics::closed)
      .candidates_into(model, [&](std::size_t i) -> const auto& { return settled[i][0]; }, scene, pairs, certain);
  std::size_t n = model.objects.size();
  stats.object_pairs = n * (n - 1) / 2 - scene.ignore.size();
  stats.candidate_pairs = pairs.size();
  stats.seconds_sweep = clock.seconds();
}
// The same, returned.
template <class K>
std::vector<std::pair<int, int>> candidate_pairs(const K& k, const Scene_model<K>& model,
                                                 const std::vector<typename S_bounds<K>::Bounds>& settled,
                                                 const Scene& scene, Check_stats& stats,
                                                 Semantics semantics = Semantics::regularised)
{
  std::vector<std::pair<int, int>> pairs;
  candidate_pairs(k, model, settled, scene, stats, semantics, pairs);
  return pairs;
}

// --earliest on unions of convex pieces by piece pairs (check/Piece_pairs.h)
// in K, on the scene's model in K; none when the query is not one it
// answers, or its points failed their check (the caller runs the cascade).
template <class K>
std::optional<Check_answer> piece_pairs_check(const K& k, const Scene& scene, const Scene_model<K>& model,
                                              const Check_options& options, const Piece_split& split,
                                              typename Piece_pairs<K>::Pair_check pair_check = {},
                                              const typename Piece_pairs<K>::Pair_list* may_meet = nullptr)
{
  Check_answer answer;
  answer.number = K::name();
  answer.semantics = options.semantics;
  answer.stats.timed = options.stage_seconds;
  std::optional<Pair_result<typename K::FT>> r = Piece_pairs<K>(k, scene, model, split, options, std::move(pair_check), may_meet).earliest(answer.stats);
  if (!r) return std::nullopt;
  if (r->collide) {
    answer.collide = true;
    pair_answer(k, model, *r, answer.pairs.emplace_back());
    answer.earliest_pair = 0;
  }
  return answer;
}

template <class K>
Check_answer run_check(const K& k, const Scene& scene, const Check_options& options)
{
  using Checker = Collision_checker<K>;
  Stage_clock clock(options.stage_seconds);
  Scene_model<K> model = Scene_model<K>::build(k, scene);
  double model_seconds = clock.seconds();
  std::optional<Piece_split> split = Piece_pairs<K>::asked(options) ? Piece_split::make(scene) : std::nullopt;
  if (split)
    if (std::optional<Check_answer> a = piece_pairs_check(k, scene, model, options, *split)) {
      a->stats.seconds_model = model_seconds;
      return std::move(*a);
    }
  Check_answer answer;
  answer.number = K::name();
  answer.semantics = options.semantics;
  answer.stats.timed = options.stage_seconds;
  answer.stats.seconds_model = model_seconds;
  auto settled = settled_bounds_all(k, model, answer.stats, options.sbounds);
  std::vector<std::pair<int, int>> pairs = candidate_pairs(k, model, settled, scene, answer.stats, options.semantics);
  auto check = [&](std::size_t i, const typename K::FT* ceiling, Semantics semantics, Check_stats& stats) {
    Checker checker(k, model, settled, stats, options.sbounds);
    checker.use_convex_lp(options.convex_lp);
    return checker.check_pair(pairs[i].first, pairs[i].second, options.earliest, ceiling, semantics);
  };
  auto answer_one = [&](const Pair_result<typename K::FT>& r, Pair_answer& p) { pair_answer(k, model, r, p); };
  run_pairs(k, pairs, options, check, answer_one, answer);
  return answer;
}

// skeleton(i, stats): the collision-region edges of pair i, in K's numbers.
template <class K, class Skeleton_one>
void run_skeleton_pairs(const K& k, const Scene_model<K>& model, const std::vector<std::pair<int, int>>& pairs,
                        Skeleton_one skeleton, Skeleton_answer& answer)
{
  std::vector<std::vector<typename Pair_skeleton<K>::Segment>> edges(pairs.size());
  std::vector<Check_stats> stats(pairs.size(), answer.stats.fresh());
  tbb::task_group_context own(tbb::task_group_context::isolated);   // as in run_pairs
  tbb::parallel_for(std::size_t(0), pairs.size(), [&](std::size_t i) { edges[i] = skeleton(i, stats[i]); }, own);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    answer.stats.add(stats[i]);
    if (edges[i].empty()) continue;
    Skeleton_answer::Pair p{model.objects[pairs[i].first].name, model.objects[pairs[i].second].name, {}};
    for (const auto& e : edges[i]) {
      std::array<std::array<std::string, 4>, 2> text;
      for (int end = 0; end < 2; ++end)
        for (int q = 0; q < 4; ++q) text[end][q] = k.to_text(e[end][q]);
      p.edges.push_back(text);
    }
    answer.pairs.push_back(p);
  }
}

template <class K>
Skeleton_answer run_skeleton(const K& k, const Scene& scene)
{
  Skeleton_answer answer;
  answer.number = K::name();
  Scene_model<K> model = Scene_model<K>::build(k, scene);
  auto settled = settled_bounds_all(k, model, answer.stats, true);
  std::vector<std::pair<int, int>> pairs = candidate_pairs(k, model, settled, scene, answer.stats);
  run_skeleton_pairs(k, model, pairs, [&](std::size_t i, Check_stats& stats) {
    return Pair_skeleton<K>(k, model, settled, stats).edges(pairs[i].first, pairs[i].second);
  }, answer);
  return answer;
}

} // namespace clash4d

#endif
