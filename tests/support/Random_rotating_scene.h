// Random rotating scenes (seeded): blocks, or unions of two, turning about
// random axes while they move, against blocks at rest, moving or turning
// (tests/test_rotation.cpp's properties, tests/test_turning_certificate.cpp's
// campaign).
#ifndef CLASH4D_TESTS_SUPPORT_RANDOM_ROTATING_SCENE_H
#define CLASH4D_TESTS_SUPPORT_RANDOM_ROTATING_SCENE_H

#include "scene/Random_draw.h"
#include <nlohmann/json.hpp>
#include <array>
#include <string>

namespace clash4d::random_rotating {

using json = nlohmann::json;

inline std::string num(long n, long d = 1) { return d == 1 ? std::to_string(n) : std::to_string(n) + "/" + std::to_string(d); }

inline json random_block(Random_draw& r)
{
  long x = r.range(-3, 1), y = r.range(-3, 1), z = r.range(-3, 1);
  json min = {num(x, 2), num(y, 2), num(z, 2)};
  json max = {num(x + r.range(1, 4), 2), num(y + r.range(1, 4), 2), num(z + r.range(1, 4), 2)};
  json block = {{"min", min}, {"max", max}};
  return {{"block", block}};
}

inline json random_poses(Random_draw& r, bool turns)
{
  json poses = json::array();
  std::array<long, 4> q = {1, 0, 0, 0};
  long t = 0;
  int n = static_cast<int>(r.range(2, 3));
  for (int i = 0; i < n; ++i) {
    json p = {{"t", t}, {"translate", {num(r.range(-4, 4), 2), num(r.range(-4, 4), 2), num(r.range(-2, 2), 2)}}};
    if (turns) {
      if (i > 0)
        for (int k = 1; k < 4; ++k) q[k] += r.range(-1, 1);   // q_{i+1} never a negative multiple: w stays 1
      p["rotate"] = {q[0], q[1], q[2], q[3]};
    }
    poses.push_back(p);
    t += r.range(1, 2);
  }
  return {{"poses", poses}};
}

// A block, or a union of two (decided piece by piece: Rotating_check.cpp).
inline json random_shape(Random_draw& r)
{
  if (r.percent(60)) return random_block(r);
  json u = json::array({random_block(r), random_block(r)});
  return {{"union", u}};
}

inline json random_rotating_scene(Random_draw& r)
{
  json objects = json::array();
  objects.push_back({{"name", "a"}, {"shape", random_shape(r)}, {"motion", random_poses(r, true)}});
  json b = {{"name", "b"}, {"shape", random_shape(r)}};
  if (r.percent(50)) b["motion"] = random_poses(r, r.percent(50));
  objects.push_back(b);
  return {{"format", "clash4d-scene/1"}, {"name", "random rotating"}, {"time", {0, 3}}, {"objects", objects}};
}

} // namespace clash4d::random_rotating

#endif
