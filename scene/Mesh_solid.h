// A checked mesh as a solid of the scene (docs/meshes.md): a convex mesh is
// the hull of its vertices; any other is the exact union of the convex
// pieces of CGAL's Nef_polyhedron_3 convex_decomposition_3, each the hull of
// its vertices. Exact throughout (CGAL's lazy exact kernel, and rationals).
#ifndef CLASH4D_SCENE_MESH_SOLID_H
#define CLASH4D_SCENE_MESH_SOLID_H

#include "scene/Mesh_check.h"
#include "scene/Mesh_options.h"
#include "scene/Mesh_record.h"
#include "scene/Scene.h"

namespace clash4d {

// Kind Hull, or Union of Hull children, of a mesh that passed
// check_mesh_surface (check_mesh is fine too): the crossing test is run here,
// unless the pieces come from the cache. Throws Input_error with place
// file_name: exit 2 for crossing facets, exit 3 beyond limits.pieces convex
// pieces. With a record, a
// non-convex mesh's pieces go through the decomposition cache
// (scene/Mesh_cache.h) and the record gets triangles, pieces and what the
// decomposition cost; without one, it is decomposed every time.
Solid mesh_solid(const Checked_mesh& mesh, const std::string& file_name, const Mesh_limits& limits = Mesh_limits(),
                 Mesh_record* record = nullptr, Mesh_decomposition method = Mesh_decomposition::bsp);

// A non-convex mesh that passed check_mesh as the union of its convex
// pieces by `method`, each the hull of its vertices (what mesh_solid does
// for a mesh that is not convex). The pieces' volumes are held to the
// facets' signed volume: exit 2 where they differ.
Solid decomposed_solid(const Checked_mesh& mesh, const std::string& file_name, const Mesh_limits& limits = Mesh_limits(),
                       Mesh_decomposition method = Mesh_decomposition::bsp);

// read_mesh_file, check_mesh and mesh_solid in turn (the record, when
// given, also gets the file's facets).
Solid read_mesh_solid(const std::string& path, const std::string& file_name, const Mesh_limits& limits = Mesh_limits(),
                      Mesh_record* record = nullptr);

// A mesh as read, scaled and repaired as the options say
// (scene/Mesh_repair.h), then the solid by the options' rule; what happened
// is written to record.
Solid repaired_solid(const Mesh& file, const std::string& file_name, const Mesh_options& options, Mesh_record& record,
                     const Mesh_limits& limits = Mesh_limits());

// read_mesh_file and repaired_solid.
Solid read_mesh_solid(const std::string& path, const std::string& file_name, const Mesh_options& options,
                      Mesh_record& record, const Mesh_limits& limits = Mesh_limits());

} // namespace clash4d

#endif
