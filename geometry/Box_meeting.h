// When two moving boxes first meet: the swept-box bound of check/
// Piece_pairs.h, asked in EK for the pairs' order and in intervals for
// which piece pairs can meet at all (exact/Filtered_runner.h).
#ifndef CLASH4D_GEOMETRY_BOX_MEETING_H
#define CLASH4D_GEOMETRY_BOX_MEETING_H

#include "geometry/Box.h"
#include "geometry/kernel_ft4.h"
#include <optional>

namespace clash4d {

// The least t in [lo, hi] at which box A moved by va t + oa and box B
// moved by vb t + ob meet (closed boxes: a lower bound on a collision's or
// a contact's time); none when they never do there. On each axis q, with
// w = va_q - vb_q and d = ob_q - oa_q, they meet at t exactly when
//   A.lo_q + va_q t + oa_q <= B.hi_q + vb_q t + ob_q,  i.e.   w t <= B.hi_q - A.lo_q + d,
//   B.lo_q + vb_q t + ob_q <= A.hi_q + va_q t + oa_q,  i.e.  -w t <= A.hi_q - B.lo_q - d,
// each of which narrows [lo, hi] (or, with w = 0, holds or not for all t).
template <class K, class FT = typename K::FT>
std::optional<FT> first_box_meeting(const K& k, const Box<FT, 3>& A, const Vector3<FT>& va, const Vector3<FT>& oa,
                                    const Box<FT, 3>& B, const Vector3<FT>& vb, const Vector3<FT>& ob, FT lo, FT hi)
{
  if (A.empty || B.empty) return std::nullopt;
  // w t <= c on [lo, hi]: lo and hi narrowed, false when no t is left.
  auto at_most = [&](const FT& w, const FT& c) {
    CGAL::Sign s = k.sign(w);
    if (s == CGAL::ZERO) return k.sign(c) != CGAL::NEGATIVE;
    FT t = c / w;
    if (s == CGAL::POSITIVE) { if (k.less(t, hi)) hi = t; }
    else if (k.less(lo, t)) lo = t;
    return !k.less(hi, lo);
  };
  for (int q = 0; q < 3; ++q) {
    FT w = va[q] - vb[q], d = ob[q] - oa[q];
    if (A.has_lo[q] && B.has_hi[q] && !at_most(w, B.hi[q] - A.lo[q] + d)) return std::nullopt;
    if (B.has_lo[q] && A.has_hi[q] && !at_most(-w, A.hi[q] - B.lo[q] - d)) return std::nullopt;
  }
  return lo;
}

} // namespace clash4d

#endif
