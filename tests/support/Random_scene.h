// Small random scenes on a coarse grid (integers and halves), so that contact
// (faces, edges, vertices touching; touching for one instant; sliding) is
// frequent. Generated as JSON text and read through clash4d::read_scene, so
// every scene is also validated and carries the validated hull/convex triples.
//
// Often the second object is placed so that, at some integer time T of the
// span (its ends included), its bounding box meets the first object's box
// face to face, or overlaps or misses it by half a unit: with integer and half
// coordinates, velocities in halves and integer breakpoints, that gives
// touching faces, edges and vertices, contact at one instant and sliding.
//
// Only the engine's raw 64-bit output is used (no std distributions, whose
// results differ between standard libraries), so a seed names one scene
// sequence everywhere.
#ifndef CLASH4D_TESTS_SUPPORT_RANDOM_SCENE_H
#define CLASH4D_TESTS_SUPPORT_RANDOM_SCENE_H

#include "scene/Input_error.h"
#include "scene/Json_reader.h"
#include "scene/Scene.h"
#include "scene/Scene_reader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace clash4d {
namespace random_scenes {

using I3 = std::array<int, 3>;   // in halves

// A solid's JSON text and a box around it (in halves; approximate for
// CSG and for rotations that are not axis permutations: only used to place).
struct Shape {
  std::string text;
  I3 lo, hi;
  bool bounded = true;
};

// A motion: velocities (halves per unit time) between integer breakpoints.
struct Motion_plan {
  std::vector<int> times;
  std::vector<I3> velocities;   // times.size() + 1
  bool omit = false;            // no "motion" key at all

  // D(t) in halves, for integer t.
  I3 displacement(int t) const
  {
    I3 d{0, 0, 0};
    int a = std::min(t, 0), b = std::max(t, 0), sign = t < 0 ? -1 : 1;
    for (std::size_t i = 0; i < velocities.size(); ++i) {
      int lo = a, hi = b;
      if (i > 0) lo = std::max(lo, times[i - 1]);
      if (i < times.size()) hi = std::min(hi, times[i]);
      if (lo >= hi) continue;
      for (int k = 0; k < 3; ++k) d[k] += sign * velocities[i][k] * (hi - lo);
    }
    return d;
  }
};

class Generator {
public:
  explicit Generator(std::mt19937_64& rng) : rng_(rng) {}

  // 0 .. n-1
  int below(int n) { return static_cast<int>(rng_() % static_cast<std::uint64_t>(n)); }
  int between(int lo, int hi) { return hi <= lo ? lo : lo + below(hi - lo + 1); }
  bool chance(int percent) { return below(100) < percent; }
  template <class T> const T& pick(const std::vector<T>& xs) { return xs[static_cast<std::size_t>(below(static_cast<int>(xs.size())))]; }

  // A number given in halves, written in one of the forms the reader accepts.
  std::string num(int halves)
  {
    std::string sign = halves < 0 ? "-" : "";
    int a = halves < 0 ? -halves : halves;
    if (a % 2 == 0) return chance(15) ? "\"" + sign + std::to_string(a / 2) + "\"" : sign + std::to_string(a / 2);
    switch (below(3)) {
      case 0: return "\"" + sign + std::to_string(a) + "/2\"";
      case 1: return sign + std::to_string(a / 2) + ".5";
      default: return "\"" + sign + std::to_string(a * 5) + "e-1\"";
    }
  }
  std::string vec(const I3& v) { return "[" + num(v[0]) + "," + num(v[1]) + "," + num(v[2]) + "]"; }

  // Grid position in halves: mostly integers.
  int coord(int lo_units, int hi_units)
  {
    if (chance(75)) return 2 * between(lo_units, hi_units);
    return between(2 * lo_units, 2 * hi_units);
  }
  int extent() { return chance(70) ? 2 * between(1, 2) : between(1, 4); }
  I3 position(int lo_units, int hi_units) { return {coord(lo_units, hi_units), coord(lo_units, hi_units), coord(lo_units, hi_units)}; }

  Shape block(const I3& lo, const I3& size)
  {
    I3 hi{lo[0] + size[0], lo[1] + size[1], lo[2] + size[2]};
    return {"{\"block\":{\"min\":" + vec(lo) + ",\"max\":" + vec(hi) + "}}", lo, hi};
  }
  Shape random_block() { return block(position(0, 3), {extent(), extent(), extent()}); }

