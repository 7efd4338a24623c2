// Greedy shrinking of a scene (or a CCD query) on which something fails (in
// the manner of delta debugging and QuickCheck's shrinkers), so a fuzz
// finding comes out small enough to read. Scene steps, largest first:
//   drop an object (at least two stay; `ignore` is renumbered);
//   replace a union, intersection, difference, translate or rotate node by
//   one of its children;
//   drop a child of a union or intersection, or a subtrahend of a difference
//   beyond the first;
//   make a motion rest, merge two adjacent motion segments, stop one segment;
//   drop a half-space of a convex solid, a point of a hull, a vertex of a prism;
//   replace a number by a simpler one (0, nearby integers, fewer decimal
//   digits, convergents of its continued fraction).
// Each step either removes something or makes a number strictly simpler, so
// the loop ends by itself; it also stops after `max_checks` predicate calls.
#ifndef CLASH4D_COMPARE_SHRINKER_H
#define CLASH4D_COMPARE_SHRINKER_H

#include "ccd/Ccd_query.h"
#include "scene/Scene.h"
#include <cstddef>
#include <functional>

namespace clash4d {

// Returns the smallest scene reached on which `still_fails` holds (the input
// itself when no step keeps it failing; otherwise named "shrunk from: NAME",
// since what the name says of the original may no longer hold). Every candidate is first written and
// read back as a scene file (write_scene, read_scene), which validates it and
// redoes its hull and convex combinatorics; invalid candidates are skipped
// and never passed to the predicate. The predicate is called at most
// `max_checks` times, never twice on the same scene; a predicate that throws
// counts as "does not fail".
Scene shrink_scene(const Scene& scene, const std::function<bool(const Scene&)>& still_fails,
                   std::size_t max_checks = 2000);

// The same for a CCD query (fuzz --ccd), by the same loop. Steps, largest
// first: a common translation removed (every vertex moved so that one of
// the eight rows is at the origin, or by the integer part of the first row:
// the exact answer and t* stay, the doubles' rounding changes); a vertex at
// rest (its two rows made equal); each coordinate replaced by a simpler
// number, as above. The query keeps its type, label and line.
Ccd_query shrink_query(const Ccd_query& query, const std::function<bool(const Ccd_query&)>& still_fails,
                       std::size_t max_checks = 2000);

} // namespace clash4d

#endif
