// A closed half-space of space-time: n.(x, y, z, t) + c <= 0.
#ifndef CLASH4D_GEOMETRY_HYPERPLANE4_H
#define CLASH4D_GEOMETRY_HYPERPLANE4_H

#include "geometry/kernel_ft4.h"
#include <CGAL/Uncertain.h>
#include <CGAL/enum.h>

namespace clash4d {

template <class FT>
struct Hyperplane4 {
  Vector4<FT> n;
  FT c;

  FT value(const Vector4<FT>& p) const { return dot_plus(n, p, c); }
  Hyperplane4 complement() const { return {{negated(n[0]), negated(n[1]), negated(n[2]), negated(n[3])}, negated(c)}; }
};

// +1 when h = lambda g with lambda > 0, -1 when lambda < 0, 0 otherwise;
// indeterminate where kernel K cannot certify a sign it needs (an interval
// kernel on planes that are one, which is common: rotated copies), without
// a throw (uncertain_sign). Each sign asked in the same order as the
// predicate below, which stops at the same places.
template <class K, class FT>
CGAL::Uncertain<int> proportional_or_unsure(const K& k, const Hyperplane4<FT>& h, const Hyperplane4<FT>& g)
{
  bool unsure = false;
  auto sign = [&](const FT& x) {
    CGAL::Uncertain<CGAL::Sign> s = k.uncertain_sign(x);
    unsure = !CGAL::is_certain(s);
    return unsure ? CGAL::ZERO : CGAL::get_certain(s);
  };
  const CGAL::Uncertain<int> unknown(-1, 1);   // every answer possible
  int j = 0;
  CGAL::Sign gj = CGAL::ZERO;
  while (j < 4 && (gj = sign(g.n[j])) == CGAL::ZERO && !unsure) ++j;
  if (unsure) return unknown;
  if (j == 4) return 0;
  CGAL::Sign hj = sign(h.n[j]);
  if (unsure) return unknown;
  if (hj == CGAL::ZERO) return 0;
  for (int i = 0; i < 4; ++i) {   // i = j is zero by construction (not so in intervals)
    if (i == j) continue;
    CGAL::Sign minor = sign(h.n[i] * g.n[j] - g.n[i] * h.n[j]);
    if (unsure) return unknown;
    if (minor != CGAL::ZERO) return 0;
  }
  CGAL::Sign offsets = sign(h.c * g.n[j] - g.c * h.n[j]);
  if (unsure) return unknown;
  if (offsets != CGAL::ZERO) return 0;
  return hj == gj ? 1 : -1;
}

// The same, a predicate of kernel K: an interval kernel throws where it
// cannot tell (CGAL::Uncertain_conversion_exception).
template <class K, class FT>
int proportional(const K& k, const Hyperplane4<FT>& h, const Hyperplane4<FT>& g)
{
  return CGAL::make_certain(proportional_or_unsure(k, h, g));
}

// The time of the point where four hyperplanes n_k.x + c_k = 0 meet, as
// num / den by Cramer's rule: den = det[n_k], num = det[n_k0 n_k1 n_k2 -c_k]
// (rows k); den is zero when they do not meet in one point. No division
// here: the caller's kernel signs den.
template <class FT>
std::array<FT, 2> meeting_time(const Hyperplane4<FT>& a, const Hyperplane4<FT>& b, const Hyperplane4<FT>& c,
                               const Hyperplane4<FT>& d)
{
  auto row = [](const Hyperplane4<FT>& h) { return Vector4<FT>{h.n[0], h.n[1], h.n[2], -h.c}; };
  return {determinant4(row(a), row(b), row(c), row(d)), determinant4(a.n, b.n, c.n, d.n)};
}

// Equation (4): the plane n.x + d <= 0 moving with D(t) = v t + o becomes
// n.x - (n.v) t + (d - n.o) <= 0.
template <class FT>
Hyperplane4<FT> extrude(const Plane3<FT>& p, const Vector3<FT>& v, const Vector3<FT>& o)
{
  Vector3<FT> n{p[0], p[1], p[2]};
  return {{p[0], p[1], p[2], negated_dot(n, v)}, dot_from(p[3], n, o)};
}

// The time slab lo <= t <= hi as two half-spaces (§3 item 3).
template <class FT>
Hyperplane4<FT> time_at_least(const FT& lo) { return {{FT(0), FT(0), FT(0), FT(-1)}, lo}; }
template <class FT>
Hyperplane4<FT> time_at_most(const FT& hi) { return {{FT(0), FT(0), FT(0), FT(1)}, -hi}; }

} // namespace clash4d

#endif