  // A block next to box (lo, hi): sharing a face (or part of one) half the time.
  Shape block_near(const Shape& b)
  {
    I3 size{extent(), extent(), extent()}, lo;
    for (int k = 0; k < 3; ++k) lo[k] = b.lo[k] + 2 * between(-1, 1) + (chance(20) ? 1 : 0);
    if (chance(60)) {
      int axis = below(3);
      lo[axis] = chance(50) ? b.hi[axis] - (chance(25) ? 1 : 0) : b.lo[axis] - size[axis] + (chance(25) ? 1 : 0);
    }
    return block(lo, size);
  }

  Shape prism(const I3& o)
  {
    static const std::vector<std::vector<std::array<int, 2>>> bases = {
        {{0, 0}, {4, 0}, {0, 4}},                    // right triangle
        {{2, 0}, {4, 2}, {2, 4}, {0, 2}},            // diamond
        {{0, 0}, {4, 0}, {4, 2}, {2, 4}, {0, 2}},    // pentagon
        {{0, 0}, {4, 0}, {2, 4}},                    // isosceles triangle
        {{0, 0}, {2, 0}, {4, 2}, {2, 2}},            // parallelogram
        {{1, 0}, {3, 0}, {4, 2}, {2, 4}, {0, 2}}};   // irregular pentagon (halves)
    const auto& b = pick(bases);
    int dz = extent();
    Shape s;
    s.text = "{\"prism\":{\"base\":[";
    s.lo = {1 << 20, 1 << 20, o[2]};
    s.hi = {-(1 << 20), -(1 << 20), o[2] + dz};
    for (std::size_t i = 0; i < b.size(); ++i) {
      int x = o[0] + b[i][0], y = o[1] + b[i][1];
      s.text += std::string(i ? "," : "") + "[" + num(x) + "," + num(y) + "]";
      s.lo[0] = std::min(s.lo[0], x); s.hi[0] = std::max(s.hi[0], x);
      s.lo[1] = std::min(s.lo[1], y); s.hi[1] = std::max(s.hi[1], y);
    }
    s.text += "],\"z\":[" + num(o[2]) + "," + num(o[2] + dz) + "]}}";
    return s;
  }

