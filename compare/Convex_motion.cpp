#include "compare/Convex_motion.h"
#include "compare/Comparer.h"
#include "model/Model_builder.h"
#include "model/Motion_path.h"
#include "exact/Rational_kernel.h"
#include "float/Double_kernel.h"
#include "scene/Input_error.h"

#include <CGAL/Cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <cmath>
#include <map>
#include <stdexcept>

namespace clash4d {
namespace {

using Kind = Solid::Kind;

struct Not_expressible {
  std::string what, path;   // "a difference", and where
};

// What the libraries cannot take in s, if anything: they take convex
// primitives, placed by translations and rotations, and their unions.
std::optional<Not_expressible> cannot_take(const Solid& s)
{
  switch (s.kind) {
    case Kind::Translate:
    case Kind::Rotate:
      return cannot_take(s.children[0]);
    case Kind::Union:
      for (const Solid& c : s.children)
        if (auto problem = cannot_take(c)) return problem;
      return std::nullopt;
    case Kind::Intersection:
      return Not_expressible{"an intersection", s.path};
    case Kind::Difference:
      return Not_expressible{"a difference", s.path};
    case Kind::Halfspace:
      return Not_expressible{"a half-space (unbounded, not a polyhedron)", s.path};
    default:
      return std::nullopt;
  }
}

using Exact_geometry = CGAL::Cartesian<Rational>;
using Point_3 = Exact_geometry::Point_3;

// The hull of the exact points (CGAL, exact: only extreme points stay), its
// vertices rounded to the nearest double; none when a coordinate has no double.
std::optional<Convex_polytope> rounded_hull(const std::vector<Vector3<Rational>>& points)
{
  std::vector<Point_3> pts;
  for (const auto& p : points) pts.emplace_back(p[0], p[1], p[2]);
  CGAL::Surface_mesh<Point_3> mesh;
  CGAL::convex_hull_3(pts.begin(), pts.end(), mesh);
  Convex_polytope out;
  std::map<std::size_t, int> index;
  for (auto v : mesh.vertices()) {
    const Point_3& p = mesh.point(v);
    std::array<double, 3> x{round_to_nearest(p.x()), round_to_nearest(p.y()), round_to_nearest(p.z())};
    for (double c : x)
      if (!std::isfinite(c)) return std::nullopt;
    index[v.idx()] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(x);
  }
  for (auto f : mesh.faces()) {
    std::vector<int> corners;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) corners.push_back(index.at(v.idx()));
    out.faces.push_back(corners);
  }
  return out;
}

// What the scene as written asks that a translation of convex pieces cannot
// do (its numbers in the messages); "" when nothing. Rounding is monotonic,
// so a velocity change outside (tL, tH) stays outside in the rounded scene.
std::string inexpressible(const Scene& scene, const std::string& engine)
{
  for (const Scene_object& o : scene.objects) {
    std::string object = "object '" + o.name + "' ";
    for (const Rational& t : o.motion.times)
      if (scene.t_lo < t && t < scene.t_hi)
        return object + "changes velocity at t = " + to_string(t) + ", inside the span (" + engine +
               "'s translation motion has one constant velocity)";
    if (auto problem = cannot_take(o.shape))
      return object + (problem->path == o.shape.path ? "is " + problem->what
                                                    : "contains " + problem->what + " at " + problem->path);
  }
  return "";
}

} // namespace

std::string Convex_motion::convert(const Scene& scene, const std::string& engine)
{
  if (std::string why = inexpressible(scene, engine); !why.empty()) return why;
  Scene rounded;
  try {
    rounded = rounded_scene(scene);
  } catch (const Input_error& e) {
    return "the scene rounded to doubles is invalid (" + e.format("rounded scene") + ")";
  } catch (const std::range_error& e) {
    return e.what();
  }
  t_lo = round_to_nearest(rounded.t_lo);
  t_hi = round_to_nearest(rounded.t_hi);
  ignore = rounded.ignore;
  // The model builder places every primitive's vertices exactly (a union's
  // primitives are its convex pieces); the motion path gives D(t) exactly.
  Rational_kernel k;
  for (const Scene_object& o : rounded.objects) {
    Object fo;
    fo.name = o.name;
    for (const auto& p : Model_builder<Rational_kernel>(k).build(o.shape).primitives) {
      std::optional<Convex_polytope> piece = rounded_hull(p.vertices);
      if (!piece) return "object '" + o.name + "' has a vertex coordinate beyond the range of doubles";
      fo.pieces.push_back(*piece);
    }
    Motion_path<Rational> path = Motion_path<Rational>::build(k, o.motion);
    Vector3<Rational> d0 = path.displacement(rounded.t_lo), d1 = path.displacement(rounded.t_hi);
    for (int i = 0; i < 3; ++i) {
      fo.begin[i] = round_to_nearest(d0[i]);
      fo.end[i] = round_to_nearest(d1[i]);
      if (!std::isfinite(fo.begin[i]) || !std::isfinite(fo.end[i])) return "object '" + o.name + "' moves beyond the range of doubles";
    }
    objects.push_back(std::move(fo));
  }
  return "";
}

Check_answer Convex_motion::answer(const Check_options& options, const std::string& number,
                                   const std::function<std::optional<double>(int, int)>& time_of_contact) const
{
  Check_answer answer;
  answer.number = number;
  double t_min = 0;
  int n = static_cast<int>(objects.size());
  auto ignored = [&](int i, int j) {
    for (const auto& p : ignore)
      if ((p.first == i && p.second == j) || (p.first == j && p.second == i)) return true;
    return false;
  };
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if (ignored(i, j)) continue;
      std::optional<double> toc = time_of_contact(i, j);
      if (!toc) continue;
      Pair_answer p;
      p.a = objects[i].name;
      p.b = objects[j].name;
      if (options.earliest) {
        double t = t_lo + *toc * (t_hi - t_lo);
        p.earliest = true;
        p.t_star = Double_kernel().to_text(t);
        p.at_start = *toc <= 0;
        if (answer.earliest_pair < 0 || t < t_min) {
          answer.earliest_pair = static_cast<int>(answer.pairs.size());
          t_min = t;
        }
      }
      answer.pairs.push_back(p);
      if (!options.all_pairs && !options.earliest) {
        answer.collide = true;
        return answer;
      }
    }
  answer.collide = !answer.pairs.empty();
  return answer;
}

} // namespace clash4d
