// A shape's planes under a pose segment: the half-space a.p + d <= 0 of the
// shape is, at time t, n(t).x + e(t) <= 0 with n = N(q(t)) a and
// e = |q(t)|^2 d - n.c(t), N(q) = |q|^2 R(q) the un-normalised rotation
// matrix: the half-space multiplied by |q(t)|^2 > 0, so no division and no
// square root (regularised-semantics.md, fact 9).
#ifndef CLASH4D_ROTATION_MOVING_PLANES_H
#define CLASH4D_ROTATION_MOVING_PLANES_H

#include "geometry/kernel_ft4.h"
#include "rotation/Pose_segments.h"
#include <CGAL/Interval_nt.h>
#include <array>
#include <vector>

namespace clash4d {

// n_x, n_y, n_z, e: one row of fact 10's matrix.
using Moving_plane = std::array<Time_poly, 4>;

// N(q(t)), row by row.
std::array<std::array<Time_poly, 3>, 3> unnormalised_rotation(const std::array<Time_poly, 4>& q);

// Each plane of planes (shape coordinates) under segment s.
std::vector<Moving_plane> moving_planes(const std::vector<Plane3<Rational>>& planes, const Pose_segment& s);

// The row's value at the point x and time t: n(t).x + e(t).
Rational plane_value(const Moving_plane& h, const std::array<Rational, 3>& x, const Rational& t);

// p's coefficients as the intervals that hold them, made once for the
// interval filters (Interval_poly::at bounds p over an interval of times,
// under upward rounding).
using Interval_poly = Polynomial<CGAL::Interval_nt<false>, 16>;
Interval_poly enclosed(const Time_poly& p);

} // namespace clash4d

#endif
