// The static closed tests of a CCD query at one time (docs/ccd-queries.md):
// does the vertex lie in the closed triangle, do the closed segments meet?
// Written once on the signs of the named polynomials (Ccd_polynomials.h),
// asked through `sign(name)` in the order the test needs them, so that the
// names a test asked are exactly what its answer depends on (the sweep,
// Ccd_sweep.h, reads them). Every degenerate case is a branch of its own,
// never a perturbation: a triangle whose corners are collinear is the
// segment they span, a zero-length edge is its point, parallel edges meet
// where an endpoint of one lies on the other.
#ifndef CLASH4D_CCD_CCD_CONTACT_H
#define CLASH4D_CCD_CCD_CONTACT_H

#include "ccd/Ccd_polynomials.h"
#include "ccd/Ccd_query.h"
#include <optional>

namespace clash4d {

// Which branch of the test held: it names the contact's (u, v).
struct Ccd_contact {
  enum class Kind {
    face,     // N_k != 0: vertex-face through the triangle's plane, edge-edge crossing; index = k
    segment,  // a point on a segment of the degenerate case; index = the segment (Ccd_polynomials::segment)
  };
  Kind kind = Kind::face;
  int index = 0;
  bool point_segment = false;   // segment: its direction is zero (the segment is a point)
};

namespace ccd_contact_detail {

// X in the closed segment [S, S + U]: U x W = 0 and, when U != 0,
// 0 <= W . U <= U . U (W = X - S = sigma U, 0 <= sigma <= 1); when U = 0,
// W = 0.
template <class Sign>
std::optional<Ccd_contact> on_segment(Sign& sign, int s, int first)
{
  for (int k = 0; k < 3; ++k)
    if (sign(first + 6 + k) != 0) return std::nullopt;
  bool point = true;
  for (int k = 0; k < 3 && point; ++k) point = sign(first + k) == 0;
  if (point) {
    for (int k = 0; k < 3; ++k)
      if (sign(first + 3 + k) != 0) return std::nullopt;
  } else if (sign(first + 9) < 0 || sign(first + 10) < 0) {
    return std::nullopt;
  }
  return Ccd_contact{Ccd_contact::Kind::segment, s, point};
}

// The degenerate case: the contact is a point on one of the segments.
template <class Sign>
std::optional<Ccd_contact> on_any_segment(Sign& sign, int count, int first)
{
  for (int s = 0; s < count; ++s)
    if (auto c = on_segment(sign, s, first + s * ccd_name::segment_names)) return c;
  return std::nullopt;
}

// Three names whose signs, times sigma = sign(N_k), must all be >= 0.
template <class Sign>
bool all_nonnegative(Sign& sign, int sigma, std::initializer_list<int> names)
{
  for (int name : names)
    if (sigma * sign(name) < 0) return false;
  return true;
}

} // namespace ccd_contact_detail

// Whether the primitives meet at the time `sign` evaluates at; which way.
// F != 0: the four vertices are not coplanar, no contact. Otherwise, with
// the first k where N_k != 0 (the triangle is proper, the edges are not
// parallel), the barycentric or edge parameters are quotients by N_k, and
// their bounds are the signs of the numerators times that of N_k. With
// N = 0 the test is one of points on segments.
template <class Sign>
std::optional<Ccd_contact> static_contact(Ccd_type type, Sign&& sign)
{
  using namespace ccd_name;
  using namespace ccd_contact_detail;
  if (sign(F) != 0) return std::nullopt;
  for (int k = 0; k < 3; ++k) {
    int sigma = sign(N + k);
    if (sigma == 0) continue;
    bool inside = type == Ccd_type::vertex_face
                      ? all_nonnegative(sign, sigma, {face_u + k, face_v + k, face_w + k})
                      : all_nonnegative(sign, sigma, {cut_u + k, cut_u1 + k, cut_v + k, cut_v1 + k});
    if (!inside) return std::nullopt;
    return Ccd_contact{Ccd_contact::Kind::face, k, false};
  }
  return type == Ccd_type::vertex_face ? on_any_segment(sign, 3, vf_segment) : on_any_segment(sign, 4, ee_segment);
}

// The contact's (u, v) as quotients of polynomials in t, to be evaluated at
// the contact's time: u = u_num / u_den, v = v_num / v_den.
template <class FT>
struct Ccd_uv_fraction {
  Polynomial<FT> u_num, u_den, v_num, v_den;
};

template <class FT>
Ccd_uv_fraction<FT> uv_fraction(Ccd_polynomials<FT>& p, const Ccd_contact& c)
{
  using namespace ccd_name;
  using Poly = Polynomial<FT>;
  const Poly zero(FT(0)), one(FT(1));
  if (c.kind == Ccd_contact::Kind::face) {
    const Poly& n = p(N + c.index);
    if (p.type() == Ccd_type::vertex_face) return {p(face_u + c.index), n, p(face_v + c.index), n};
    return {p(cut_u + c.index), n, p(cut_v + c.index), n};
  }
  // sigma = W . U / U . U along the segment (0 on a point segment).
  int first = (p.type() == Ccd_type::vertex_face ? vf_segment : ee_segment) + c.index * segment_names;
  Poly num = c.point_segment ? zero : p(first + 9);
  Poly den = c.point_segment ? one : p(first + 9) + p(first + 10);
  if (p.type() == Ccd_type::vertex_face) {
    if (c.index == 0) return {num, den, zero, one};        // on [a, b]: u = sigma
    if (c.index == 1) return {zero, one, num, den};        // on [a, c]: v = sigma
    return {den - num, den, num, den};                     // on [b, c]: u = 1 - sigma, v = sigma
  }
  if (c.index == 0) return {num, den, zero, one};          // b0 on edge a
  if (c.index == 1) return {num, den, one, one};           // b1 on edge a
  if (c.index == 2) return {zero, one, num, den};          // a0 on edge b
  return {one, one, num, den};                             // a1 on edge b
}

} // namespace clash4d

#endif
