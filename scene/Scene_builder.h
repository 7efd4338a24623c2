// Building scenes in code, exactly: the generators (grid, hull, the fuzz
// families) and the tests make a Scene from these pieces and write it with
// scene/Scene_writer.h, instead of concatenating JSON text. Nothing here
// validates: read the written text back (read_scene) to get a checked scene
// with its hull and convex combinatorics.
#ifndef CLASH4D_SCENE_SCENE_BUILDER_H
#define CLASH4D_SCENE_SCENE_BUILDER_H

#include "scene/Scene.h"
#include <nlohmann/json.hpp>
#include <array>
#include <string>
#include <vector>

namespace clash4d {

using Vec3 = std::array<Rational, 3>;
using Point2 = std::array<Rational, 2>;

inline Vec3 vec(const Rational& x, const Rational& y, const Rational& z) { return {x, y, z}; }
Vec3 plus(Vec3 a, const Vec3& b);
Vec3 minus(Vec3 a, const Vec3& b);
Vec3 times(const Rational& s, Vec3 a);

// Solids, numbers in the flat order of scene/Scene.h.
Solid block(const Vec3& lo, const Vec3& hi);
Solid halfspace(const Rational& a, const Rational& b, const Rational& c, const Rational& d);
Solid hull(const std::vector<Vec3>& points);
Solid convex(const std::vector<std::array<Rational, 4>>& planes);
// The base is put counter-clockwise and z0, z1 in order; it must be strictly convex.
Solid prism(std::vector<Point2> base, Rational z0, Rational z1);
// Union, intersection or difference of the children.
Solid csg(Solid::Kind kind, std::vector<Solid> children);
Solid translate(const Vec3& d, Solid child);
// A rotate carries its exact matrix, as the reader makes it (rotation_rows),
// so a scene built here and the same scene read from its file give every
// kernel the same numbers.
Solid rotate(const std::array<Rational, 4>& q, Solid child);
// The rows of q's rotation matrix, flat (Solid::constructed of a rotate):
// exact, so a kernel that rounds them (reads_exact_rotations) sees one
// plane where two rotations share a face.
std::vector<Rational> rotation_rows(const std::array<Rational, 4>& q);

// Motions.
Motion steady(const Vec3& velocity);
Motion rest();
// Velocities vs[0..k] changing at the increasing times ts (k = ts.size()).
Motion piecewise(std::vector<Vec3> vs, std::vector<Rational> ts);

class Scene_builder {
public:
  Scene_builder(std::string name, const Rational& t_lo, const Rational& t_hi);
  Scene_builder& object(std::string name, Solid shape, Motion motion = rest());
  // The object (already added) moving by these poses (spec: Motion with
  // rotation (poses)), checked as the reader checks them: Input_error at
  // "objects[i].motion..." (scene/Pose_motion.h).
  Scene_builder& motion_poses(const std::string& name, std::vector<Pose> poses);
  // Objects by name; both must have been added.
  Scene_builder& ignore(const std::string& a, const std::string& b);
  const Scene& scene() const { return scene_; }
  // The scene file text, with `meta` (when not null) under its meta key.
  std::string text(const nlohmann::ordered_json& meta = nullptr) const;

private:
  int index_of(const std::string& name) const;
  Scene scene_;
};

} // namespace clash4d

#endif
