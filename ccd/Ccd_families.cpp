#include "ccd/Ccd_families.h"

#include "geometry/Rotation_matrix.h"
#include "scene/Random_draw.h"
#include <cmath>

namespace clash4d {

namespace {

using Point = Ccd_query::Point;
using Rows = Ccd_query::Rows;
using Four = std::array<Point, 4>;

Point add(const Point& a, const Point& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Point sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point scale(const Rational& s, const Point& a) { return {s * a[0], s * a[1], s * a[2]}; }
Point cross3(const Point& a, const Point& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
bool is_zero(const Point& a) { return CGAL::is_zero(a[0]) && CGAL::is_zero(a[1]) && CGAL::is_zero(a[2]); }

Rational small(Random_draw& d, long span = 8, long den = 4) { return Rational(d.range(-span, span), den); }
Point small_point(Random_draw& d, long span = 8, long den = 4) { return {small(d, span, den), small(d, span, den), small(d, span, den)}; }
// A fraction strictly between 0 and 1.
Rational inside_fraction(Random_draw& d)
{
  long q = d.pick<long>({2, 3, 4, 5, 7, 8, 16});
  return Rational(d.range(1, q - 1), q);
}
// The largest |coordinate|, to make a push of about eps in that norm.
Rational norm_inf(const Point& a)
{
  Rational m = 0;
  for (const Rational& x : a) m = std::max(m, CGAL::abs(x));
  return m;
}
Point unit_inf(const Point& a) { return scale(Rational(1) / norm_inf(a), a); }

// The rows of four vertices at `at` when t = t*, each moving with its own
// random velocity.
Rows through(const Four& at, const Rational& tstar, Random_draw& d)
{
  Rows q;
  for (std::size_t i = 0; i < 4; ++i) {
    Point v = small_point(d, 8, 2);
    q[i] = sub(at[i], scale(tstar, v));
    q[i + 4] = add(at[i], scale(Rational(1) - tstar, v));
  }
  return q;
}

Rational contact_time(Random_draw& d, int end_percent = 10)
{
  if (d.percent(end_percent)) return Rational(d.percent(50) ? 1 : 0);
  return inside_fraction(d);
}

// A proper triangle (corners not collinear).
void triangle(Random_draw& d, Point& a, Point& b, Point& c)
{
  do {
    a = small_point(d), b = small_point(d), c = small_point(d);
  } while (is_zero(cross3(sub(b, a), sub(c, a))));
}

// The query moved as a rigid body with a scale: a random rational rotation,
// a translation and a factor keep every contact and t* exactly.
void similar(Rows& q, Random_draw& d)
{
  auto r = rotation_matrix<Rational>(Rational(d.range(-4, 4)), Rational(d.range(-4, 4)), Rational(d.range(-4, 4)),
                                     Rational(d.range(1, 4)));
  Point shift = small_point(d, 64, 8);
  Rational factor(d.range(1, 8), d.range(1, 8));
  for (Point& p : q) {
    Point rotated{r[0][0] * p[0] + r[0][1] * p[1] + r[0][2] * p[2], r[1][0] * p[0] + r[1][1] * p[1] + r[1][2] * p[2],
                  r[2][0] * p[0] + r[2][1] * p[1] + r[2][2] * p[2]};
    p = add(scale(factor, rotated), shift);
  }
}

// Every coordinate replaced by its nearest double, as the benchmark's
// inputs are doubles: the exact answer of the rounded query may differ.
void to_doubles(Rows& q)
{
  for (Point& p : q)
    for (Rational& x : p) x = Rational(round_to_nearest(x));
}

Rows vertex_face(const std::string& name, Random_draw& d)
{
  Point a, b, c;
  triangle(d, a, b, c);
  Rational u = inside_fraction(d), v = (Rational(1) - u) * inside_fraction(d), t = contact_time(d);
  if (name == "vf-edge" || name == "vf-near-9" || name == "vf-near-15") v = 0;
  if (name == "vf-corner") u = v = 0;
  if (name == "vf-end") t = 1;
  if (name == "vf-degenerate") c = add(a, scale(small(d), sub(b, a)));   // collinear at t*
  Point p = add(a, add(scale(u, sub(b, a)), scale(v, sub(c, a))));
  if (name == "vf-near-9" || name == "vf-near-15") {
    // Out of the triangle by about eps, in its plane, across edge ab.
    Point n = cross3(sub(b, a), sub(c, a)), out = cross3(sub(b, a), n);
    Rational eps = name == "vf-near-9" ? Rational(1, 1000000000) : Rational("1/1000000000000000");
    Point dir = unit_inf(out), ca = sub(c, a);
    if (CGAL::sign(dir[0] * ca[0] + dir[1] * ca[1] + dir[2] * ca[2]) > 0) dir = scale(Rational(-1), dir);
    p = add(p, scale(eps, dir));
  }
  Rows q = through({p, a, b, c}, t, d);
  if (name == "vf-degenerate" && d.percent(50)) {
    // Degenerate throughout: c stays on the line of a and b.
    Rational s = small(d);
    q[3] = add(q[1], scale(s, sub(q[2], q[1])));
    q[7] = add(q[5], scale(s, sub(q[6], q[5])));
  }
  if (name == "vf-coplanar")
    for (Point& r : q) r[2] = 0;   // every vertex in z = 0 throughout (then rotated)
  return q;
}

Rows edge_edge(const std::string& name, Random_draw& d)
{
  Point a0 = small_point(d), a1 = small_point(d), B = small_point(d);
  while (is_zero(sub(a1, a0))) a1 = small_point(d);
  while (is_zero(cross3(sub(a1, a0), B))) B = small_point(d);
  Rational u = inside_fraction(d), v = inside_fraction(d), t = contact_time(d);
  if (name == "ee-endpoint") v = 0;
  if (name == "ee-endpoints") u = v = 0;
  if (name == "ee-end") t = 1;
  if (name == "ee-parallel" || name == "ee-parallel-near") B = scale(Rational(d.range(1, 3), d.range(1, 3)) * d.sign(), sub(a1, a0));
  if (name == "ee-zero-length") u = 0;
  if (name == "ee-near-9" || name == "ee-near-15") {
    // The lines cross at t*, about eps beyond b's end.
    Rational eps = name == "ee-near-15" ? Rational("1/1000000000000000") : Rational(1, 1000000000);
    v = -eps / norm_inf(B);
  }
  Point x = add(a0, scale(u, sub(a1, a0)));
  if (name == "ee-parallel-near") {
    Point off = cross3(sub(a1, a0), small_point(d));
    if (!is_zero(off)) x = add(x, scale(Rational(1, 1000000000), unit_inf(off)));
  }
  Point b0 = sub(x, scale(v, B)), b1 = add(b0, B);
  Rows q = through({a0, a1, b0, b1}, t, d);
  if (name == "ee-zero-length") q[1] = q[0], q[5] = q[4];   // edge a is a moving point
  if (name == "ee-coplanar")
    for (Point& r : q) r[2] = 0;
  return q;
}

} // namespace

const std::vector<Ccd_family>& ccd_families()
{
  static const std::vector<Ccd_family> families = {
      {"vf-face", Ccd_type::vertex_face, "the vertex crosses the triangle's interior at a rational time"},
      {"vf-edge", Ccd_type::vertex_face, "the vertex passes exactly through an edge"},
      {"vf-corner", Ccd_type::vertex_face, "the vertex passes exactly through a corner"},
      {"vf-end", Ccd_type::vertex_face, "the vertex reaches the triangle exactly at t = 1"},
      {"vf-near-9", Ccd_type::vertex_face, "the vertex passes about 1e-9 outside an edge, in the triangle's plane"},
      {"vf-near-15", Ccd_type::vertex_face, "the vertex passes about 1e-15 outside an edge, in the triangle's plane"},
      {"vf-coplanar", Ccd_type::vertex_face, "vertex and triangle slide in one plane throughout"},
      {"vf-degenerate", Ccd_type::vertex_face, "the triangle's corners are collinear at the contact, or throughout"},
      {"vf-doubles", Ccd_type::vertex_face, "an interior contact with every number rounded to a double"},
      {"ee-cross", Ccd_type::edge_edge, "the edges cross at interior points at a rational time"},
      {"ee-endpoint", Ccd_type::edge_edge, "an endpoint of one edge passes through the other"},
      {"ee-endpoints", Ccd_type::edge_edge, "the edges' endpoints meet"},
      {"ee-end", Ccd_type::edge_edge, "the edges meet exactly at t = 1"},
      {"ee-parallel", Ccd_type::edge_edge, "parallel edges overlap on one line"},
      {"ee-parallel-near", Ccd_type::edge_edge, "parallel edges about 1e-9 apart"},
      {"ee-near-9", Ccd_type::edge_edge, "the edges' lines pass about 1e-9 apart"},
      {"ee-near-15", Ccd_type::edge_edge, "the edges' lines pass about 1e-15 apart"},
      {"ee-coplanar", Ccd_type::edge_edge, "the edges move in one plane throughout"},
      {"ee-zero-length", Ccd_type::edge_edge, "one edge has zero length: a point through the other"},
      {"ee-doubles", Ccd_type::edge_edge, "an interior crossing with every number rounded to a double"},
  };
  return families;
}

Ccd_query make_ccd_query(const Ccd_family& f, Random_draw& d)
{
  std::string name = f.name;
  std::string base = name == "vf-doubles" ? "vf-face" : name == "ee-doubles" ? "ee-cross" : name;
  Rows q = f.type == Ccd_type::vertex_face ? vertex_face(base, d) : edge_edge(base, d);
  similar(q, d);
  if (name == "vf-doubles" || name == "ee-doubles") to_doubles(q);
  return Ccd_query(f.type, q);
}

Ccd_case make_ccd_case(std::uint64_t seed, std::uint64_t index)
{
  const auto& families = ccd_families();
  const Ccd_family& f = families[index % families.size()];
  Random_draw d(splitmix64(seed * 0x9e3779b97f4a7c15ULL + index));
  return {f.name, make_ccd_query(f, d)};
}

Ccd_query make_simulation_query(Ccd_type type, Random_draw& d, bool& near, bool& degenerate)
{
  near = d.percent(5);
  degenerate = near && d.percent(10);
  if (near) {
    static const char* const vf_degenerate[] = {"vf-edge", "vf-corner", "vf-coplanar", "vf-degenerate", "vf-end"};
    static const char* const ee_degenerate[] = {"ee-endpoint", "ee-parallel", "ee-coplanar", "ee-zero-length", "ee-end"};
    std::string name = degenerate ? (type == Ccd_type::vertex_face ? vf_degenerate : ee_degenerate)[d.below(5)]
                                  : (type == Ccd_type::vertex_face ? "vf-doubles" : "ee-doubles");
    for (const Ccd_family& f : ccd_families())
      if (name == f.name) return make_ccd_query(f, d);
  }
  // A clear miss: two primitives of a mesh a few cells apart, each vertex
  // moving a little, every number a double.
  Rows q;
  auto coordinate = [&](double base) { return base + static_cast<double>(d.below(1u << 20)) / (1u << 20); };
  for (std::size_t i = 0; i < 4; ++i) {
    double cell = (type == Ccd_type::vertex_face ? i == 0 : i < 2) ? 0.0 : 2.0 + static_cast<double>(d.below(4));
    for (std::size_t k = 0; k < 3; ++k) {
      double x0 = coordinate(k == 0 ? cell : 0.0);
      double x1 = x0 + (static_cast<double>(d.below(1u << 10)) - 512.0) / (1u << 14);
      q[i][k] = Rational(x0);
      q[i + 4][k] = Rational(x1);
    }
  }
  return Ccd_query(type, q);
}

} // namespace clash4d
