// The turning convex pairs of clash4d_fcl_bench's rotation section (issue
// 61): box-box and hull-hull, one object turning about a fixed point by at
// most 90 degrees the shorter way while the other rests, so FCL's screw
// motion passes through the same configurations as the pose
// (regularised-semantics fact 13) and its time maps back to the pose's.
// Each family has four cases: a collision from a rational time, one from an
// irrational time, a near miss and a miss, with the verdict and t* their
// construction gives (checked by the bench against the exact answer).
//
// box-box: b = [-1, 1]^3 turns a quarter turn about z, q(t) = (1, 0, 0, t)
// over [0, 1]; its farthest x is the corner (1, -1)'s, cos + sin =
// (1 + 2t - t^2) / (1 + t^2), rising to sqrt 2 at t = sqrt 2 - 1. a is the
// block [X, X + 2] x [-2, 2] x [-1, 1]: b enters it when the corner passes
// x = X, at t = (1 - sqrt(2 - X^2)) / (X + 1). X = 23/17 gives t* = 1/4,
// X = 13/10 gives t* = (10 - sqrt 31) / 23; X = 1.415 (just past sqrt 2)
// and X = 3/2 are missed (the corner's y, sin - cos, stays in [-1, 1]).
//
// hull-hull: b the hull of 20 random points of [-1, 1]^3 (a 1/997 grid)
// turning by 90 degrees about the axis (2, 2, 1) / 3 through the origin,
// q(t) = (1, 2t/3, 2t/3, t/3) over [0, 1]; a the hull of a square face
// {s x = X} x [-3, 3]^2 and 16 random points from 1/2 to 2 behind it
// (s = +1 or -1: a on the side b's support rises towards). Every point of
// b is within sqrt 3 of the origin, where a holds all of s x in (X, X +
// eps], so b overlaps a exactly when its support h(t) = max s (R(q(t)) p)_x
// exceeds X: t* is the first time h passes X. X is h(t0) at a rational t0
// where h is higher than ever before and rising (t* = t0), a 10^-6 grid point halfway up h's
// range (an irrational t*, the root of a quadratic), h's maximum plus
// 10^-3 (near miss) or plus 1/20 (miss). h is sampled in doubles to choose
// them; the rational X and t0 are exact.
#ifndef CLASH4D_BENCH_FCL_ROTATION_CASES_H
#define CLASH4D_BENCH_FCL_ROTATION_CASES_H

#include "bench/Fcl_cases.h"
#include "geometry/Rotation_matrix.h"
#include "numbers/Rational.h"

#include <cmath>
#include <optional>
#include <stdexcept>

namespace clash4d::fcl_cases {

struct Turning_case {
  Case c;
  bool collide;                  // the regularised verdict by construction
  std::optional<Rational> t0;    // t*, when rational
  double t_approx = 0;           // t* in doubles (collisions)
};

inline std::string number_text(const Rational& x) { return "\"" + to_string(x) + "\""; }

// A scene over [0, 1]: a at rest, b turning from the identity to q_end
// about its origin, which stays at 0.
inline std::string turning_scene_json(const std::string& name, const std::string& a, const std::string& b,
                                      const std::string& q_end)
{
  return "{\"format\":\"clash4d-scene/1\",\"name\":\"" + name + "\",\"time\":[0,1],\"objects\":[" +
         "{\"name\":\"a\",\"shape\":" + a + "}," + "{\"name\":\"b\",\"shape\":" + b +
         ",\"motion\":{\"poses\":[{\"t\":0,\"translate\":[0,0,0],\"rotate\":[1,0,0,0]}," +
         "{\"t\":1,\"translate\":[0,0,0],\"rotate\":" + q_end + "}]}}]}";
}

inline std::vector<Turning_case> box_rotation_cases()
{
  const std::string b = "{\"block\":{\"min\":[-1,-1,-1],\"max\":[1,1,1]}}";
  struct Entry {
    const char* what;
    Rational x;
    bool collide;
    std::optional<Rational> t0;
    double t;
  };
  const Entry entries[] = {
      {"hit 1/4", Rational(23) / 17, true, Rational(1) / 4, 0.25},
      {"hit irrational", Rational(13) / 10, true, std::nullopt, (10 - std::sqrt(31.0)) / 23},
      {"near miss", Rational(1415) / 1000, false, std::nullopt, 0},
      {"miss", Rational(3) / 2, false, std::nullopt, 0},
  };
  std::vector<Turning_case> out;
  for (const Entry& e : entries) {
    std::string a = "{\"block\":{\"min\":[" + number_text(e.x) + ",-2,-1],\"max\":[" + number_text(e.x + 2) + ",2,1]}}";
    std::string name = std::string("box-box turn ") + e.what;
    out.push_back({make_case(name, turning_scene_json(name, a, b, "[1,0,0,1]")), e.collide, e.t0, e.t});
  }
  return out;
}

// The hull family's turning object and its support function.
struct Turning_hull {
  std::vector<Grid_point> points;   // b's, over 997
  int side = 1;                     // s

