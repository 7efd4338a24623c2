// --earliest on unions (check/Piece_pairs.h) in the filtered kernel: the
// piece pairs that may meet, searched before the scene is made in
// rationals, which is most of a small query's time (5x double on random
// unions, before).
//
// Which pairs may meet is the piece scene's sweep (ties decided exactly)
// and, for each pair it keeps, the moving boxes' first meeting in
// intervals (Piece_pairs' own bound). The pairs are then searched
// (--earliest, no ceiling) by their meeting time's lower bound, up to the
// first that collides. None does: that is the answer, in either
// semantics, with nothing made in rationals. One does: Piece_pairs runs
// and takes each search it would make again from here, when it is the
// same search: a pair that does not collide has no collision below any
// ceiling; a colliding pair's answer is the one Piece_pairs gets only when
// it asks with no ceiling (no pair before it in its exact order collides).
// The answer is Piece_pairs', whichever searches are reused.
#ifndef CLASH4D_EXACT_PIECE_PREPASS_H
#define CLASH4D_EXACT_PIECE_PREPASS_H

#include "check/Piece_pairs.h"
#include "numbers/Rational.h"
#include <algorithm>
#include <map>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace clash4d {

template <class Runner>
class Piece_prepass {
public:
  using Pair_list = std::vector<std::pair<int, int>>;

  // None when the sweep cannot be made in intervals (Piece_pairs then asks
  // every pair itself). runner: the piece scene's (split.scene).
  static std::optional<Piece_prepass> make(const Scene& scene, const Piece_split& split, Runner& runner,
                                           const Check_options& options)
  {
    const Pair_list* swept = runner.swept_pairs(options.semantics);
    if (!swept) return std::nullopt;
    Piece_prepass p;
    p.stats_.timed = options.stage_seconds;
    // The first meeting's lower bound, then Piece_pairs' tie order: the
    // owners' pair, then the pieces (numbered by owner: i < j).
    std::vector<std::tuple<double, int, int, int, int>> order;
    for (auto [i, j] : *swept) {
      if (j < i) std::swap(i, j);
      int a = split.owner[static_cast<std::size_t>(i)], b = split.owner[static_cast<std::size_t>(j)];
      if (a == b || scene.ignored(a, b)) continue;
      if (auto t = runner.box_meeting(i, j)) order.emplace_back(t->inf(), a, b, i, j);
    }
    std::sort(order.begin(), order.end());
    for (const auto& [t, a, b, i, j] : order) p.meeting_.push_back({i, j});
    p.search(runner, options);
    return p;
  }

  // The piece pairs of two objects not ignored that may meet; every
  // other's boxes never do.
  const Pair_list& meeting() const { return meeting_; }

  // Every pair that may meet was searched, and none collides: no pair of
  // pieces does.
  bool apart() const
  {
    return searched_.size() == meeting_.size() &&
           std::none_of(searched_.begin(), searched_.end(), [](const auto& s) { return s.second.collide; });
  }

  // The searches' counts.
  const Check_stats& stats() const { return stats_; }

  // Piece pair (i, j) searched below `ceiling` as this pass searched it;
  // none: not searched here, or searched with no ceiling and colliding.
  std::optional<Pair_result<Rational>> answer(int i, int j, const Rational* ceiling) const
  {
    auto it = searched_.find({i, j});
    if (it == searched_.end() || (it->second.collide && ceiling)) return std::nullopt;
    return it->second;
  }

private:
  Pair_list meeting_;
  std::map<std::pair<int, int>, Pair_result<Rational>> searched_;
  Check_stats stats_;

  // Each meeting pair in order, up to the first that collides.
  void search(Runner& runner, const Check_options& options)
  {
    for (auto [i, j] : meeting_) {
      if (searched_.size() % 64 == 63) Work_budget::check();
      std::optional<Pair_result<Rational>> r = runner.check_one(i, j, options, nullptr, stats_);
      if (!r) return;
      bool collide = r->collide;
      searched_.emplace(std::pair<int, int>{i, j}, std::move(*r));
      if (collide) return;
    }
  }
};

} // namespace clash4d

#endif
