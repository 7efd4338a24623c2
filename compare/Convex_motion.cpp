#include "compare/Convex_motion.h"
#include "compare/Comparer.h"
#include "model/Model_builder.h"
#include "model/Motion_path.h"
#include "rotation/Pose_segments.h"
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
    if (o.motion.rotates())
      for (const Pose& p : o.motion.poses)
        if (scene.t_lo < p.t && p.t < scene.t_hi)
          return object + "has a pose at t = " + to_string(p.t) + ", inside the span (" + engine +
                 "'s motion turns at one constant angular velocity over the span)";
    if (auto problem = cannot_take(o.shape))
      return object + (problem->path == o.shape.path ? "is " + problem->what
                                                    : "contains " + problem->what + " at " + problem->path);
  }
  return "";
}

// q / |q| in doubles (the libraries take unit quaternions).
std::array<double, 4> unit(const std::array<Rational, 4>& q)
{
  std::array<double, 4> d;
  double n = 0;
  for (int i = 0; i < 4; ++i) {
    d[i] = round_to_nearest(q[i]);
    n += d[i] * d[i];
  }
  n = std::sqrt(n);
  for (double& x : d) x /= n;
  return d;
}

// A turning object's placements at tL and tH (its origin c into d0, d1) and
// orientations, from its one pose segment over the span (exact, then
// rounded); r = conj(q_L) q_H / |q_L|^2, the pose's turn relative to q_L.
void place_turning(Convex_motion::Object& fo, const Motion& m, const Rational& lo, const Rational& hi,
                   Vector3<Rational>& d0, Vector3<Rational>& d1)
{
  std::vector<Pose_segment> segments = pose_segments(m);
  const Pose_segment& a = segment_at(segments, lo);
  const Pose_segment& b = segment_at(segments, hi);
  std::array<Rational, 4> qa, qb;
  for (int i = 0; i < 4; ++i) {
    qa[i] = a.q[i].at(lo);
    qb[i] = b.q[i].at(hi);
  }
  for (int i = 0; i < 3; ++i) {
    d0[i] = a.c[i].at(lo);
    d1[i] = b.c[i].at(hi);
  }
  fo.begin_q = unit(qa);
  fo.end_q = unit(qb);
  Rational n = qa[0] * qa[0] + qa[1] * qa[1] + qa[2] * qa[2] + qa[3] * qa[3];
  // conj(qa) qb (Hamilton product), divided by |qa|^2.
  std::array<Rational, 4> r = {qa[0] * qb[0] + qa[1] * qb[1] + qa[2] * qb[2] + qa[3] * qb[3],
                               qa[0] * qb[1] - qa[1] * qb[0] - qa[2] * qb[3] + qa[3] * qb[2],
                               qa[0] * qb[2] + qa[1] * qb[3] - qa[2] * qb[0] - qa[3] * qb[1],
                               qa[0] * qb[3] - qa[1] * qb[2] + qa[2] * qb[1] - qa[3] * qb[0]};
  for (int i = 0; i < 4; ++i) fo.relative[i] = round_to_nearest(r[i] / n);
  fo.turns = CGAL::sign(r[1]) != CGAL::ZERO || CGAL::sign(r[2]) != CGAL::ZERO || CGAL::sign(r[3]) != CGAL::ZERO;
  fo.longer_arc = fo.turns && CGAL::sign(r[0]) != CGAL::POSITIVE;
}

bool rests(const Convex_motion::Object& o) { return !o.turns && o.begin == o.end; }

// The pose's s in [0, 1] at which it has turned by `angle` (radians) of
// its turn r: the relative quaternion (1 - s) + s r has half-angle a where
// tan a = s |r_v| / ((1 - s) + s r_w).
double pose_fraction(const Convex_motion::Object& o, double angle)
{
  double rv = std::sqrt(o.relative[1] * o.relative[1] + o.relative[2] * o.relative[2] + o.relative[3] * o.relative[3]);
  double a = angle / 2;
  return std::sin(a) / (rv * std::cos(a) - (o.relative[0] - 1) * std::sin(a));
}

// The whole turn's angle, as the libraries take it (the shorter arc).
double turn_angle(const Convex_motion::Object& o)
{
  double rv = std::sqrt(o.relative[1] * o.relative[1] + o.relative[2] * o.relative[2] + o.relative[3] * o.relative[3]);
  return 2 * std::atan2(rv, std::fabs(o.relative[0]));
}

} // namespace

std::string Convex_motion::law_differs(int i, int j, double max_angle) const
{
  const Object &a = objects[i], &b = objects[j];
  if (!a.turns && !b.turns) return "";
  const Object& turning = a.turns ? a : b;
  const Object& other = a.turns ? b : a;
  std::string pair = "'" + a.name + "' and '" + b.name + "': ";
  if (other.turns) return pair + "both turn (the library turns each at its own constant angular velocity)";
  if (!rests(other)) return pair + "'" + other.name + "' moves while '" + turning.name + "' turns";
  if (turning.begin != turning.end)
    return pair + "'" + turning.name + "' turns while its origin moves (the library's motion is a screw or a "
                  "rotation about the moving centre at constant speeds, not the pose's)";
  if (turning.longer_arc) return pair + "'" + turning.name + "' turns the longer way (the library takes the shorter arc)";
  if (turn_angle(turning) > max_angle)
    return pair + "'" + turning.name + "' turns by more than the library's step allows (it clamps the turn)";
  return "";
}

std::string Convex_motion::law_differs(double max_angle) const
{
  int n = static_cast<int>(objects.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      bool ignored = false;
      for (const auto& p : ignore) ignored = ignored || (p.first == i && p.second == j) || (p.first == j && p.second == i);
      if (ignored) continue;
      if (std::string why = law_differs(i, j, max_angle); !why.empty()) return why;
    }
  return "";
}

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
    Vector3<Rational> d0, d1;
    if (o.motion.rotates()) {
      place_turning(fo, o.motion, rounded.t_lo, rounded.t_hi, d0, d1);
    } else {
      Motion_path<Rational> path = Motion_path<Rational>::build(k, o.motion);
      d0 = path.displacement(rounded.t_lo);
      d1 = path.displacement(rounded.t_hi);
    }
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
        // The change of time (fact 13) where the library's turn is the pose's.
        double s = *toc;
        const Object& turning = objects[i].turns ? objects[i] : objects[j];
        if (turning.turns && law_differs(i, j, 4 * std::atan(1.0)).empty())
          s = pose_fraction(turning, *toc * turn_angle(turning));
        double t = t_lo + s * (t_hi - t_lo);
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
