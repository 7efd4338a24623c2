// The convex pieces of a closed, oriented mesh as the inside cells of a
// binary space partition by its facets' planes (an autopartition; Naylor,
// Amanatides and Thibault, "Merging BSP trees yields polyhedral set
// operations", 1990). docs/meshes.md, "The solid".
//
// Each node's plane is one facet's plane; the facet fragments are split by
// it, the coplanar ones stay at the node, and a side left with no fragment
// is one cell, wholly inside or wholly outside: inside on the side a
// fragment at the node faces away from. Every sign is exact (CGAL's lazy
// exact kernel), and every point is made from input planes and points at
// a fixed depth (a cut fragment's corner is its facet's plane met by two
// cut planes, or a facet edge met by one; a cell's corner is three of its
// planes), never from points made before, so no construction grows with
// the tree.
#ifndef CLASH4D_SCENE_BSP_PIECES_H
#define CLASH4D_SCENE_BSP_PIECES_H

#include "scene/Exact_validation.h"
#include "scene/Mesh_check.h"
#include <cstddef>
#include <string>
#include <vector>

namespace clash4d {

// The inside cells' corners, each cell the hull of its corners; their
// union is the solid the triangles bound, their interiors disjoint. Past
// max_pieces cells it stops, with more than max_pieces (the caller
// refuses, docs/meshes.md, Limits). Throws Input_error (exit 2)
// naming file_name where the facets' orientations contradict (they bound
// no solid).
std::vector<std::vector<Rational3>> bsp_pieces(const Checked_mesh& mesh, const std::string& file_name,
                                               std::size_t max_pieces);

} // namespace clash4d

#endif
