// Scaling scenes for the many-object stage (§6): n unit blocks on a grid with
// spacing 4, each wobbling inside its own cell (so no two ever meet), except
// `colliding` disjoint pairs of x-neighbours driven into each other: they
// close their gap of 3 at relative speed 3/5 and so collide from t* = 5 on.
#ifndef CLASH4D_SCENE_GRID_SCENE_H
#define CLASH4D_SCENE_GRID_SCENE_H

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace clash4d {

struct Grid_scene {
  std::string json;                               // the scene file text
  std::vector<std::pair<int, int>> colliding;     // object indices, by construction
};

// Throws std::invalid_argument when colliding pairs do not fit in n blocks.
Grid_scene make_grid_scene(int n, int colliding, std::uint64_t seed);

} // namespace clash4d

#endif
