// The six convex pairs the FCL benchmarks time (clash4d_fcl_bench,
// clash4d_gbench): box-box and hull-hull (12-point random hulls from a
// seed), each touching, separated and penetrating, moving by translation so
// FCL can express them. One construction, so both benchmarks time the same
// scenes.
#ifndef CLASH4D_BENCH_FCL_CASES_H
#define CLASH4D_BENCH_FCL_CASES_H

#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"

#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace clash4d::fcl_cases {

// A point with integer coordinates on a 1/997 grid: (x, y, z) / 997.
using Grid_point = std::array<long, 3>;

inline std::string coordinate(long k) { return "\"" + std::to_string(k) + "/997\""; }

inline std::string hull_json(const std::vector<Grid_point>& points)
{
  std::string s = "{\"hull\":[";
  for (std::size_t i = 0; i < points.size(); ++i)
    s += std::string(i ? "," : "") + "[" + coordinate(points[i][0]) + "," + coordinate(points[i][1]) + "," +
         coordinate(points[i][2]) + "]";
  return s + "]}";
}

// The solid moved by (x, y, z) / d, exactly.
inline std::string translated(const std::string& solid, const Grid_point& by, long d)
{
  auto q = [&](long k) { return "\"" + std::to_string(k) + "/" + std::to_string(d) + "\""; };
  return "{\"translate\":[" + q(by[0]) + "," + q(by[1]) + "," + q(by[2]) + "],\"solid\":" + solid + "}";
}

// 12 points in [-1, 1]^3 with pairwise different x, so the largest and the
// smallest x are each taken by one point, which is then a vertex of the hull.
inline std::vector<Grid_point> random_points(std::mt19937_64& rng)
{
  std::uniform_int_distribution<long> d(-997, 997);
  std::vector<Grid_point> out;
  std::set<long> xs;
  while (out.size() < 12) {
    Grid_point p{d(rng), d(rng), d(rng)};
    if (xs.insert(p[0]).second) out.push_back(p);
  }
  return out;
}

inline std::string scene_json(const std::string& name, const std::string& a, const std::string& b,
                              const std::string& b_motion)
{
  return "{\"format\":\"clash4d-scene/1\",\"name\":\"" + name + "\",\"time\":[0,10],\"objects\":[" +
         "{\"name\":\"a\",\"shape\":" + a + "}," + "{\"name\":\"b\",\"shape\":" + b + ",\"motion\":\"" + b_motion +
         "\"}]}";
}

struct Case {
  std::string name;   // "box-box touching", ...
  std::string json;   // the scene file's text
  Scene scene;
};

inline Case make_case(const std::string& name, const std::string& json)
{
  return {name, json, read_scene(read_json_text(json))};
}

// a = [0,1]^3 at rest; b a unit block sliding along y past a's face x = 1:
// flush (touching, no collision), 1/2 away, or 1/2 into a (collision at t = 2).
inline std::vector<Case> box_cases()
{
  std::vector<Case> out;
  const std::string a = "{\"block\":{\"min\":[0,0,0],\"max\":[1,1,1]}}";
  for (auto [what, x] : {std::pair<const char*, const char*>{"touching", "1"}, {"separated", "3/2"}, {"penetrating", "1/2"}}) {
    std::string b = "{\"translate\":[\"" + std::string(x) + "\",-3,0],\"solid\":{\"block\":{\"min\":[0,0,0],\"max\":[1,1,1]}}}";
    std::string name = std::string("box-box ") + what;
    out.push_back(make_case(name, scene_json(name, a, b, "vel 0 1 0")));
  }
  return out;
}

// a and b random hulls; b passes a along y. Touching: b's smallest-x vertex
// q is placed on the plane x = p_x of a's largest-x vertex p, at p's z, and
// reaches p at t = 5 (a single vertex-vertex contact, the hulls on either
// side of that plane: no collision). Separated: b 1/2 further in x.
// Penetrating: at t = 5 the mean of b's points is exactly that of a's, a
// point inside both hulls (collision).
inline std::vector<Case> hull_cases(std::mt19937_64& rng)
{
  std::vector<Grid_point> pa = random_points(rng), pb = random_points(rng);
  auto by_x = [](const Grid_point& u, const Grid_point& v) { return u[0] < v[0]; };
  Grid_point p = *std::max_element(pa.begin(), pa.end(), by_x), q = *std::min_element(pb.begin(), pb.end(), by_x);
  Grid_point touch{p[0] - q[0], p[1] - q[1] - 5 * 997, p[2] - q[2]}, mean{0, -5 * 997 * 12, 0};
  for (int i = 0; i < 3; ++i)
    for (std::size_t k = 0; k < pa.size(); ++k) mean[i] += pa[k][i] - pb[k][i];
  std::string a = hull_json(pa), b = hull_json(pb);
  std::vector<Case> out;
  auto add = [&](const char* what, const std::string& moved) {
    std::string name = std::string("hull-hull ") + what;
    out.push_back(make_case(name, scene_json(name, a, moved, "vel 0 1 0")));
  };
  add("touching", translated(b, touch, 997));
  add("separated", translated(b, {2 * touch[0] + 997, 2 * touch[1], 2 * touch[2]}, 2 * 997));
  add("penetrating", translated(b, mean, 12 * 997));
  return out;
}

// All six, box-box first; the hulls are drawn from the seed.
inline std::vector<Case> all_cases(unsigned long seed)
{
  std::mt19937_64 rng(seed);
  std::vector<Case> cases = box_cases();
  for (Case& c : hull_cases(rng)) cases.push_back(std::move(c));
  return cases;
}

// The scene's motions, and the same motions restated: one more breakpoint
// after the span, between equal velocities (the same path, sub-spans and
// answer). Checks that alternate the two (Exact_checker::check(motions,
// options)) make the motions, the sweep and the guides' motions on every
// query, as a query with new transforms does.
inline std::array<std::vector<Motion>, 2> restated_motions(const Scene& scene)
{
  std::array<std::vector<Motion>, 2> out;
  for (const Scene_object& o : scene.objects) {
    out[0].push_back(o.motion);
    Motion later = o.motion;
    later.times.push_back((later.times.empty() ? scene.t_hi : std::max(later.times.back(), scene.t_hi)) + 1);
    later.velocities.push_back(later.velocities.back());
    out[1].push_back(later);
  }
  return out;
}

} // namespace clash4d::fcl_cases

#endif
