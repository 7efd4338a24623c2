// Minimum, maximum and sameness of two numbers, as constructions rather than
// decisions. On a totally ordered number type they are the usual ones; the
// interval kernel specialises them (exact/Interval_kernel.h) to enclose the
// exact minimum and maximum without asking which operand is smaller, so a
// box meet or join never fails the filter (CGAL's Min/Max on Interval_nt).
#ifndef CLASH4D_CORE_NUMBER_OPS_H
#define CLASH4D_CORE_NUMBER_OPS_H

namespace clash4d {

template <class FT>
struct Number_ops {
  static FT lower(const FT& a, const FT& b) { return b < a ? b : a; }
  static FT upper(const FT& a, const FT& b) { return a < b ? b : a; }
  // Used only to stop repeating S-bound passes early: an interval kernel may
  // answer "same" for bounds it cannot tell apart (fewer passes, still valid
  // bounds), never "different" for equal ones.
  static bool same(const FT& a, const FT& b) { return a == b; }
};

} // namespace clash4d

#endif
