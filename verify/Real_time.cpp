#include "verify/Real_time.h"
#include <stdexcept>

namespace clash4d::verifier {

Real_time::Real_time(const Rational_poly& poly, const mpq_class& lo, const mpq_class& hi)
  : lo_(lo), hi_(hi), sqfree_(square_free_part(poly))
{
}

void Real_time::refine()
{
  if (exact_) return;
  mpq_class m = (lo_ + hi_) / 2;
  int s = sgn(sqfree_(m));
  if (s == 0) exact_ = true, value_ = m;
  else if (sgn(sqfree_(lo_)) != s) hi_ = m;
  else lo_ = m;
}

Root_check valid_root(const Rational_poly& poly, const mpq_class& lo, const mpq_class& hi)
{
  if (poly(lo) == 0) return Root_check::root_at_lo;
  if (poly(hi) == 0) return Root_check::root_at_hi;
  return count_roots(poly, lo, hi) == 1 ? Root_check::ok : Root_check::not_one_root;
}

// Section 8.1: zero exactly when gcd(p, P) has a root in (lo, hi);
// otherwise halve until p has no root in the interval.
int sign_at(const Rational_poly& p, const Real_time& r0)
{
  if (r0.exact()) return sgn(p(r0.value()));
  if (p.is_zero()) return 0;
  Rational_poly g = gcd(p, r0.poly());
  if (g.degree() > 0 && count_roots(g, r0.lo(), r0.hi()) > 0) return 0;
  Real_time r = r0;
  Sturm_sequence roots(p);
  while (!r.exact() && roots.count(r.lo(), r.hi()) > 0) r.refine();
  return r.exact() ? sgn(p(r.value())) : sgn(p((r.lo() + r.hi()) / 2));
}

bool equal(const Real_time& a, const Real_time& b)
{
  if (a.exact() && b.exact()) return a.value() == b.value();
  if (a.exact() || b.exact()) {
    const Real_time& x = a.exact() ? a : b;
    const Real_time& y = a.exact() ? b : a;
    return y.lo() < x.value() && x.value() < y.hi() && y.poly()(x.value()) == 0;
  }
  mpq_class lo = a.lo() < b.lo() ? b.lo() : a.lo(), hi = a.hi() < b.hi() ? a.hi() : b.hi();
  if (!(lo < hi)) return false;
  Rational_poly g = gcd(a.poly(), b.poly());
  return g.degree() > 0 && count_roots(g, lo, hi) > 0;
}

bool less(const Real_time& a0, const Real_time& b0)
{
  if (equal(a0, b0)) return false;
  Real_time a = a0, b = b0;
  while (true) {   // distinct: the intervals part after finitely many halvings
    if (a.upper() <= b.lower()) return true;
    if (b.upper() <= a.lower()) return false;
    a.refine(), b.refine();
  }
}

mpq_class rational_between(Real_time a, Real_time b)
{
  if (!less(a, b)) throw std::logic_error("no rational between a TIME and one not after it");
  while (!(a.upper() < b.lower())) a.refine(), b.refine();
  return (a.upper() + b.lower()) / 2;
}

namespace {

// Refine r until its interval holds no root of f but possibly r itself.
void isolate_from(const Rational_poly& f, const Sturm_sequence& roots, Real_time& r)
{
  long own = sign_at(f, r) == 0 ? 1 : 0;
  while (!r.exact() && roots.count(r.lo(), r.hi()) > own) r.refine();
}

} // namespace

// Section 8.1: refine the ends until their intervals hold no other root of
// f and are apart, then count between the intervals' inner ends with Sturm,
// plus those inner ends that are roots and lie strictly inside (a, b).
long count_roots(const Rational_poly& f, Real_time a, Real_time b)
{
  if (!less(a, b)) throw std::logic_error("counting roots in an empty interval of TIMEs");   // the loops below need a < b
  Sturm_sequence roots(f);
  isolate_from(f, roots, a), isolate_from(f, roots, b);
  while (!(a.upper() <= b.lower())) a.refine(), b.refine();
  mpq_class x = a.upper(), y = b.lower();
  long n = x < y ? roots.count(x, y) : 0;
  bool x_inside = !a.exact() && !(b.exact() && x == b.value());
  bool y_inside = !b.exact() && !(a.exact() && y == a.value()) && !(x_inside && x == y);
  if (x_inside && f(x) == 0) ++n;
  if (y_inside && f(y) == 0) ++n;
  return n;
}

bool nonnegative_on(const Rational_poly& p, const Real_time& a, const Real_time& b)
{
  if (p.is_zero()) return true;
  Rational_poly g = odd_part(p);   // p = s^2 g: sign(p) = sign(g) off s's roots
  if (g.degree() > 0 && count_roots(g, a, b) > 0) return false;
  return sgn(g(rational_between(a, b))) > 0;   // g has no root in (a, b)
}

bool positive_on(const Rational_poly& p, const Real_time& a, const Real_time& b)
{
  return sign_at(p, a) > 0 && sign_at(p, b) > 0 && count_roots(p, a, b) == 0;
}

bool positive_on_half_open(const Rational_poly& p, const Real_time& a, const Real_time& b)
{
  return sign_at(p, a) > 0 && count_roots(p, a, b) == 0;
}

} // namespace clash4d::verifier
