#include "rotation/Moving_planes.h"

namespace clash4d {

std::vector<Moving_plane> moving_planes(const std::vector<Plane3<Rational>>& planes, const Pose_segment& s)
{
  auto N = unnormalised_rotation(s.q);
  Time_poly norm = squared_norm(s.q);
  std::vector<Moving_plane> out;
  out.reserve(planes.size());
  for (const Plane3<Rational>& p : planes) out.push_back(moved_plane(p, N, norm, s.c));
  return out;
}

Rational plane_value(const Moving_plane& h, const std::array<Rational, 3>& x, const Rational& t)
{
  return h[0].at(t) * x[0] + h[1].at(t) * x[1] + h[2].at(t) * x[2] + h[3].at(t);
}

Interval_poly enclosed(const Time_poly& p)
{
  std::vector<CGAL::Interval_nt<false>> c;
  for (int i = 0; i < p.size(); ++i) c.emplace_back(enclosing_interval(p[i]));
  return Interval_poly(c);
}

} // namespace clash4d
