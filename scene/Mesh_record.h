// What happened to one mesh file while a scene was read (docs/meshes.md):
// the options it was read with, the repairs that changed it, and what the
// decomposition cost. `check --stats` and the report show it, so a user
// sees that an answer is about a repaired, scaled or stand-in solid.
#ifndef CLASH4D_SCENE_MESH_RECORD_H
#define CLASH4D_SCENE_MESH_RECORD_H

#include <string>
#include <vector>

namespace clash4d {

struct Mesh_record {
  std::string file;                    // as written in the scene
  std::string place;                   // the scene's JSON path of the first use
  int facets = 0;                      // as read from the file
  int triangles = 0;                   // after the repairs, of the checked surface
  int pieces = 0;                      // convex pieces of the solid (1: a hull)
  std::string scale;                   // the exact factor applied ("1" when none)
  std::string solid_rule;              // "odd shells", "union of shells" or "hull of the vertices"
  std::vector<std::string> repairs;    // one line per repair that changed something
  std::string decomposition;           // "bsp" or "nef" ("": none, a convex mesh or a hull)
  double decomposition_seconds = 0;    // the convex decomposition (0: convex, or cached)
  std::string cache;                   // "hit", "miss", "off" or "" (no decomposition)
};

} // namespace clash4d

#endif
