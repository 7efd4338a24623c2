// The far bound (issue 16): an exact power of two R = 2^e such that every
// vertex of the scene's space-time arrangement lies in |x'_q| < R in every
// frame the search uses, so a pair of objects both unbounded along an axis
// can be searched in a box (search/Span_region.h) without losing an answer.
//
// Derivation. Let H be the scene's space-time hyperplanes: every plane of
// every primitive extruded (eq. 4) on every motion segment, the time ends
// t = tL, t = tH and every velocity-change time, and the coordinate
// hyperplanes x = 0, y = 0, z = 0, t = 0. Every constant-velocity piece of a
// pair's collision region (regularised: open; closed: its closure within
// the sub-span's slab, regularised-semantics item 6) is a union of faces of
// the arrangement of H. The coordinate hyperplanes' normals span R^4, so no
// face contains a line (its lineality space is {0}): the closure of every
// face is a pointed polyhedron and has a vertex of the arrangement, and a
// linear function bounded below on it (t, for --earliest: t >= tL) attains
// its minimum at such a vertex.
// Write each hyperplane with coprime integer coefficients (n, c). A vertex
// solves M x = -c for four of them, M a nonsingular integer 4x4 matrix, so
// by Cramer's rule |x_i| = |det M_i| / |det M| <= |det M_i| (|det M| >= 1),
// and by Hadamard's inequality |det M_i| <= the product of M_i's row norms,
// each at most the L1 norm of its hyperplane's (n, c): |x_i| <= B^4 = R0,
// B the largest L1 norm in H.
// The search measures an axis in a sheared frame x'_q = x_q - w_q t, w a
// velocity of the scene (Appendix B's fitting), so |x'_q| <= R0 (1 + W)
// with W the largest |velocity component|. R = 2^e is the least power of
// two above R0 (1 + W): strictly beyond every vertex, in every frame.
#ifndef CLASH4D_MODEL_FAR_BOUND_H
#define CLASH4D_MODEL_FAR_BOUND_H

#include "model/Model_builder.h"
#include "model/Motion_path.h"
#include "geometry/Hyperplane4.h"
#include "scene/Scene.h"
#include <algorithm>

namespace clash4d {

namespace far_bound_detail {

// What Model_builder and Motion_path ask of a kernel, on the scene's own
// rationals: the exact planes and motions, whatever kernel runs the check.
struct Exact_reader {
  using FT = Rational;
  static constexpr bool reads_exact_constructions = true;
  FT from_rational(const Rational& q) const { return q; }
  CGAL::Sign sign(const FT& x) const { return CGAL::sign(x); }
  bool less(const FT& a, const FT& b) const { return a < b; }
};

inline bool has_halfspace(const Solid& s)
{
  if (s.kind == Solid::Kind::Halfspace) return true;
  return std::any_of(s.children.begin(), s.children.end(), has_halfspace);
}

inline Rational magnitude(const Rational& x) { return x < 0 ? -x : x; }

// The L1 norm of h in coprime integers.
inline Rational l1_norm(const Hyperplane4<Rational>& h)
{
  Rational x[5] = {h.n[0], h.n[1], h.n[2], h.n[3], h.c};
  scale_to_coprime_integers(x, 5);
  Rational sum(0);
  for (const Rational& v : x) sum += magnitude(v);
  return sum;
}

} // namespace far_bound_detail

// The exponent e of R = 2^e (derivation above); -1 when no pair can need
// it: only a half-space makes an object unbounded (convex solids are
// validated bounded), so it takes two objects with one each.
inline int far_exponent(const Scene& scene)
{
  using namespace far_bound_detail;
  int unbounded = 0;
  for (const auto& o : scene.objects) unbounded += has_halfspace(o.shape);
  if (unbounded < 2) return -1;
  Exact_reader r;
  Rational B(1), W(0);                      // the coordinate hyperplanes: L1 norm 1
  auto time_plane = [&](const Rational& t) { B = std::max(B, l1_norm(time_at_most(t))); };
  time_plane(scene.t_lo);
  time_plane(scene.t_hi);
  for (const auto& o : scene.objects) {
    Csg_model<Rational> csg = Model_builder<Exact_reader>(r).build(o.shape);
    Motion_path<Rational> m = Motion_path<Rational>::build(r, o.motion);
    for (const Rational& t : m.times) time_plane(t);
    for (std::size_t s = 0; s < m.velocity.size(); ++s) {
      for (int q = 0; q < 3; ++q) W = std::max(W, magnitude(m.velocity[s][q]));
      for (const auto& p : csg.primitives)
        for (const auto& plane : p.planes) B = std::max(B, l1_norm(extrude(plane, m.velocity[s], m.offset[s])));
    }
  }
  Rational bound = B * B * B * B * (Rational(1) + W);
  return 1 - grid_exponent(bound);          // 2^-k <= bound < 2^(1-k), k = grid_exponent
}

} // namespace clash4d

#endif
