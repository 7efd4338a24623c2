#include "float/Double_kernel.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace clash4d {

double Double_kernel::from_rational(const Rational& q) const
{
  double r = nearest_double(q);
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
