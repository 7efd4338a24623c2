// The repairs a user may ask for on a mesh file (docs/meshes.md, "Repairs,
// scale and units"), each exact and on the file's own vertices: the scale,
// facets cut into triangles, zero-area facets dropped, facets turned, a
// pinched vertex split into one vertex per fan. The result is then
// checked as strictly as any mesh (scene/Mesh_check.h); a repair never
// hides a fault it was not asked to mend.
#ifndef CLASH4D_SCENE_MESH_REPAIR_H
#define CLASH4D_SCENE_MESH_REPAIR_H

#include "scene/Mesh_options.h"
#include "scene/Mesh_reader.h"
#include <string>
#include <vector>

namespace clash4d {

struct Repaired_mesh {
  Mesh mesh;                           // equal points merged (but a split pinched vertex's copies); the facets after the repairs
  std::vector<int> file_facet;         // the file's facet of each facet
  std::vector<std::string> repairs;    // what each repair changed (none: it changed nothing)
};

// The file's mesh scaled and repaired as the options say.
Repaired_mesh repaired_mesh(const Mesh& file, const Mesh_options& options, const std::string& file_name);

// Its shells: the facets joined across the edges that exactly two facets
// share, each with the whole vertex list (a check drops the points a shell
// does not use).
std::vector<Repaired_mesh> shells_of(const Repaired_mesh& mesh);

} // namespace clash4d

#endif
