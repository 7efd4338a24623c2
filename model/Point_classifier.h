// Membership of a point in a solid with strict signs (regularised-semantics.md,
// item 1): True strictly inside, False strictly outside, Unknown when the
// answer hangs on a boundary plane. Independent of the extrusion code, so it
// checks witnesses against the scene as written.
#ifndef CLASH4D_MODEL_POINT_CLASSIFIER_H
#define CLASH4D_MODEL_POINT_CLASSIFIER_H

#include "model/Csg_model.h"
#include "model/Formula.h"
#include "model/Scene_model.h"
#include <algorithm>
#include <functional>
#include <vector>

namespace clash4d {

inline Truth truth_not(Truth a) { return a == Truth::Unknown ? a : (a == Truth::True ? Truth::False : Truth::True); }
inline Truth truth_and(Truth a, Truth b)
{
  if (a == Truth::False || b == Truth::False) return Truth::False;
  return (a == Truth::True && b == Truth::True) ? Truth::True : Truth::Unknown;
}
inline Truth truth_or(Truth a, Truth b) { return truth_not(truth_and(truth_not(a), truth_not(b))); }

// The CSG tree's truth at y when plane j of primitive p has sign side(p, j)
// there (Kleene: a zero sign is Unknown). classify_point below takes the
// signs from the point; a closed-membership test prescribes them for the
// planes through the point, cell by cell.
template <class FT, class Side>
Truth classify_with(const Csg_model<FT>& m, Side side, int node = 0)
{
  const Csg_node& n = m.nodes[node];
  switch (n.op) {
    case Csg_node::Op::Primitive: {
      Truth r = Truth::True;
      for (std::size_t j = 0; j < m.primitives[n.primitive].planes.size(); ++j) {
        CGAL::Sign s = side(n.primitive, j);
        r = truth_and(r, s == CGAL::NEGATIVE ? Truth::True : s == CGAL::POSITIVE ? Truth::False : Truth::Unknown);
      }
      return r;
    }
    case Csg_node::Op::Union: {
      Truth r = Truth::False;
      for (int c : n.children) r = truth_or(r, classify_with(m, side, c));
      return r;
    }
    case Csg_node::Op::Intersection: {
      Truth r = Truth::True;
      for (int c : n.children) r = truth_and(r, classify_with(m, side, c));
      return r;
    }
    case Csg_node::Op::Difference: {
      Truth r = classify_with(m, side, n.children[0]);
      for (std::size_t c = 1; c < n.children.size(); ++c) r = truth_and(r, truth_not(classify_with(m, side, n.children[c])));
      return r;
    }
  }
  return Truth::Unknown;
}

template <class K>
Truth classify_point(const K& k, const Csg_model<typename K::FT>& m, const Vector3<typename K::FT>& y)
{
  using FT = typename K::FT;
  return classify_with(m, [&](int p, std::size_t j) {
    const Plane3<FT>& pl = m.primitives[p].planes[j];
    return k.side(Vector3<FT>{pl[0], pl[1], pl[2]}, pl[3], y);
  });
}

// The point of object o's solid that is at p = (x, t) at time t: x - D(t).
template <class K>
Vector3<typename K::FT> solid_point(const K& k, const Object_model<typename K::FT>& o, const Vector4<typename K::FT>& p)
{
  Vector3<typename K::FT> d = o.motion.displacement(k, p[3]);
  return {p[0] - d[0], p[1] - d[1], p[2] - d[2]};
}

// The side of every plane of solid m at y, primitive after primitive
// (Plane_sides::at(p, j)): each plane evaluated once, for the membership
// and closure tests below.
template <class FT>
struct Plane_sides {
  std::vector<CGAL::Sign> sides;
  std::vector<std::size_t> first;   // primitive p's planes start at first[p]
  CGAL::Sign at(int p, std::size_t j) const { return sides[first[static_cast<std::size_t>(p)] + j]; }

