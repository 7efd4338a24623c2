#include "compare/Contact_families.h"
#include "exact/Rational_kernel.h"
#include "model/Model_builder.h"
#include "model/Motion_path.h"
#include "scene/Exact_validation.h"
#include "scene/Number_text.h"
#include "scene/Random_draw.h"
#include "scene/Scene_builder.h"
#include "scene/Scene_writer.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/convex_hull_2.h>
#include <algorithm>
#include <iterator>
#include <random>
#include <set>
#include <stdexcept>

namespace clash4d {
namespace {

using Kind = Solid::Kind;

// ------------------------------------------------------------------ numbers

using Rng = Random_draw;

Rational frac(long p, long q = 1) { return Rational(p) / Rational(q); }
Rational pow10(long k) { return parse_number_text("1e" + std::to_string(k), false).value; }
Rational decimal(long units, long digits) { return Rational(units) * pow10(-digits); }

Vec3 zero3() { return vec(0, 0, 0); }
// Drawn in order: p first, then q.
Rational random_fraction(Rng& rng, long lo, long hi, std::initializer_list<long> denominators)
{
  long p = rng.range(lo, hi);
  return frac(p, rng.pick(denominators));
}

bool is_zero(const Vec3& a) { return CGAL::is_zero(a[0]) && CGAL::is_zero(a[1]) && CGAL::is_zero(a[2]); }

// ------------------------------------------------------------------ solids

// The same prism as a hull of its corners (for frames that move the z axis).
Solid prism_as_hull(const Solid& p)
{
  const auto& n = p.numbers;
  std::vector<Vec3> points;
  for (std::size_t i = 0; i + 2 < n.size(); i += 2)
    for (std::size_t k : {n.size() - 2, n.size() - 1}) points.push_back(vec(n[i], n[i + 1], n[k]));
  return hull(points);
}

// x -> scale * M x + shift, where M is a signed permutation of the axes:
// (M v)[i] = sign[i] * v[axis[i]].
struct Frame {
  std::array<int, 3> axis{{0, 1, 2}};
  std::array<int, 3> sign{{1, 1, 1}};
  Rational scale{1};
  Vec3 shift = zero3();

