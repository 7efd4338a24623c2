#include "rotation/Shape_planes.h"

#include "model/Far_bound.h"
#include "model/Model_builder.h"

#include <map>

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
