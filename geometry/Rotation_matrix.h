// The scene format's rotation (spec: "rotate"), as a matrix of rationals:
// the unit quaternion q / |q| acts as R x, and each entry of R is a
// polynomial in q over |q|^2 = w^2 + x^2 + y^2 + z^2, so no square root is
// taken and rational q gives a rational R (exact, orthogonal).
#ifndef CLASH4D_GEOMETRY_ROTATION_MATRIX_H
#define CLASH4D_GEOMETRY_ROTATION_MATRIX_H

#include "geometry/kernel_ft4.h"
#include <array>

namespace clash4d {

// N(q) = |q|^2 R(q), row by row, for numbers or polynomials of any ring
// (the time slices' rows are polynomials in t over the rationals, the
// integers or intervals, rotation/Moving_planes.h): twice a product made as
// a sum.
template <class T>
std::array<std::array<T, 3>, 3> unnormalised_rotation(const std::array<T, 4>& q)
{
  const T &w = q[0], &x = q[1], &y = q[2], &z = q[3];
  T ww = w * w, xx = x * x, yy = y * y, zz = z * z;
  auto twice = [](const T& p) { return T(p + p); };
  return {{{T(ww + xx - yy - zz), twice(x * y - w * z), twice(x * z + w * y)},
           {twice(x * y + w * z), T(ww - xx + yy - zz), twice(y * z - w * x)},
           {twice(x * z - w * y), twice(y * z + w * x), T(ww - xx - yy + zz)}}};
}

// |q|^2.
template <class T>
T squared_norm(const std::array<T, 4>& q)
{
  return q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
}

// The rows of R for q = (w, x, y, z), q != 0.
template <class FT>
std::array<Vector3<FT>, 3> rotation_matrix(const FT& w, const FT& x, const FT& y, const FT& z)
{
  std::array<FT, 4> q = {w, x, y, z};
  FT n = squared_norm(q);
  std::array<Vector3<FT>, 3> m = unnormalised_rotation(q);
  for (auto& row : m)
    for (auto& e : row) e /= n;
  return m;
}

} // namespace clash4d

#endif
