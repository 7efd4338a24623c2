// The search policy of a rational run that goes straight to the point an
// interval run found (exact/Search_trail.h says why that is the rational
// run's own point): earlier sub-spans are skipped, the division takes only
// the trail's child at each depth, and generate-and-test only the trail's
// line. Wherever the rational run's path leaves the trail, the trail is
// marked diverged and the runner searches the whole pair again. A
// sub-span's region stage the interval run had made in rationals, or made
// itself in numbers that came out exact (exact/Exact_stage.h), is adopted,
// not made again.
#ifndef CLASH4D_EXACT_TRAIL_REPLAY_H
#define CLASH4D_EXACT_TRAIL_REPLAY_H

#include "exact/Exact_stage.h"
#include "exact/Search_trail.h"
#include "search/No_filter.h"
#include <type_traits>

namespace clash4d {

template <class FT>
class Trail_replay : public No_filter {
public:
  Trail_replay() = default;   // only as a stage's unused default
  explicit Trail_replay(Search_trail& trail, const Exact_stages<FT>* stages = nullptr)
    : trail_(&trail), stages_(stages) {}

  template <class M, class Run>
  void region_stage(int, int, std::size_t index, M& A, M& B, Region_stage<FT>& st, Run run)
  {
    if (stages_)
      if (auto it = stages_->find(index); it != stages_->end()) {
        it->second.adopt(A, B, st);
        ++adopted_;
        return;
      }
    run();
  }

  // Earlier spans were proven free of collisions; the trail's must hold it.
  bool skips_span(std::size_t index) const { return index < trail_->span; }
  bool stops_after(std::size_t) const
  {
    trail_->diverged = true;
    return true;
  }

  bool takes_child(std::size_t depth, int child) const
  {
    if (depth >= trail_->path.size()) {
      trail_->diverged = true;
      return false;
    }
    return child == trail_->path[depth];
  }
  // A region that decides (conquers or folds to inside) must be the trail's
  // last, and decide the same way.
  bool decides_here(std::size_t depth, bool conquers) const
  {
    if (depth == trail_->path.size() && trail_->on_line == conquers) return true;
    trail_->diverged = true;
    return false;
  }

  // The region at the trail's end, when the interval run knew it exactly:
  // the rational run's own, with its own simplified formula.
  bool jumps_to(Box<FT, 4>& region, Pair_formula& f, bool& on_line, std::vector<int>& path) const
  {
    static_assert(std::is_same_v<FT, Rational>, "a trail's region is in rationals");
    if (!trail_->region_known) return false;
    for (int q = 0; q < 4; ++q) region.set(q, trail_->region[2 * q], trail_->region[2 * q + 1]);
    f = trail_->formula;
    on_line = trail_->on_line;
    path = trail_->path;
    return true;
  }

  // Every line before the trail's was certified to hold no point inside.
  const std::array<std::size_t, 3>* replay_line() const { return trail_->line_known ? &trail_->line : nullptr; }
  void replayed(bool found) { trail_->diverged = trail_->diverged || !found; }

  // Region stages adopted instead of made again.
  std::size_t adopted() const { return adopted_; }

private:
  Search_trail* trail_ = nullptr;
  const Exact_stages<FT>* stages_ = nullptr;
  std::size_t adopted_ = 0;
};

// Earliest mode: the trail ends at the interval run's last improvement,
// the rational run's (exact/Interval_filter.h). The rational run starts
// from nothing found in the trail's sub-span and examines only the trail's
// line (or fold): the least time of the points inside there is t*, first
// recorded at the edge the whole search records last, so the goal, the
// witness and the contact point are the whole search's. Later sub-spans
// cannot improve on t* (none did in the interval run): the run stops.
template <class FT>
class Earliest_replay : public Trail_replay<FT> {
public:
  Earliest_replay() = default;
  explicit Earliest_replay(Search_trail& trail, const Exact_stages<FT>* stages = nullptr)
    : Trail_replay<FT>(trail, stages) {}
  bool stops_after(std::size_t) const { return true; }
};

} // namespace clash4d

#endif
