// Where an approximate run found a point inside a pair's collision region
// (earliest mode: its last improvement), so that the exact run can go
// straight there (the "recomputed exactly on demand" half of the filtered
// kernel, exact/Filtered_runner.h), when the approximate run could not make
// the witness itself. An any-witness run keeps only whether its path is
// certified (complete, not approximate): the line that found the point is
// then the rational run's first with a point, and is run again alone.
//
// Why following the trail gives the exact run's own answer: every decision
// the approximate run made was a certified sign, the heuristic ones included
// (S-bound passes and frames are decided on grid points,
// Kernel_base::grid_point), except a box simplification it could not decide
// (it kept the leaf and marked the trail `approximate`: no replay then). So
// the approximate numbers enclose exactly the exact run's S-bounds, region,
// planes and formula, every region the division visited before the found
// one, and every line before the found one, is certified empty for the
// exact run too: the exact run's first point inside is the one at the end
// of the trail. Earlier spans hold no collision at all (the approximate run
// proved it), so they are skipped. The exact run still checks that the
// trail leads somewhere (Earliest_replay::diverged otherwise, and a full
// run follows).
#ifndef CLASH4D_EXACT_SEARCH_TRAIL_H
#define CLASH4D_EXACT_SEARCH_TRAIL_H

#include "model/Pair_formula.h"
#include "numbers/Rational.h"
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace clash4d {

struct Search_trail {
  bool complete = false;                // a point inside was found and the trail leads to it
  bool approximate = false;             // a simplification was skipped as uncertain, so the
                                        // path may differ from the exact run's: no replay
  std::size_t span = 0;                 // index of the sub-span, in time order
  std::vector<int> path;                // division: child index at each depth
  bool on_line = false;                 // found on a line (else a region folded to "inside")
  std::array<std::size_t, 3> line{};    // the line's three planes, in generate-and-test's order
  // The region at the end of the path, when its faces are exact (point
  // intervals: the rational run's region), with the formula simplified
  // there (the rational run's: every simplification on the way was
  // certified): the replay goes there directly (Divide_and_conquer::jumped).
  struct Known_region {
    std::array<Rational, 8> faces;      // lo and hi per axis, x y z t
    Pair_formula formula;
  };
  std::optional<Known_region> region;
};

} // namespace clash4d

#endif
