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
  std::map<std::array<Rational, 4>, int> planes;
  std::map<Mesh::Face_index, int> plane_of;
  for (auto f : mesh.faces()) {
    std::vector<int> around;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) around.push_back(index.at(mesh.point(v)));
    std::array<int, 3> t{around[0], around[1], around[2]};
    // The hull's faces are outward: each triangle of a face's fan adds six
    // times the volume of its tetrahedron with the origin.
    for (std::size_t i = 1; i + 1 < around.size(); ++i) {
      const Point_3 &a = pts[around[0]], &b = pts[around[i]], &c = pts[around[i + 1]];
      out.six_volume += CGAL::determinant(a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(), c.z());
    }
    // One triple per facet plane: triangles of the same facet repeat it. The
    // plane, scaled so its first non-zero coefficient is +-1 (keeping its
    // orientation), is the key.
    Rational_geometry::Plane_3 h(pts[t[0]], pts[t[1]], pts[t[2]]);
    std::array<Rational, 4> key{h.a(), h.b(), h.c(), h.d()};
    Rational lead = CGAL::is_zero(key[0]) ? (CGAL::is_zero(key[1]) ? key[2] : key[1]) : key[0];
    if (lead < 0) lead = -lead;
    for (auto& x : key) x /= lead;
    auto [it, fresh] = planes.emplace(key, static_cast<int>(out.triples.size()));
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
