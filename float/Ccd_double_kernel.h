// The double time kernel of the CCD sweep (ccd/Ccd_sweep.h): the same
// decider in IEEE doubles, as float CCD code is written: the query's
// numbers rounded to the nearest double, the named polynomials' roots found
// numerically (bisection on the monotone pieces between the derivative's
// roots), signs by plain comparison with zero or, with a tolerance,
// |value| <= tolerance taken as zero. It is a subject the comparer holds
// against the exact kernels, not an answer.
#ifndef CLASH4D_FLOAT_CCD_DOUBLE_KERNEL_H
#define CLASH4D_FLOAT_CCD_DOUBLE_KERNEL_H

#include "ccd/Ccd_polynomials.h"
#include "ccd/Ccd_sweep.h"
#include "ccd/Swept_boxes.h"
#include <optional>
#include <vector>

namespace clash4d {

class Ccd_double_kernel {
public:
  static constexpr bool is_exact = false;
  // A time, and the named polynomial it is a root of (-1: 0 or 1): that
  // polynomial's sign there is zero by construction, as in the exact kernels.
  struct Time {
    double value = 0;
    int name = -1;
  };

  // Throws std::range_error when a number is beyond the double range.
  // separation: the minimum separation D (0: the plain question).
  Ccd_double_kernel(const Ccd_query& q, double tolerance, double separation = 0);

  Ccd_type type() const { return p_.type(); }
  bool separated() const { return p_.separated(); }
  Ccd_polynomials<double>& polynomials() { return p_; }
  // Boxes closer than the separation and the tolerance are not apart, as a
  // float engine pads its boxes by its contact tolerance.
  bool swept_boxes_apart() const
  {
    double pad = separation_ + tolerance_;
    return clash4d::swept_boxes_apart(type(), rows_, [pad](double a, double b) { return a + pad < b; });
  }
  Time zero() const { return {}; }
  bool is_end(const Time& t) const { return t.value >= 1; }
  int sign_at(int name, const Time& t);
  int sign_after(int name, const Time& t);
  Time next_time(const Ccd_path& names, const Time& t);

private:
  int sign(double x) const { return x > tolerance_ ? 1 : (x < -tolerance_ ? -1 : 0); }
  const std::vector<double>& roots(int name);

  double tolerance_, separation_;
  std::array<Vector3<double>, 8> rows_;
  Ccd_polynomials<double> p_;
  std::array<std::optional<std::vector<double>>, ccd_name::max_count> roots_;
};

} // namespace clash4d

#endif
