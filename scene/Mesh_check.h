// Whether a mesh bounds a solid, decided exactly (docs/meshes.md): closed,
// edge-manifold, consistently and outward oriented, non-degenerate strictly
// convex planar facets, no pinched vertex, no self-intersection, a positive
// volume; and whether it is convex.
#ifndef CLASH4D_SCENE_MESH_CHECK_H
#define CLASH4D_SCENE_MESH_CHECK_H

#include "scene/Mesh_reader.h"

namespace clash4d {

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

// Throws Input_error (exit 2) with place "FILE_NAME: facet F" (or "vertex
// ..." or "FILE_NAME") and what is wrong, e.g. "edge shared by 3 facets".
Checked_mesh check_mesh(const Mesh& mesh, const std::string& file_name);

} // namespace clash4d

#endif
