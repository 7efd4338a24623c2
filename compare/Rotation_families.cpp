#include "compare/Rotation_families.h"

#include "geometry/Rotation_matrix.h"
#include "scene/Json_reader.h"
#include "scene/Number_text.h"
#include "scene/Random_draw.h"
#include "scene/Scene_reader.h"
#include "scene/Scene_writer.h"

#include <nlohmann/json.hpp>
#include <array>
#include <iterator>
#include <string>

namespace clash4d {
namespace {

using json = nlohmann::ordered_json;
using Rng = Random_draw;
using Q = Rational;
using Vec = std::array<Q, 3>;
using Quat = std::array<Q, 4>;

Q frac(long p, long q = 1) { return Q(p) / Q(q); }
std::string text(const Q& x) { return to_string(x); }
json numbers(const Vec& v) { return json::array({text(v[0]), text(v[1]), text(v[2])}); }
json numbers(const Quat& q) { return json::array({text(q[0]), text(q[1]), text(q[2]), text(q[3])}); }

json block(const Vec& min, const Vec& max) { return {{"block", {{"min", numbers(min)}, {"max", numbers(max)}}}}; }
json pose(const Q& t, const Vec& c, const Quat& q) { return {{"t", text(t)}, {"translate", numbers(c)}, {"rotate", numbers(q)}}; }
json object(const std::string& name, const json& shape) { return {{"name", name}, {"shape", shape}}; }
json turning(const std::string& name, const json& shape, const json& poses)
{
  return {{"name", name}, {"shape", shape}, {"motion", {{"poses", poses}}}};
}

const Quat identity = {Q(1), Q(0), Q(0), Q(0)};
const Quat quarter_z = {Q(1), Q(0), Q(0), Q(1)};   // q(t) = (1, 0, 0, t) over [0, 1]: a quarter turn about z

// A touch, an overlap or a gap of eps (a size times 10^-3, -9 or -15):
// side 0, -1 (towards overlap) or +1 (apart).
struct Variant {
  int side;
  Q eps;
  std::string name() const
  {
    return side == 0 ? "touching" : (side < 0 ? "overlapping by " : "apart by ") + text(eps);
  }
};

Variant draw_variant(Rng& rng, const Q& size)
{
  int side = static_cast<int>(rng.range(-1, 1));
  long k = rng.pick<long>({3, 9, 15});
  return {side, size * parse_number_text("1e-" + std::to_string(k), false).value};
}

// The reach of the corner (a, -a) of a square turning about z by q(t) =
// (1, 0, 0, t): a (cos + sin) = a (1 + 2t - t^2) / (1 + t^2), increasing
// for 0 <= t < sqrt 2 - 1.
Q reach(const Q& a, const Q& t) { return a * (1 + 2 * t - t * t) / (1 + t * t); }

// Expected verdicts: touching only at an instant or along a rest (reg no,
// closed yes), a collision, or apart.
Rotation_expectation touch_like(const Variant& v, bool overlap_collides)
{
  if (v.side == 0) return {false, true};
  if (v.side < 0 && overlap_collides) return {true, true};
  return {false, false};
}

// A square turning a quarter turn about z reaches a slab's face x = X at a
// rational time t0 < sqrt 2 - 1 (X its reach then). Ending the span at t0
// makes it a touch at the span's end (the slab moved by the variant);
// with the span to 1 the corner goes on into the slab whatever the variant.
Rotation_case corner_at_rational_time(Rng& rng)
{
  Q a = rng.pick<Q>({Q(1), frac(1, 2), frac(3, 2), Q(2), frac(7, 10)});
  Q t0 = rng.pick<Q>({frac(1, 5), frac(1, 4), frac(1, 3), frac(1, 10), frac(3, 10), frac(2, 7)});
  Variant v = draw_variant(rng, a);
  bool to_end = rng.percent(50);
  Q x = reach(a, t0) + v.side * v.eps;   // overlap (side -1): the slab nearer
  json objects = json::array({turning("square", block({-a, -a, -a}, {a, a, a}),
                                      json::array({pose(0, {0, 0, 0}, identity), pose(1, {0, 0, 0}, quarter_z)})),
                              object("slab", block({x, -2 * a, -a}, {x + 2 * a, 2 * a, a}))});
  json scene = {{"format", "clash4d-scene/1"},
                {"name", "a turning square's corner reaches a slab at t = " + text(t0) + ", " + v.name()},
                {"time", {"0", text(to_end ? t0 : Q(1))}},
                {"objects", objects}};
  Rotation_expectation e = to_end ? touch_like(v, true) : Rotation_expectation{true, true};
  return {{"", scene.dump()}, e};
}

// tests/../fixtures/rotation/touch_at_irrational_time.json scaled by a: a
// turning, sliding square's corner edge passes exactly through a static
// edge at t = sqrt 2 - 1, and at no other time does any of it reach x = a
// on y >= 0 (that fixture's derivation), so the static block moved by the
// variant along x is touched at that instant, overlapped, or missed.
Rotation_case edge_through_edge_at_irrational_time(Rng& rng)
{
  Q a = rng.pick<Q>({Q(1), frac(1, 2), frac(3, 2), Q(2), frac(7, 10)});
  Variant v = draw_variant(rng, a);
  Q x = a + v.side * v.eps;   // overlap (side -1): the block nearer
  json objects = json::array({turning("diamond", block({-a, -a, -a}, {a, a, a}),
                                      json::array({pose(0, {0, 0, 0}, identity), pose(1, {-a, 0, 0}, quarter_z)})),
                              object("corner", block({x, 0, -a}, {x + 2 * a, 2 * a, a}))});
  json scene = {{"format", "clash4d-scene/1"},
                {"name", "a turning square's corner edge through a static edge at t = sqrt 2 - 1, " + v.name()},
                {"time", {"1/5", "1"}},
                {"objects", objects}};
  return {{"", scene.dump()}, touch_like(v, true)};
}

// A door [0, w] x [0, d] x [0, h] hinged on the z axis shuts by a quarter
// turn over [0, T] and rests; shut, it is x in [-d, 0], y in [0, w], and
// while it turns no point of it has x < -d (x = p_x cos - p_y sin >= -d
// sin). A stop behind the shut face x = -d (moved by the variant) is
// touched from T on, overlapped, or missed.
Rotation_case door_against_stop(Rng& rng)
{
  Q w = rng.pick<Q>({Q(2), Q(3), frac(5, 2), Q(4)}), d = rng.pick<Q>({frac(1, 10), frac(1, 4), frac(1, 2)});
  Q h = rng.pick<Q>({Q(2), Q(3)}), T = rng.pick<Q>({Q(1), Q(2), frac(1, 2)});
  Variant v = draw_variant(rng, d);
  Q face = -d - v.side * v.eps;   // overlap (side -1): the stop's face past the shut door's
  json objects = json::array({turning("door", block({0, 0, 0}, {w, d, h}),
                                      json::array({pose(0, {0, 0, 0}, identity), pose(T, {0, 0, 0}, quarter_z)})),
                              object("stop", block({face - 1, w / 2, 0}, {face, w, h}))});
  json scene = {{"format", "clash4d-scene/1"},
                {"name", "a door shuts against a stop at t = " + text(T) + ", " + v.name()},
                {"time", {"0", text(T + 1)}},
                {"objects", objects}};
  return {{"", scene.dump()}, touch_like(v, true)};
}

// A square peg turning inside a square pocket (a block minus a through
// hole of half-width c): its corners reach the four walls together at a
// rational time t0 when c is its reach then; the span ends at t0.
Rotation_case peg_in_pocket(Rng& rng)
{
  Q a = rng.pick<Q>({Q(1), frac(1, 2), frac(3, 2)});
  Q t0 = rng.pick<Q>({frac(1, 5), frac(1, 4), frac(1, 3), frac(3, 10)});
  Variant v = draw_variant(rng, a);
  Q c = reach(a, t0) + v.side * v.eps;   // overlap (side -1): the walls nearer
  json pocket = {{"difference", json::array({block({-3 * a, -3 * a, -a}, {3 * a, 3 * a, a}),
                                             block({-c, -c, -2 * a}, {c, c, 2 * a})})}};
  json objects = json::array({object("pocket", pocket),
                              turning("peg", block({-a, -a, -a / 2}, {a, a, a / 2}),
                                      json::array({pose(0, {0, 0, 0}, identity), pose(1, {0, 0, 0}, quarter_z)}))});
  json scene = {{"format", "clash4d-scene/1"},
                {"name", "a peg turning in a pocket reaches its walls at t = " + text(t0) + ", " + v.name()},
                {"time", {"0", text(t0)}},
                {"objects", objects}};
  return {{"", scene.dump()}, touch_like(v, true)};
}

// A block B of half-size s turns from the identity to a Pythagorean
// rotation g (cos and sin rational, so its faces' planes are rational)
// while its centre comes in along g's x axis from 4s away, arriving at T
// with its face flush on a block A that rests turned by g (A's face moved
// by the variant). Before T, B's front in g's frame is at most
// -4s (1 - t/T) + s (cos + |sin|) < s: the two first touch, face to face,
// at T, and rest touching.
Rotation_case flush_after_turning(Rng& rng)
{
  static const int turns[][4] = {{2, 0, 0, 1}, {3, 0, 0, 1}, {2, 1, 0, 0}, {3, 0, 1, 0}, {1, 0, 0, 1}};
  const int* g = turns[rng.below(std::size(turns))];
  Quat q = {Q(g[0]), Q(g[1]), Q(g[2]), Q(g[3])};
  Q s = rng.pick<Q>({Q(1), frac(1, 2), frac(3, 2)}), T = rng.pick<Q>({Q(1), Q(2), frac(1, 2)});
  Variant v = draw_variant(rng, s);
  Q face = s + v.side * v.eps;   // overlap (side -1): A's face nearer
  // g's x axis, R(g) (1, 0, 0) = N(g) e_x / |g|^2.
  Q n = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  Vec ex = {(q[0] * q[0] + q[1] * q[1] - q[2] * q[2] - q[3] * q[3]) / n, 2 * (q[1] * q[2] + q[0] * q[3]) / n,
            2 * (q[1] * q[3] - q[0] * q[2]) / n};
  Vec start = {-4 * s * ex[0], -4 * s * ex[1], -4 * s * ex[2]};
  json a = {{"rotate", numbers(q)}, {"solid", block({face, -2 * s, -2 * s}, {face + 2 * s, 2 * s, 2 * s})}};
  json objects = json::array({object("a", a), turning("b", block({-s, -s, -s}, {s, s, s}),
                                                       json::array({pose(0, start, identity), pose(T, {0, 0, 0}, q)}))});
  json scene = {{"format", "clash4d-scene/1"},
                {"name", "a block turns by (" + std::to_string(g[0]) + "," + std::to_string(g[1]) + "," +
                             std::to_string(g[2]) + "," + std::to_string(g[3]) + ") onto a face, " + v.name()},
                {"time", {"0", text(T + 1)}},
                {"objects", objects}};
  return {{"", scene.dump()}, touch_like(v, true)};
}

// The control group: two blocks at random places, both turning by small
// integer quaternions that never pass through 0.
Rotation_case both_turning(Rng& rng)
{
  json objects = json::array();
  for (const char* name : {"a", "b"}) {
    Vec lo = {frac(rng.range(-4, 0), 2), frac(rng.range(-4, 0), 2), frac(rng.range(-4, 0), 2)};
    Vec hi = {lo[0] + frac(rng.range(1, 4), 2), lo[1] + frac(rng.range(1, 4), 2), lo[2] + frac(rng.range(1, 4), 2)};
    json poses = json::array();
    Quat q = identity;
    for (int i = 0; i < 3; ++i) {
      poses.push_back(pose(i, {frac(rng.range(-4, 4), 2), frac(rng.range(-4, 4), 2), frac(rng.range(-2, 2), 2)}, q));
      for (int k = 1; k < 4; ++k) q[k] += rng.range(-1, 1);   // w stays 1: never a negative multiple
    }
    objects.push_back(turning(name, block(lo, hi), poses));
  }
  json scene = {{"format", "clash4d-scene/1"}, {"name", "two blocks turning"}, {"time", {"0", "2"}}, {"objects", objects}};
  return {{"", scene.dump()}, {}};
}

struct Family_entry {
  Fuzz_family family;
  Rotation_case (*make)(Rng&);
};

const std::vector<Family_entry>& family_table()
{
  static const std::vector<Family_entry> table{
      {{"rotation_corner_rational", "a turning square's corner reaches a slab's face at a rational time (the span ending there or going on), touching, overlapping or apart by 1e-3, 1e-9 or 1e-15 of its size"}, corner_at_rational_time},
      {{"rotation_edge_irrational", "a turning, sliding square's corner edge passes through a static edge at t = sqrt 2 - 1 (an irrational instant), touching, overlapping or missing"}, edge_through_edge_at_irrational_time},
      {{"rotation_door", "a door shuts by a quarter turn against a stop and rests there, touching, pressing into it or short of it"}, door_against_stop},
      {{"rotation_pocket", "a square peg turning inside a pocket reaches the four walls at once at a rational time"}, peg_in_pocket},
      {{"rotation_flush", "a block turns by a Pythagorean rotation (rational cos and sin) while coming in, and ends face to face with a block turned the same way"}, flush_after_turning},
      {{"rotation_general", "two blocks at random places, both turning: the control group"}, both_turning},
  };
  return table;
}

// g a (Hamilton product): turn by a, then by g.
Quat product(const Quat& g, const Quat& a)
{
  return {g[0] * a[0] - g[1] * a[1] - g[2] * a[2] - g[3] * a[3], g[0] * a[1] + g[1] * a[0] + g[2] * a[3] - g[3] * a[2],
          g[0] * a[2] - g[1] * a[3] + g[2] * a[0] + g[3] * a[1], g[0] * a[3] + g[1] * a[2] - g[2] * a[1] + g[3] * a[0]};
}

Q number(const json& v) { return parse_number_text(v.get<std::string>(), true).value; }

// The whole scene turned by g about the origin, moved by d, and its time
// multiplied by u > 0: every verdict stays, t* is multiplied by u.
json finished(json scene, const Quat& g, const Vec& d, const Q& u)
{
  auto R = rotation_matrix<Q>(g[0], g[1], g[2], g[3]);   // the scene format's R(g), exact
  for (auto& t : scene["time"]) t = text(number(t) * u);
  for (auto& o : scene["objects"]) {
    if (!o.contains("motion")) {   // at rest: the shape turned, then moved
      o["shape"] = {{"translate", numbers(d)}, {"solid", {{"rotate", numbers(g)}, {"solid", o["shape"]}}}};
      continue;
    }
    for (auto& p : o["motion"]["poses"]) {
      Vec c = {number(p["translate"][0]), number(p["translate"][1]), number(p["translate"][2])};
      Quat q = {number(p["rotate"][0]), number(p["rotate"][1]), number(p["rotate"][2]), number(p["rotate"][3])};
      Vec moved;
      for (int i = 0; i < 3; ++i) moved[i] = R[i][0] * c[0] + R[i][1] * c[1] + R[i][2] * c[2] + d[i];
      p["translate"] = numbers(moved);
      p["rotate"] = numbers(product(g, q));
      p["t"] = text(number(p["t"]) * u);
    }
  }
  return scene;
}

json finish(const json& scene, Rng& rng)
{
  static const int turns[][4] = {{1, 0, 0, 0}, {1, 0, 0, 0}, {3, 0, 0, 4}, {1, 1, 1, 1}, {2, 1, 1, 1}, {1, 2, 2, 0}, {4, 1, 2, 3}};
  const int* g = turns[rng.below(std::size(turns))];
  Vec d = {Q(0), Q(0), Q(0)};
  if (rng.percent(50))
    for (auto& c : d) c = frac(rng.range(-30, 30), 10);   // decimals such as 0.1 and 0.7
  Q u = rng.pick<Q>({Q(1), Q(1), frac(1, 10), Q(10), frac(3, 10)});
  return finished(scene, {Q(g[0]), Q(g[1]), Q(g[2]), Q(g[3])}, d, u);
}

} // namespace

const std::vector<Fuzz_family>& rotation_families()
{
  static const std::vector<Fuzz_family> families = [] {
    std::vector<Fuzz_family> out;
    for (const auto& e : family_table()) out.push_back(e.family);
    return out;
  }();
  return families;
}

Rotation_case make_rotation_case(std::uint64_t seed, std::uint64_t index)
{
  const auto& table = family_table();
  const Family_entry& e = table[index % table.size()];
  Rng rng(splitmix64(splitmix64(seed ^ 0x5eed0f7u) + index));
  Rotation_case c = e.make(rng);
  json scene = finish(json::parse(c.scene.json), rng);
  scene["name"] = std::string(e.family.name) + ": " + scene["name"].get<std::string>();
  // Read back: a valid scene, written in the toolkit's own form.
  c.scene = {e.family.name, write_scene(read_scene(read_json_text(scene.dump())))};
  return c;
}

} // namespace clash4d
