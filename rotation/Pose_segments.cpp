#include "rotation/Pose_segments.h"

#include "model/Far_bound.h"
#include "model/Motion_path.h"

#include <stdexcept>

namespace clash4d {

namespace {

Time_poly constant(const Rational& v) { return Time_poly(v); }

// v0 + (t - t0) / (t1 - t0) (v1 - v0): the linear interpolation of a pose
// coordinate between two pose times.
Time_poly between(const Rational& v0, const Rational& v1, const Rational& t0, const Rational& t1)
{
  // A coordinate that does not change is a constant, of degree 0: every
  // product it enters then keeps its true degree (a resting body's planes,
  // their minors and enclosures are made with no terms that are exactly 0).
  if (v0 == v1) return Time_poly(v0);
  Rational slope = (v1 - v0) / (t1 - t0);
  return Time_poly(v0 - slope * t0, slope);
}

Pose_segment resting_at(const Pose& p)
{
  Pose_segment s;
  for (int i = 0; i < 4; ++i) s.q[i] = constant(p.rotate[i]);
  for (int i = 0; i < 3; ++i) s.c[i] = constant(p.translate[i]);
  return s;
}

std::vector<Pose_segment> from_poses(const std::vector<Pose>& poses)
{
  std::vector<Pose_segment> out;
  Pose_segment first = resting_at(poses.front());
  first.from_minus_infinity = true;
  first.hi = poses.front().t;
  out.push_back(first);
  for (std::size_t i = 0; i + 1 < poses.size(); ++i) {
    const Pose &a = poses[i], &b = poses[i + 1];
    Pose_segment s;
    s.lo = a.t;
    s.hi = b.t;
    for (int k = 0; k < 4; ++k) s.q[k] = between(a.rotate[k], b.rotate[k], a.t, b.t);
    for (int k = 0; k < 3; ++k) s.c[k] = between(a.translate[k], b.translate[k], a.t, b.t);
    out.push_back(s);
  }
  Pose_segment last = resting_at(poses.back());
  last.lo = poses.back().t;
  last.to_plus_infinity = true;
  out.push_back(last);
  return out;
}

// D(t) = v_i t + o_i on segment i, as the translation pipeline's own path
// makes it (model/Motion_path.h), in the scene's rationals.
std::vector<Pose_segment> from_robmod(const Motion& m)
{
  far_bound_detail::Exact_reader reader;
  Motion_path<Rational> path = Motion_path<Rational>::build(reader, m);
  std::size_t n = path.velocity.size();
  std::vector<Pose_segment> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    Pose_segment& s = out[i];
    s.from_minus_infinity = i == 0;
    s.to_plus_infinity = i + 1 == n;
    if (i > 0) s.lo = path.times[i - 1];
    if (i + 1 < n) s.hi = path.times[i];
    s.q = {constant(Rational(1)), constant(Rational(0)), constant(Rational(0)), constant(Rational(0))};
    for (int a = 0; a < 3; ++a)
      s.c[a] = CGAL::is_zero(path.velocity[i][a]) ? Time_poly(path.offset[i][a])
                                                 : Time_poly(path.offset[i][a], path.velocity[i][a]);
  }
  return out;
}

} // namespace

std::vector<Pose_segment> pose_segments(const Motion& m)
{
  if (m.rotates()) return from_poses(m.poses);
  if (m.velocities.empty()) {   // at rest
    Pose_segment s = resting_at(Pose{});
    s.from_minus_infinity = s.to_plus_infinity = true;
    return {s};
  }
  return from_robmod(m);
}

const Pose_segment& segment_at(const std::vector<Pose_segment>& segments, const Rational& t)
{
  for (const Pose_segment& s : segments)
    if (s.holds(t)) return s;
  throw std::logic_error("segment_at: segments that do not cover the line");
}

} // namespace clash4d
