// The rational run's own region where an interval run's region only
// encloses it (exact/Interval_filter.h): a sub-span that ends off the grid
// (a velocity change at t = 6.000000001) leaves the region's time face at
// that end, a number intervals cannot hold, and lines decided against the
// exact t* (earliest mode) need the rational run's region exactly.
//  - The root region (Span_region::on_grid, with S-bounds, regularised):
//    every face is a grid point except a time face clipped to a sub-span
//    end, lo' = max(g, lo) for a grid point g, which intervals enclose as
//    [max(g, l1), max(g, l2)] for lo in [l1, l2]; so lo' = max(inf, lo)
//    (if g <= l1, inf = l1 <= lo; otherwise inf = g). Likewise
//    hi' = min(sup, hi).
//  - A region generate-and-test is handed is the root bisected at most
//    Divide_and_conquer::max_depth times at midpoints (sub_region), so each
//    face is L + (H - L) k / 2^D on the root's faces L, H, with
//    D = max_depth: an enclosure holding one such number alone names it.
#ifndef CLASH4D_EXACT_REGION_FACES_H
#define CLASH4D_EXACT_REGION_FACES_H

#include "geometry/Box.h"
#include "numbers/Rational.h"
#include "search/Divide_and_conquer.h"
#include <optional>

namespace clash4d {

template <class AK, class EK>
class Region_faces {
public:
  using AFT = typename AK::FT;
  using EFT = typename EK::FT;
  using ABox = Box<AFT, 4>;
  using EBox = Box<EFT, 4>;

  Region_faces(const AK& ak, const EK& ek) : ak_(ak), ek_(ek) {}

  // The root region on a sub-span [lo, hi] (exact ends); nothing when a
  // face other than such a time face is not a point.
  std::optional<EBox> root(const ABox& r, const EFT& lo, const EFT& hi) const
  {
    EBox out;
    for (int q = 0; q < 4; ++q) {
      std::optional<Rational> a = ak_.exact_value(r.lo[q]), b = ak_.exact_value(r.hi[q]);
      if (q < 3 && (!a || !b)) return std::nullopt;
      EFT l = a ? ek_.from_rational(*a) : Number_ops<EFT>::upper(ek_.from_rational(Rational(r.lo[q].inf())), lo);
      EFT h = b ? ek_.from_rational(*b) : Number_ops<EFT>::lower(ek_.from_rational(Rational(r.hi[q].sup())), hi);
      out.set(q, l, h);
    }
    return out;
  }

  // A region bisected from `root` (exact); nothing when some face's
  // enclosure holds more than one candidate.
  std::optional<EBox> descendant(const ABox& r, const EBox& root) const
  {
    EBox out;
    for (int q = 0; q < 4; ++q) {
      std::optional<EFT> l = face(r.lo[q], root.lo[q], root.hi[q]), h = face(r.hi[q], root.lo[q], root.hi[q]);
      if (!l || !h) return std::nullopt;
      out.set(q, *l, *h);
    }
    return out;
  }

private:
  const AK& ak_;
  const EK& ek_;
  static constexpr int depth_bits = static_cast<int>(Divide_and_conquer<EK>::max_depth);

  std::optional<EFT> face(const AFT& f, const EFT& lo, const EFT& hi) const
  {
    if (std::optional<Rational> v = ak_.exact_value(f)) return ek_.from_rational(*v);
    Rational L = ek_.to_rational(lo), W = ek_.to_rational(hi) - L;
    if (CGAL::sign(W) != CGAL::POSITIVE) return std::nullopt;
    // The multiples of 2^-D within the enclosure's fractions of [L, H]: the
    // largest, and whether the one below it is out.
    Rational from = (Rational(f.inf()) - L) / W, to = (Rational(f.sup()) - L) / W;
    Rational k = floor_to_grid(to, depth_bits);
    if (k < from || !(k - power_of_two(-depth_bits) < from)) return std::nullopt;
    return ek_.from_rational(L + W * k);
  }
};

} // namespace clash4d

#endif
