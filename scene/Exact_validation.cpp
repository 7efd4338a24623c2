#include "scene/Exact_validation.h"
#include "geometry/Polytope_ft.h"
#include "numbers/Exact_lp.h"
#include "scene/Lazy_point.h"

#include <CGAL/Cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <map>
#include <set>
#include <stdexcept>

namespace clash4d {
namespace {

using Rational_geometry = CGAL::Cartesian<Rational>;
using Point_2 = Rational_geometry::Point_2;
using Point_3 = Rational_geometry::Point_3;
using Program = CGAL::Quadratic_program<Rational>;
using Solution = CGAL::Quadratic_program_solution<Rational>;

Point_3 to_point(const Rational3& p) { return Point_3(p[0], p[1], p[2]); }

// Linear program over (x, y, z, s): a.x + d + w*s <= 0 for each half-space.
Program make_program(const std::vector<Rational4>& planes, const Rational& w)
{
  Program lp(CGAL::SMALLER, false, 0, false, 0);
  for (std::size_t i = 0; i < planes.size(); ++i) {
    int row = static_cast<int>(i);
    for (int k = 0; k < 3; ++k) lp.set_a(k, row, planes[i][k]);
    lp.set_a(3, row, w);
    lp.set_b(row, -planes[i][3]);
  }
  lp.set_l(3, true, 0);
  lp.set_u(3, true, 1);
  return lp;
}

// A rational point as integers over one positive denominator:
// (x, y, z) = (X, Y, Z) / W. Hull keys and volumes are computed on these, as
// products of integers, where rationals would reduce a fraction (a GCD) at
// each step: the pieces of a mesh have long denominators (issue 58).
struct Integer_point {
  std::array<mpz_class, 3> x;
  mpz_class w;
};

Integer_point integer_point(const Rational3& p)
{
  Integer_point q;
  q.w = 1;
  for (const Rational& c : p) mpz_lcm(q.w.get_mpz_t(), q.w.get_mpz_t(), mpq_denref(c.mpq()));
  for (int k = 0; k < 3; ++k) {
    mpz_divexact(q.x[k].get_mpz_t(), q.w.get_mpz_t(), mpq_denref(p[k].mpq()));
    q.x[k] *= mpz_class(mpq_numref(p[k].mpq()));
  }
  return q;
}

// The oriented plane through p q r, normal (q - p) x (r - p), as its
// primitive integer vector (a, b, c, d), a x + b y + c z + d = 0: a positive
// multiple of every other vector of that plane and orientation, so two
// triples give the same key exactly when they span the same oriented plane.
// With u = (q - p) Wp Wq and v = (r - p) Wp Wr (integers), n = u x v is a
// positive multiple of the normal, and (n Wp, -n . Xp) of the plane.
std::array<mpz_class, 4> plane_key(const Integer_point& p, const Integer_point& q, const Integer_point& r)
{
  std::array<mpz_class, 3> u, v;
  for (int k = 0; k < 3; ++k) {
    u[k] = q.x[k] * p.w - p.x[k] * q.w;
    v[k] = r.x[k] * p.w - p.x[k] * r.w;
  }
  std::array<mpz_class, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  std::array<mpz_class, 4> key{n[0] * p.w, n[1] * p.w, n[2] * p.w, -(n[0] * p.x[0] + n[1] * p.x[1] + n[2] * p.x[2])};
  mpz_class g = 0;
  for (const auto& c : key) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_mpz_t());
  if (g != 0)
    for (auto& c : key) mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), g.get_mpz_t());
  return key;
}

// det(a, b, c) of the three points' coordinates: (det of the integer rows)
// / (Wa Wb Wc).
Rational determinant_of(const Integer_point& a, const Integer_point& b, const Integer_point& c)
{
  mpz_class det = a.x[0] * (b.x[1] * c.x[2] - b.x[2] * c.x[1]) - a.x[1] * (b.x[0] * c.x[2] - b.x[2] * c.x[0]) +
                  a.x[2] * (b.x[0] * c.x[1] - b.x[1] * c.x[0]);
  mpz_class w = a.w * b.w * c.w;
  Rational r;
  mpz_set(mpq_numref(r.mpq()), det.get_mpz_t());
  mpz_set(mpq_denref(r.mpq()), w.get_mpz_t());
  mpq_canonicalize(r.mpq());
  return r;
}

} // namespace

std::string prism_base_problem(const std::vector<std::array<Rational, 2>>& base)
{
  std::size_t n = base.size();
  if (n < 3) return "polygon needs at least 3 vertices, found " + std::to_string(n);
  bool all_right = true;
  for (std::size_t i = 0; i < n; ++i) {
    Point_2 p(base[i][0], base[i][1]), q(base[(i + 1) % n][0], base[(i + 1) % n][1]);
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i || j == (i + 1) % n) continue;
      CGAL::Orientation o = CGAL::orientation(p, q, Point_2(base[j][0], base[j][1]));
      if (o == CGAL::COLLINEAR)
        return "polygon is not strictly convex: vertices " + std::to_string(i) + ", " + std::to_string((i + 1) % n) +
               " and " + std::to_string(j) + " are collinear";
      if (o == CGAL::LEFT_TURN) all_right = false;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    Point_2 p(base[i][0], base[i][1]), q(base[(i + 1) % n][0], base[(i + 1) % n][1]);
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i || j == (i + 1) % n) continue;
      if (CGAL::orientation(p, q, Point_2(base[j][0], base[j][1])) != CGAL::LEFT_TURN)
        return all_right ? "polygon is clockwise; list the vertices counter-clockwise"
                         : "polygon is not strictly convex";
    }
  }
  return "";
}

