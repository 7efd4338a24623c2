// The interval kernel: the approximate half of the filtered exact kernel.
// Numbers are CGAL::Interval_nt<false> (the rounding mode must be upward
// while it computes: the filtered runner holds CGAL::Protect_FPU_rounding),
// each enclosing the rational the same formula gives in exact arithmetic. A
// sign is returned only when the interval excludes the other signs; otherwise
// CGAL::Uncertain_conversion_exception is thrown and the filtered runner
// redoes the work in rationals, as CGAL's Filtered_predicate does.
#ifndef CLASH4D_EXACT_INTERVAL_KERNEL_H
#define CLASH4D_EXACT_INTERVAL_KERNEL_H

#include "core/Kernel_base.h"
#include "core/Number_ops.h"
#include "exact/Rational.h"
#include <CGAL/Interval_nt.h>
#include <cstdio>
#include <string>

namespace clash4d {

using Interval = CGAL::Interval_nt<false>;

// Enclosures of min and max, no decision (see core/Number_ops.h). Two
// intervals with the same bounds count as the same S-bound: that can only end
// the S-bound passes early, which keeps the bounds valid.
template <>
struct Number_ops<Interval> {
  static Interval lower(const Interval& a, const Interval& b) { return CGAL::min(a, b); }
  static Interval upper(const Interval& a, const Interval& b) { return CGAL::max(a, b); }
  static bool same(const Interval& a, const Interval& b) { return a.is_same(b); }
};

class Interval_kernel : public Kernel_base<Interval_kernel, Interval> {
public:
  static constexpr const char* name() { return "interval"; }
  static constexpr bool is_exact = false;
  CGAL::Sign sign(const FT& x) const { return CGAL::make_certain(CGAL::sign(x)); }
  bool possibly_positive(const FT& x) const { return CGAL::possibly(CGAL::sign(x) == CGAL::POSITIVE); }
  CGAL::Uncertain<bool> is_nonnegative(const FT& x, bool strict) const { return strict ? x > 0 : x >= 0; }
  bool prefer_less(const FT& a, const FT& b) const { return a.inf() + a.sup() < b.inf() + b.sup(); }
  FT from_rational(const Rational& q) const { return FT(CGAL::to_interval(q)); }
  // Statistics only (answers are never printed from intervals): a point
  // interval is an exact number, otherwise the enclosure "~[inf, sup]".
  std::string to_text(const FT& x) const
  {
    if (x.is_point()) return to_string(Rational(x.inf()));
    char text[64];
    std::snprintf(text, sizeof text, "~[%.17g, %.17g]", x.inf(), x.sup());
    return text;
  }
};

} // namespace clash4d

#endif
