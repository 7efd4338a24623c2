#include "scene/Hull_scene.h"
#include "scene/Random_draw.h"
#include "scene/Scene_builder.h"

namespace clash4d {

namespace {

// 8 points in a cube of side 4 around (cx, cy, cz), on the 1/997 grid.
Solid random_hull(Random_draw& draw, int cx, int cy, int cz)
{
  std::vector<Vec3> points;
  for (int i = 0; i < 8; ++i) {
    Vec3 p;
    for (int a = 0; a < 3; ++a) p[a] = Rational((a == 0 ? cx : a == 1 ? cy : cz) * 997 + draw.range(-1994, 1994)) / 997;
    points.push_back(p);
  }
  return hull(points);
}

Motion random_motion(Random_draw& draw)
{
  auto velocity = [&] {
    Vec3 v;
    for (auto& c : v) c = Rational(draw.range(-300, 300)) / 101;
    return v;
  };
  Vec3 v0 = velocity(), v1 = velocity(), v2 = velocity();
  return piecewise({v0, v1, v2}, {3, 7});
}

} // namespace

std::string make_hull_scene(std::mt19937_64& rng)
{
  Random_draw draw(rng);
  Solid a0 = random_hull(draw, 0, 0, 0), a1 = random_hull(draw, 2, 0, 0);
  Motion ma = random_motion(draw);
  Solid b0 = random_hull(draw, 6, 1, 0), b1 = random_hull(draw, 6, 1, 2);
  Motion mb = random_motion(draw);
  return Scene_builder("", 0, 10)
      .object("a", csg(Solid::Kind::Union, {a0, a1}), ma)
      .object("b", csg(Solid::Kind::Difference, {b0, b1}), mb)
      .text();
}

} // namespace clash4d
