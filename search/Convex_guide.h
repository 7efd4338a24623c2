// One object's guide for the convex pairs it is in (search/Convex_pair.h):
// its one primitive in doubles, made from the scene's own numbers rounding
// to nearest (Guide_numbers), so the same doubles in every kernel's run.
// Guesses only: the simplex's, never a sign of an answer.
// It depends on the object alone, so a holder of many pairs (a check of
// many objects, a prepared scene's repeated queries: exact/
// Filtered_runner.h) makes it once per object, through a Guide_source.
#ifndef CLASH4D_SEARCH_CONVEX_GUIDE_H
#define CLASH4D_SEARCH_CONVEX_GUIDE_H

#include "model/Model_builder.h"
#include "model/Motion_path.h"
#include "scene/Scene.h"
#include <CGAL/FPU.h>
#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace clash4d {

// The guide's numbers: a scene's rationals rounded to the nearest double,
// plain signs (what Model_builder and Motion_path need). Guesses only.
struct Guide_numbers {
  using FT = double;
  static constexpr bool reads_exact_constructions = true;   // the reader's exact hull planes, rounded
  double from_rational(const Rational& q) const { return nearest_double(q); }
  double from_approximation(const Approximation& a) const { return a.nearest; }
  CGAL::Sign sign(double x) const { return CGAL::sign(x); }
};

// An object's planes (as a model's, in the world), its motion, and a point
// strictly inside its solid, guessed (its vertices' mean).
struct Convex_guide {
  std::vector<Plane3<double>> planes;
  Motion_path<double> motion;
  Vector3<double> deep{};

  static std::shared_ptr<Convex_guide> make(const Scene_object& object)
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    auto guide = std::make_shared<Convex_guide>();
    Guide_numbers g;
    Primitive<double> p = Model_builder<Guide_numbers>(g).placed_geometry(object.shape);
    guide->deep = deep_point(p);
    guide->planes = std::move(p.planes);
    guide->motion = Motion_path<double>::build(g, object.motion);
    return guide;
  }

  // The motion made again (a prepared scene's object moved: exact/
  // Exact_checker.h): planes and deep point depend on the shape alone.
  void set_motion(const Motion& m)
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    motion.rebuild(Guide_numbers(), m);
  }

  // A point strictly inside the primitive, in doubles: its vertices' mean
  // (interior for a polytope with interior), or for a half-space
  // n.x + d <= 0, -(d + 1) n / (n.n), where it is -1.
  static Vector3<double> deep_point(const Primitive<double>& p)
  {
    Vector3<double> m{0, 0, 0};
    if (p.vertices.empty()) {
      const Plane3<double>& h = p.planes[0];
      double nn = h[0] * h[0] + h[1] * h[1] + h[2] * h[2];
      for (int q = 0; q < 3; ++q) m[q] = -(h[3] + 1) * h[q] / nn;
      return m;
    }
    for (const auto& v : p.vertices)
      for (int q = 0; q < 3; ++q) m[q] += v[q];
    for (int q = 0; q < 3; ++q) m[q] /= static_cast<double>(p.vertices.size());
    return m;
  }
};

// A pair's two guides, A's then B's; an empty one is made by the pair.
using Convex_guides = std::array<std::shared_ptr<const Convex_guide>, 2>;

// Object i's guide, from whoever keeps them (Collision_checker::use_guides).
using Guide_source = std::function<std::shared_ptr<const Convex_guide>(int object)>;

} // namespace clash4d

#endif
