#include "scene/Pose_motion.h"
#include "scene/Input_error.h"

#include <stdexcept>

namespace clash4d {
namespace {

using Quaternion = std::array<Rational, 4>;
using Vec = std::array<Rational, 3>;

std::string pose_place(const std::string& place, std::size_t i, const char* key)
{
  return place + ".poses[" + std::to_string(i) + "]" + (key ? std::string(".") + key : "");
}

bool is_zero(const Quaternion& q)
{
  for (const Rational& x : q)
    if (!CGAL::is_zero(x)) return false;
  return true;
}

// b = lambda a with lambda < 0, exactly: a and b parallel (every 2x2 minor
// zero) and a . b < 0 (both non-zero).
bool negative_multiple(const Quaternion& a, const Quaternion& b)
{
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (a[i] * b[j] != a[j] * b[i]) return false;
  Rational dot(0);
  for (int i = 0; i < 4; ++i) dot += a[i] * b[i];
  return dot < 0;
}

Vec velocity(const Pose& a, const Pose& b)
{
  Vec v;
  for (int k = 0; k < 3; ++k) v[k] = (b.translate[k] - a.translate[k]) / (b.t - a.t);
  return v;
}

} // namespace

void check_poses(const std::vector<Pose>& poses, const std::string& place)
{
  if (poses.empty()) throw Input_error(place + ".poses", "expected at least one pose");
  if (poses.size() > CLASH4D_MAX_POSES)
    throw Input_error(place + ".poses", "more than the limit of " + std::to_string(CLASH4D_MAX_POSES) + " poses",
                      CLASH4D_EXIT_LIMIT);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    if (i > 0 && !(poses[i - 1].t < poses[i].t))
      throw Input_error(pose_place(place, i, "t"), "times must be strictly increasing (" + to_string(poses[i].t) +
                                                       " after " + to_string(poses[i - 1].t) + ")");
    if (is_zero(poses[i].rotate)) throw Input_error(pose_place(place, i, "rotate"), "the quaternion must not be zero");
    // Spec: q(t) = (1 - s) q_i + s q_{i+1} would be 0 between them.
    if (i > 0 && negative_multiple(poses[i - 1].rotate, poses[i].rotate))
      throw Input_error(pose_place(place, i, "rotate"),
                        "a negative multiple of the quaternion of poses[" + std::to_string(i - 1) +
                            "]: the interpolated quaternion would pass through 0 (to turn through half a turn or more, "
                            "add poses)");
  }
}

Vec pose_origin_at_zero(const std::vector<Pose>& poses)
{
  const Rational zero(0);
  if (!(poses.front().t < zero)) return poses.front().translate;
  if (!(zero < poses.back().t)) return poses.back().translate;
  std::size_t i = 0;
  while (!(zero < poses[i + 1].t)) ++i;   // t_i <= 0 < t_{i+1}
  Vec c = poses[i].translate;
  Vec v = velocity(poses[i], poses[i + 1]);
  for (int k = 0; k < 3; ++k) c[k] += (zero - poses[i].t) * v[k];
  return c;
}

void set_pose_motion(Scene_object& object, std::vector<Pose> poses, const std::string& place)
{
  check_poses(poses, place);
  Solid written = written_shape(object);
  Motion m;
  m.poses = std::move(poses);
  const Vec zero{Rational(0), Rational(0), Rational(0)};
  m.velocities.push_back(zero);   // rest before the first pose (and for a rotating motion)
  object.shape = std::move(written);
  if (!m.rotates()) {
    // D(t) = c(t) - c(0): the ROBMOD displacement (D(0) = 0), the shape
    // put at c(0). A pose time where the velocity does not change is no
    // breakpoint: the same motion written in ROBMOD has none there, and so
    // the same time sub-spans and answers.
    for (std::size_t i = 0; i < m.poses.size(); ++i) {
      Vec v = i + 1 < m.poses.size() ? velocity(m.poses[i], m.poses[i + 1]) : zero;
      if (v == m.velocities.back()) continue;
      m.times.push_back(m.poses[i].t);
      m.velocities.push_back(v);
    }
    Vec c0 = pose_origin_at_zero(m.poses);
    if (c0 != zero) {
      Solid moved;
      moved.kind = Solid::Kind::Translate;
      moved.path = object.shape.path;
      moved.numbers.assign(c0.begin(), c0.end());
      moved.children.push_back(std::move(object.shape));
      object.shape = std::move(moved);
    }
  }
  object.motion = std::move(m);
}

const Solid& written_shape(const Scene_object& object)
{
  const Motion& m = object.motion;
  if (m.poses.empty() || m.rotates()) return object.shape;
  Vec c0 = pose_origin_at_zero(m.poses);
  if (c0 == Vec{Rational(0), Rational(0), Rational(0)}) return object.shape;
  const Solid& s = object.shape;
  if (s.kind != Solid::Kind::Translate || s.children.size() != 1 ||
      s.numbers != std::vector<Rational>(c0.begin(), c0.end()))
    throw std::logic_error("internal error: object \"" + object.name +
                           "\" has a pose motion but not its shape at c(0) (set it with set_pose_motion)");
  return s.children.front();
}

void set_motion(Scene_object& object, Motion motion)
{
  Solid written = written_shape(object);
  object.shape = std::move(written);
  object.motion = Motion();   // the shape is now as written
  if (motion.poses.empty()) {
    object.motion = std::move(motion);
    return;
  }
  std::vector<Pose> poses = std::move(motion.poses);
  set_pose_motion(object, std::move(poses), "motion");
}

} // namespace clash4d
