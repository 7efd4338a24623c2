// A scene as written in the file: exact rationals, no number-type choice yet.
#ifndef CLASH4D_SCENE_SCENE_H
#define CLASH4D_SCENE_SCENE_H

#include "numbers/Approximation.h"
#include "numbers/Rational.h"
#include "scene/Mesh_record.h"
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace clash4d {

// Points where four or more of a polytope's planes meet, each as the
// indices of those planes.
using Corners = std::vector<std::vector<int>>;

struct Solid {
  enum class Kind { Halfspace, Block, Convex, Prism, Hull, Union, Intersection, Difference, Translate, Rotate };
  Kind kind = Kind::Halfspace;
  std::string path;                    // JSON path of the solid, for messages
  // Kind-dependent numbers, flat: halfspace a b c d; block min max; convex
  // 4 per half-space; prism x y per vertex then z0 z1; hull x y z per point;
  // translate dx dy dz; rotate w x y z. A mesh file ({"mesh": FILE}) is
  // read as a Hull or a Union of Hulls (scene/Mesh_solid.h).
  std::vector<Rational> numbers;
  std::vector<Solid> children;
  // Exact combinatorics found by validation, so every number type builds the
  // same polytope: hull facets as point triples (outward by right-hand rule),
  // convex vertices as triples of half-space indices.
  std::vector<std::array<int, 3>> triples;
  // Hull and convex: the corners found by validation (scene/Exact_validation.h,
  // Polytope_combinatorics), each as the indices of its four or more planes;
  // none, null. Shared, never changed: every model of the solid (one per
  // check and kernel) holds them without a copy.
  std::shared_ptr<const Corners> corners;
  // Their exact geometry, made by the reader (geometry/Polytope_ft.h), for the
  // kernels that read constructions rather than compute them
  // (K::reads_exact_constructions): hull facet planes a b c d, convex
  // vertices x y z, in the order of triples; rotate: its matrix's rows
  // (geometry/Rotation_matrix.h); empty when not made.
  std::vector<Rational> constructed;
  // Their approximations (numbers/Approximation.h), made by the reader
  // (approximate_numbers) for the kernels that convert (Model_builder):
  // each is read only for the number it was made from, so numbers changed
  // after reading are converted again.
  std::vector<Approximation> numbers_approximated, constructed_approximated;
};

// Every number of s and of the solids under it approximated, once (the
// reader does it for every scene it reads).
void approximate_numbers(Solid& s);

// One pose of a pose motion (spec: Motion with rotation (poses)): at time t
// the object occupies { R(rotate) p + translate : p in shape }, R the
// un-normalised quaternion's rational matrix (geometry/Rotation_matrix.h).
struct Pose {
  Rational t;
  std::array<Rational, 3> translate{Rational(0), Rational(0), Rational(0)};
  std::array<Rational, 4> rotate{Rational(1), Rational(0), Rational(0), Rational(0)};   // w x y z, != 0
};

struct Motion {
  // The poses as written ({"poses": [...]}); empty for a ROBMOD string. A
  // pose motion that never rotates is also read into times and velocities
  // (a piecewise-linear translation, spec: "a motion written either way
  // gives the same answers"); one that rotates is not (rotates()).
  std::vector<Pose> poses;
  std::vector<Rational> times;                    // strictly increasing breakpoints
  std::vector<std::array<Rational, 3>> velocities; // times.size() + 1 segments
  // Their approximations, as a Solid's (made by approximate_numbers):
  // the times, and the velocities' coordinates in order (3 per segment).
  // A motion made or changed in code without them is converted.
  std::vector<Approximation> times_approximated, velocities_approximated;

  // Whether some pose turns the shape: a rotate with x, y or z non-zero
  // (a quaternion (w, 0, 0, 0) is the identity, whatever w).
  bool rotates() const
  {
    for (const Pose& p : poses)
      for (int i = 1; i < 4; ++i)
        if (p.rotate[i] != 0) return true;
    return false;
  }
};

// The motion's numbers approximated, once (the reader does it for every
// object's motion).
void approximate_numbers(Motion& m);

struct Scene_object {
  std::string name;
  Solid shape;
  Motion motion;
};

struct Scene {
  std::string name;
  Rational t_lo, t_hi;
  std::vector<Scene_object> objects;
  std::vector<std::pair<int, int>> ignore;        // object indices, i < j
  std::vector<Mesh_record> meshes;                // each mesh file read, once (docs/meshes.md)

  bool ignored(int i, int j) const
  {
    for (const auto& p : ignore)
      if ((p.first == i && p.second == j) || (p.first == j && p.second == i)) return true;
    return false;
  }
};

const char* solid_key(Solid::Kind k);

// The object moving by `motion` (already valid), its shape as written: a
// rotation-free pose motion's shape is kept at c(0) (scene/Pose_motion.h),
// so the shape is taken back to its written form first.
void set_motion(Scene_object& object, Motion motion);

// The scene with object i moving by motions[i] (one per object, already
// valid): its shapes under other motions (exact/Exact_checker.h, the API).
inline Scene with_motions(Scene scene, const std::vector<Motion>& motions)
{
  for (std::size_t i = 0; i < motions.size(); ++i) set_motion(scene.objects[i], motions[i]);
  return scene;
}

} // namespace clash4d

#endif
