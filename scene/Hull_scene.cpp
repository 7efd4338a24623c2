#include "scene/Hull_scene.h"

namespace clash4d {

namespace {

// 8 points in a cube of side 4 around (cx, cy, cz).
std::string random_hull(std::mt19937_64& rng, int cx, int cy, int cz)
{
  std::uniform_int_distribution<int> d(-1994, 1994);
  std::string s = "{\"hull\":[";
  for (int i = 0; i < 8; ++i)
    s += std::string(i ? "," : "") + "[\"" + std::to_string(cx * 997 + d(rng)) + "/997\",\"" +
         std::to_string(cy * 997 + d(rng)) + "/997\",\"" + std::to_string(cz * 997 + d(rng)) + "/997\"]";
  return s + "]}";
}

std::string random_motion(std::mt19937_64& rng)
{
  std::uniform_int_distribution<int> v(-300, 300);
  auto vel = [&] { return "vel " + std::to_string(v(rng)) + "/101 " + std::to_string(v(rng)) + "/101 " + std::to_string(v(rng)) + "/101"; };
  return vel() + " until 3 " + vel() + " until 7 " + vel();
}

} // namespace

std::string make_hull_scene(std::mt19937_64& rng)
{
  std::string text = "{\"format\":\"clash4d-scene/1\",\"time\":[0,10],\"objects\":[";
  text += "{\"name\":\"a\",\"shape\":{\"union\":[" + random_hull(rng, 0, 0, 0) + "," + random_hull(rng, 2, 0, 0) +
          "]},\"motion\":\"" + random_motion(rng) + "\"},";
  text += "{\"name\":\"b\",\"shape\":{\"difference\":[" + random_hull(rng, 6, 1, 0) + "," + random_hull(rng, 6, 1, 2) +
          "]},\"motion\":\"" + random_motion(rng) + "\"}]}";
  return text;
}

} // namespace clash4d
