// The search policy of a rational run that replays an earliest-mode
// interval run's last improvement (exact/Interval_filter.h): its trail
// ends there, at the rational run's own last improvement
// (exact/Search_trail.h says why). Earlier sub-spans are skipped, the
// division takes only the trail's child at each depth, and generate-and-
// test only the trail's line (or fold). The run starts from nothing found
// in the trail's sub-span: the least time of the points inside there is
// t*, first recorded at the edge the whole search records last, so the
// goal, the witness and the contact point are the whole search's. Later
// sub-spans cannot improve on t* (none did in the interval run): the run
// stops. Wherever the rational run's path leaves the trail, the replay
// has diverged and the runner searches the whole pair again. A
// sub-span's region stage the interval run had made in rationals
// (exact/Exact_stage.h) is adopted, not made again.
#ifndef CLASH4D_EXACT_EARLIEST_REPLAY_H
#define CLASH4D_EXACT_EARLIEST_REPLAY_H

#include "exact/Exact_stage.h"
#include "exact/Search_trail.h"
#include "search/No_filter.h"
#include <type_traits>

namespace clash4d {

template <class FT>
class Earliest_replay : public No_filter {
public:
  Earliest_replay() = default;   // only as a stage's unused default
  Earliest_replay(const Search_trail& trail, const Exact_stages<FT>& stages) : trail_(&trail), stages_(&stages) {}

  template <class M, class Run>
  void region_stage(int, int, std::size_t index, M& A, M& B, Region_stage<FT>& st, Run run)
  {
    if (auto it = stages_->find(index); it != stages_->end()) {
      it->second.adopt(A, B, st);
      ++adopted_;
      return;
    }
    run();
  }

  // Earlier spans were proven free of collisions; later ones cannot
  // improve on the trail's t*.
  bool skips_span(std::size_t index) const { return index < trail_->span; }
  bool stops_after(std::size_t) const { return true; }

  bool takes_child(std::size_t depth, int child) const
  {
    if (depth >= trail_->path.size()) {
      diverged_ = true;
      return false;
    }
    return child == trail_->path[depth];
  }
  // A region that decides (conquers or folds to inside) must be the trail's
  // last, and decide the same way.
  bool decides_here(std::size_t depth, bool conquers) const
  {
    if (depth == trail_->path.size() && trail_->on_line == conquers) return true;
    diverged_ = true;
    return false;
  }

  // The region at the trail's end, when the interval run knew it exactly:
  // the rational run's own, with its own simplified formula.
  bool jumps_to(Box<FT, 4>& region, Pair_formula& f, bool& on_line, std::vector<int>& path) const
  {
    static_assert(std::is_same_v<FT, Rational>, "a trail's region is in rationals");
    if (!trail_->region) return false;
    const auto& faces = trail_->region->faces;
    for (int q = 0; q < 4; ++q) region.set(q, faces[2 * q], faces[2 * q + 1]);
    f = trail_->region->formula;
    on_line = trail_->on_line;
    path = trail_->path;
    return true;
  }

  // Every line before the trail's made no improvement.
  const std::array<std::size_t, 3>* replay_line() const { return &trail_->line; }
  void replayed(bool found) { diverged_ = diverged_ || !found; }

  // Region stages adopted instead of made again.
  std::size_t adopted() const { return adopted_; }
  // Whether the rational run's path left the trail: its answer is not the
  // whole search's.
  bool diverged() const { return diverged_; }

private:
  const Search_trail* trail_ = nullptr;
  const Exact_stages<FT>* stages_ = nullptr;
  std::size_t adopted_ = 0;
  mutable bool diverged_ = false;   // set by the const hooks the stages call
};

} // namespace clash4d

#endif
