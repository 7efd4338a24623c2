// A shape's planes under a pose segment: the half-space a.p + d <= 0 of the
// shape is, at time t, n(t).x + e(t) <= 0 with n = N(q(t)) a and
// e = |q(t)|^2 d - n.c(t), N(q) = |q|^2 R(q) the un-normalised rotation
// matrix: the half-space multiplied by |q(t)|^2 > 0, so no division and no
// square root (regularised-semantics.md, fact 9).
#ifndef CLASH4D_ROTATION_MOVING_PLANES_H
#define CLASH4D_ROTATION_MOVING_PLANES_H

#include "geometry/Rotation_matrix.h"
#include "geometry/kernel_ft4.h"
#include "numbers/Integer_poly.h"
#include "rotation/Pose_segments.h"
#include <CGAL/Interval_nt.h>
#include <algorithm>
#include <array>
#include <vector>

namespace clash4d {

// n_x, n_y, n_z, e: one row of fact 10's matrix.
using Moving_plane = std::array<Time_poly, 4>;

// The plane a.p + d <= 0 (p: a, b, c, d, numbers of Poly) under the
// rotation n = N a and the origin c: (n, |q|^2 d - n.c).
template <class Poly, class FT>
std::array<Poly, 4> moved_plane(const std::array<FT, 4>& p, const std::array<std::array<Poly, 3>, 3>& N,
                                const Poly& norm, const std::array<Poly, 3>& c)
{
  std::array<Poly, 4> h;
  for (int r = 0; r < 3; ++r) h[r] = p[0] * N[r][0] + p[1] * N[r][1] + p[2] * N[r][2];
  h[3] = p[3] * norm - (h[0] * c[0] + h[1] * c[1] + h[2] * c[2]);
  return h;
}

// Polynomials in t with integer coefficients (the exact stage's minors).
using Integer_time_poly = Integer_poly;

// The polynomials' coefficients over their least common denominator d > 0
// (a positive factor, made once for all of them): the numerators.
// Whether every coefficient of p is an integer (integer_moving_planes' rows).
inline bool has_integer_coefficients(const Time_poly& p)
{
  for (int i = 0; i < p.size(); ++i)
    if (!is_integer(p[i])) return false;
  return true;
}

template <std::size_t N>
std::array<Integer_time_poly, N> integer_polys(const std::array<Time_poly, N>& p, mpz_class& d)
{
  std::array<Integer_time_poly, N> out;
  // The usual rows (integer_moving_planes): d = 1, the numerators as they are.
  if (std::all_of(p.begin(), p.end(), has_integer_coefficients)) {
    d = 1;
    for (std::size_t k = 0; k < N; ++k)
      for (int i = p[k].size(); i-- > 0;) out[k].set_coefficient(i, mpq_numref(p[k][i].mpq()));
    return out;
  }
  std::vector<Rational> all;
  for (const Time_poly& x : p)
    for (int i = 0; i < x.size(); ++i) all.push_back(x[i]);
  std::vector<mpz_class> numerators(all.size());
  over_common_denominator(all.data(), all.size(), numerators.data(), d);
  std::size_t next = 0;
  for (std::size_t k = 0; k < N; ++k) {
    std::vector<mpz_class> c(numerators.begin() + next, numerators.begin() + next + p[k].size());
    next += p[k].size();
    out[k] = Integer_time_poly(c);
  }
  return out;
}

// p times factor over the rationals (no fraction to reduce).
Time_poly rational_poly(const Integer_time_poly& p, const mpz_class& factor = 1);

// Each plane of planes (shape coordinates) under segment s.
std::vector<Moving_plane> moving_planes(const std::vector<Plane3<Rational>>& planes, const Pose_segment& s);
// The same rows, each times a positive integer (its denominators'
// product): polynomials with integer coefficients, made with no fraction
// reduced. The same half-spaces, so the same signs, roots and meeting
// points: for the stages that ask only those (the exact time slices).
std::vector<Moving_plane> integer_moving_planes(const std::vector<Plane3<Rational>>& planes, const Pose_segment& s);

// The row's plane at the rational time t = n / d: its four values at t,
// or, when the row's coefficients are integers (integer_moving_planes),
// those values times d^k > 0 (k the row's largest degree), made in
// integers with no fraction reduced. The same half-space either way, so
// the same sides and meeting points.
std::array<Rational, 4> plane_at(const Moving_plane& h, const Rational& t);
// plane_at of every row, the same numbers, with the powers of t made once.
std::vector<std::array<Rational, 4>> planes_at(const std::vector<Moving_plane>& rows, const Rational& t);

// The row's value at the point x and time t: n(t).x + e(t).
Rational plane_value(const Moving_plane& h, const std::array<Rational, 3>& x, const Rational& t);

// p's coefficients as the intervals that hold them, made once for the
// interval filters (Interval_poly::at bounds p over an interval of times),
// under the caller's upward rounding. Capacity 8: a row is of degree 3 at
// most and the apart cover's reaches of degree 5 (Apart_cover.h); every
// polynomial is a fixed array, so a larger capacity is only more memory
// copied per operation.
using Interval_poly = Polynomial<CGAL::Interval_nt<false>, 8>;
Interval_poly enclosed(const Time_poly& p);

// The numbers of a point or a plane as the intervals that hold them, under
// the caller's upward rounding.
template <std::size_t N>
std::array<CGAL::Interval_nt<false>, N> enclosed(const std::array<Rational, N>& x)
{
  std::array<CGAL::Interval_nt<false>, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = CGAL::Interval_nt<false>(enclosing_interval(x[i]));
  return out;
}

} // namespace clash4d

#endif
