#include "compare/Bullet_subject.h"

#include <cmath>
#include <stdexcept>

#ifdef CLASH4D_HAVE_BULLET
#include "compare/Convex_motion.h"

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btContinuousConvexCollision.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

namespace clash4d {

struct Bullet_subject::Impl {
  Convex_motion scene;
  std::vector<std::vector<std::unique_ptr<btConvexHullShape>>> pieces;   // per object
};

bool Bullet_subject::built_in() { return true; }

Bullet_subject::Bullet_subject(const Scene& scene) : impl_(std::make_unique<Impl>())
{
  reason_ = impl_->scene.convert(scene, "bullet");
  if (!reason_.empty()) {
    reason_ = "not expressible by bullet: " + reason_;
    impl_.reset();
    return;
  }
  for (const auto& o : impl_->scene.objects) {
    impl_->pieces.emplace_back();
    for (const auto& p : o.pieces) {
      auto shape = std::make_unique<btConvexHullShape>();
      for (const auto& v : p.vertices) shape->addPoint(btVector3(v[0], v[1], v[2]), false);
      shape->recalcLocalAabb();
      shape->setMargin(0);   // the default 0.04 would make every near miss a hit
      impl_->pieces.back().push_back(std::move(shape));
    }
  }
}

std::optional<double> Bullet_subject::time_of_contact(int i, int j) const
{
  const Convex_motion::Object &a = impl_->scene.objects[i], &b = impl_->scene.objects[j];
  auto placed = [](const std::array<double, 3>& t, const std::array<double, 4>& q) {
    btTransform tf;
    tf.setIdentity();
    tf.setRotation(btQuaternion(q[1], q[2], q[3], q[0]));   // Bullet's order: x, y, z, w
    tf.setOrigin(btVector3(t[0], t[1], t[2]));
    return tf;
  };
  btTransform a0 = placed(a.begin, a.begin_q), a1 = placed(a.end, a.end_q), b0 = placed(b.begin, b.begin_q),
              b1 = placed(b.end, b.end_q);
  std::optional<double> first;
  for (const auto& p : impl_->pieces[i])
    for (const auto& q : impl_->pieces[j]) {
      btVoronoiSimplexSolver simplex;
      btGjkEpaPenetrationDepthSolver penetration;
      btContinuousConvexCollision cast(p.get(), q.get(), &simplex, &penetration);
      btConvexCast::CastResult result;
      if (cast.calcTimeOfImpact(a0, a1, b0, b1, result) && (!first || result.m_fraction < *first))
        first = static_cast<double>(result.m_fraction);
    }
  return first;
}

std::string Bullet_subject::motion_law() const
{
  // btTransformUtil::integrateTransform clamps a step's turn to a quarter
  // of pi (ANGULAR_MOTION_THRESHOLD).
  return impl_ ? impl_->scene.law_differs(std::atan(1.0)) : "";
}

Check_answer Bullet_subject::check(const Check_options& options) const
{
  if (!impl_) throw std::logic_error("bullet subject: " + reason_);
  return impl_->scene.answer(options, "bullet", [&](int i, int j) { return time_of_contact(i, j); });
}

#else // no Bullet: the subject exists and says so

namespace clash4d {

struct Bullet_subject::Impl {};

bool Bullet_subject::built_in() { return false; }

Bullet_subject::Bullet_subject(const Scene&)
    : reason_("bullet: not built in (clash4d was configured without Bullet: install libbullet-dev and reconfigure, "
              "CMake option CLASH4D_WITH_BULLET)")
{
}

std::optional<double> Bullet_subject::time_of_contact(int, int) const { throw std::logic_error(reason_); }
std::string Bullet_subject::motion_law() const { return ""; }
Check_answer Bullet_subject::check(const Check_options&) const { throw std::logic_error(reason_); }

#endif

Bullet_subject::~Bullet_subject() = default;

} // namespace clash4d
