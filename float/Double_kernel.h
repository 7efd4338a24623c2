// The double kernel: the same stages on IEEE doubles, with plain comparisons
// against zero, or |value| <= tolerance treated as zero the way float
// collision code is usually written.
#ifndef CLASH4D_FLOAT_DOUBLE_KERNEL_H
#define CLASH4D_FLOAT_DOUBLE_KERNEL_H

#include "geometry/Kernel_base.h"
#include "geometry/Kernel_concept.h"
#include "numbers/Rational.h"
#include "numbers/Stat_number.h"
#include "scene/Input_error.h"
#include <cmath>
#include <string>

namespace clash4d {

class Double_kernel : public Kernel_base<Double_kernel, double> {
public:
  explicit Double_kernel(double tolerance = 0) : tolerance_(tolerance) {}
  static constexpr const char* name() { return "double"; }
  static constexpr bool reads_exact_constructions = false;   // float code computes its own (model/Model_builder.h)
  // But a rotation is its exact matrix rounded entry by entry, as a scene
  // number is: a face two rotations share stays one plane (geometry/Kernel_concept.h).
  static constexpr bool reads_exact_rotations = true;
  static constexpr bool is_exact = false;
  double tolerance() const { return tolerance_; }
  CGAL::Sign sign(double x) const
  {
    return x > tolerance_ ? CGAL::POSITIVE : (x < -tolerance_ ? CGAL::NEGATIVE : CGAL::ZERO);
  }
  // The scene's rational rounded to the nearest double; a number beyond the
  // double range cannot be read by this instantiation (std::range_error).
  double from_rational(const Rational& q) const;
  // The reader's nearest double of a.q (the same number); one beyond the
  // range is refused by from_rational.
  double from_approximation(const Approximation& a) const
  {
    return std::isfinite(a.nearest) ? a.nearest : from_rational(a.q);
  }
  Rational to_rational(double x) const { return Rational(x); }
  double floor_to_grid(double x, int bits) const
  {
    if (bits > 900) return std::ldexp(std::floor(std::ldexp(x, bits)), -bits);
    return std::floor(x * power_of_two_double(bits)) * power_of_two_double(-bits);
  }
  double power_of_two(int e) const { return power_of_two_double(e); }
  // The far bound (model/Far_bound.h) beyond 2^900 leaves no room for the
  // search's products in doubles (Interval_kernel's limit): refused, exit 3.
  double far_power_of_two(int e) const
  {
    if (e > 900)
      throw Input_error("", "the search box of a pair unbounded along an axis reaches 2^" + std::to_string(e) +
                                ", beyond what the double instantiation can search (use --number exact or rational)",
                        CLASH4D_EXIT_LIMIT);
    return power_of_two(e);
  }
  int grid_exponent(double x) const
  {
    int e = 0;
    std::frexp(x, &e);
    return 1 - e;
  }
  // The shortest decimal that reads back to the same double (spec: output).
  std::string to_text(double x) const;
  Stat_number to_stat(double x) const { return {Stat_number::Kind::Double, Rational(), x, x}; }

private:
  double tolerance_;
};

static_assert(is_kernel_v<Double_kernel>, "Double_kernel must model the kernel concept (geometry/Kernel_concept.h)");

} // namespace clash4d

#endif
