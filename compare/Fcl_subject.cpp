#include "compare/Fcl_subject.h"

#ifdef CLASH4D_HAVE_FCL
#include "compare/Convex_motion.h"
#include "float/Double_kernel.h"

#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/continuous_collision.h>
#endif

#include <cmath>
#include <map>
#include <stdexcept>

namespace clash4d {

#ifdef CLASH4D_HAVE_FCL

namespace {

// A piece as an FCL convex mesh.
std::shared_ptr<fcl::Convexd> fcl_convex(const Convex_polytope& piece)
{
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
  for (const auto& v : piece.vertices) vertices->emplace_back(v[0], v[1], v[2]);
  auto faces = std::make_shared<std::vector<int>>();
  for (const auto& f : piece.faces) {
    faces->push_back(static_cast<int>(f.size()));
    faces->insert(faces->end(), f.begin(), f.end());
  }
  auto convex = std::make_shared<fcl::Convexd>(vertices, static_cast<int>(piece.faces.size()), faces);
  convex->computeLocalAABB();
  return convex;
}

} // namespace

struct Fcl_subject::Impl {
  Convex_motion scene;
  std::vector<std::vector<std::shared_ptr<fcl::Convexd>>> pieces;   // per object
};

bool Fcl_subject::built_in() { return true; }

Fcl_subject::Fcl_subject(const Scene& scene) : impl_(std::make_unique<Impl>())
{
  reason_ = impl_->scene.convert(scene, "fcl");
  if (!reason_.empty()) {
    reason_ = "not expressible by fcl: " + reason_;
    impl_.reset();
    return;
  }
  for (const auto& o : impl_->scene.objects) {
    impl_->pieces.emplace_back();
    for (const auto& p : o.pieces) impl_->pieces.back().push_back(fcl_convex(p));
  }
}

std::optional<double> Fcl_subject::time_of_contact(int i, int j) const
{
  if (!impl_) throw std::logic_error("fcl subject: " + reason_);
  const Convex_motion::Object &a = impl_->scene.objects[i], &b = impl_->scene.objects[j];
  auto placed = [](const std::array<double, 3>& t, const std::array<double, 4>& q) {
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.linear() = fcl::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
    tf.translation() = fcl::Vector3d(t[0], t[1], t[2]);
    return tf;
  };
  fcl::Transform3d a0 = placed(a.begin, a.begin_q), a1 = placed(a.end, a.end_q), b0 = placed(b.begin, b.begin_q),
                   b1 = placed(b.end, b.end_q);
  // Conservative advancement is FCL's solver for convex shapes under a
  // motion (the naive one only samples, the polynomial one wants meshes).
  // Its distances come from FCL's own GJK/EPA (GST_INDEP), not the default
  // libccd: libccd returns distance 0 with no direction at contact, so the
  // advancement sees no approach and steps past it (measured on
  // fixtures/contact/clear_collision_head_on.json: t* = 2.25 for 2, and
  // touch_only_at_tH_overlap_1e-9.json missed).
  fcl::ContinuousCollisionRequestd request;
  // A turn: FCL's screw motion between the two placements (constant
  // angular velocity about a fixed axis; its InterpMotion from two
  // transforms computes no velocities).
  request.ccd_motion_type = a.turns || b.turns ? fcl::CCDM_SCREW : fcl::CCDM_TRANS;
  request.gjk_solver_type = fcl::GST_INDEP;
  request.ccd_solver_type = fcl::CCDC_CONSERVATIVE_ADVANCEMENT;
  std::optional<double> first;
  for (const auto& p : impl_->pieces[i])
    for (const auto& q : impl_->pieces[j]) {
      fcl::ContinuousCollisionResultd result;
      double r = fcl::continuousCollide<double>(p.get(), a0, a1, q.get(), b0, b1, request, result);
      if (r < 0) throw std::runtime_error("fcl: continuousCollide refused the convex pair (returned " + Double_kernel().to_text(r) + ")");
      if (result.is_collide && (!first || result.time_of_contact < *first)) first = result.time_of_contact;
      if (first && *first <= 0) return first;
    }
  return first;
}

std::string Fcl_subject::motion_law() const
{
  return impl_ ? impl_->scene.law_differs(4 * std::atan(1.0)) : "";
}

Check_answer Fcl_subject::check(const Check_options& options) const
{
  if (!impl_) throw std::logic_error("fcl subject: " + reason_);
  return impl_->scene.answer(options, "fcl", [&](int i, int j) { return time_of_contact(i, j); });
}

#else // no FCL: the subject exists and says so

struct Fcl_subject::Impl {};

bool Fcl_subject::built_in() { return false; }

Fcl_subject::Fcl_subject(const Scene&)
    : reason_("fcl: not built in (clash4d was configured without FCL: install libfcl-dev and reconfigure, "
              "CMake option CLASH4D_WITH_FCL)")
{
}

std::optional<double> Fcl_subject::time_of_contact(int, int) const { throw std::logic_error(reason_); }
std::string Fcl_subject::motion_law() const { return ""; }
Check_answer Fcl_subject::check(const Check_options&) const { throw std::logic_error(reason_); }

#endif

Fcl_subject::~Fcl_subject() = default;
Fcl_subject::Fcl_subject(Fcl_subject&&) noexcept = default;
Fcl_subject& Fcl_subject::operator=(Fcl_subject&&) noexcept = default;

} // namespace clash4d
