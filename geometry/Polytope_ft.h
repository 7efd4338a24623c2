// The constructions of a polytope's combinatorics, written once over the
// number type FT (kernel_ft4.h style): a hull facet's plane from its three
// points and a convex solid's vertex from its three planes. The scene reader
// runs them on the scene's rationals, Model_builder on any kernel's numbers.
#ifndef CLASH4D_GEOMETRY_POLYTOPE_FT_H
#define CLASH4D_GEOMETRY_POLYTOPE_FT_H

#include "geometry/kernel_ft4.h"

namespace clash4d {

// n.x + d <= 0 with n = (b - a) x (c - a), d = -n.a: the plane through a, b,
// c, inside below when they turn counter-clockwise seen from outside.
template <class FT>
std::array<FT, 4> facet_plane(const Vector3<FT>& a, const Vector3<FT>& b, const Vector3<FT>& c)
{
  Vector3<FT> n = cross(Vector3<FT>{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                        Vector3<FT>{c[0] - a[0], c[1] - a[1], c[2] - a[2]});
  return {n[0], n[1], n[2], -dot(n, a)};
}

// The point on three planes n.x + d = 0, by Cramer's rule.
template <class FT>
Vector3<FT> vertex_of(const std::array<FT, 4>& a, const std::array<FT, 4>& b, const std::array<FT, 4>& c)
{
  Vector3<FT> na{a[0], a[1], a[2]}, nb{b[0], b[1], b[2]}, nc{c[0], c[1], c[2]};
  FT det = determinant3(na, nb, nc);
  Vector3<FT> rhs{-a[3], -b[3], -c[3]}, v;
  for (int axis = 0; axis < 3; ++axis) {
    Vector3<FT> ra = na, rb = nb, rc = nc;
    ra[axis] = rhs[0];
    rb[axis] = rhs[1];
    rc[axis] = rhs[2];
    v[axis] = determinant3(ra, rb, rc) / det;
  }
  return v;
}

} // namespace clash4d

#endif
