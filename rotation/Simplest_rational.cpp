#include "rotation/Simplest_rational.h"

#include <functional>
#include <stdexcept>

namespace clash4d {

namespace {

// Where a rational lies against the open interval (lo, hi): -1 at or below
// lo, +1 at or above hi, 0 inside. Exact comparisons only, so the answer is
// the numbers', not their isolating intervals'.
using Place = std::function<int(const Rational&)>;

struct Fraction { mpz_class p, q; };   // p / q, q >= 0 (1/0 is infinity)

// Every fraction made here is a + k b for neighbours a, b of the
// Stern-Brocot tree (a.p b.q - a.q b.p = +-1, which a + k b keeps with b),
// so p and q are coprime and q > 0: the rational is written as it is, with
// no gcd.
Rational as_rational(const Fraction& f)
{
  Rational r;   // a new number: written through mpq()
  mpz_set(mpq_numref(r.mpq()), f.p.get_mpz_t());
  mpz_set(mpq_denref(r.mpq()), f.q.get_mpz_t());
  return r;
}

// The largest k >= 1 with place((a + k b)) == side, given that k = 1 has it:
// doubling, then halving, so a run of one direction costs its logarithm.
mpz_class longest_run(const Fraction& a, const Fraction& b, int side, const Place& place)
{
  auto holds = [&](const mpz_class& k) {
    return place(as_rational(Fraction{a.p + k * b.p, a.q + k * b.q})) == side;
  };
  mpz_class good = 1, bad = 2;
  while (holds(bad)) good = bad, bad *= 2;
  while (bad - good > 1) {
    mpz_class mid = (good + bad) / 2;
    (holds(mid) ? good : bad) = mid;
  }
  return good;
}

// The Stern-Brocot descent from 0/1 and 1/0 to the first mediant inside:
// the simplest positive rational there (lo >= 0). Invariant: left at or
// below lo, right at or above hi.
Rational simplest_positive(const Place& place)
{
  Fraction left{0, 1}, right{1, 0};
  for (;;) {
    Fraction mid{left.p + right.p, left.q + right.q};
    int side = place(as_rational(mid));
    if (side == 0) return as_rational(mid);
    if (side < 0) {
      mpz_class k = longest_run(left, right, -1, place);
      left = Fraction{left.p + k * right.p, left.q + k * right.q};
    } else {
      mpz_class k = longest_run(right, left, +1, place);
      right = Fraction{right.p + k * left.p, right.q + k * left.q};
    }
  }
}

} // namespace

Rational simplest_between(const Algebraic& lo, const Algebraic& hi)
{
  if (!(lo < hi)) throw std::logic_error("simplest_between: an empty interval");
  if (compare(lo, Rational(0)) < 0 && compare(hi, Rational(0)) > 0) return Rational(0);
  if (compare(hi, Rational(0)) <= 0) {   // mirrored: the simplest in (-hi, -lo)
    return -simplest_positive([&](const Rational& x) {
      if (compare(hi, -x) <= 0) return -1;
      if (compare(lo, -x) >= 0) return 1;
      return 0;
    });
  }
  return simplest_positive([&](const Rational& x) {
    if (compare(lo, x) >= 0) return -1;
    if (compare(hi, x) <= 0) return 1;
    return 0;
  });
}

} // namespace clash4d
