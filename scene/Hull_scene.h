// Random general-position scenes for the filtered kernel's benchmark and
// tests: a union of two random convex hulls against the difference of two,
// each under three constant-velocity segments over [0, 10]. Coordinates are
// on a 1/997 grid and velocities on a 1/101 grid, so nothing is axis-aligned
// or dyadic and no plane meets another by design.
#ifndef CLASH4D_SCENE_HULL_SCENE_H
#define CLASH4D_SCENE_HULL_SCENE_H

#include <random>
#include <string>

namespace clash4d {

// The scene file text; successive calls on one generator give the sequence
// the benchmark reports as "random #i". Only the generator's raw output is
// used (scene/Random_draw.h), so the sequence is the same everywhere.
std::string make_hull_scene(std::mt19937_64& rng);

} // namespace clash4d

#endif
