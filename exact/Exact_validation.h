// Geometric validity of solids, decided exactly with CGAL (exact predicates,
// convex hull, linear programming). Only the exact scene is validated; every
// number type then builds from the combinatorics found here.
#ifndef CLASH4D_EXACT_EXACT_VALIDATION_H
#define CLASH4D_EXACT_EXACT_VALIDATION_H

#include "exact/Rational.h"
#include <array>
#include <string>
#include <vector>

namespace clash4d {

using Rational3 = std::array<Rational, 3>;
using Rational4 = std::array<Rational, 4>;   // a x + b y + c z + d <= 0

// Empty string when the polygon is strictly convex and counter-clockwise with
// at least 3 vertices and no three collinear; otherwise why not.
std::string prism_base_problem(const std::vector<std::array<Rational, 2>>& base);

// Facets of the convex hull as point-index triples oriented outward (right
// hand rule). Throws std::invalid_argument when the points are coplanar.
std::vector<std::array<int, 3>> hull_facets(const std::vector<Rational3>& points);

// For an intersection of half-spaces: empty string when it is bounded with an
// interior, else why not (decided by exact linear programming).
std::string convex_problem(const std::vector<Rational4>& planes);

// The vertices of a bounded convex polytope with interior, each as the three
// (independent) half-space indices whose planes meet there.
std::vector<std::array<int, 3>> convex_vertex_triples(const std::vector<Rational4>& planes);

} // namespace clash4d

#endif
