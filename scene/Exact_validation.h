// Geometric validity of solids, decided exactly with CGAL (exact predicates,
// convex hull, linear programming). Only the exact scene is validated; every
// number type then builds from the combinatorics found here.
#ifndef CLASH4D_SCENE_EXACT_VALIDATION_H
#define CLASH4D_SCENE_EXACT_VALIDATION_H

#include "numbers/Rational.h"
#include <array>
#include <string>
#include <vector>

namespace clash4d {

using Rational3 = std::array<Rational, 3>;
using Rational4 = std::array<Rational, 4>;   // a x + b y + c z + d <= 0

// Empty string when the polygon is strictly convex and counter-clockwise with
// at least 3 vertices and no three collinear; otherwise why not.
std::string prism_base_problem(const std::vector<std::array<Rational, 2>>& base);

// A convex polytope's combinatorics: `triples` as below, and its corners,
// the points where four or more of its planes meet, each as the indices of
// those planes (in triples' order for a hull, half-space indices for a
// convex solid). Three planes meet at every vertex; a fourth through it is a
// zero that arithmetic on enclosures cannot see and the search writes
// instead (model/Motion_groups.h).
struct Polytope_combinatorics {
  std::vector<std::array<int, 3>> triples;
  std::vector<std::vector<int>> corners;
  Rational six_volume{0};   // hull_facets only: six times the hull's volume
};

// Facets of the convex hull as point-index triples oriented outward (right
// hand rule), one per facet plane. Throws std::invalid_argument when the
// points are coplanar.
Polytope_combinatorics hull_facets(const std::vector<Rational3>& points);

// For an intersection of half-spaces: empty string when it is bounded with an
// interior, else why not (decided by exact linear programming).
std::string convex_problem(const std::vector<Rational4>& planes);

// The vertices of a bounded convex polytope with interior, each as the three
// (independent) half-space indices whose planes meet there.
Polytope_combinatorics convex_vertex_triples(const std::vector<Rational4>& planes);

} // namespace clash4d

#endif