  // The kernel's signs of m's planes at y.
  template <class K>
  Plane_sides(const K& k, const Csg_model<FT>& m, const Vector3<FT>& y)
    : Plane_sides(m, [&](int p, std::size_t j) {
        const Plane3<FT>& pl = m.primitives[static_cast<std::size_t>(p)].planes[j];
        return k.side(Vector3<FT>{pl[0], pl[1], pl[2]}, pl[3], y);
      })
  {}
  // side(p, j): the sign of plane j of primitive p, however it is decided.
  template <class Side>
  Plane_sides(const Csg_model<FT>& m, Side side)
  {
    first.reserve(m.primitives.size());
    sides.reserve(m.plane_count());
    for (std::size_t p = 0; p < m.primitives.size(); ++p) {
      first.push_back(sides.size());
      for (std::size_t j = 0; j < m.primitives[p].planes.size(); ++j) sides.push_back(side(static_cast<int>(p), j));
    }
  }
  // Strictly inside the solid, on none of its planes.
  bool generic_inside(const Csg_model<FT>& m) const
  {
    if (std::find(sides.begin(), sides.end(), CGAL::ZERO) != sides.end()) return false;
    return classify_with(m, [&](int p, std::size_t j) { return at(p, j); }) == Truth::True;
  }
};

// Where the checks below take the sides of object i's planes at a point y
// of its solid: none, the kernel's signs on the model's planes; otherwise
// the same signs of the same model's planes, decided another way (a
// filter's, intervals first: exact/Certified_sides.h).
template <class FT>
using Sides_at = std::function<Plane_sides<FT>(int i, const Vector3<FT>& y)>;

template <class K>
Plane_sides<typename K::FT> sides_at(const K& k, const Scene_model<K>& model, int i,
                                     const Vector3<typename K::FT>& y, const Sides_at<typename K::FT>* sides)
{
  return sides ? (*sides)(i, y) : Plane_sides<typename K::FT>(k, model.objects[i].csg, y);
}

// g is strictly inside object i at its time, on none of its planes.
template <class K>
bool is_generic_inside(const K& k, const Scene_model<K>& model, int i, const Vector4<typename K::FT>& g,
                       const Sides_at<typename K::FT>* sides = nullptr)
{
  using FT = typename K::FT;
  const Object_model<FT>& o = model.objects[i];
  Vector3<FT> y = solid_point(k, o, g);
  if (sides || o.csg.nodes.size() != 1 || o.csg.nodes[0].op != Csg_node::Op::Primitive)
    return sides_at(k, model, i, y, sides).generic_inside(o.csg);
  // One primitive (a convex pair's object): inside and generic is every
  // plane negative, Plane_sides' answer without its two vectors. Every
  // sign is still asked, in its order, so that one the kernel cannot tell
  // fails here as it fails there.
  bool inside = true;
  for (const Plane3<FT>& pl : o.csg.primitives[static_cast<std::size_t>(o.csg.nodes[0].primitive)].planes)
    inside = (k.side(Vector3<FT>{pl[0], pl[1], pl[2]}, pl[3], y) == CGAL::NEGATIVE) && inside;
  return inside;
}

// Whether p = (x, t) is in the closure of the cell of object i whose sides
// are at_g: every plane of the object is zero at p or has its side there
// (the cell is convex, so the segment from g to p minus p lies in it). p
// is taken back by its own D(t), which is the extrusion's when both times
// lie in one constant-velocity piece of the motion (the callers' points
// do).
template <class K>
bool is_in_closure_of(const K& k, const Scene_model<K>& model, int i, const Vector4<typename K::FT>& p,
                      const Plane_sides<typename K::FT>& at_g, const Sides_at<typename K::FT>* sides = nullptr)
{
  Plane_sides<typename K::FT> at_p = sides_at(k, model, i, solid_point(k, model.objects[i], p), sides);
  for (std::size_t n = 0; n < at_p.sides.size(); ++n)
    if (at_p.sides[n] != CGAL::ZERO && at_p.sides[n] != at_g.sides[n]) return false;
  return true;
}
// g strictly inside object i at its time, on none of its planes, with p
// in the closure of its cell: its sides evaluated once for both.
template <class K>
bool is_generic_inside_near(const K& k, const Scene_model<K>& model, int i, const Vector4<typename K::FT>& p,
                            const Vector4<typename K::FT>& g, const Sides_at<typename K::FT>* sides = nullptr)
{
  const Object_model<typename K::FT>& o = model.objects[i];
  Plane_sides<typename K::FT> at_g = sides_at(k, model, i, solid_point(k, o, g), sides);
  return at_g.generic_inside(o.csg) && is_in_closure_of(k, model, i, p, at_g, sides);
}

// A witness (x, y, z, t) of a collision of objects a and b: tL < t < tH, and
// x - D(t) strictly inside both solids and on none of their planes. Evaluated
// on the 3D solids moved back by D(t), independently of the extrusion.
template <class K>
bool is_valid_witness(const K& k, const Scene_model<K>& model, int a, int b, const Vector4<typename K::FT>& w,
                      const Sides_at<typename K::FT>* sides = nullptr)
{
  if (!(k.less(model.t_lo, w[3]) && k.less(w[3], model.t_hi))) return false;
  return is_generic_inside(k, model, a, w, sides) && is_generic_inside(k, model, b, w, sides);
}

// Closed semantics (scene-format.md): p with tL <= t <= tH lies in both
// closed objects, shown by ga strictly inside a, gb strictly inside b, at
// p's time, each with p in the closure of its cell.
template <class K>
bool is_valid_touch(const K& k, const Scene_model<K>& model, int a, int b, const Vector4<typename K::FT>& p,
                    const Vector4<typename K::FT>& ga, const Vector4<typename K::FT>& gb,
                    const Sides_at<typename K::FT>* sides = nullptr)
{
  if (k.less(p[3], model.t_lo) || k.less(model.t_hi, p[3])) return false;
  for (auto [i, g] : {std::pair<int, const Vector4<typename K::FT>*>{a, &ga}, {b, &gb}}) {
    if (k.compare((*g)[3], p[3]) != CGAL::ZERO) return false;
    if (!is_generic_inside_near(k, model, i, p, *g, sides)) return false;
  }
  return true;
}

// Earliest mode, regularised: g is a witness of the collision of a and b
// (is_valid_witness) whose cell's closure holds the contact point c in
// both objects.
template <class K>
bool is_valid_contact_cell(const K& k, const Scene_model<K>& model, int a, int b, const Vector4<typename K::FT>& c,
                           const Vector4<typename K::FT>& g, const Sides_at<typename K::FT>* sides = nullptr)
{
  if (!(k.less(model.t_lo, g[3]) && k.less(g[3], model.t_hi))) return false;
  return is_generic_inside_near(k, model, a, c, g, sides) && is_generic_inside_near(k, model, b, c, g, sides);
}

} // namespace clash4d

#endif