Polytope_combinatorics hull_facets(const std::vector<Rational3>& points)
{
  std::vector<Point_3> pts;
  for (const auto& p : points) pts.push_back(to_point(p));
  // Linear scans for a non-degenerate tetrahedron: a second point, then one
  // off their line, then one off their plane.
  std::size_t i = 1, j, k;
  while (i < pts.size() && pts[i] == pts[0]) ++i;
  for (j = i + 1; j < pts.size() && CGAL::collinear(pts[0], pts[i], pts[j]); ++j) {}
  for (k = j + 1; k < pts.size() && CGAL::coplanar(pts[0], pts[i], pts[j], pts[k]); ++k) {}
  if (k >= pts.size()) throw std::invalid_argument("all points lie in one plane: the hull has no interior");

  // The hull on the lazy exact kernel (its signs are exact), its vertices
  // found again among the input points; what follows uses the rationals.
  // Tag_false keeps each plane as its three points, so a side test is one
  // filtered orientation of four input points, not a lazy Plane_3 whose
  // exact value (normalised rationals) coplanar vertices force (issue 58:
  // most of a cached mesh read).
  std::vector<CGAL::Epeck::Point_3> lazy;
  for (const auto& p : points) lazy.push_back(lazy_point(p));
  std::map<CGAL::Epeck::Point_3, int> index;
  for (std::size_t i = 0; i < lazy.size(); ++i) index.emplace(lazy[i], static_cast<int>(i));
  using Mesh = CGAL::Surface_mesh<CGAL::Epeck::Point_3>;
  Mesh mesh;
  CGAL::convex_hull_3(lazy.begin(), lazy.end(), mesh, CGAL::Convex_hull_traits_3<CGAL::Epeck, Mesh, CGAL::Tag_false>());
  Polytope_combinatorics out;
  std::vector<Integer_point> whole;
  for (const auto& p : points) whole.push_back(integer_point(p));
  std::map<std::array<mpz_class, 4>, int> planes;
  std::map<Mesh::Face_index, int> plane_of;
  for (auto f : mesh.faces()) {
    std::vector<int> around;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) around.push_back(index.at(mesh.point(v)));
    std::array<int, 3> t{around[0], around[1], around[2]};
    // The hull's faces are outward: each triangle of a face's fan adds six
    // times the volume of its tetrahedron with the origin.
    for (std::size_t i = 1; i + 1 < around.size(); ++i)
      out.six_volume += determinant_of(whole[around[0]], whole[around[i]], whole[around[i + 1]]);
    // One triple per facet plane: triangles of the same facet repeat it.
    // The plane's primitive integer vector (its orientation kept) is the key.
    auto [it, fresh] = planes.emplace(plane_key(whole[t[0]], whole[t[1]], whole[t[2]]), static_cast<int>(out.triples.size()));
    if (fresh) out.triples.push_back(t);
    plane_of[f] = it->second;
  }
  for (auto v : mesh.vertices()) {
    std::set<int> through;
    for (auto f : CGAL::faces_around_target(mesh.halfedge(v), mesh))
      if (f != Mesh::null_face()) through.insert(plane_of.at(f));
    if (through.size() >= 4) out.corners.emplace_back(through.begin(), through.end());
  }
  return out;
}

std::string convex_problem(const std::vector<Rational4>& planes)
{
  // Interior: maximise s with a.x + d + s <= 0, 0 <= s <= 1 (no square roots:
  // the slack is not normalised, which is fine for a sign decision).
  Program interior = make_program(planes, Rational(1));
  interior.set_c(3, Rational(-1));
  Solution sol = solve_exact_lp(interior, Rational());
  if (sol.is_infeasible()) return "the half-spaces have no common point: the convex solid is empty";
  if (!CGAL::is_negative(sol.objective_value()))
    return "the convex solid has no interior (it is flat)";
  // Bounded: every coordinate is bounded above and below.
  const char* axis = "xyz";
  for (int k = 0; k < 3; ++k)
    for (int sign : {1, -1}) {
      Program extent = make_program(planes, Rational(0));
      extent.set_u(3, true, 0);
      extent.set_c(k, Rational(sign));
      if (solve_exact_lp(extent, Rational()).is_unbounded())
        return std::string("the convex solid is unbounded in the ") + (sign > 0 ? "-" : "+") + axis[k] + " direction";
    }
  return "";
}

Polytope_combinatorics convex_vertex_triples(const std::vector<Rational4>& planes)
{
  Polytope_combinatorics out;
  // Each distinct point is classified once: where many planes pass through
  // one vertex (a cone's apex), every triple of them gives it again.
  std::set<Rational3> seen;
  int m = static_cast<int>(planes.size());
  auto normal = [&](int i) { return Rational3{planes[i][0], planes[i][1], planes[i][2]}; };
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k) {
        Rational3 a = normal(i), b = normal(j), c = normal(k);
        Rational det = determinant3(a, b, c);
        if (CGAL::is_zero(det)) continue;
        Rational3 p = vertex_of(planes[i], planes[j], planes[k]);
        if (!seen.insert(p).second) continue;
        bool inside = true;
        std::vector<int> through;
        for (int h = 0; h < m && inside; ++h) {
          CGAL::Sign s = CGAL::sign(planes[h][0] * p[0] + planes[h][1] * p[1] + planes[h][2] * p[2] + planes[h][3]);
          inside = s != CGAL::POSITIVE;
          if (s == CGAL::ZERO) through.push_back(h);
        }
        if (!inside) continue;
        out.triples.push_back({i, j, k});
        if (through.size() >= 4) out.corners.push_back(through);
      }
  return out;
}

} // namespace clash4d
