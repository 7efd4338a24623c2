#include "numbers/Approximation.h"
#include <CGAL/FPU.h>

namespace clash4d {

// CGAL's conversion is the tightest enclosure in any rounding mode (MPFR);
// nearest_double's quick path divides, so its mode is set here.
Approximation::Approximation(const Rational& x) : q(x), enclosure(CGAL::to_interval(x))
{
  CGAL::Protect_FPU_rounding<true> to_nearest(CGAL_FE_TONEAREST);
  nearest = nearest_double(x);
}

std::vector<Approximation> approximations(const std::vector<Rational>& numbers)
{
  std::vector<Approximation> a;
  a.reserve(numbers.size());
  for (const Rational& x : numbers) a.emplace_back(x);
  return a;
}

} // namespace clash4d
