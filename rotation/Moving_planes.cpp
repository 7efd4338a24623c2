#include "rotation/Moving_planes.h"

namespace clash4d {

std::array<std::array<Time_poly, 3>, 3> unnormalised_rotation(const std::array<Time_poly, 4>& q)
{
  const Time_poly &w = q[0], &x = q[1], &y = q[2], &z = q[3];
  Time_poly ww = w * w, xx = x * x, yy = y * y, zz = z * z;
  Rational two(2);
  // The scene format's matrix of rotate, times n = |q|^2.
  return {{{ww + xx - yy - zz, two * (x * y - w * z), two * (x * z + w * y)},
           {two * (x * y + w * z), ww - xx + yy - zz, two * (y * z - w * x)},
           {two * (x * z - w * y), two * (y * z + w * x), ww - xx - yy + zz}}};
}

std::vector<Moving_plane> moving_planes(const std::vector<Plane3<Rational>>& planes, const Pose_segment& s)
{
  auto N = unnormalised_rotation(s.q);
  Time_poly norm = s.q[0] * s.q[0] + s.q[1] * s.q[1] + s.q[2] * s.q[2] + s.q[3] * s.q[3];
  std::vector<Moving_plane> out;
  out.reserve(planes.size());
  for (const Plane3<Rational>& p : planes) {
    Moving_plane h;
    for (int r = 0; r < 3; ++r) h[r] = p[0] * N[r][0] + p[1] * N[r][1] + p[2] * N[r][2];
    h[3] = p[3] * norm - (h[0] * s.c[0] + h[1] * s.c[1] + h[2] * s.c[2]);
    out.push_back(h);
  }
  return out;
}

Rational plane_value(const Moving_plane& h, const std::array<Rational, 3>& x, const Rational& t)
{
  return h[0].at(t) * x[0] + h[1].at(t) * x[1] + h[2].at(t) * x[2] + h[3].at(t);
}

Interval_poly enclosed(const Time_poly& p)
{
  std::vector<CGAL::Interval_nt<false>> c;
  for (int i = 0; i < p.size(); ++i) c.emplace_back(CGAL::to_interval(p[i]));
  return Interval_poly(c);
}

} // namespace clash4d
