#include "exact/Witness_depth.h"
#include "exact/Rational_kernel.h"
#include "model/Point_classifier.h"
#include "model/Scene_model.h"
#include "numbers/Exact_lp.h"

#include <CGAL/QP_models.h>
#include <vector>

namespace clash4d {
namespace {

using FT = Rational;

// One plane of a cell, with the sign the witness has there: -1 inside the
// plane's half-space, +1 outside it.
struct Literal {
  Plane3<FT> plane;
  int side;
};

template <class Side>
class Term_collector {
public:
  Term_collector(const Csg_model<FT>& m, const Side& side) : m_(m), side_(side) {}

  // The planes of one term of node's formula true at the point: a
  // primitive's planes, one true child of a union, every child of an
  // intersection, a difference's first child and each other one false.
  void true_term(int node, std::vector<Literal>& out) const
  {
    const Csg_node& n = m_.nodes[node];
    if (n.op == Csg_node::Op::Primitive)
      for (const auto& plane : m_.primitives[n.primitive].planes) out.push_back({plane, -1});
    if (n.op == Csg_node::Op::Union) true_term(first(n.children, 0, Truth::True), out);
    if (n.op == Csg_node::Op::Intersection)
      for (int c : n.children) true_term(c, out);
    if (n.op == Csg_node::Op::Difference) {
      true_term(n.children[0], out);
      for (std::size_t c = 1; c < n.children.size(); ++c) false_term(n.children[c], out);
    }
  }

  // Dually, planes that keep node's formula false: one plane of a primitive
  // the point is outside of, and so on.
  void false_term(int node, std::vector<Literal>& out) const
  {
    const Csg_node& n = m_.nodes[node];
    if (n.op == Csg_node::Op::Primitive) {
      const auto& planes = m_.primitives[n.primitive].planes;
      for (std::size_t j = 0; j < planes.size(); ++j)
        if (side_(n.primitive, j) == CGAL::POSITIVE) return out.push_back({planes[j], 1});
    }
    if (n.op == Csg_node::Op::Union)
      for (int c : n.children) false_term(c, out);
    if (n.op == Csg_node::Op::Intersection) false_term(first(n.children, 0, Truth::False), out);
    if (n.op == Csg_node::Op::Difference) {
      if (truth(n.children[0]) == Truth::False) return false_term(n.children[0], out);
      true_term(first(n.children, 1, Truth::True), out);
    }
  }

private:
  Truth truth(int node) const { return classify_with(m_, side_, node); }
  int first(const std::vector<int>& children, std::size_t from, Truth t) const
  {
    for (std::size_t c = from; c < children.size(); ++c)
      if (truth(children[c]) == t) return children[c];
    return children[from];   // not reached: the node's own truth says one is
  }

  const Csg_model<FT>& m_;
  const Side& side_;
};

// The literals of object o's witness cell at the world point w, in world
// coordinates at w's time; false when w is not strictly inside.
bool witness_cell(const Rational_kernel& k, const Object_model<FT>& o, const Vector4<FT>& w, std::vector<Literal>& out)
{
  Vector3<FT> y = solid_point(k, o, w), d = o.motion.displacement(k, w[3]);
  auto side = [&](int p, std::size_t j) {
    const Plane3<FT>& pl = o.csg.primitives[p].planes[j];
    return k.side(Vector3<FT>{pl[0], pl[1], pl[2]}, pl[3], y);
  };
  if (classify_with(o.csg, side) != Truth::True) return false;
  std::vector<Literal> cell;
  Term_collector<decltype(side)>(o.csg, side).true_term(0, cell);
  for (Literal& l : cell) {   // n.(x - D) + e = n.x + (e - n.D)
    l.plane[3] -= l.plane[0] * d[0] + l.plane[1] * d[1] + l.plane[2] * d[2];
    out.push_back(l);
  }
  return true;
}

// max d subject to: -side (n.y + e) + d |n|_1 <= 0 for every literal, d >= 0;
// variables y (the cube's centre, free) and d.
std::optional<Rational> deepest_cube(const std::vector<Literal>& cell)
{
  CGAL::Quadratic_program<Rational> lp(CGAL::SMALLER, false, 0, false, 0);
  for (std::size_t i = 0; i < cell.size(); ++i) {
    int row = static_cast<int>(i);
    const Plane3<FT>& h = cell[i].plane;
    Rational s(-cell[i].side), l1 = CGAL::abs(h[0]) + CGAL::abs(h[1]) + CGAL::abs(h[2]);
    for (int c = 0; c < 3; ++c) lp.set_a(c, row, s * h[c]);
    lp.set_a(3, row, l1);
    lp.set_b(row, -s * h[3]);
  }
  lp.set_l(3, true, 0);
  lp.set_c(3, -1);
  CGAL::Quadratic_program_solution<Rational> sol = solve_exact_lp(lp, Rational());
  if (!sol.is_optimal()) return std::nullopt;
  return -(sol.objective_value_numerator() / sol.objective_value_denominator());
}

} // namespace

Witness_depth::Witness_depth(const Scene& scene)
  : model_(std::make_shared<Scene_model<Rational_kernel>>(Scene_model<Rational_kernel>::build(Rational_kernel(), scene)))
{}

std::optional<Rational> Witness_depth::operator()(int a, int b, const std::array<Rational, 4>& w) const
{
  Rational_kernel k;
  Vector4<FT> p{w[0], w[1], w[2], w[3]};
  std::vector<Literal> cell;
  if (!witness_cell(k, model_->objects[a], p, cell) || !witness_cell(k, model_->objects[b], p, cell)) return std::nullopt;
  return deepest_cube(cell);
}

} // namespace clash4d