  // q(t) = (1, 2t/3, 2t/3, t/3); R(q(t)) p's x times s, exactly.
  Rational support_at(const Rational& t) const
  {
    auto r = rotation_matrix<Rational>(Rational(1), 2 * t / 3, 2 * t / 3, t / 3);
    std::optional<Rational> best;
    for (const Grid_point& p : points) {
      Rational x = (r[0][0] * p[0] + r[0][1] * p[1] + r[0][2] * p[2]) * side / 997;
      if (!best || *best < x) best = x;
    }
    return *best;
  }
  double support_at(double t) const
  {
    auto r = rotation_matrix<double>(1.0, 2 * t / 3, 2 * t / 3, t / 3);
    double best = -HUGE_VAL;
    for (const Grid_point& p : points)
      best = std::max(best, side * (r[0][0] * p[0] + r[0][1] * p[1] + r[0][2] * p[2]) / 997);
    return best;
  }
};

inline std::vector<Turning_case> hull_rotation_cases(std::mt19937_64& rng)
{
  std::uniform_int_distribution<long> unit(-997, 997), depth(997 / 2, 2 * 997), wide(-3 * 997, 3 * 997);
  Turning_hull b;
  for (int i = 0; i < 20; ++i) b.points.push_back({unit(rng), unit(rng), unit(rng)});
  std::vector<Grid_point> behind;   // a's points: depth behind the face, y, z (over 997)
  for (int i = 0; i < 16; ++i) behind.push_back({depth(rng), wide(rng), wide(rng)});

  // h sampled; the side and a rational t0 where h first reaches a new
  // height and goes on rising (every sample before t0 below h(t0), h above
  // it just after).
  const int n = 20000;
  auto rises_to = [&](double t0) {
    double top = b.support_at(t0);
    for (int k = 0; k < n; ++k)
      if (!(b.support_at(k * t0 / n) < top)) return false;
    return b.support_at(t0 + 1e-3) > top;
  };
  std::optional<Rational> t0;
  for (int side : {1, -1}) {
    b.side = side;
    for (auto [p, q] : {std::pair{1, 4}, {1, 3}, {1, 5}, {2, 5}, {1, 2}, {1, 6}, {3, 5}, {1, 8}, {2, 3}, {3, 4}, {4, 5}})
      if (rises_to(double(p) / q)) {
        t0 = Rational(p) / q;
        break;
      }
    if (t0) break;
  }
  if (!t0) throw std::runtime_error("hull-hull turn: the seed's hull has no rational time where its support rises; try another --seed");
  double h_max = -HUGE_VAL, h_zero = b.support_at(0.0);
  for (int k = 0; k <= n; ++k) h_max = std::max(h_max, b.support_at(double(k) / n));
  // The first time h passes x, by bisection between samples.
  auto first_pass = [&](double x) {
    double lo = 0;
    for (int k = 1; k <= n; ++k)
      if (b.support_at(double(k) / n) > x) {
        double hi = double(k) / n;
        for (int i = 0; i < 60; ++i) (b.support_at((lo + hi) / 2) > x ? hi : lo) = (lo + hi) / 2;
        return hi;
      } else {
        lo = double(k) / n;
      }
    return 1.0;
  };
  auto grid = [](double x) { return Rational(static_cast<long>(std::ceil(x * 1e6))) / 1000000; };

  std::string b_json = hull_json(b.points);
  std::vector<Turning_case> out;
  auto add = [&](const char* what, const Rational& x, bool collide, std::optional<Rational> t, double t_approx) {
    // a: the face s x = X, |y|, |z| <= 3, and the points behind it.
    Rational s(b.side);
    std::string a = "{\"hull\":[";
    for (int y : {-3, 3})
      for (int z : {-3, 3}) a += "[" + number_text(s * x) + "," + std::to_string(y) + "," + std::to_string(z) + "],";
    for (std::size_t i = 0; i < behind.size(); ++i)
      a += std::string(i ? "," : "") + "[" + number_text(s * (x + Rational(behind[i][0]) / 997)) + "," +
           coordinate(behind[i][1]) + "," + coordinate(behind[i][2]) + "]";
    a += "]}";
    std::string name = std::string("hull-hull turn ") + what;
    out.push_back({make_case(name, turning_scene_json(name, a, b_json, "[1,\"2/3\",\"2/3\",\"1/3\"]")), collide, t,
                   t_approx});
  };
  add(("hit " + to_string(*t0)).c_str(), b.support_at(*t0), true, t0, round_to_nearest(*t0));
  Rational mid = grid((h_zero + h_max) / 2);
  add("hit irrational", mid, true, std::nullopt, first_pass(round_to_nearest(mid)));
  add("near miss", grid(h_max + 1e-3), false, std::nullopt, 0);
  add("miss", grid(h_max + 0.05), false, std::nullopt, 0);
  return out;
}

// All eight, box-box first; the hulls are drawn from the seed.
inline std::vector<Turning_case> all_rotation_cases(unsigned long seed)
{
  std::mt19937_64 rng(seed);
  std::vector<Turning_case> cases = box_rotation_cases();
  for (Turning_case& c : hull_rotation_cases(rng)) cases.push_back(std::move(c));
  return cases;
}

// The scene's motions, and the same restated (a pose motion: its last pose
// once more after the span; a velocity motion as restated_motions does).
inline std::array<std::vector<Motion>, 2> restated_turning_motions(const Scene& scene)
{
  std::array<std::vector<Motion>, 2> out = restated_motions(scene);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    Motion& later = out[1][i];
    if (scene.objects[i].motion.poses.empty()) continue;
    later = scene.objects[i].motion;
    Pose p = later.poses.back();
    p.t = std::max(p.t, scene.t_hi) + 1;
    later.poses.push_back(p);
  }
  return out;
}

} // namespace clash4d::fcl_cases

#endif
