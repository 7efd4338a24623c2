#include "compare/Fcl_subject.h"

#ifdef CLASH4D_HAVE_FCL
#include "compare/Comparer.h"
#include "model/Model_builder.h"
#include "model/Motion_path.h"
#include "exact/Rational_kernel.h"
#include "float/Double_kernel.h"
#include "scene/Input_error.h"

#include <CGAL/Cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/continuous_collision.h>
#endif

#include <cmath>
#include <map>
#include <stdexcept>

namespace clash4d {

#ifdef CLASH4D_HAVE_FCL

namespace {

using Kind = Solid::Kind;

struct Not_expressible {
  std::string what, path;   // "a difference", and where
};

// What FCL cannot take in s, if anything: it takes convex primitives, placed
// by translations and rotations, and their unions.
std::optional<Not_expressible> fcl_cannot_take(const Solid& s)
{
  switch (s.kind) {
    case Kind::Translate:
    case Kind::Rotate:
      return fcl_cannot_take(s.children[0]);
    case Kind::Union:
      for (const Solid& c : s.children)
        if (auto problem = fcl_cannot_take(c)) return problem;
      return std::nullopt;
    case Kind::Intersection:
      return Not_expressible{"an intersection", s.path};
    case Kind::Difference:
      return Not_expressible{"a difference", s.path};
    case Kind::Halfspace:
      return Not_expressible{"a half-space (unbounded, not a polyhedron)", s.path};
    default:
      return std::nullopt;
  }
}

using Exact_geometry = CGAL::Cartesian<Rational>;
using Point_3 = Exact_geometry::Point_3;

// The hull of the exact points (CGAL, exact: only extreme points stay),
// its vertices rounded to the nearest double, as an FCL convex mesh of
// outward triangles. Empty when a coordinate has no double.
std::shared_ptr<fcl::Convexd> fcl_convex(const std::vector<Vector3<Rational>>& points)
{
  std::vector<Point_3> pts;
  for (const auto& p : points) pts.emplace_back(p[0], p[1], p[2]);
  CGAL::Surface_mesh<Point_3> mesh;
  CGAL::convex_hull_3(pts.begin(), pts.end(), mesh);
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
  std::map<std::size_t, int> index;
  for (auto v : mesh.vertices()) {
    const Point_3& p = mesh.point(v);
    fcl::Vector3d x(round_to_nearest(p.x()), round_to_nearest(p.y()), round_to_nearest(p.z()));
    if (!x.allFinite()) return nullptr;
    index[v.idx()] = static_cast<int>(vertices->size());
    vertices->push_back(x);
  }
  auto faces = std::make_shared<std::vector<int>>();
  int count = 0;
  for (auto f : mesh.faces()) {
    std::vector<int> corners;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) corners.push_back(index.at(v.idx()));
    faces->push_back(static_cast<int>(corners.size()));
    faces->insert(faces->end(), corners.begin(), corners.end());
    ++count;
  }
  auto convex = std::make_shared<fcl::Convexd>(vertices, count, faces);
  convex->computeLocalAABB();
  return convex;
}

} // namespace

struct Fcl_subject::Impl {
  struct Object {
    std::string name;
    std::vector<std::shared_ptr<fcl::Convexd>> pieces;
    fcl::Vector3d begin, end;   // placements (translations) at tL and tH
  };
  double t_lo = 0, t_hi = 1;
  std::vector<Object> objects;
  std::vector<std::pair<int, int>> ignore;   // the scene's ignored pairs
};

bool Fcl_subject::built_in() { return true; }

Fcl_subject::Fcl_subject(const Scene& scene) : impl_(std::make_unique<Impl>())
{
  Impl& m = *impl_;
  reason_ = [&]() -> std::string {
    // What FCL cannot express, read on the scene as written (its numbers in
    // the messages). Rounding is monotonic, so a velocity change outside
    // (tL, tH) stays outside in the rounded scene.
    for (const Scene_object& o : scene.objects) {
      std::string object = "object '" + o.name + "' ";
      for (const Rational& t : o.motion.times)
        if (scene.t_lo < t && t < scene.t_hi)
          return object + "changes velocity at t = " + to_string(t) +
                 ", inside the span (fcl's translation motion has one constant velocity)";
      if (auto problem = fcl_cannot_take(o.shape))
        return object + (problem->path == o.shape.path ? "is " + problem->what
                                                      : "contains " + problem->what + " at " + problem->path);
    }
    // FCL works on doubles: it gets the scene with every number rounded to
    // the nearest double, as the double subject reads it (and as a user of
    // FCL would have it), so its input-rounding errors are classified as
    // everyone's. Translations, rotations and motions are then applied
    // exactly and each vertex and placement rounded once more.
    Scene rounded;
    try {
      rounded = rounded_scene(scene);
    } catch (const Input_error& e) {
      return "the scene rounded to doubles is invalid (" + e.format("rounded scene") + ")";
    } catch (const std::range_error& e) {
      return e.what();
    }
    m.t_lo = round_to_nearest(rounded.t_lo);
    m.t_hi = round_to_nearest(rounded.t_hi);
    m.ignore = rounded.ignore;
    // The model builder places every primitive's vertices exactly (a union's
    // primitives are its convex pieces); the motion path gives D(t) exactly.
    Rational_kernel k;
    for (const Scene_object& o : rounded.objects) {
      Impl::Object fo;
      fo.name = o.name;
      for (const auto& p : Model_builder<Rational_kernel>(k).build(o.shape).primitives) {
        fo.pieces.push_back(fcl_convex(p.vertices));
        if (!fo.pieces.back()) return "object '" + o.name + "' has a vertex coordinate beyond the range of doubles";
      }
      Motion_path<Rational> path = Motion_path<Rational>::build(k, o.motion);
      Vector3<Rational> d0 = path.displacement(rounded.t_lo), d1 = path.displacement(rounded.t_hi);
      for (int i = 0; i < 3; ++i) {
        fo.begin[i] = round_to_nearest(d0[i]);
        fo.end[i] = round_to_nearest(d1[i]);
      }
      if (!fo.begin.allFinite() || !fo.end.allFinite()) return "object '" + o.name + "' moves beyond the range of doubles";
      m.objects.push_back(std::move(fo));
    }
    return "";
  }();
  if (!reason_.empty()) {
    reason_ = "not expressible by fcl: " + reason_;
    impl_.reset();
  }
}