  bool turns() const { return axis != std::array<int, 3>{{0, 1, 2}} || sign != std::array<int, 3>{{1, 1, 1}}; }
  Vec3 turn(const Vec3& v) const
  {
    Vec3 r;
    for (int i = 0; i < 3; ++i) r[i] = v[axis[i]] * Rational(sign[i]);
    return r;
  }
  Vec3 linear(const Vec3& v) const { return times(scale, turn(v)); }
  Vec3 point(const Vec3& p) const { return plus(linear(p), shift); }
};

Frame shift_frame(const Vec3& d)
{
  Frame f;
  f.shift = d;
  return f;
}

// The image of a solid under the frame, exactly.
Solid mapped(const Solid& s, const Frame& f)
{
  Solid r = s;
  auto& n = r.numbers;
  switch (s.kind) {
    case Kind::Halfspace:
    case Kind::Convex:
      // a.x + d <= 0 with x = M^T (y - shift) / scale becomes, times scale,
      // (M a).y + scale d - (M a).shift <= 0.
      for (std::size_t i = 0; i < n.size(); i += 4) {
        Vec3 a = f.turn(vec(n[i], n[i + 1], n[i + 2]));
        for (int k = 0; k < 3; ++k) n[i + k] = a[k];
        n[i + 3] = f.scale * n[i + 3] - dot(a, f.shift);
      }
      break;
    case Kind::Block: {
      Vec3 lo = f.point(vec(n[0], n[1], n[2])), hi = f.point(vec(n[3], n[4], n[5]));
      for (int k = 0; k < 3; ++k) {
        n[k] = std::min(lo[k], hi[k]);
        n[k + 3] = std::max(lo[k], hi[k]);
      }
      break;
    }
    case Kind::Hull:
      for (std::size_t i = 0; i < n.size(); i += 3) {
        Vec3 p = f.point(vec(n[i], n[i + 1], n[i + 2]));
        for (int k = 0; k < 3; ++k) n[i + k] = p[k];
      }
      break;
    case Kind::Prism: {
      if (f.axis[2] != 2) return mapped(prism_as_hull(s), f);
      std::vector<Point2> base;
      for (std::size_t i = 0; i + 2 < n.size(); i += 2) {
        Vec3 p = f.point(vec(n[i], n[i + 1], 0));
        base.push_back({p[0], p[1]});
      }
      return prism(base, f.point(vec(0, 0, n[n.size() - 2]))[2], f.point(vec(0, 0, n[n.size() - 1]))[2]);
    }
    case Kind::Translate: {
      Vec3 d = f.linear(vec(n[0], n[1], n[2]));
      n.assign(d.begin(), d.end());
      r.children[0] = mapped(s.children[0], f);
      break;
    }
    case Kind::Rotate: {
      // scale R x + shift = R (scale x + R^T shift): only scale and shift pass a rotation.
      if (f.turns()) throw std::logic_error("mapped: axes are permuted before rotating, not after");
      auto R = rotation_matrix<Rational>(n[0], n[1], n[2], n[3]);
      Frame inner;
      inner.scale = f.scale;
      for (int i = 0; i < 3; ++i) inner.shift = plus(inner.shift, times(f.shift[i], R[i]));
      r.children[0] = mapped(s.children[0], inner);
      break;
    }
    default:
      for (auto& c : r.children) c = mapped(c, f);
  }
  return r;
}

// ------------------------------------------------------------------ motions

// D(t), with D(0) = 0 (spec: Motion), by the pipeline's own motion path.
Vec3 displacement(const Motion& m, const Rational& t)
{
  return Motion_path<Rational>::build(Rational_kernel(), m).displacement(t);
}

// a * ma + b * mb, over the union of their breakpoints.
Motion combined(const Motion& ma, const Rational& a, const Motion& mb, const Rational& b)
{
  std::set<Rational> all(ma.times.begin(), ma.times.end());
  all.insert(mb.times.begin(), mb.times.end());
  Motion m;
  m.times.assign(all.begin(), all.end());
  auto velocity = [&](const Motion& x, std::size_t j) {   // x's velocity on merged interval j
    std::size_t k = 0;
    if (j > 0)
      while (k < x.times.size() && !(m.times[j - 1] < x.times[k])) ++k;
    return x.velocities[k];
  };
  for (std::size_t j = 0; j <= m.times.size(); ++j)
    m.velocities.push_back(plus(times(a, velocity(ma, j)), times(b, velocity(mb, j))));
  return m;
}

// The same displacement with one more breakpoint at t (same velocity both sides).
Motion split(Motion m, const Rational& t)
{
  std::size_t j = 0;
  while (j < m.times.size() && m.times[j] < t) ++j;
  if (j < m.times.size() && m.times[j] == t) return m;
  m.times.insert(m.times.begin() + j, t);
  m.velocities.insert(m.velocities.begin() + j, m.velocities[j]);
  return m;
}

// ------------------------------------------------------------------ scenes

void map_scene(Scene& s, const Frame& f)
{
  for (auto& o : s.objects) {
    o.shape = mapped(o.shape, f);
    for (auto& v : o.motion.velocities) v = f.linear(v);
  }
}

// Time measured in units of 1/unit: times scaled by unit, velocities divided.
void scale_time(Scene& s, const Rational& unit)
{
  s.t_lo *= unit;
  s.t_hi *= unit;
  for (auto& o : s.objects) {
    for (auto& t : o.motion.times) t *= unit;
    for (auto& v : o.motion.velocities) v = times(1 / unit, v);
  }
}

// Every shape wrapped in rotate(q) and every velocity turned by the spec's matrix.
void rotate_scene(Scene& s, const std::array<Rational, 4>& q)
{
  auto R = rotation_matrix<Rational>(q[0], q[1], q[2], q[3]);
  for (auto& o : s.objects) {
    o.shape = rotate(q, std::move(o.shape));
    for (auto& v : o.motion.velocities) v = vec(dot(R[0], v), dot(R[1], v), dot(R[2], v));
  }
}

void shuffle_objects(Scene& s, Rng& rng)
{
  std::vector<std::pair<std::string, std::string>> ignored;
  for (const auto& p : s.ignore) ignored.emplace_back(s.objects[p.first].name, s.objects[p.second].name);
  rng.shuffle(s.objects);
  auto index = [&](const std::string& name) {
    for (std::size_t i = 0; i < s.objects.size(); ++i)
      if (s.objects[i].name == name) return static_cast<int>(i);
    return -1;
  };
  s.ignore.clear();
  for (const auto& p : ignored) {
    int i = index(p.first), j = index(p.second);
    s.ignore.emplace_back(std::min(i, j), std::max(i, j));
  }
}

// ------------------------------------------------------------------ contacts

// Two solids in contact, with a variant offset already applied to b. Moving b
// relative to a by l*n (l > 0) separates them; so does any relative motion
// along `tangents` (directions b may slide in while touching).
struct Contact {
  Solid a, b;
  Vec3 n = vec(1, 0, 0);
  std::vector<Vec3> tangents{vec(0, 1, 0), vec(0, 0, 1)};
  bool movable = true;           // relative motion along n keeps the verdict
  std::string what;
  int expect = -1;               // 1 collision, 0 none, -1 not known
};

// The variant: touching (g = 0), or b pushed into overlap (g < 0) or apart
// (g > 0) by a small amount along n.
struct Offset {
  Rational g;
  std::string what;
};

Offset draw_offset(Rng& rng, int touch, int overlap, long k_lo, long k_hi)
{
  long roll = static_cast<long>(rng.below(100));
  if (roll < touch) return {Rational(0), "touching"};
  Rational eps = rng.percent(85) ? pow10(-rng.range(k_lo, k_hi)) : frac(1, 1L << rng.range(10, 30));
  if (roll < touch + overlap) return {-eps, "overlap " + to_string(eps)};
  return {eps, "gap " + to_string(eps)};
}

int expect_of(const Offset& o) { return o.g < 0 ? 1 : 0; }

// Three vertices in the plane x = x0 strictly around (x0, cy, cz).
std::vector<Vec3> triangle_around(Rng& rng, const Rational& x0, const Rational& cy, const Rational& cz)
{
  std::array<long, 5> k;
  for (auto& x : k) x = rng.range(1, 3);
  return {vec(x0, cy + k[0], cz), vec(x0, cy - k[1], cz + k[2]), vec(x0, cy - k[3], cz - k[4])};
}

// A solid in x <= 0 (side -1) or x >= 0 (side 1) whose face on x = 0 holds
// the origin in its relative interior.
Solid face_solid(Rng& rng, int side, bool allow_halfspace, std::string& what)
{
  Rational w = frac(side * rng.range(1, 3));
  Rational y0 = -rng.range(1, 3), y1 = rng.range(1, 3), z0 = -rng.range(1, 3), z1 = rng.range(1, 3);
  switch (rng.below(allow_halfspace ? 5 : 4)) {
    case 0:
      what += "block";
      return block(vec(std::min(w, Rational(0)), y0, z0), vec(std::max(w, Rational(0)), y1, z1));
    case 1: {
      what += "hull";
      std::vector<Vec3> points = triangle_around(rng, 0, 0, 0);
      long u = rng.range(-2, 2), v = rng.range(-2, 2);
      std::vector<Vec3> back = rng.percent(50) ? std::vector<Vec3>{vec(w, u, v)} : triangle_around(rng, w, u / 2, v / 2);
      points.insert(points.end(), back.begin(), back.end());
      rng.shuffle(points);
      return hull(points);
    }
    case 2: {
      what += "prism";
      long d0 = rng.range(-1, 1), d1 = rng.range(-1, 1);
      if (!(y0 + d0 < y1 - d1)) d0 = d1 = 0;
      std::vector<Point2> base{{0, y0}, {w, y0 + d0}, {w, y1 - d1}, {0, y1}};
      if (rng.percent(30)) base = {{0, y0}, {w, rng.range(-1, 1)}, {0, y1}};
      return prism(base, z0, z1);
    }
    case 3: {
      what += "convex";
      Rational t = w * side;   // the depth |w|
      std::vector<std::array<Rational, 4>> planes{
          {frac(-side), 0, 0, 0}, {frac(side), 0, 0, -t}, {0, 1, 0, -y1}, {0, -1, 0, y0}, {0, 0, 1, -z1}, {0, 0, -1, z0}};
      // Chamfers on the back edges: side*x + y <= t + y1 - 1/2 and the like,
      // which leave the face on x = 0 whole.
      if (rng.percent(50)) planes.push_back({frac(side), 1, 0, -(t + y1 - frac(1, 2))});
      if (rng.percent(50)) planes.push_back({frac(side), 0, -1, -(t - z0 - frac(1, 2))});
      for (auto& h : planes) {
        Rational k = rng.pick<Rational>({1, 1, 2, 3, frac(1, 2)});
        for (auto& c : h) c *= k;
      }
      rng.shuffle(planes);
      return convex(planes);
    }
    default: {
      what += "half-space";
      Rational k = rng.pick<Rational>({1, 2, 5, frac(1, 3)});
      return halfspace(-side * k, 0, 0, 0);
    }
  }
}

// A solid on `side` of x = 0 meeting the plane in a segment through the origin
// along dir = (0, dy, dz).
Solid edge_solid(Rng& rng, int side, const Vec3& dir, std::string& what)
{
  Rational w = frac(side * rng.range(1, 3));
  if (CGAL::is_zero(dir[1]) && rng.percent(50)) {
    what += "prism edge";
    std::vector<Point2> base{{0, 0}, {w, -rng.range(1, 3)}, {w, rng.range(1, 3)}};
    Rational c0 = -rng.range(1, 3), c1 = rng.range(1, 3);
    return prism(base, c0 * dir[2], c1 * dir[2]);
  }
  what += "hull edge";
  Vec3 across = vec(0, -dir[2], dir[1]);
  Vec3 back = vec(w, 0, 0);
  std::array<long, 6> k;
  for (auto& x : k) x = rng.range(1, 3);
  std::vector<Vec3> points{times(k[0], dir), times(-k[1], dir),
                         plus(back, plus(times(k[2], across), times(k[3] - 2, dir))),
                         plus(back, plus(times(-k[4], across), times(k[5] - 2, dir)))};
  if (rng.percent(40)) points.push_back(plus(back, times(k[0] + 1, dir)));
  rng.shuffle(points);
  return hull(points);
}

// A pyramid on `side` of x = 0 with its apex at the origin.
Solid vertex_solid(Rng& rng, int side, std::string& what)
{
  what += "pyramid apex";
  long depth = rng.range(1, 3), cy = rng.range(-1, 1), cz = rng.range(-1, 1);
  std::vector<Vec3> points = triangle_around(rng, side * depth, cy, cz);
  points.push_back(zero3());
  rng.shuffle(points);
  return hull(points);
}

Vec3 edge_direction(Rng& rng)
{
  switch (rng.below(6)) {
    case 0: return vec(0, 1, 0);
    case 1: return vec(0, 0, 1);
    case 2: return vec(0, 1, 1);
    case 3: return vec(0, 1, -1);
    case 4: return vec(0, 2, 1);
    default: return vec(0, 1, 2);
  }
}

// Face, edge or vertex contact across x = 0: a in x <= 0, b in x >= 0.
// Two edges crossing: directions whose cross product has a non-zero x.
void crossing_edges(Rng& rng, Contact& c)
{
  c.what = "crossing edges (";
  Vec3 d1 = edge_direction(rng), d2 = edge_direction(rng);
  while (CGAL::is_zero(d1[1] * d2[2] - d1[2] * d2[1])) d2 = edge_direction(rng);
  c.a = edge_solid(rng, -1, d1, c.what);
  c.what += "/";
  c.b = edge_solid(rng, 1, d2, c.what);
}

// Two blocks meeting at the origin: along an edge (normal (1, 1, 0)), or
// corner on corner (normal (1, 1, 1)).
void block_contact(Rng& rng, Contact& c, bool parallel_edges)
{
  c.what = parallel_edges ? "parallel edges (blocks" : "corner on corner (blocks";
  c.n = parallel_edges ? vec(1, 1, 0) : vec(1, 1, 1);
  c.a = block(Vec3{-rng.range(1, 3), -rng.range(1, 3), -rng.range(1, 3)}, zero3());
  if (parallel_edges) c.a.numbers[5] = rng.range(1, 3);
  c.b = block(zero3(), Vec3{rng.range(1, 3), rng.range(1, 3), rng.range(1, 3)});
  if (parallel_edges) c.b.numbers[2] = -rng.range(1, 3);
}

Contact basic_contact(Rng& rng, const Offset& off, bool allow_halfspace)
{
  Contact c;
  std::string& w = c.what;
  switch (rng.below(9)) {
    case 0:
    case 1:
      w = "face on face (";
      c.a = face_solid(rng, -1, allow_halfspace, w);
      w += "/";
      c.b = face_solid(rng, 1, false, w);
      break;
    case 2:
      w = "edge on face (";
      c.a = face_solid(rng, -1, allow_halfspace, w);
      w += "/";
      c.b = edge_solid(rng, 1, edge_direction(rng), w);
      break;
    case 3:
      w = "vertex on face (";
      c.a = face_solid(rng, -1, allow_halfspace, w);
      w += "/";
      c.b = vertex_solid(rng, 1, w);
      break;
    case 4:
      w = "face on vertex (";
      c.a = vertex_solid(rng, -1, w);
      w += "/";
      c.b = face_solid(rng, 1, false, w);
      break;
    case 5: crossing_edges(rng, c); break;
    case 6:
      w = "face on edge (";
      c.a = edge_solid(rng, -1, edge_direction(rng), w);
      w += "/";
      c.b = face_solid(rng, 1, false, w);
      break;
    case 7: block_contact(rng, c, true); break;
    default: block_contact(rng, c, false);
  }
  w += "), " + off.what;
  c.b = mapped(c.b, shift_frame(times(off.g, c.n)));
  c.expect = expect_of(off);
  return c;
}

// A box split into two or three blocks (abutting or overlapping), against a
// solid across the seam (always a collision), on the outside at the seam, or
// filling an L-shaped notch.
Contact union_contact(Rng& rng, const Offset& off)
{
  long L = rng.range(2, 5), W = rng.range(1, 3), H = rng.range(1, 3), s = rng.range(1, L - 1);
  Rational overlap = rng.pick<Rational>({0, 0, frac(1, 2)});
  auto piece = [&](const Vec3& lo, const Vec3& hi) {
    if (!rng.percent(30)) return block(lo, hi);
    std::vector<Point2> base{{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}};
    return prism(base, lo[2], hi[2]);
  };
  Contact c;
  c.tangents = {vec(1, 0, 0), vec(0, 1, 0)};
  c.n = vec(0, 0, 1);
  std::vector<Solid> pieces;
  long kind = static_cast<long>(rng.below(100));
  if (kind < 70) {
    pieces.push_back(piece(vec(0, 0, 0), vec(s + overlap, W, H)));
    if (W > 1 && rng.percent(40)) {   // the right part split again, along y
      pieces.push_back(piece(vec(s, 0, 0), vec(L, 1, H)));
      pieces.push_back(piece(vec(s, 1, 0), vec(L, W, H)));
    } else {
      pieces.push_back(piece(vec(s, 0, 0), vec(L, W, H)));
    }
    Rational c0 = s - frac(rng.range(1, 2 * s), 2), c1 = s + frac(rng.range(1, 2 * (L - s)), 2);
    if (kind < 25) {
      c.what = "across the seam, flush with the faces";
      c.b = block(vec(c0, 0, 0), vec(c1, W, H));
      c.expect = 1;
    } else {
      c.what = "on the outside at the seam";
      Rational y0 = rng.percent(50) ? Rational(0) : frac(rng.range(0, 2 * W - 1), 2);
      c.b = block(vec(c0, y0, H), vec(c1, W, H + rng.range(1, 2)));
      c.expect = expect_of(off);
    }
  } else {
    long h = rng.range(1, H);
    c.what = "filling an L notch";
    pieces.push_back(piece(vec(0, 0, 0), vec(L, W, h)));
    pieces.push_back(piece(vec(0, 0, h - overlap), vec(s, W, H + 1)));
    long dx = rng.range(0, 1), dz = rng.range(0, 1);
    c.b = block(vec(s, 0, h), vec(L + dx, W, H + 1 + dz));
    c.n = vec(1, 0, 1);
    c.tangents = {vec(0, 1, 0)};
    c.expect = expect_of(off);
  }
  rng.shuffle(pieces);
  c.a = csg(Kind::Union, pieces);
  c.what = "union: " + c.what + (CGAL::is_zero(overlap) ? ", pieces abutting" : ", pieces overlapping") + ", " + off.what;
  c.b = mapped(c.b, shift_frame(times(off.g, c.n)));
  return c;
}

// A bar minus a full-section slab flush with its faces: regularisation drops
// the dangling strips left on those faces. b rests on the top strip, inside
// the cut (never a collision) or reaching past it (a collision when it dips).
Contact difference_contact(Rng& rng, const Offset& off)
{
  long L = rng.range(3, 6), W = rng.range(1, 3), H = rng.range(1, 3);
  long c0 = rng.range(1, L - 2), c1 = c0 + rng.range(1, L - 1 - c0);
  Rational ylo = rng.percent(70) ? Rational(0) : Rational(-1), yhi = ylo < 0 ? Rational(W + 1) : Rational(W);
  Rational zlo = rng.percent(70) ? Rational(0) : Rational(-1);
  std::vector<Solid> parts{block(vec(0, 0, 0), vec(L, W, H)), block(vec(c0, ylo, zlo), vec(c1, yhi, H))};
  if (rng.percent(30))   // a hole in the bottom, far from b
    parts.push_back(block(vec(c1 + frac(1, 4), frac(W, 4), -1), vec(c1 + frac(1, 2), frac(W, 2), frac(H, 2))));
  Contact c;
  c.a = csg(Kind::Difference, parts);
  c.n = vec(0, 0, 1);
  Rational x0 = c0 + rng.pick<Rational>({0, frac(1, 4)}), y0 = rng.pick<Rational>({0, 0, frac(W, 4)});
  Rational y1 = rng.pick<Rational>({Rational(W), Rational(W), frac(3 * W, 4), Rational(W + 1)});
  if (rng.percent(50)) {
    c.what = "inside the cut";
    Rational x1 = c1 - rng.pick<Rational>({0, frac(1, 4)});
    c.b = block(vec(x0, y0, H), vec(x1, y1, H + rng.range(1, 2)));
    c.tangents = {vec(0, 1, 0)};
    c.expect = 0;
  } else {
    c.what = "reaching past the cut";
    Rational x1 = c1 + rng.pick<Rational>({frac(1, 4), frac(1, 2), 1});
    c.b = block(vec(x0, y0, H), vec(x1, y1, H + rng.range(1, 2)));
    c.tangents = {vec(1, 0, 0), vec(0, 1, 0)};
    c.expect = expect_of(off);
  }
  c.what = "difference with dangling faces, b on the top strip " + c.what + ", " + off.what;
  c.b = mapped(c.b, shift_frame(times(off.g, c.n)));
  return c;
}

// A closed cavity exactly filled (b grown or shrunk on one face by the
// offset), or a pocket or slot with a peg of exactly its section (widened or
// narrowed) that may slide in along it.
Contact cavity_contact(Rng& rng, const Offset& off)
{
  long L = rng.range(3, 5), W = rng.range(3, 5), H = rng.range(3, 5);
  Vec3 lo = vec(1, 1, 1), hi{rng.range(2, L - 1), rng.range(2, W - 1), rng.range(2, H - 1)};
  Contact c;
  c.expect = expect_of(off);
  int face = static_cast<int>(rng.below(6));
  if (rng.percent(50)) {
    c.what = "closed cavity exactly filled";
    c.a = csg(Kind::Difference, {block(zero3(), vec(L, W, H)), block(lo, hi)});
    Vec3 blo = lo, bhi = hi;
    if (face < 3) blo[face] += off.g;
    else bhi[face - 3] -= off.g;
    long form = static_cast<long>(rng.below(4));
    if (form == 0) {
      std::vector<Vec3> corners;
      for (int i = 0; i < 8; ++i) corners.push_back(vec(i & 1 ? bhi[0] : blo[0], i & 2 ? bhi[1] : blo[1], i & 4 ? bhi[2] : blo[2]));
      rng.shuffle(corners);
      c.b = hull(corners);
      c.what += " (hull of corners)";
    } else if (form == 1) {
      Vec3 mid_hi = bhi, mid_lo = blo;
      mid_hi[2] = mid_lo[2] = (blo[2] + bhi[2]) / 2;
      c.b = csg(Kind::Union, {block(blo, mid_hi), block(mid_lo, bhi)});
      c.what += " (union of halves)";
    } else {
      c.b = block(blo, bhi);
    }
    c.movable = false;
    c.tangents.clear();
  } else {
    bool through = rng.percent(30);
    c.what = through ? "slot with a peg of its section" : "pocket with a peg of its section";
    Vec3 plo = lo, phi = hi;
    plo[2] = through ? Rational(-1) : lo[2];
    phi[2] = H + 1;
    c.a = csg(Kind::Difference, {block(zero3(), vec(L, W, H)), block(plo, phi)});
    Vec3 blo = plo, bhi = phi;
    blo[2] = through ? Rational(-2) : lo[2];
    bhi[2] = H + rng.range(1, 2);
    if (face % 3 == 2) face = 0;   // the peg's sides only
    if (face < 3) blo[face] += off.g;
    else bhi[face - 3] -= off.g;
    c.b = block(blo, bhi);
    c.n = vec(0, 0, 1);
    c.tangents.clear();
  }
  c.what += ", " + off.what;
  return c;
}

// ------------------------------------------------------------------ motion kinds

enum class Move { Static, Instant, Sliding, Approach, Co_moving, Span_end };

const char* move_name(Move m)
{
  switch (m) {
    case Move::Static: return "at rest";
    case Move::Instant: return "touching at one instant";
    case Move::Sliding: return "sliding";
    case Move::Approach: return "approach and stop";
    case Move::Co_moving: return "moving together";
    case Move::Span_end: return "at the span's end";
  }
  return "?";
}

Move any_move(Rng& rng, const Contact& c)
{
  std::vector<Move> ok{Move::Static, Move::Co_moving};
  if (c.movable) ok.insert(ok.end(), {Move::Instant, Move::Approach, Move::Span_end});
  if (!c.tangents.empty()) ok.push_back(Move::Sliding);
  return ok[rng.below(ok.size())];
}

// Speeds and times: small fractions, or one- and two-digit decimals.
Rational speed(Rng& rng, bool decimals)
{
  if (decimals) return rng.percent(70) ? decimal(rng.range(1, 19), 1) : decimal(rng.range(1, 99), 2);
  return random_fraction(rng, 1, 4, {1, 1, 2, 3, 4});
}

Vec3 random_velocity(Rng& rng, bool decimals)
{
  Vec3 v;
  for (auto& x : v) {
    x = 0;
    if (rng.percent(40)) continue;
    x = speed(rng, decimals);
    x *= rng.sign();
  }
  return v;
}

Vec3 tangent_velocity(Rng& rng, const Contact& c, bool decimals)
{
  Vec3 v = zero3();
  for (const auto& t : c.tangents) {
    long k = rng.range(-1, 1);
    v = plus(v, times(k * speed(rng, decimals), t));
  }
  if (is_zero(v) && !c.tangents.empty()) {
    const Vec3& t = c.tangents[rng.below(c.tangents.size())];
    v = times(speed(rng, decimals), t);
  }
  return v;
}

Vec3 maybe_tangent(Rng& rng, const Contact& c, bool decimals)
{
  return rng.percent(50) || c.tangents.empty() ? zero3() : tangent_velocity(rng, c, decimals);
}

// Away from contact (direction 1) or toward it (-1), sometimes sideways too.
Vec3 along(Rng& rng, const Contact& c, int direction, bool decimals)
{
  Vec3 v = times(direction * speed(rng, decimals), c.n);
  return plus(v, maybe_tangent(rng, c, decimals));
}

// Vectors that make sums: a random decimal vector.
Vec3 decimal_vector(Rng& rng)
{
  Vec3 v;
  for (auto& x : v) {
    long units = rng.range(-99, 99);
    x = decimal(units, rng.range(1, 2));
  }
  return v;
}

// A decimal p such that the doubles of p and d - p do not add up to the
// double of d (0.1 + 0.2 against 0.3). Doubles only choose p; the scene gets
// p and d - p exactly. Gives up after a few draws and returns the last one.
Rational missing_part(Rng& rng, const Rational& d)
{
  Rational p;
  for (int tries = 0; tries < 16; ++tries) {
    long units = rng.range(-99, 99);
    p = decimal(units, rng.range(1, 2));
    if (round_to_nearest(p) + round_to_nearest(d - p) != round_to_nearest(d)) break;
  }
  return p;
}

// s moved by d: the numbers changed, or a translate node, or (sums) both,
// split so that the double sum misses.
Solid shifted(Rng& rng, const Solid& s, const Vec3& d, bool sums)
{
  if (sums) {
    Vec3 part;
    for (int i = 0; i < 3; ++i) part[i] = missing_part(rng, d[i]);
    return translate(part, mapped(s, shift_frame(minus(d, part))));
  }
  if (is_zero(d)) return s;
  return rng.percent(60) ? mapped(s, shift_frame(d)) : translate(d, s);
}

// How b moves relative to a (rel), what both share (common), and the
// contact time tc, which a span-end contact moves to an end.
struct Relative_motion {
  Motion rel, common;
  Rational tc;
};

Relative_motion relative_motion(Rng& rng, const Contact& c, Move move, const Scene& s, const Rational& span,
                                Relative_motion m, bool decimals)
{
  switch (move) {
    case Move::Static: break;
    case Move::Instant:
      m.rel = piecewise({along(rng, c, -1, decimals), along(rng, c, 1, decimals)}, {m.tc});
      break;
    case Move::Sliding:
      m.rel = steady(tangent_velocity(rng, c, decimals));
      if (rng.percent(30)) m.rel = piecewise({m.rel.velocities[0], tangent_velocity(rng, c, decimals)}, {m.tc});
      break;
    case Move::Approach: {
      Vec3 v = along(rng, c, -1, decimals);
      Rational t0 = m.tc - (decimals ? decimal(rng.range(1, 30), 1) : span * frac(rng.range(1, 4), 8));
      m.rel = rng.percent(50) ? piecewise({v, zero3()}, {m.tc}) : piecewise({zero3(), v, zero3()}, {t0, m.tc});
      break;
    }
    case Move::Co_moving:
      m.common = steady(random_velocity(rng, decimals));
      for (long k = rng.range(0, 2); k > 0; --k) {
        Rational t = s.t_lo + span * frac(rng.range(0, 8), 8);
        m.common = combined(m.common, 1, piecewise({zero3(), random_velocity(rng, decimals)}, {t}), 1);
      }
      break;
    case Move::Span_end: {
      bool start = rng.percent(50);
      m.tc = start ? s.t_lo : s.t_hi;
      m.rel = steady(along(rng, c, start ? 1 : -1, decimals));
      break;
    }
  }
  return m;
}

// The contact as a scene: b relative to a moves as `move` prescribes and is
// in its contact pose at the time tc.
Scene contact_scene(Rng& rng, const Contact& c, Move move, bool decimals)
{
  Scene s;
  Rational span;
  if (decimals) {
    s.t_lo = rng.percent(70) ? Rational(0) : decimal(rng.range(1, 9), 1);
    span = decimal(rng.range(8, 60), 1);
  } else {
    s.t_lo = rng.pick<long>({0, 0, 0, -2, 1});
    span = rng.range(2, 10);
  }
  s.t_hi = s.t_lo + span;
  Rational tc = s.t_lo + span * frac(rng.range(1, 7), 8);
  if (decimals) tc = s.t_lo + span * decimal(rng.range(1, 9), 1);
  Motion common = rng.percent(60) ? rest() : steady(random_velocity(rng, decimals));
  Relative_motion m = relative_motion(rng, c, move, s, span, {rest(), common, tc}, decimals);
  // Who moves: b, a, or both (toward each other); `common` is added to both.
  long who = static_cast<long>(rng.below(10));
  Rational share_a = who < 5 ? Rational(0) : who < 8 ? Rational(-1) : frac(-1, 2);
  auto with_share = [&](const Rational& share) { return CGAL::is_zero(share) ? m.common : combined(m.common, 1, m.rel, share); };
  Motion da = with_share(share_a), db = with_share(share_a + 1);
  if (move == Move::Co_moving || rng.percent(15)) db = split(db, s.t_lo + span * frac(rng.range(1, 7), 8));
  // With decimals, both are moved by a decimal vector, one of them by a sum that misses.
  Vec3 base = decimals ? decimal_vector(rng) : zero3();
  bool split_a = rng.percent(50);
  s.objects.push_back({"a", shifted(rng, c.a, minus(base, displacement(da, m.tc)), decimals && split_a), da});
  s.objects.push_back({"b", shifted(rng, c.b, minus(base, displacement(db, m.tc)), decimals && !split_a), db});
  if (rng.percent(15)) {   // an ignored copy of a: it meets b exactly as a does
    s.objects.push_back({"c", s.objects[0].shape, da});
    s.ignore.emplace_back(0, 2);
  }
  s.name = c.what + ", " + move_name(move);
  if (c.expect >= 0) s.name += c.expect ? "; expect collision" : "; expect no collision";
  shuffle_objects(s, rng);
  return s;
}

// ------------------------------------------------------------------ general position

// The 2D convex hull (counter-clockwise from the lexicographically smallest
// vertex, no collinear vertices), exactly, by CGAL.
std::vector<Point2> convex_polygon(const std::vector<Point2>& p)
{
  using K = CGAL::Simple_cartesian<Rational>;
  std::vector<K::Point_2> in, out;
  for (const auto& q : p) in.emplace_back(q[0], q[1]);
  CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(out));
  if (out.size() < 3) return {};
  std::vector<Point2> h;
  for (const auto& q : out) h.push_back({q.x(), q.y()});
  std::rotate(h.begin(), std::min_element(h.begin(), h.end()), h.end());
  return h;
}

Rational random_coordinate(Rng& rng) { return random_fraction(rng, -8, 8, {2, 3, 4, 5, 7}); }
Vec3 random_point(Rng& rng) { return Vec3{random_coordinate(rng), random_coordinate(rng), random_coordinate(rng)}; }

Solid random_solid(Rng& rng, const Vec3& centre)
{
  for (;;) {
    if (rng.percent(60)) {
      std::vector<Vec3> points;
      for (long i = rng.range(4, 7); i > 0; --i)
        points.push_back(plus(centre, random_point(rng)));
      try {
        hull_facets(points);
        return hull(points);
      } catch (const std::invalid_argument&) {
        continue;   // coplanar: draw again
      }
    }
    std::vector<Point2> base;
    for (long i = rng.range(4, 8); i > 0; --i)
      base.push_back({centre[0] + random_coordinate(rng), centre[1] + random_coordinate(rng)});
    base = convex_polygon(base);
    if (base.size() < 3 || !prism_base_problem(base).empty()) continue;
    Rational z0 = centre[2] + random_coordinate(rng), z1 = z0 + random_fraction(rng, 1, 8, {1, 2, 3});
    return prism(base, z0, z1);
  }
}

// ------------------------------------------------------------------ families

Scene static_touch(Rng& rng) { return contact_scene(rng, basic_contact(rng, draw_offset(rng, 50, 35, 2, 9), true), Move::Static, false); }
Scene instant_touch(Rng& rng) { return contact_scene(rng, basic_contact(rng, draw_offset(rng, 50, 35, 2, 9), true), Move::Instant, false); }
Scene sliding(Rng& rng) { return contact_scene(rng, basic_contact(rng, draw_offset(rng, 50, 35, 2, 9), true), Move::Sliding, false); }
Scene approach_stop(Rng& rng) { return contact_scene(rng, basic_contact(rng, draw_offset(rng, 50, 35, 2, 9), true), Move::Approach, false); }
Scene co_moving(Rng& rng) { return contact_scene(rng, basic_contact(rng, draw_offset(rng, 50, 35, 2, 9), true), Move::Co_moving, false); }
Scene span_end(Rng& rng) { return contact_scene(rng, basic_contact(rng, draw_offset(rng, 50, 35, 2, 9), true), Move::Span_end, false); }

Scene union_seam(Rng& rng)
{
  Contact c = union_contact(rng, draw_offset(rng, 50, 35, 2, 9));
  return contact_scene(rng, c, any_move(rng, c), false);
}

Scene difference_dangling(Rng& rng)
{
  Contact c = difference_contact(rng, draw_offset(rng, 40, 45, 2, 9));
  return contact_scene(rng, c, any_move(rng, c), false);
}

Scene filled_cavity(Rng& rng)
{
  Contact c = cavity_contact(rng, draw_offset(rng, 50, 35, 2, 9));
  return contact_scene(rng, c, any_move(rng, c), false);
}

Scene (*const contact_makers[])(Rng&) = {static_touch, instant_touch, sliding, approach_stop, co_moving,
                                        span_end, union_seam, difference_dangling, filled_cavity};

Scene rotated(Rng& rng) { return contact_makers[rng.below(std::size(contact_makers))](rng); }

Scene decimal_sums(Rng& rng)
{
  Contact c = basic_contact(rng, draw_offset(rng, 60, 25, 2, 9), true);
  Move m = rng.pick({Move::Static, Move::Approach, Move::Approach, Move::Sliding, Move::Instant, Move::Span_end, Move::Co_moving});
  return contact_scene(rng, c, m, true);
}

Scene tiny_gap(Rng& rng)
{
  Offset off = draw_offset(rng, 10, 50, 6, 16);
  Contact c = rng.percent(70) ? basic_contact(rng, off, true)
                              : (rng.percent(50) ? union_contact(rng, off) : cavity_contact(rng, off));
  return contact_scene(rng, c, rng.percent(50) ? Move::Static : any_move(rng, c), false);
}

Scene general_position(Rng& rng)
{
  Scene s;
  s.t_lo = 0;
  s.t_hi = rng.range(1, 5);
  s.name = "general position";
  long n = rng.percent(80) ? 2 : 3;
  for (long i = 0; i < n; ++i) {
    Vec3 centre = zero3();
    if (i > 0) centre = times(frac(1, 2), Vec3{rng.range(-6, 6), rng.range(-6, 6), rng.range(-6, 6)});
    Motion m = rest();
    if (rng.percent(60)) m = steady(random_point(rng));
    if (rng.percent(30)) {
      Rational t = frac(rng.range(1, 4), 2);
      m = combined(m, 1, piecewise({zero3(), random_point(rng)}, {t}), 1);
    }
    s.objects.push_back({std::string(1, static_cast<char>('a' + i)), random_solid(rng, centre), m});
  }
  return s;
}

// ------------------------------------------------------------------ the family table

enum class Finish { Plain, Rotated, Decimal, Tiny };

struct Family_entry {
  Fuzz_family family;
  Scene (*make)(Rng&);
  Finish finish;
};

const std::vector<Family_entry>& family_table()
{
  static const std::vector<Family_entry> table{
      {{"static_touch", "solids at rest touching face to face, edge or vertex to face, along crossing or parallel edges, or corner to corner (blocks, hulls, prisms, convex solids, a half-space floor)"}, static_touch, Finish::Plain},
      {{"instant_touch", "the same contacts made at one instant: one solid comes in along the contact normal and turns back"}, instant_touch, Finish::Plain},
      {{"sliding", "a solid sliding along another while touching it"}, sliding, Finish::Plain},
      {{"approach_stop", "a solid approaches and stops exactly at contact, resting there"}, approach_stop, Finish::Plain},
      {{"co_moving", "touching solids moving together with one piecewise motion, its breakpoints split differently"}, co_moving, Finish::Plain},
      {{"span_end", "contact exactly at tL or tH, the overlap (if any) only outside the span"}, span_end, Finish::Plain},
      {{"union_seam", "unions with internal faces: a solid across the seam (a collision), touching the outside at the seam, or filling an L notch"}, union_seam, Finish::Plain},
      {{"difference_dangling", "differences by a slab flush with the faces, whose dangling strips regularisation drops; a solid rests on a strip"}, difference_dangling, Finish::Plain},
      {{"filled_cavity", "a closed cavity exactly filled, or a pocket or slot with a peg of exactly its section"}, filled_cavity, Finish::Plain},
      {{"rotated", "any of the contact families rotated whole, velocities included, by a rational quaternion such as (3,0,0,4), (1,1,1,1), (2,1,1,1), (1,2,2,0)"}, rotated, Finish::Rotated},
      {{"decimal_sums", "contacts placed by decimal translations and decimal velocities times decimal durations, whose double sums and products miss (0.1+0.2 against 0.3)"}, decimal_sums, Finish::Decimal},
      {{"tiny_gap", "gaps and overlaps of 10^-k, k = 6..16, at coordinates of 1 to 7 digits (1.0000000001 against 1)"}, tiny_gap, Finish::Tiny},
      {{"general_position", "random hulls and prisms with random rational coordinates and motions: the control group"}, general_position, Finish::Plain},
  };
  return table;
}

// A random signed permutation of the axes (half of them keeping z, so prisms stay prisms).
Frame random_turn(Rng& rng)
{
  Frame f;
  std::vector<int> axes{0, 1, 2};
  if (rng.percent(50)) rng.shuffle(axes);
  else if (rng.percent(50)) std::swap(axes[0], axes[1]);
  for (int i = 0; i < 3; ++i) {
    f.axis[i] = axes[i];
    f.sign[i] = rng.sign();
  }
  return f;
}

std::array<Rational, 4> random_quaternion(Rng& rng)
{
  if (rng.percent(25)) {
    std::array<Rational, 4> q;
    do {
      for (auto& x : q) x = rng.range(-3, 3);
    } while (CGAL::is_zero(q[0]) && CGAL::is_zero(q[1]) && CGAL::is_zero(q[2]) && CGAL::is_zero(q[3]));
    return q;
  }
  static const int known[][4] = {{3, 0, 0, 4}, {1, 1, 1, 1}, {2, 1, 1, 1}, {1, 2, 2, 0}, {1, 1, 1, 0}, {1, 1, 0, 0}, {2, 0, 1, 0}, {4, 1, 2, 3}};
  const int* q = known[rng.below(std::size(known))];
  return {q[0], q[1], q[2], q[3]};
}

// A coordinate of 1 to 7 integer digits, sometimes with two decimals.
Rational large_coordinate(Rng& rng)
{
  long digits = rng.range(1, 7), top = 1;
  for (long i = 0; i < digits; ++i) top *= 10;
  Rational x = rng.range(top / 10, top - 1);
  if (rng.percent(40)) x += decimal(rng.range(1, 99), 2);
  return x;
}

// The variations every family gets (none changes the exact verdict): axes
// permuted and mirrored, then (rotated family) a rotation, then scale, time
// unit and a shift of the whole scene.
void finish(Scene& s, Rng& rng, Finish how)
{
  map_scene(s, random_turn(rng));
  if (how == Finish::Rotated) {
    auto q = random_quaternion(rng);
    rotate_scene(s, q);
    s.name += "; rotated by (" + to_string(q[0]) + "," + to_string(q[1]) + "," + to_string(q[2]) + "," + to_string(q[3]) + ")";
  }
  if (how == Finish::Decimal) return;   // its sums were chosen to miss as they are
  Frame f;
  Rational unit(1);
  if (how == Finish::Tiny) {
    f.scale = rng.pick<Rational>({1, 1, 10, frac(1, 10), 100});
    for (auto& x : f.shift) x = large_coordinate(rng);
    map_scene(s, f);
    return;
  }
  if (rng.percent(60)) f.scale = rng.pick<Rational>({10, 100, 1000, frac(1, 10), frac(1, 100), frac(1, 1000), frac(7, 10), frac(3, 10), frac(11, 10), frac(5, 2), frac(1, 3), frac(2, 7)});
  if (rng.percent(40)) unit = rng.pick<Rational>({frac(1, 10), 10, frac(1, 2), frac(3, 10), frac(7, 10), 4});
  map_scene(s, f);
  scale_time(s, unit);
  if (rng.percent(50)) {   // the same shift for all, for some objects by a sum that misses
    Vec3 d = decimal_vector(rng);
    for (auto& o : s.objects) {
      bool sums = rng.percent(50);
      o.shape = shifted(rng, o.shape, d, sums);
    }
  }
}

} // namespace

const std::vector<Fuzz_family>& fuzz_families()
{
  static const std::vector<Fuzz_family> families = [] {
    std::vector<Fuzz_family> out;
    for (const auto& e : family_table()) out.push_back(e.family);
    return out;
  }();
  return families;
}

Fuzz_case make_fuzz_case(std::uint64_t seed, std::uint64_t index)
{
  const auto& table = family_table();
  const Family_entry& e = table[index % table.size()];
  Rng rng(splitmix64(splitmix64(seed) + index));
  Scene s = e.make(rng);
  finish(s, rng, e.finish);
  s.name = std::string(e.family.name) + ": " + s.name;
  return {e.family.name, write_scene(s)};
}

} // namespace clash4d
