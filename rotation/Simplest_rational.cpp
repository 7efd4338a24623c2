#include "rotation/Simplest_rational.h"

#include <stdexcept>

namespace clash4d {

namespace {

Rational floor_of(const Rational& q)
{
  mpz_class n(q.numerator().mpz()), d(q.denominator().mpz()), f;
  mpz_fdiv_q(f.get_mpz_t(), n.get_mpz_t(), d.get_mpz_t());
  return Rational(CGAL::Gmpz(f.get_mpz_t()));
}

// The simplest q with lo < q < hi; hi_infinite: no upper end.
Rational simplest(const Rational& lo, const Rational& hi, bool hi_infinite)
{
  Rational f = floor_of(lo), next = f + 1;
  if (hi_infinite || next < hi) return next;
  // lo and hi lie in [f, f + 1]: continue on the reciprocals of what is left.
  Rational a = hi - f, b = lo - f;   // 0 < a <= 1, 0 <= b < a
  bool b_zero = CGAL::sign(b) == CGAL::ZERO;
  Rational inner = simplest(Rational(1) / a, b_zero ? Rational(0) : Rational(1) / b, b_zero);
  return f + Rational(1) / inner;
}

} // namespace

Rational simplest_between(const Rational& lo, const Rational& hi)
{
  if (!(lo < hi)) throw std::logic_error("simplest_between: an empty interval");
  if (lo < 0 && 0 < hi) return Rational(0);
  if (hi <= 0) return -simplest(-hi, -lo, false);
  return simplest(lo, hi, false);
}

Rational simplest_between(const Algebraic& lo, const Algebraic& hi)
{
  // Rational ends of the open interval: the isolating intervals' inner ends
  // once they are apart.
  while (!(lo.upper() < hi.lower())) {
    if (!lo.is_rational()) lo.refine();
    if (!hi.is_rational()) hi.refine();
    if (lo.is_rational() && hi.is_rational()) break;
  }
  return simplest_between(lo.upper(), hi.lower());
}

} // namespace clash4d
