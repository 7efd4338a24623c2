// Where an approximate run found its first point inside a pair's collision
// region, so that the exact run can go straight there (the "recomputed
// exactly on demand" half of the filtered kernel, core/Filtered_runner.h).
//
// Why following the trail gives the exact run's own answer: every decision
// the approximate run made was a certified sign, except when to stop the
// S-bound passes and which frame to fit the region in (core/Number_ops.h,
// Kernel_base::prefer_less). The trail records both; the exact run compares
// its own with them at the span, and leaves the trail (diverged) on any
// difference. With equal pass counts and frames the approximate numbers
// enclose exactly the exact run's S-bounds, region, planes and formula, so
// every region the division visited before the found one, and every line
// before the found one, is certified empty for the exact run too: the exact
// run's first point inside is the one at the end of the trail. Earlier spans
// hold no collision at all (the approximate run proved it, whatever its
// S-bounds), so they are skipped.
#ifndef CLASH4D_CORE_SEARCH_TRAIL_H
#define CLASH4D_CORE_SEARCH_TRAIL_H

#include <array>
#include <cstddef>
#include <vector>

namespace clash4d {

struct Search_trail {
  enum class Mode { Record, Replay };
  Mode mode = Mode::Record;

  bool complete = false;                // Record: a point inside was found and the trail leads to it
  bool diverged = false;                // Replay: the exact run's path differs; use a full run
  bool approximate = false;             // Record: a simplification was skipped as uncertain, so
                                        // the path may differ from the exact run's: no replay
  std::size_t span = 0;                 // index of the sub-span, in time order
  std::vector<int> sbound_passes;       // pass counts of that span's S-bound stage, in order
  std::array<bool, 3> frame_of_a{};     // per axis: measured in the first object's frame
  std::vector<int> path;                // division: child index at each depth
  bool on_line = false;                 // found on a line (else a region folded to "inside")
  std::array<std::size_t, 3> line{};    // the line's three planes, in generate-and-test's order
  bool line_known = true;               // false: the region was conquered exactly, replay it whole

  bool recording() const { return mode == Mode::Record; }
  bool replaying() const { return mode == Mode::Replay; }
};

} // namespace clash4d

#endif
