// Membership of a point in a solid with strict signs (regularised-semantics.md,
// item 1): True strictly inside, False strictly outside, Unknown when the
// answer hangs on a boundary plane. Independent of the extrusion code, so it
// checks witnesses against the scene as written.
#ifndef CLASH4D_CORE_POINT_CLASSIFIER_H
#define CLASH4D_CORE_POINT_CLASSIFIER_H

#include "core/Csg_model.h"
#include "core/Formula.h"

namespace clash4d {

inline Truth truth_not(Truth a) { return a == Truth::Unknown ? a : (a == Truth::True ? Truth::False : Truth::True); }
inline Truth truth_and(Truth a, Truth b)
{
  if (a == Truth::False || b == Truth::False) return Truth::False;
  return (a == Truth::True && b == Truth::True) ? Truth::True : Truth::Unknown;
}
inline Truth truth_or(Truth a, Truth b) { return truth_not(truth_and(truth_not(a), truth_not(b))); }

template <class K>
Truth classify_point(const K& k, const Csg_model<typename K::FT>& m, const Vector3<typename K::FT>& y, int node = 0)
{
  using FT = typename K::FT;
  const Csg_node& n = m.nodes[node];
  switch (n.op) {
    case Csg_node::Op::Primitive: {
      Truth r = Truth::True;
      for (const auto& p : m.primitives[n.primitive].planes) {
        CGAL::Sign s = k.side(Vector3<FT>{p[0], p[1], p[2]}, p[3], y);
        r = truth_and(r, s == CGAL::NEGATIVE ? Truth::True : s == CGAL::POSITIVE ? Truth::False : Truth::Unknown);
      }
      return r;
    }
    case Csg_node::Op::Union: {
      Truth r = Truth::False;
      for (int c : n.children) r = truth_or(r, classify_point(k, m, y, c));
      return r;
    }
    case Csg_node::Op::Intersection: {
      Truth r = Truth::True;
      for (int c : n.children) r = truth_and(r, classify_point(k, m, y, c));
      return r;
    }
    case Csg_node::Op::Difference: {
      Truth r = classify_point(k, m, y, n.children[0]);
      for (std::size_t c = 1; c < n.children.size(); ++c) r = truth_and(r, truth_not(classify_point(k, m, y, n.children[c])));
      return r;
    }
  }
  return Truth::Unknown;
}

} // namespace clash4d

#endif