std::optional<double> Fcl_subject::time_of_contact(int i, int j) const
{
  if (!impl_) throw std::logic_error("fcl subject: " + reason_);
  const Impl::Object &a = impl_->objects[i], &b = impl_->objects[j];
  auto placed = [](const fcl::Vector3d& t) {
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.translation() = t;
    return tf;
  };
  fcl::Transform3d a0 = placed(a.begin), a1 = placed(a.end), b0 = placed(b.begin), b1 = placed(b.end);
  // Conservative advancement is FCL's solver for convex shapes under a
  // motion (the naive one only samples, the polynomial one wants meshes).
  // Its distances come from FCL's own GJK/EPA (GST_INDEP), not the default
  // libccd: libccd returns distance 0 with no direction at contact, so the
  // advancement sees no approach and steps past it (measured on
  // fixtures/contact/clear_collision_head_on.json: t* = 2.25 for 2, and
  // touch_only_at_tH_overlap_1e-9.json missed).
  fcl::ContinuousCollisionRequestd request;
  request.ccd_motion_type = fcl::CCDM_TRANS;
  request.gjk_solver_type = fcl::GST_INDEP;
  request.ccd_solver_type = fcl::CCDC_CONSERVATIVE_ADVANCEMENT;
  std::optional<double> first;
  for (const auto& p : a.pieces)
    for (const auto& q : b.pieces) {
      fcl::ContinuousCollisionResultd result;
      double r = fcl::continuousCollide<double>(p.get(), a0, a1, q.get(), b0, b1, request, result);
      if (r < 0) throw std::runtime_error("fcl: continuousCollide refused the convex pair (returned " + Double_kernel().to_text(r) + ")");
      if (result.is_collide && (!first || result.time_of_contact < *first)) first = result.time_of_contact;
      if (first && *first <= 0) return first;
    }
  return first;
}

Check_answer Fcl_subject::check(const Check_options& options) const
{
  if (!impl_) throw std::logic_error("fcl subject: " + reason_);
  Check_answer answer;
  answer.number = "fcl";
  double t_min = 0;
  int n = static_cast<int>(impl_->objects.size());
  auto ignored = [&](int i, int j) {
    for (const auto& p : impl_->ignore)
      if ((p.first == i && p.second == j) || (p.first == j && p.second == i)) return true;
    return false;
  };
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if (ignored(i, j)) continue;
      std::optional<double> toc = time_of_contact(i, j);
      if (!toc) continue;
      Pair_answer p;
      p.a = impl_->objects[i].name;
      p.b = impl_->objects[j].name;
      if (options.earliest) {
        double t = impl_->t_lo + *toc * (impl_->t_hi - impl_->t_lo);
        p.earliest = true;
        p.t_star = Double_kernel().to_text(t);
        p.at_start = *toc <= 0;
        if (answer.earliest_pair < 0 || t < t_min) {
          answer.earliest_pair = static_cast<int>(answer.pairs.size());
          t_min = t;
        }
      }
      answer.pairs.push_back(p);
      if (!options.all_pairs && !options.earliest) {
        answer.collide = true;
        return answer;
      }
    }
  answer.collide = !answer.pairs.empty();
  return answer;
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
Check_answer Fcl_subject::check(const Check_options&) const { throw std::logic_error(reason_); }

#endif

Fcl_subject::~Fcl_subject() = default;
Fcl_subject::Fcl_subject(Fcl_subject&&) noexcept = default;
Fcl_subject& Fcl_subject::operator=(Fcl_subject&&) noexcept = default;

} // namespace clash4d
