#include "exact/Closed_in_field.h"
#include "check/Check_runner.h"
#include "exact/Number_field_kernel.h"
#include "geometry/Rotation_matrix.h"
#include <mutex>

namespace clash4d {

namespace {

using K = Number_field_kernel;
using FT = K::FT;

// x -> R(q(r)) x + c(r): the pose at r, R = N(q) / |q|^2 (the spec's
// matrix; a quotient in the field, not a normalisation).
Affine3<FT> placement(const K& k, const Field_posed& o)
{
  std::array<FT, 4> q = {k.at(o.q[0]), k.at(o.q[1]), k.at(o.q[2]), k.at(o.q[3])};
  Affine3<FT> T;
  T.R = rotation_matrix(q[0], q[1], q[2], q[3]);
  T.b = {k.at(o.c[0]), k.at(o.c[1]), k.at(o.c[2])};
  return T;
}

bool unbounded(const Csg_model<FT>& m)
{
  for (const auto& p : m.primitives)
    if (p.vertices.empty()) return true;
  return false;
}

// The far exponent (model/Far_bound.h) of two objects at rest: every
// vertex of their space-time arrangement has t in {0, 1} (the span's ends;
// the objects' planes have no t term) and its (x, y, z) is where three of
// their planes and the coordinate planes meet, so R = 2^e above every such
// point's largest |coordinate| bounds them all, in every frame (no
// velocity shears one). The points are made exactly; the planes are few
// (this runs for pairs of unbounded objects only, whose shapes are a few
// half-spaces), and a pair with many is refused (none), not searched for
// long.
constexpr std::size_t most_planes = 37;

std::optional<int> far_exponent_at_rest(const K& k, const Csg_model<FT>& a, const Csg_model<FT>& b)
{
  if (!unbounded(a) || !unbounded(b)) return -1;
  std::vector<Plane3<FT>> planes = {{FT(1), FT(0), FT(0), FT(0)}, {FT(0), FT(1), FT(0), FT(0)},
                                    {FT(0), FT(0), FT(1), FT(0)}};
  for (const Csg_model<FT>* m : {&a, &b})
    for (const auto& p : m->primitives) planes.insert(planes.end(), p.planes.begin(), p.planes.end());
  if (planes.size() > most_planes + 3) return std::nullopt;
  FT bound(1);
  auto normal = [&](std::size_t i) { return Vector3<FT>{planes[i][0], planes[i][1], planes[i][2]}; };
  for (std::size_t i = 0; i < planes.size(); ++i)
    for (std::size_t j = i + 1; j < planes.size(); ++j)
      for (std::size_t l = j + 1; l < planes.size(); ++l) {
        // x = -(d_i u + d_j v + d_l w) / det, u = n_j x n_l, v = n_l x n_i,
        // w = n_i x n_j, det = n_i . u (Cramer by cross products).
        Vector3<FT> u = cross(normal(j), normal(l)), v = cross(normal(l), normal(i)), w = cross(normal(i), normal(j));
        FT det = dot(normal(i), u);
        if (k.sign(det) == CGAL::ZERO) continue;
        for (int c = 0; c < 3; ++c) {
          FT x = (planes[i][3] * u[c] + planes[j][3] * v[c] + planes[l][3] * w[c]) / det;
          if (k.less(bound, Number_ops<FT>::magnitude(x))) bound = Number_ops<FT>::magnitude(x);
        }
      }
  return 1 - k.grid_exponent(bound);   // 2^-g <= bound < 2^(1-g)
}

Object_model<FT> at_rest(const K& k, std::string name, Csg_model<FT> csg)
{
  Motion still;
  still.velocities.push_back({Rational(0), Rational(0), Rational(0)});
  return {std::move(name), std::move(csg), Motion_path<FT>::build(k, still)};
}

// Both posed shapes over the span [0, 1] at rest, as posed_pair makes a
// rational time's scene (rotation/Rotating_pair.cpp); none when the far
// bound is refused.
std::optional<Scene_model<K>> posed_model(const K& k, const Field_posed& a, const Field_posed& b)
{
  Scene_model<K> m;
  m.kernel = k;
  m.t_lo = FT(0);
  m.t_hi = FT(1);
  m.exact_t_lo = Rational(0);
  m.exact_t_hi = Rational(1);
  m.exact_span = true;
  Model_builder<K> builder(k);
  Csg_model<FT> ca = builder.build(*a.shape, placement(k, a));
  Csg_model<FT> cb = builder.build(*b.shape, placement(k, b));
  std::optional<int> far = far_exponent_at_rest(k, ca, cb);
  if (!far) return std::nullopt;
  m.far_exponent = *far;
  m.objects.push_back(at_rest(k, "a", std::move(ca)));
  m.objects.push_back(at_rest(k, "b", std::move(cb)));
  return m;
}

} // namespace

Field_answer closed_point_in_field(const Algebraic& r, const Field_posed& a, const Field_posed& b)
{
  static std::mutex serial;
  std::lock_guard<std::mutex> lock(serial);
  K k(r);
  Field_answer answer;
  std::optional<Scene_model<K>> model = posed_model(k, a, b);
  if (!model) {
    answer.refused = "two unbounded objects with more than " + std::to_string(most_planes) + " planes";
    return answer;
  }
  Check_stats stats;
  auto settled = settled_bounds_all(k, *model, stats, true);
  Collision_checker<K> checker(k, *model, settled, stats, true);
  Pair_result<FT> hit = checker.check_pair(0, 1, false, nullptr, Semantics::closed);
  answer.meet = hit.collide;
  if (hit.collide)
    for (int i = 0; i < 3; ++i) answer.point[i] = k.coefficients(hit.witness[i]);
  return answer;
}

} // namespace clash4d
