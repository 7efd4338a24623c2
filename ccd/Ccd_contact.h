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
    face,     // through the triangle's plane, or the edges' lines crossing (closest); index = k of N_k
    segment,  // a point at (within D of) a segment; index = the segment (Ccd_polynomials::segment)
  };
  // Where on the segment: at the ratio W . U / U . U, or at its start or end
  // (a segment that is a point is at its start).
  enum class At { ratio, start, end };
  Kind kind = Kind::face;
  int index = 0;
  At at = At::ratio;
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
  return Ccd_contact{Ccd_contact::Kind::segment, s, point ? Ccd_contact::At::start : Ccd_contact::At::ratio};
}

// With a separation D: X within D of [S, S + U]: of its start or its end,
// or, U != 0, of the line where X's projection lies on the segment
// (0 <= W . U <= U . U). The distance is the least of those that apply.
template <class Sign>
std::optional<Ccd_contact> near_segment(Sign& sign, int s, int first)
{
  if (sign(first + 3) >= 0) return Ccd_contact{Ccd_contact::Kind::segment, s, Ccd_contact::At::start};
  if (sign(first + 4) >= 0) return Ccd_contact{Ccd_contact::Kind::segment, s, Ccd_contact::At::end};
  if (sign(first) > 0 && sign(first + 1) >= 0 && sign(first + 2) >= 0 && sign(first + 5) >= 0)
    return Ccd_contact{Ccd_contact::Kind::segment, s, Ccd_contact::At::ratio};
  return std::nullopt;
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

// Within D: the interior closest points (the projection on the triangle's
// plane inside it; the lines' closest points inside both edges), where the
// distance is that to the plane (lines), or else the least distance of a
// point to a segment (a vertex to an edge; an edge's end to the other).
template <class Sign>
std::optional<Ccd_contact> separated_contact(Ccd_type type, Sign& sign)
{
  using namespace ccd_name::separated;
  bool interior = sign(NN) > 0 &&
                  (type == Ccd_type::vertex_face ? all_nonnegative(sign, 1, {face_u, face_v, face_w})
                                                 : all_nonnegative(sign, 1, {cut_u, cut_u1, cut_v, cut_v1}));
  if (interior) {
    if (sign(plane) < 0) return std::nullopt;
    return Ccd_contact{Ccd_contact::Kind::face, 0, Ccd_contact::At::ratio};
  }
  int count = type == Ccd_type::vertex_face ? 3 : 4, start = type == Ccd_type::vertex_face ? vf_segment : ee_segment;
  for (int s = 0; s < count; ++s)
    if (auto c = near_segment(sign, s, start + s * segment_names)) return c;
  return std::nullopt;
}

} // namespace ccd_contact_detail

// Whether the primitives meet (come within D, when the names are
// separated ones) at the time `sign` evaluates at; which way.
// F != 0: the four vertices are not coplanar, no contact. Otherwise, with
// the first k where N_k != 0 (the triangle is proper, the edges are not
// parallel), the barycentric or edge parameters are quotients by N_k, and
// their bounds are the signs of the numerators times that of N_k. With
// N = 0 the test is one of points on segments.
template <class Sign>
std::optional<Ccd_contact> static_contact(Ccd_type type, bool separated, Sign&& sign)
{
  using namespace ccd_name;
  using namespace ccd_contact_detail;
  if (separated) return separated_contact(type, sign);
  if (sign(F) != 0) return std::nullopt;
  for (int k = 0; k < 3; ++k) {
    int sigma = sign(N + k);
    if (sigma == 0) continue;
    bool inside = type == Ccd_type::vertex_face
                      ? all_nonnegative(sign, sigma, {face_u + k, face_v + k, face_w + k})
                      : all_nonnegative(sign, sigma, {cut_u + k, cut_u1 + k, cut_v + k, cut_v1 + k});
    if (!inside) return std::nullopt;
    return Ccd_contact{Ccd_contact::Kind::face, k, Ccd_contact::At::ratio};
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
  using Poly = Polynomial<FT>;
  const Poly zero(FT(0)), one(FT(1));
  bool vf = p.type() == Ccd_type::vertex_face;
  if (c.kind == Ccd_contact::Kind::face) {
    if (p.separated()) {
      namespace sn = ccd_name::separated;
      const Poly& nn = p(sn::NN);
      return vf ? Ccd_uv_fraction<FT>{p(sn::face_u), nn, p(sn::face_v), nn}
                : Ccd_uv_fraction<FT>{p(sn::cut_u), nn, p(sn::cut_v), nn};
    }
    using namespace ccd_name;
    const Poly& n = p(N + c.index);
    return vf ? Ccd_uv_fraction<FT>{p(face_u + c.index), n, p(face_v + c.index), n}
              : Ccd_uv_fraction<FT>{p(cut_u + c.index), n, p(cut_v + c.index), n};
  }
  // sigma along the segment: W . U / U . U, or its start or end.
  Poly num = zero, den = one;
  if (c.at == Ccd_contact::At::end) {
    num = one;
  } else if (c.at == Ccd_contact::At::ratio) {
    if (p.separated()) {
      namespace sn = ccd_name::separated;
      int first = (vf ? sn::vf_segment : sn::ee_segment) + c.index * sn::segment_names;
      num = p(first + 1), den = p(first);
    } else {
      int first = (vf ? ccd_name::vf_segment : ccd_name::ee_segment) + c.index * ccd_name::segment_names;
      num = p(first + 9), den = p(first + 9) + p(first + 10);
    }
  }
  if (vf) {
    if (c.index == 0) return {num, den, zero, one};        // on [a, b]: u = sigma
    if (c.index == 1) return {zero, one, num, den};        // on [a, c]: v = sigma
    return {den - num, den, num, den};                     // on [b, c]: u = 1 - sigma, v = sigma
  }
  if (c.index == 0) return {num, den, zero, one};          // b0 on (near) edge a
  if (c.index == 1) return {num, den, one, one};           // b1 on (near) edge a
  if (c.index == 2) return {zero, one, num, den};          // a0 on (near) edge b
  return {one, one, num, den};                             // a1 on (near) edge b
}

} // namespace clash4d

#endif
