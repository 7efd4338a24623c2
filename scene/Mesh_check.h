// Whether a mesh bounds a solid, decided exactly (docs/meshes.md): closed,
// edge-manifold, consistently and outward oriented, non-degenerate strictly
// convex planar facets, no pinched vertex, no self-intersection (but where
// the copies of a split pinched vertex meet at their point), a positive
// volume; and whether it is convex.
#ifndef CLASH4D_SCENE_MESH_CHECK_H
#define CLASH4D_SCENE_MESH_CHECK_H

#include "scene/Mesh_reader.h"

namespace clash4d {

// How a non-convex mesh is cut into convex pieces (docs/meshes.md, "The
// solid"): the inside cells of a partition by its facets' planes
// (scene/Bsp_pieces.h), or CGAL's Nef polyhedron convex_decomposition_3.
enum class Mesh_decomposition { bsp, nef };

inline const char* decomposition_name(Mesh_decomposition d) { return d == Mesh_decomposition::bsp ? "bsp" : "nef"; }

// A mesh that bounds a solid: its distinct points (equal points of the
// file merged, unused ones dropped) and its facets triangulated (fans of
// the strictly convex facets), outward by the right-hand rule.
struct Checked_mesh {
  std::vector<std::array<Rational, 3>> vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> facet_of;    // the file's facet index of each triangle
  Rational volume;              // > 0, exact
  bool convex = false;          // every edge convex and one connected surface
};

// Whether equal points are one vertex: a file's mesh is merged (STL writes
// each facet's own copies), a repaired one (scene/Mesh_repair.h) is merged
// already and keeps apart the copies of a split pinched vertex.
enum class Equal_points { merge, keep };

// Throws Input_error (exit 2) with place "FILE_NAME: facet F" (or "vertex
// ..." or "FILE_NAME") and what is wrong, e.g. "edge shared by 3 facets".
// F is file_facet[f] for the mesh's facet f when given (a repaired mesh or
// one shell of it, scene/Mesh_repair.h), so messages name the file's facet.
Checked_mesh check_mesh(const Mesh& mesh, const std::string& file_name, const std::vector<int>& file_facet = {});

// check_mesh in two steps, so that a mesh whose pieces come from the
// decomposition cache skips the costliest check (scene/Mesh_solid.h): every
// check but the crossings, then the crossings (CGAL's exact
// self-intersection test) on the result.
// Vertices at the same point (the copies of a split pinched vertex, kept by
// Equal_points::keep) may meet there: two facets whose only common point is
// such a point do not cross; any other common point is a crossing.
Checked_mesh check_mesh_surface(const Mesh& mesh, const std::string& file_name,
                                const std::vector<int>& file_facet = {}, Equal_points equal = Equal_points::merge);
void check_no_crossing(const Checked_mesh& mesh, const std::string& file_name);

// The shell of each triangle: the triangles joined through shared vertices
// (the copies of a split pinched vertex are distinct vertices), named by a
// vertex of the shell.
std::vector<int> shell_of_triangles(const Checked_mesh& mesh);

// The mesh with the points no facet uses dropped and, with
// Equal_points::merge, equal points as one vertex; throws Input_error for a
// vertex index out of range.
Mesh merged_points(const Mesh& mesh, const std::string& file_name, const std::vector<int>& file_facet = {},
                   Equal_points equal = Equal_points::merge);

// Newell's normal of a polygon (unnormalised): zero exactly when its area is.
std::array<Rational, 3> newell_normal(const std::vector<int>& polygon, const std::vector<std::array<Rational, 3>>& V);

// Why a polygon of more than three vertices with Newell normal N is not a
// facet the check accepts (not planar, or not strictly convex), or empty.
std::string polygon_fault(const std::vector<int>& polygon, const std::array<Rational, 3>& N,
                          const std::vector<std::array<Rational, 3>>& V);

} // namespace clash4d

#endif
