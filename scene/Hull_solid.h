// A hull solid made from its points: the combinatorics and constructions
// the scene reader validates and stores for every hull (Solid::triples,
// corners, constructed), shared by JSON hulls and mesh solids.
#ifndef CLASH4D_SCENE_HULL_SOLID_H
#define CLASH4D_SCENE_HULL_SOLID_H

#include "scene/Exact_validation.h"
#include "scene/Scene.h"

namespace clash4d {

// Fills s (kind Hull) from the points, and returns six times its volume
// (what the mesh cache checks pieces by); throws std::invalid_argument when
// they all lie in one plane.
Rational make_hull_solid(const std::vector<Rational3>& points, Solid& s);

} // namespace clash4d

#endif
