#include "float/Double_kernel.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace clash4d {

double Double_kernel::from_rational(const Rational& q) const
{
  // A numerator and denominator of at most 53 bits are exact doubles, and
  // IEEE division rounds their exact quotient to nearest: MPFR's answer, at
  // a fraction of its cost.
  double n = 0, d = 0;
  if (small_double(mpq_numref(q.mpq()), n) && small_double(mpq_denref(q.mpq()), d))
    return n / d;
  double r = round_to_nearest(q);
  if (!std::isfinite(r)) throw std::range_error("the number " + to_string(q) + " is beyond the range of double");
  return r;
}

std::string Double_kernel::to_text(double x) const
{
  char buffer[64];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

} // namespace clash4d
