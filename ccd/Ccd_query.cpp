#include "ccd/Ccd_query.h"

#include <CGAL/FPU.h>

namespace clash4d {

namespace {

// A double's value (a numerator of at most 53 bits over a power of two of
// at most one limb): that double, exactly; most inputs are doubles.
bool exact_double(const Rational& q, double& out)
{
  double n = 0;
  mpz_srcptr den = mpq_denref(q.mpq());
  if (!small_double(mpq_numref(q.mpq()), n) || mpz_size(den) != 1) return false;
  mp_limb_t m = mpz_getlimbn(den, 0);
  if ((m & (m - 1)) != 0) return false;
  out = n * power_of_two_double(-__builtin_ctzll(m));
  return true;
}

} // namespace

Ccd_query::Ccd_query(Ccd_type type, const Rows& rows) : type_(type), rows_(rows)
{
  for (std::size_t i = 0; i < 8; ++i) approximate(i);
}

void Ccd_query::set_row(int i, const Point& p)
{
  rows_[static_cast<std::size_t>(i)] = p;
  approximate(static_cast<std::size_t>(i));
}

void Ccd_query::approximate(std::size_t i)
{
  for (std::size_t k = 0; k < 3; ++k) {
    const Rational& q = rows_[i][k];
    double x = 0;
    if (exact_double(q, x)) {
      nearest_[i][k] = x;
      enclosure_[i][k] = CGAL::Interval_nt<false>(x);
      continue;
    }
    // CGAL's conversion is the tightest enclosure in any rounding mode
    // (MPFR); nearest_double's quick path divides, so its mode is set.
    enclosure_[i][k] = CGAL::Interval_nt<false>(CGAL::to_interval(q));
    CGAL::Protect_FPU_rounding<true> to_nearest(CGAL_FE_TONEAREST);
    nearest_[i][k] = nearest_double(q);
  }
}

} // namespace clash4d
