// The open cells next to a point that several planes pass through, at an
// algebraic time r: the topes of the central arrangement of the planes'
// normals there (regularised-semantics.md, fact 12: the closed question at
// an irrational critical time asks whether one of them is inside a CSG
// shape). Where at most three independent planes pass through the point,
// every choice of sides is a cell; a vertex of four faces, or planes
// through one line, have fewer, and a choice no cell has must not be taken.
#ifndef CLASH4D_ROTATION_CENTRAL_TOPES_H
#define CLASH4D_ROTATION_CENTRAL_TOPES_H

#include "numbers/Algebraic.h"
#include "rotation/Pose_segments.h"
#include <array>
#include <set>
#include <vector>

namespace clash4d {

// A direction in space as polynomials in t: a plane's normal n(t), or one
// made from normals by cross products and sums.
using Time_direction = std::array<Time_poly, 3>;

// The sign of p at t, exactly in Q(t).
CGAL::Sign sign_at(const Time_poly& p, const Algebraic& t);

// The strict sides (each -1 or +1, one per normal) of every open cell of
// the planes through a point with these normals at r, none of them zero
// there. Each is the side of a direction, so no cell is made up:
//  - rank 3: every cell has on its boundary a line v = +-(n_i x n_j) of two
//    independent normals; next to v it is a sector between two
//    consecutive planes through v, which holds the sum of their rays
//    +-(v x n_a) (both in the plane normal to v), and it is on v's side of
//    every plane not through v. So each cell is v + d w for some v, some
//    pair of rays with w their sum, and d > 0 small;
//  - rank 2 (every normal normal to one line v): the cells are the
//    sectors about v, found the same way;
//  - rank 1 (parallel normals): the two sides.
std::set<std::vector<int>> central_topes(const std::vector<Time_direction>& normals, const Algebraic& r);

} // namespace clash4d

#endif
