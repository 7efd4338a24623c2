// A scene number's approximations, made once when the scene is read
// (approximate_numbers in scene/Scene.h, called by read_scene; read by
// read_number, geometry/Kernel_concept.h): the tightest interval of
// doubles around it and its nearest double. A check converts every number
// of the scene to its kernel (Model_builder), the interval run and the
// convex pairs' guide each (an exact hull's plane coefficients are
// rationals of many digits): a hull-hull pair's check spent a fifth of its
// instructions converting.
// Each approximation holds the number it was made from, and is read only
// for that very number (the same GMP value, not an equal one), so a scene
// whose numbers are changed after reading (the shrinker, tests) reads
// them again instead of an approximation of another number.
#ifndef CLASH4D_NUMBERS_APPROXIMATION_H
#define CLASH4D_NUMBERS_APPROXIMATION_H

#include "numbers/Rational.h"
#include <CGAL/Interval_nt.h>
#include <vector>

namespace clash4d {

struct Approximation {
  Rational q;                          // the number (the same GMP value, shared)
  CGAL::Interval_nt<false> enclosure;  // [q rounded down, q rounded up] (CGAL::to_interval)
  double nearest = 0;                  // nearest_double(q), rounding to nearest

  explicit Approximation(const Rational& x);
  // Whether this approximates x itself: x is a copy of q (CGAL's Gmpq
  // shares one value among its copies and never changes it in place).
  bool of(const Rational& x) const { return static_cast<mpq_srcptr>(x.mpq()) == static_cast<mpq_srcptr>(q.mpq()); }
};

std::vector<Approximation> approximations(const std::vector<Rational>& numbers);

} // namespace clash4d

#endif
