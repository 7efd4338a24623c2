#include "scene/Scene_builder.h"
#include "geometry/Rotation_matrix.h"
#include "scene/Pose_motion.h"
#include "scene/Scene_writer.h"

#include <algorithm>
#include <stdexcept>

namespace clash4d {
namespace {

Solid leaf(Solid::Kind k, std::vector<Rational> numbers)
{
  Solid s;
  s.kind = k;
  s.numbers = std::move(numbers);
  return s;
}

Solid wrap(Solid::Kind k, std::vector<Rational> numbers, Solid child)
{
  Solid s = leaf(k, std::move(numbers));
  s.children.push_back(std::move(child));
  return s;
}

} // namespace

Vec3 plus(Vec3 a, const Vec3& b)
{
  for (int i = 0; i < 3; ++i) a[i] += b[i];
  return a;
}

Vec3 minus(Vec3 a, const Vec3& b)
{
  for (int i = 0; i < 3; ++i) a[i] -= b[i];
  return a;
}

Vec3 times(const Rational& s, Vec3 a)
{
  for (auto& x : a) x *= s;
  return a;
}

Solid block(const Vec3& lo, const Vec3& hi) { return leaf(Solid::Kind::Block, {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]}); }

Solid halfspace(const Rational& a, const Rational& b, const Rational& c, const Rational& d)
{
  return leaf(Solid::Kind::Halfspace, {a, b, c, d});
}

Solid hull(const std::vector<Vec3>& points)
{
  Solid s = leaf(Solid::Kind::Hull, {});
  for (const auto& p : points) s.numbers.insert(s.numbers.end(), p.begin(), p.end());
  return s;
}

Solid convex(const std::vector<std::array<Rational, 4>>& planes)
{
  Solid s = leaf(Solid::Kind::Convex, {});
  for (const auto& h : planes) s.numbers.insert(s.numbers.end(), h.begin(), h.end());
  return s;
}

Solid prism(std::vector<Point2> base, Rational z0, Rational z1)
{
  Rational area(0);   // twice the signed area: negative when clockwise
  for (std::size_t i = 0; i < base.size(); ++i) {
    const Point2& p = base[i];
    const Point2& q = base[(i + 1) % base.size()];
    area += p[0] * q[1] - q[0] * p[1];
  }
  if (area < 0) std::reverse(base.begin(), base.end());
  if (z1 < z0) std::swap(z0, z1);
  Solid s = leaf(Solid::Kind::Prism, {});
  for (const auto& p : base) s.numbers.insert(s.numbers.end(), p.begin(), p.end());
  s.numbers.push_back(z0);
  s.numbers.push_back(z1);
  return s;
}

Solid csg(Solid::Kind kind, std::vector<Solid> children)
{
  Solid s = leaf(kind, {});
  s.children = std::move(children);
  return s;
}

Solid translate(const Vec3& d, Solid child) { return wrap(Solid::Kind::Translate, {d[0], d[1], d[2]}, std::move(child)); }

Solid rotate(const std::array<Rational, 4>& q, Solid child)
{
  Solid s = wrap(Solid::Kind::Rotate, {q[0], q[1], q[2], q[3]}, std::move(child));
  s.constructed = rotation_rows(q);
  return s;
}

std::vector<Rational> rotation_rows(const std::array<Rational, 4>& q)
{
  // R(q) = N(Q) / |Q|^2 for Q = d q, d > 0 the common denominator of q's
  // parts (R(s q) = R(q) for s != 0): integer products, and one fraction
  // reduced per entry instead of one per operation (the time slices pose
  // a turning pair at every sample time, rotation/Rotating_pair.cpp).
  std::array<mpz_class, 4> Q;
  mpz_class d;
  over_common_denominator(q.data(), 4, Q.data(), d);
  auto N = unnormalised_rotation(Q);
  mpz_class n = squared_norm(Q);
  std::vector<Rational> out;
  for (const auto& row : N)
    for (const mpz_class& e : row) out.push_back(quotient_of_integers(e, n));
  return out;
}

Motion steady(const Vec3& velocity)
{
  Motion m;
  m.velocities.push_back(velocity);
  return m;
}

Motion rest() { return steady(vec(0, 0, 0)); }

Motion piecewise(std::vector<Vec3> vs, std::vector<Rational> ts)
{
  if (vs.size() != ts.size() + 1) throw std::invalid_argument("piecewise: one more velocity than times");
  Motion m;
  m.velocities = std::move(vs);
  m.times = std::move(ts);
  return m;
}

Scene_builder::Scene_builder(std::string name, const Rational& t_lo, const Rational& t_hi)
{
  scene_.name = std::move(name);
  scene_.t_lo = t_lo;
  scene_.t_hi = t_hi;
}

Scene_builder& Scene_builder::object(std::string name, Solid shape, Motion motion)
{
  std::vector<Pose> poses = std::move(motion.poses);
  scene_.objects.push_back({std::move(name), std::move(shape), std::move(motion)});
  if (!poses.empty()) motion_poses(scene_.objects.back().name, std::move(poses));
  return *this;
}

int Scene_builder::index_of(const std::string& name) const
{
  for (std::size_t i = 0; i < scene_.objects.size(); ++i)
    if (scene_.objects[i].name == name) return static_cast<int>(i);
  throw std::invalid_argument("Scene_builder: no object named \"" + name + "\"");
}

Scene_builder& Scene_builder::motion_poses(const std::string& name, std::vector<Pose> poses)
{
  int i = index_of(name);
  set_pose_motion(scene_.objects[i], std::move(poses), "objects[" + std::to_string(i) + "].motion");
  return *this;
}

Scene_builder& Scene_builder::ignore(const std::string& a, const std::string& b)
{
  int i = index_of(a), j = index_of(b);
  scene_.ignore.emplace_back(std::min(i, j), std::max(i, j));
  return *this;
}

std::string Scene_builder::text(const nlohmann::ordered_json& meta) const { return write_scene(scene_, meta); }

} // namespace clash4d
