// Triangles of a CSG solid for the report's 3D view, in doubles: drawing
// only. Nothing here feeds an answer; the exact check never sees these
// numbers.
#ifndef CLASH4D_COMPARE_DISPLAY_MESH_H
#define CLASH4D_COMPARE_DISPLAY_MESH_H

#include "model/Csg_model.h"
#include <array>
#include <cstddef>
#include <vector>

namespace clash4d {

struct Display_mesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<int, 3>> triangles;   // outward by the right-hand rule
  std::size_t cells = 0;      // non-empty convex cells drawn
  bool clipped = false;       // some cell reached the drawing box (an unbounded cell, cut)
  bool truncated = false;     // more cells than drawn (the DNF grew past the cap)
};

// A bound of the solid of CSG node i: join for union, meet for intersection,
// the first child for difference.
Box<double, 3> node_box(const Csg_model<double>& m, int i);

// The solid as the union of the convex cells of its DNF (a difference's
// subtrahend complemented plane by plane), each cell cut by the box
// [lo, hi]; cells may overlap (drawn twice, which looks the same). Vertices
// are shared within a cell, not between cells.
Display_mesh display_mesh(const Csg_model<double>& m, const std::array<double, 3>& lo,
                          const std::array<double, 3>& hi);

} // namespace clash4d

#endif