  Shape hull(const I3& o)
  {
    static const std::vector<std::vector<I3>> shapes = {
        {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}},                                  // corner tetrahedron
        {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {2, 2, 4}},                       // pyramid, square base
        {{2, 2, 0}, {0, 2, 2}, {4, 2, 2}, {2, 0, 2}, {2, 4, 2}, {2, 2, 4}},            // octahedron
        {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {4, 4, 0}, {0, 0, 4}, {4, 0, 4}, {0, 4, 4}, {4, 4, 4}, {2, 2, 2}},   // cube + interior point
        {{0, 0, 0}, {4, 4, 0}, {4, 0, 4}, {0, 4, 4}},                                  // regular tetrahedron
        {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 2}, {4, 0, 2}, {0, 4, 2}}};           // wedge (triangular prism)
    std::vector<I3> pts = pick(shapes);
    if (chance(30)) {
      // random grid points instead (may be flat: the caller draws again)
      pts.clear();
      int n = between(4, 6);
      for (int i = 0; i < n; ++i) pts.push_back({2 * between(0, 2), 2 * between(0, 2), 2 * between(0, 2)});
    }
    Shape s;
    s.text = "{\"hull\":[";
    s.lo = {1 << 20, 1 << 20, 1 << 20};
    s.hi = {-(1 << 20), -(1 << 20), -(1 << 20)};
    for (std::size_t i = 0; i < pts.size(); ++i) {
      I3 p{o[0] + pts[i][0], o[1] + pts[i][1], o[2] + pts[i][2]};
      s.text += std::string(i ? "," : "") + vec(p);
      for (int k = 0; k < 3; ++k) { s.lo[k] = std::min(s.lo[k], p[k]); s.hi[k] = std::max(s.hi[k], p[k]); }
    }
    s.text += "]}";
    return s;
  }

  // A plane through the box (lo, hi) with a small integer normal.
  Shape halfspace_cut(const Shape& b)
  {
    I3 n{between(-1, 1), between(-1, 1), between(-1, 1)};
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) n[below(3)] = 1;
    // through a grid point of the box: n.(x - p) <= 0, d = -n.p (p in halves: d in halves)
    I3 p;
    for (int k = 0; k < 3; ++k) p[k] = 2 * between((b.lo[k] + 1) / 2, b.hi[k] / 2);
    int d = -(n[0] * p[0] + n[1] * p[1] + n[2] * p[2]);
    Shape s = b;
    s.text = "{\"halfspace\":[" + std::to_string(n[0]) + "," + std::to_string(n[1]) + "," + std::to_string(n[2]) + "," + num(d) + "]}";
    return s;
  }

  static Shape join(const char* op, const std::vector<Shape>& parts, bool grow)
  {
    Shape s = parts[0];
    s.text = std::string("{\"") + op + "\":[";
    for (std::size_t i = 0; i < parts.size(); ++i) {
      s.text += (i ? "," : "") + parts[i].text;
      if (grow)
        for (int k = 0; k < 3; ++k) { s.lo[k] = std::min(s.lo[k], parts[i].lo[k]); s.hi[k] = std::max(s.hi[k], parts[i].hi[k]); }
    }
    s.text += "]}";
    return s;
  }

  Shape csg(const I3& o)
  {
    Shape first = block(o, {extent() + 2, extent() + 2, extent()});
    switch (below(6)) {
      case 0: {
        std::vector<Shape> parts{first, block_near(first)};
        if (chance(30)) parts.push_back(block_near(first));
        return join("union", parts, true);
      }
      case 1: return join("intersection", {first, block_near(first)}, false);
      case 2: {
        std::vector<Shape> parts{first, block_near(first)};
        if (chance(30)) parts.push_back(block_near(first));
        return join("difference", parts, false);
      }
      case 3: return join("intersection", {first, halfspace_cut(first)}, false);
      case 4: return join("difference", {first, halfspace_cut(first)}, false);
      default: {
        Shape u = join("union", {first, block_near(first)}, true);
        return join("difference", {u, block_near(first)}, false);
      }
    }
  }

  Shape convex(const I3& o)
  {
    // a block written as half-spaces, with a corner cut off
    I3 size{extent() + 1, extent() + 1, extent() + 1};
    Shape s;
    s.lo = o;
    s.hi = {o[0] + size[0], o[1] + size[1], o[2] + size[2]};
    s.text = "{\"convex\":[";
    s.text += "[-1,0,0," + num(o[0]) + "],[1,0,0," + num(-s.hi[0]) + "],";
    s.text += "[0,-1,0," + num(o[1]) + "],[0,1,0," + num(-s.hi[1]) + "],";
    s.text += "[0,0,-1," + num(o[2]) + "],[0,0,1," + num(-s.hi[2]) + "],";
    int far = s.hi[0] + s.hi[1] + s.hi[2];
    s.text += "[1,1,1," + num(-(far - 2 * between(1, 2))) + "]]}";
    return s;
  }

  Shape rotated(const I3& o)
  {
    static const std::vector<std::array<int, 4>> quats = {
        {1, 0, 0, 1}, {3, 0, 0, 4}, {1, 1, 1, 1}, {2, 0, 0, 1}, {1, 0, 1, 0}, {0, 1, 0, 0}, {1, 1, 0, 0}, {1, -1, 1, -1}};
    const auto& q = pick(quats);
    I3 size{extent(), extent(), extent()};
    I3 lo = chance(70) ? I3{-(size[0] / 2), -(size[1] / 2), -(size[2] / 2)} : I3{0, 0, 0};
    Shape inner = block(lo, size);
    // the box of the rotated corners, rounded outward to halves
    double w = q[0], x = q[1], y = q[2], z = q[3], n = w * w + x * x + y * y + z * z;
    double R[3][3] = {{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
                      {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
                      {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
    Shape s;
    for (int k = 0; k < 3; ++k) {
      double mn = 1e9, mx = -1e9;
      for (int c = 0; c < 8; ++c) {
        double v = 0;
        for (int j = 0; j < 3; ++j) v += R[k][j] / n * ((c >> j) & 1 ? inner.hi[j] : inner.lo[j]);
        mn = std::min(mn, v);
        mx = std::max(mx, v);
      }
      s.lo[k] = o[k] + static_cast<int>(std::floor(mn + 1e-9));
      s.hi[k] = o[k] + static_cast<int>(std::ceil(mx - 1e-9));
    }
    s.text = "{\"translate\":" + vec(o) + ",\"solid\":{\"rotate\":[" + std::to_string(q[0]) + "," + std::to_string(q[1]) + "," +
             std::to_string(q[2]) + "," + std::to_string(q[3]) + "],\"solid\":" + inner.text + "}}";
    return s;
  }

  Shape shape()
  {
    int r = below(100);
    I3 o = position(0, 2);
    if (r < 28) return random_block();
    if (r < 40) return prism(o);
    if (r < 52) return hull(o);
    if (r < 76) return csg(o);
    if (r < 84) return convex(o);
    return rotated(o);
  }

  static Shape translated(const Shape& s, const I3& d, Generator& g)
  {
    Shape t = s;
    t.text = "{\"translate\":" + g.vec(d) + ",\"solid\":" + s.text + "}";
    for (int k = 0; k < 3; ++k) { t.lo[k] += d[k]; t.hi[k] += d[k]; }
    return t;
  }

  I3 velocity()
  {
    static const std::vector<int> c = {-4, -2, -2, -1, 1, 2, 2, 4};   // halves per unit time
    I3 v{0, 0, 0};
    if (chance(20)) return v;
    int axes = chance(65) ? 1 : chance(70) ? 2 : 3;
    for (int i = 0; i < axes; ++i) v[below(3)] = pick(c);
    return v;
  }

  Motion_plan motion(int t_lo)
  {
    Motion_plan m;
    if (chance(15)) {
      m.omit = chance(50);
      m.velocities.push_back({0, 0, 0});
      return m;
    }
    int segments = between(0, 3);
    int t = t_lo - between(0, 1);
    for (int i = 0; i < segments; ++i) {
      t += between(1, 2);
      m.times.push_back(t);
    }
    m.velocities.push_back(segments > 0 && chance(40) ? I3{0, 0, 0} : velocity());
    for (int i = 0; i < segments; ++i) {
      // often: come back the way it came, or stop
      if (chance(25)) m.velocities.push_back({-m.velocities.back()[0], -m.velocities.back()[1], -m.velocities.back()[2]});
      else m.velocities.push_back(velocity());
    }
    return m;
  }

  // p/q in lowest terms (q > 0)
  static std::string fraction(long p, long q)
  {
    long a = p < 0 ? -p : p, b = q;
    while (b) { long r = a % b; a = b; b = r; }
    if (a > 1) { p /= a; q /= a; }
    return q == 1 ? std::to_string(p) : std::to_string(p) + "/" + std::to_string(q);
  }

  // The spec's quaternion matrix times the norm n (integer entries).
  static std::array<std::array<long, 3>, 3> quaternion_integer_matrix(const std::array<int, 4>& q, long& n)
  {
    long w = q[0], x = q[1], y = q[2], z = q[3];
    n = w * w + x * x + y * y + z * z;
    return {{{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
             {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
             {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}}};
  }

  // With `turn`, every velocity is rotated by that quaternion (the whole
  // scene is, see scene_text).
  std::string motion_text(const Motion_plan& m, const std::array<int, 4>* turn = nullptr)
  {
    auto seg = [&](const I3& v) {
      if (v[0] == 0 && v[1] == 0 && v[2] == 0 && chance(80)) return std::string("rest");
      if (turn) {
        long n;
        auto M = quaternion_integer_matrix(*turn, n);
        std::string out = "vel";
        for (int k = 0; k < 3; ++k) out += " " + fraction(M[k][0] * v[0] + M[k][1] * v[1] + M[k][2] * v[2], 2 * n);
        return out;
      }
      auto plain = [](int h) { return h % 2 == 0 ? std::to_string(h / 2) : std::to_string(h) + "/2"; };
      return "vel " + plain(v[0]) + " " + plain(v[1]) + " " + plain(v[2]);
    };
    std::string s = seg(m.velocities[0]);
    for (std::size_t i = 0; i < m.times.size(); ++i) s += " until " + std::to_string(m.times[i]) + " " + seg(m.velocities[i + 1]);
    return s;
  }

  // Moves `b` so that at time T its box meets a's box (a moving by da, b by
  // db at T): face to face along one axis, or overlapping/missing by half a unit.
  Shape place_against(const Shape& a, const I3& da, const Shape& b, const I3& db)
  {
    int axis = below(3);
    int gap = chance(60) ? 0 : pick(std::vector<int>{-1, 1, -2});
    I3 target_lo;   // where b's box lower corner goes at T (world, halves)
    for (int k = 0; k < 3; ++k) {
      int alo = a.lo[k] + da[k], ahi = a.hi[k] + da[k], bsize = b.hi[k] - b.lo[k];
      if (k == axis) target_lo[k] = chance(50) ? ahi + gap : alo - bsize - gap;
      else {
        int r = below(4);
        target_lo[k] = r == 0 ? alo : r == 1 ? ahi - bsize : r == 2 ? ahi : alo + between(-bsize, ahi - alo);
      }
    }
    I3 d;
    for (int k = 0; k < 3; ++k) d[k] = target_lo[k] - b.lo[k] - db[k];
    return translated(b, d, *this);
  }

  std::string scene_text()
  {
    // in halves: mostly integer ends, sometimes half-unit ends
    static const std::vector<std::array<int, 2>> spans = {{0, 8}, {-2, 6}, {0, 4}, {2, 6}, {0, 6}, {0, 8}, {-2, 6}, {1, 7}, {3, 6}};
    auto span = pick(spans);
    int t_first = (span[0] + 1) >> 1, t_last = span[1] >> 1;   // integer times inside the closed span
    int n = chance(20) ? 3 : 2;
    std::vector<Shape> shapes;
    std::vector<Motion_plan> motions;
    for (int i = 0; i < n; ++i) {
      Motion_plan m = (i == 0 && chance(60)) ? Motion_plan{{}, {{0, 0, 0}}, true} : motion(t_first);
      Shape s = shape();
      if (i > 0 && chance(65)) {
        int T = between(t_first, t_last);
        const Shape& a = shapes[static_cast<std::size_t>(below(i))];
        s = place_against(a, motions[&a - &shapes[0]].displacement(T), s, m.displacement(T));
      } else if (chance(8)) {
        s = translated(s, position(-1, 1), *this);
      }
      shapes.push_back(s);
      motions.push_back(m);
    }
    // sometimes a floor or a wall (unbounded) in a two-object scene
    if (n == 2 && chance(6)) {
      int k = below(3);
      int side = chance(50) ? 1 : -1;
      int at = side > 0 ? shapes[1].lo[k] : shapes[1].hi[k];
      at += pick(std::vector<int>{0, 0, 1, -1});
      I3 nrm{0, 0, 0};
      nrm[k] = side;
      shapes[0].text = "{\"halfspace\":[" + std::to_string(nrm[0]) + "," + std::to_string(nrm[1]) + "," + std::to_string(nrm[2]) +
                       "," + num(-side * at) + "]}";
    }
    // sometimes the whole scene turned by one rotation that does not keep the
    // grid (shapes and velocities alike): contact stays exact, on tilted planes
    static const std::vector<std::array<int, 4>> turns = {{2, 0, 0, 1}, {3, 0, 0, 4}, {2, 1, 0, 0}, {1, 1, 1, 0}, {2, 1, 1, 1}};
    const std::array<int, 4>* turn = chance(15) ? &pick(turns) : nullptr;
    if (turn)
      for (auto& sh : shapes)
        sh.text = "{\"rotate\":[" + std::to_string((*turn)[0]) + "," + std::to_string((*turn)[1]) + "," + std::to_string((*turn)[2]) + "," +
                  std::to_string((*turn)[3]) + "],\"solid\":" + sh.text + "}";
    std::string s = "{\"format\":\"clash4d-scene/1\",\"time\":[" + num(span[0]) + "," + num(span[1]) + "],\"objects\":[";
    for (int i = 0; i < n; ++i) {
      s += std::string(i ? "," : "") + "{\"name\":\"o" + std::to_string(i) + "\",\"shape\":" + shapes[i].text;
      if (!motions[i].omit) s += ",\"motion\":\"" + motion_text(motions[i], turn) + "\"";
      s += "}";
    }
    s += "]";
    if (n == 3 && chance(30)) {
      int a = below(3), b = (a + 1 + below(2)) % 3;
      s += ",\"ignore\":[[\"o" + std::to_string(a) + "\",\"o" + std::to_string(b) + "\"]]";
    }
    return s + "}";
  }

private:
  std::mt19937_64& rng_;
};

} // namespace random_scenes

struct Random_scene {
  std::string json;   // the text that was read
  Scene scene;
};

// A valid random scene and its JSON text; a draw the reader rejects (a flat
// random hull) is drawn again.
inline Random_scene random_scene_with_text(std::mt19937_64& rng)
{
  random_scenes::Generator g(rng);
  for (int attempt = 0;; ++attempt) {
    std::string text = g.scene_text();
    try {
      return {text, read_scene(read_json_text(text))};
    } catch (const Input_error&) {
      if (attempt > 100) throw;
    }
  }
}

inline Scene random_scene(std::mt19937_64& rng) { return random_scene_with_text(rng).scene; }

} // namespace clash4d

#endif
