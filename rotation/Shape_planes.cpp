#include "rotation/Shape_planes.h"

#include "model/Far_bound.h"
#include "model/Model_builder.h"
#include "rotation/Moving_planes.h"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <map>
#include <set>

namespace clash4d {

namespace {

Rational magnitude(const Rational& x) { return x < 0 ? -x : x; }

// The plane scaled so its first non-zero coefficient is 1 or -1 ... and the
// sign: +1 when the scaling was by a positive number.
std::pair<Plane3<Rational>, int> canonical(const Plane3<Rational>& p)
{
  int lead = 0;
  while (lead < 4 && CGAL::sign(p[lead]) == CGAL::ZERO) ++lead;
  if (lead == 4) return {p, 1};
  Rational s = magnitude(p[lead]);
  Plane3<Rational> c = p;
  for (auto& x : c) x /= s;
  int orientation = 1;
  if (c[lead] < 0) {
    for (auto& x : c) x = -x;
    orientation = -1;
  }
  return {c, orientation};
}

// A dyadic r with r^2 >= q >= 0, within 2^-10 of sqrt q: the square root
// of q 2^20 in integers, rounded up (no floating point).
Rational root_above(const Rational& q)
{
  mpz_class scaled(q.numerator().mpz());
  scaled <<= 20;
  mpz_class den(q.denominator().mpz()), n, r;
  mpz_cdiv_q(n.get_mpz_t(), scaled.get_mpz_t(), den.get_mpz_t());   // ceil(q 2^20)
  mpz_sqrt(r.get_mpz_t(), n.get_mpz_t());
  r += 1;                                                             // r^2 > n
  return Rational(CGAL::Gmpz(r.get_mpz_t()), CGAL::Gmpz(1 << 10));
}

bool union_of_primitives(const Csg_model<Rational>& csg)
{
  for (const Csg_node& n : csg.nodes)
    if (n.op != Csg_node::Op::Primitive && n.op != Csg_node::Op::Union) return false;
  return true;
}

struct Plane_less {
  bool operator()(const Plane3<Rational>& a, const Plane3<Rational>& b) const
  {
    for (int i = 0; i < 4; ++i) {
      if (a[i] < b[i]) return true;
      if (b[i] < a[i]) return false;
    }
    return false;
  }
};

Rational det3(const Plane3<Rational>& a, const Plane3<Rational>& b, const Plane3<Rational>& c)
{
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// "Point v is on plane h" (h . (v, 1) = 0), one predicate filtered: in
// intervals first (a value that excludes 0 is off the plane, surely), exactly
// where they cannot tell. A piece's V points against its F planes are V F
// questions, nearly all of them far from 0; only the few planes through a
// vertex are decided exactly.
class Plane_incidence {
public:
  using I = CGAL::Interval_nt<false>;

  explicit Plane_incidence(const std::vector<Plane3<Rational>>& planes) : planes_(planes)
  {
    CGAL::Protect_FPU_rounding<true> upward;
    for (const auto& h : planes) enclosed_.push_back(enclosed(h));
  }

  // The planes of `among` through v.
  std::vector<int> planes_through(const Vector3<Rational>& v, const std::vector<int>& among) const
  {
    std::vector<int> on;
    CGAL::Protect_FPU_rounding<true> upward;
    std::array<I, 3> x = enclosed(v);
    for (int p : among) {
      const std::array<I, 4>& e = enclosed_[p];
      I value = e[0] * x[0] + e[1] * x[1] + e[2] * x[2] + e[3];
      if (value.inf() > 0 || value.sup() < 0) continue;
      const Plane3<Rational>& h = planes_[p];
      if (sign_of_sum_of_products(h.data(), v.data(), 3, &h[3]) == 0) on.push_back(p);
    }
    return on;
  }

private:
  const std::vector<Plane3<Rational>>& planes_;
  std::vector<std::array<I, 4>> enclosed_;
};

// The features of one bounded convex primitive (its exact vertices and its
// planes, as indices into out.planes): the planes through each vertex
// (exact incidences), one independent triple of them per vertex, and the
// pairs of planes sharing two distinct vertices. A point of the list on no
// independent triple of the planes is not a vertex (a hull's points may lie
// inside it) and is skipped: a point of the polytope on three independent
// planes of it is a vertex (the least face holding it lies in their meet).
// Left unset unless the polytope is full-dimensional (four affinely
// independent points).
void convex_features(const std::vector<Vector3<Rational>>& vertices, const std::vector<int>& planes, Shape_planes& out)
{
  if (vertices.size() < 4) return;
  // Full-dimensional: some vertex off the plane of three others.
  bool full = false;
  {
    const auto& o = vertices[0];
    auto diff = [&](const Vector3<Rational>& v) { return Plane3<Rational>{v[0] - o[0], v[1] - o[1], v[2] - o[2], Rational(0)}; };
    for (std::size_t i = 1; i < vertices.size() && !full; ++i)
      for (std::size_t j = i + 1; j < vertices.size() && !full; ++j)
        for (std::size_t k = j + 1; k < vertices.size() && !full; ++k)
          full = CGAL::sign(det3(diff(vertices[i]), diff(vertices[j]), diff(vertices[k]))) != CGAL::ZERO;
  }
  if (!full) return;
  std::vector<int> distinct = planes;
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  std::vector<std::vector<int>> through;   // [vertex]: the planes through it
  std::vector<std::array<int, 3>> triples;
  std::vector<Vector3<Rational>> points;   // the vertices
  std::set<std::array<Rational, 3>> seen;   // each point once (a hull may repeat one)
  Plane_incidence incidence(out.planes);
  for (const auto& v : vertices) {
    if (!seen.insert({v[0], v[1], v[2]}).second) continue;
    std::vector<int> on = incidence.planes_through(v, distinct);
    bool found = false;
    for (std::size_t i = 0; i < on.size() && !found; ++i)
      for (std::size_t j = i + 1; j < on.size() && !found; ++j)
        for (std::size_t k = j + 1; k < on.size() && !found; ++k)
          if (CGAL::sign(det3(out.planes[on[i]], out.planes[on[j]], out.planes[on[k]])) != CGAL::ZERO) {
            triples.push_back({on[i], on[j], on[k]});
            found = true;
          }
    // A point of the polytope on no independent triple is no vertex (a
    // hull's point inside it, or inside a face or an edge): it is left out.
    if (!found) continue;
    through.push_back(std::move(on));
    points.push_back(v);
  }
  if (triples.size() < 4) return;
  // The vertices in the order of their triples (distinct: an independent
  // triple meets in one point), so that vertex i is on triple i.
  std::vector<std::size_t> order(triples.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return triples[i] < triples[j]; });
  std::map<std::pair<int, int>, std::vector<int>> shared;   // the vertices on both planes
  for (std::size_t v = 0; v < order.size(); ++v) {
    const std::vector<int>& on = through[order[v]];
    for (std::size_t i = 0; i < on.size(); ++i)
      for (std::size_t j = i + 1; j < on.size(); ++j) shared[{on[i], on[j]}].push_back(static_cast<int>(v));
    out.vertex_triples.push_back(triples[order[v]]);
    out.vertices.push_back(points[order[v]]);
  }
  for (auto& [pq, on] : shared)
    if (on.size() >= 2) {
      out.edges.push_back(pq);
      out.edge_vertices.push_back(std::move(on));
    }
  out.convex_features = true;
}

} // namespace

Shape_planes shape_planes(const Solid& shape)
{
  far_bound_detail::Exact_reader reader;
  Csg_model<Rational> csg = Model_builder<far_bound_detail::Exact_reader>(reader).build(shape);
  Shape_planes out;
  std::map<Plane3<Rational>, int, Plane_less> index;
  bool bounded = true, convex_union = union_of_primitives(csg);
  Rational reach(0);
  for (const auto& prim : csg.primitives) {
    std::vector<std::pair<int, int>> piece;
    for (const auto& p : prim.planes) {
      auto [c, orientation] = canonical(p);
      auto [it, added] = index.emplace(c, static_cast<int>(out.planes.size()));
      if (added) out.planes.push_back(c);
      piece.emplace_back(it->second, orientation);
    }
    if (prim.vertices.empty()) bounded = false;
    for (const auto& v : prim.vertices) reach = std::max(reach, v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    out.primitives.push_back(std::move(piece));
  }
  out.nodes = csg.nodes;
  if (bounded && convex_union) out.convex_pieces = out.primitives;
  if (bounded && convex_union && csg.primitives.size() == 1) {
    std::vector<int> piece;
    for (auto [plane, orientation] : out.primitives.front()) piece.push_back(plane);
    convex_features(csg.primitives.front().vertices, piece, out);
  }
  if (bounded) out.reach = root_above(reach);
  // The normals span R^3 when some three are independent.
  const auto& P = out.planes;
  for (std::size_t i = 0; i < P.size() && !out.spans_space; ++i)
    for (std::size_t j = i + 1; j < P.size() && !out.spans_space; ++j)
      for (std::size_t k = j + 1; k < P.size() && !out.spans_space; ++k) {
        Rational d = P[i][0] * (P[j][1] * P[k][2] - P[j][2] * P[k][1]) - P[i][1] * (P[j][0] * P[k][2] - P[j][2] * P[k][0]) +
                     P[i][2] * (P[j][0] * P[k][1] - P[j][1] * P[k][0]);
        out.spans_space = CGAL::sign(d) != CGAL::ZERO;
      }
  return out;
}

namespace {

bool node_inside(const Shape_planes& shape, int n, const std::vector<int>& side)
{
  const Csg_node& node = shape.nodes[n];
  switch (node.op) {
  case Csg_node::Op::Primitive:
    for (auto [plane, orientation] : shape.primitives[node.primitive])
      if (orientation * side[plane] > 0) return false;
    return true;
  case Csg_node::Op::Union:
    for (int c : node.children)
      if (node_inside(shape, c, side)) return true;
    return false;
  case Csg_node::Op::Intersection:
    for (int c : node.children)
      if (!node_inside(shape, c, side)) return false;
    return true;
  case Csg_node::Op::Difference:
    if (!node_inside(shape, node.children.front(), side)) return false;
    for (std::size_t i = 1; i < node.children.size(); ++i)
      if (node_inside(shape, node.children[i], side)) return false;
    return true;
  }
  return false;
}

} // namespace

bool inside_at_generic(const Shape_planes& shape, const std::vector<int>& side)
{
  return !shape.nodes.empty() && node_inside(shape, 0, side);
}

} // namespace clash4d
