#include "numbers/Algebraic.h"

#include "numbers/Interval_isolation.h"
#include "numbers/Polynomial.h"
#include "numbers/Quadratic_element.h"
#include <CGAL/FPU.h>
#include <cmath>
#include <optional>

#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_poly_factor.h>
#include <acb.h>
#include <arb.h>
#include <arb_fmpz_poly.h>
#include <algorithm>
#include <charconv>
#include <stdexcept>

namespace clash4d {

namespace {

// FLINT's C types with their lifetimes (the library's init/clear pairs).
struct Fmpz_poly {
  fmpz_poly_t p;
  Fmpz_poly() { fmpz_poly_init(p); }
  ~Fmpz_poly() { fmpz_poly_clear(p); }
  Fmpz_poly(const Fmpz_poly&) = delete;
  Fmpz_poly& operator=(const Fmpz_poly&) = delete;
};
struct Fmpq_poly {
  fmpq_poly_t p;
  Fmpq_poly() { fmpq_poly_init(p); }
  ~Fmpq_poly() { fmpq_poly_clear(p); }
  Fmpq_poly(const Fmpq_poly&) = delete;
  Fmpq_poly& operator=(const Fmpq_poly&) = delete;
};
struct Fmpq {
  fmpq_t q;
  Fmpq() { fmpq_init(q); }
  explicit Fmpq(const Rational& x) { fmpq_init(q); fmpq_set_mpq(q, x.mpq()); }
  ~Fmpq() { fmpq_clear(q); }
  Fmpq(const Fmpq&) = delete;
  Fmpq& operator=(const Fmpq&) = delete;
};
struct Arb {
  arb_t x;
  Arb() { arb_init(x); }
  ~Arb() { arb_clear(x); }
  Arb(const Arb&) = delete;
  Arb& operator=(const Arb&) = delete;
};
struct Arf {
  arf_t x;
  Arf() { arf_init(x); }
  ~Arf() { arf_clear(x); }
  Arf(const Arf&) = delete;
  Arf& operator=(const Arf&) = delete;
};

void set_poly(Fmpq_poly& out, const std::vector<Rational>& p)
{
  fmpq_poly_zero(out.p);
  for (std::size_t i = 0; i < p.size(); ++i) fmpq_poly_set_coeff_mpq(out.p, static_cast<slong>(i), p[i].mpq());
}

void set_poly(Fmpq_poly& out, const std::vector<mpz_class>& p)
{
  fmpq_poly_zero(out.p);
  Fmpz_poly z;
  for (std::size_t i = 0; i < p.size(); ++i) fmpz_poly_set_coeff_mpz(z.p, static_cast<slong>(i), p[i].get_mpz_t());
  fmpq_poly_set_fmpz_poly(out.p, z.p);
}

// A polynomial's coefficients as GMP integers, made primitive with a
// positive leading coefficient (the spec's normal form of a minimal
// polynomial).
std::vector<mpz_class> normal_coefficients(const fmpz_poly_t g)
{
  Fmpz_poly prim;
  fmpz_poly_primitive_part(prim.p, g);
  slong len = fmpz_poly_length(prim.p);
  std::vector<mpz_class> out(static_cast<std::size_t>(len));
  for (slong i = 0; i < len; ++i) fmpz_poly_get_coeff_mpz(out[static_cast<std::size_t>(i)].get_mpz_t(), prim.p, i);
  if (len > 0 && out.back() < 0)
    for (auto& c : out) c = -c;
  return out;
}

Rational from_fmpq(const fmpq_t q)
{
  mpq_t m;
  mpq_init(m);
  fmpq_get_mpq(m, q);
  Rational r(m);
  mpq_clear(m);
  return r;
}

Rational from_arf(const arf_t x)
{
  fmpz_t man, exp;
  fmpz_init(man);
  fmpz_init(exp);
  arf_get_fmpz_2exp(man, exp, x);
  mpz_class m;
  fmpz_get_mpz(m.get_mpz_t(), man);
  slong e = fmpz_get_si(exp);
  fmpz_clear(man);
  fmpz_clear(exp);
  Rational r(m.get_mpz_t());
  return e >= 0 ? r * power_of_two(static_cast<int>(e)) : r / power_of_two(static_cast<int>(-e));
}

// A dyadic rational (isolating intervals keep dyadic ends) as an arf.
void to_arf(arf_t out, const Rational& q)
{
  mpz_srcptr den = mpq_denref(q.mpq());
  mp_bitcnt_t k = mpz_scan1(den, 0);
  if (mpz_sizeinbase(den, 2) != k + 1) throw std::logic_error("Algebraic: an isolating interval's end is not dyadic");
  fmpz_t man, exp;
  fmpz_init(man);
  fmpz_init(exp);
  fmpz_set_mpz(man, mpq_numref(q.mpq()));
  fmpz_set_si(exp, -static_cast<slong>(k));
  arf_set_fmpz_2exp(out, man, exp);
  fmpz_clear(man);
  fmpz_clear(exp);
}

int sign_at_rational(const fmpq_poly_t g, const Rational& q)
{
  Fmpq x(q), v;
  fmpq_poly_evaluate_fmpq(v.q, g, x.q);
  return fmpq_sgn(v.q);
}

// A power of two above |root| for every root of g (Cauchy's bound
// 1 + max |g_i / g_d|, rounded up).
Rational root_bound(const fmpz_poly_t g)
{
  slong d = fmpz_poly_degree(g);
  mpz_class lead, c, top = 0;
  fmpz_get_mpz(lead.get_mpz_t(), g->coeffs + d);
  for (slong i = 0; i < d; ++i) {
    fmpz_get_mpz(c.get_mpz_t(), g->coeffs + i);
    c = abs(c);
    if (c > top) top = c;
  }
  mpz_class q = top / abs(lead) + 2;
  return power_of_two(static_cast<int>(mpz_sizeinbase(q.get_mpz_t(), 2)));
}

// The real roots of an irreducible g of degree >= 2 in [lo, hi], each in an
// interval with dyadic ends that holds it and no other root of g.
struct Isolated {
  std::vector<std::pair<Rational, Rational>> intervals;   // ascending
};

// Every real root, by Arb: it isolates every complex root in disjoint
// balls, the real ones first with an imaginary part exactly zero; a real
// ball's segment [m - r, m + r] holds that root and no other.
Isolated isolate_real_roots(const fmpz_poly_t g)
{
  slong deg = fmpz_poly_degree(g);
  acb_ptr roots = _acb_vec_init(deg);
  arb_fmpz_poly_complex_roots(roots, g, 0, 24);
  Isolated out;
  Arf lo, hi, rad;
  for (slong j = 0; j < deg; ++j) {
    if (!arb_is_zero(acb_imagref(roots + j))) continue;
    arb_srcptr re = acb_realref(roots + j);
    arf_set_mag(rad.x, arb_radref(re));
    arf_sub(lo.x, arb_midref(re), rad.x, ARF_PREC_EXACT, ARF_RND_DOWN);
    arf_add(hi.x, arb_midref(re), rad.x, ARF_PREC_EXACT, ARF_RND_UP);
    out.intervals.emplace_back(from_arf(lo.x), from_arf(hi.x));
  }
  _acb_vec_clear(roots, deg);
  return out;
}

// g's real roots in [a, b] certified in doubles (numbers/Interval_isolation.h),
// searched beyond [a, b] by half its width each side, so that a root at or
// near an end is inside (the callers keep those in [a, b]); false when
// intervals cannot certify them (a multiple root, roots closer than doubles
// tell, a degree past the capacity). narrow: each enclosure narrowed to a
// few ulps (Interval_isolation::isolate).
bool roots_in_doubles(const fmpz_poly_t g, const Rational& a, const Rational& b, std::vector<Isolated_root>& found,
                      bool narrow)
{
  constexpr int capacity = 7;
  slong len = fmpz_poly_length(g);
  if (len > capacity) return false;
  CGAL::Protect_FPU_rounding<true> upward;
  Polynomial<CGAL::Interval_nt<false>, capacity> p;
  for (slong i = len - 1; i >= 0; --i) {
    mpz_class c;
    fmpz_get_mpz(c.get_mpz_t(), g->coeffs + i);
    p = p * Polynomial<CGAL::Interval_nt<false>, capacity>(CGAL::Interval_nt<false>(0), CGAL::Interval_nt<false>(1));
    p = p + Polynomial<CGAL::Interval_nt<false>, capacity>(CGAL::Interval_nt<false>(CGAL::to_interval(Rational(c.get_mpz_t()))));
  }
  double lo = CGAL::to_interval(a).first, hi = CGAL::to_interval(b).second, half = (hi - lo) / 2;
  lo -= half, hi += half;
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi)) return false;
  return Interval_isolation<capacity>::isolate(p, lo, hi, found, narrow);
}

// The roots of an irreducible g in [a, b] first in doubles (its roots are
// simple and irrational, so intervals certify them unless they are closer
// than doubles tell): no Arb call where that suffices. Nothing when it
// does not.
std::optional<Isolated> isolate_in_doubles(const fmpz_poly_t g, const Rational& a, const Rational& b)
{
  std::vector<Isolated_root> found;
  if (!roots_in_doubles(g, a, b, found, true)) return std::nullopt;
  Isolated out;
  for (const Isolated_root& r : found) {
    if (r.at.inf() == r.at.sup()) return std::nullopt;   // a rational root: not of an irreducible g
    out.intervals.emplace_back(Rational(r.at.inf()), Rational(r.at.sup()));
  }
  return out;
}

// The rational root of g in the enclosure r (holding one simple root),
// sought as the simplest rational there, cutting r at each one tried that
// is not the root (its exact sign tells which side the root is on), up to
// 3 times; nothing when none is. A small fraction is found in a few cuts
// (1/4 in [0.2, 0.9]: 1/2, 1/3, 1/4); each cut costs an irrational root,
// which is factored after them, a microsecond (8 cuts made the turning
// box pair's irrational hit 5% slower).
std::optional<Rational> simple_root_in(const fmpq_poly_t g, const Isolated_root& r)
{
  Rational lo(r.at.inf()), hi(r.at.sup());
  if (lo == hi) return lo;
  for (int cut = 0; cut < 3; ++cut) {
    Rational q = simplest_between(lo, hi);
    int s = sign_at_rational(g, q);
    if (s == 0) return q;
    (s == r.lower_sign ? lo : hi) = q;
  }
  return std::nullopt;
}

// f's real roots in [a, b] when each is rational and found without
// factoring f: its roots certified in doubles, each a double where f is
// surely 0 in intervals, or a simple fraction where f is exactly 0
// (simple_root_in). Nothing (factor f) when isolation fails or a root in
// or near [a, b] is not found so. Critical times are often simple
// fractions (a contact at t = 1/4): factoring cost a turning box pair a
// tenth of its query. The enclosures are not narrowed to a few ulps first:
// that cost the pairs whose critical time is irrational (and is then
// factored anyway) more than it saved.
std::optional<std::vector<Algebraic>> rational_roots(const fmpz_poly_t f, const Rational& a, const Rational& b)
{
  std::vector<Isolated_root> found;
  if (!roots_in_doubles(f, a, b, found, false)) return std::nullopt;
  Fmpq_poly g;
  fmpq_poly_set_fmpz_poly(g.p, f);
  std::vector<Algebraic> out;
  for (const Isolated_root& r : found) {
    if (Rational(r.at.sup()) < a || b < Rational(r.at.inf())) continue;
    std::optional<Rational> q = simple_root_in(g.p, r);
    if (!q) return std::nullopt;
    if (!(*q < a) && !(b < *q)) out.emplace_back(*q);
  }
  return out;
}

// g's sign over [lo, hi] when an enclosure in doubles is sure of it and
// not zero (the filter before the exact test), else 2.
CGAL::Interval_nt<false> enclosure_of(const Rational& x) { return CGAL::Interval_nt<false>(CGAL::to_interval(x)); }
CGAL::Interval_nt<false> enclosure_of(const mpz_class& x) { return CGAL::Interval_nt<false>(enclosing_interval(x)); }

template <class Coefficient>
int sign_in_doubles(const std::vector<Coefficient>& g, const Rational& lo, const Rational& hi)
{
  using I = CGAL::Interval_nt<false>;
  CGAL::Protect_FPU_rounding<true> upward;
  I x(CGAL::to_interval(lo).first, CGAL::to_interval(hi).second), v(0);
  for (std::size_t i = g.size(); i-- > 0;) v = v * x + enclosure_of(g[i]);
  if (v.inf() > 0) return 1;
  if (v.sup() < 0) return -1;
  return 2;
}

// N(r) / D(r)'s enclosure over r's interval, as dyadic rationals.
std::pair<Rational, Rational> quotient_enclosure(const Algebraic& r, const fmpz_poly_struct* n,
                                                 const fmpz_poly_struct* d, slong prec)
{
  Arb x, nv, dv, q;
  Arf lo, hi;
  to_arf(lo.x, r.lower());
  to_arf(hi.x, r.upper());
  arb_set_interval_arf(x.x, lo.x, hi.x, prec);
  arb_fmpz_poly_evaluate_arb(nv.x, n, x.x, prec);
  arb_fmpz_poly_evaluate_arb(dv.x, d, x.x, prec);
  arb_div(q.x, nv.x, dv.x, prec);
  Arf qlo, qhi;
  arb_get_lbound_arf(qlo.x, q.x, prec);
  arb_get_ubound_arf(qhi.x, q.x, prec);
  if (!arf_is_finite(qlo.x) || !arf_is_finite(qhi.x)) return {Rational(1), Rational(-1)};   // D's enclosure holds 0
  return {from_arf(qlo.x), from_arf(qhi.x)};
}

// Whether g surely has no root in [lo, hi]: its enclosure there excludes 0.
bool surely_no_root(const fmpz_poly_struct* g, const Rational& lo, const Rational& hi)
{
  Arb x, y;
  Arf a, b;
  to_arf(a.x, lo);
  to_arf(b.x, hi);
  arb_set_interval_arf(x.x, a.x, b.x, 128);
  arb_fmpz_poly_evaluate_arb(y.x, g, x.x, 128);
  return !arb_contains_zero(y.x);
}

// Whether g has exactly one root in [lo, hi] and none at the ends: its
// signs at the ends differ (exactly) and g' surely has no zero between.
bool single_root(const fmpz_poly_struct* g, const Rational& lo, const Rational& hi)
{
  Fmpq_poly q;
  fmpq_poly_set_fmpz_poly(q.p, g);
  if (sign_at_rational(q.p, lo) * sign_at_rational(q.p, hi) >= 0) return false;
  Fmpz_poly dg;
  fmpz_poly_derivative(dg.p, g);
  Arb x, y;
  Arf a, b;
  to_arf(a.x, lo);
  to_arf(b.x, hi);
  arb_set_interval_arf(x.x, a.x, b.x, 128);
  arb_fmpz_poly_evaluate_arb(y.x, dg.p, x.x, 128);
  return !arb_contains_zero(y.x);
}

// a b mod m.
void mul_mod(fmpq_poly_t out, const fmpq_poly_t a, const fmpq_poly_t b, const fmpq_poly_t m)
{
  fmpq_poly_mul(out, a, b);
  fmpq_poly_rem(out, out, m);
}

// The root -c0 / c1 of a linear factor.
Rational linear_root(const fmpz_poly_struct* g)
{
  mpz_class c0, c1;
  fmpz_get_mpz(c0.get_mpz_t(), g->coeffs);
  fmpz_get_mpz(c1.get_mpz_t(), g->coeffs + 1);
  return quotient_of_integers(-c0, c1);
}

void primitive_integer_poly(Fmpz_poly& out, const std::vector<mpz_class>& p)
{
  fmpz_poly_zero(out.p);
  for (std::size_t i = 0; i < p.size(); ++i) fmpz_poly_set_coeff_mpz(out.p, static_cast<slong>(i), p[i].get_mpz_t());
  if (fmpz_poly_is_zero(out.p)) throw std::logic_error("Algebraic: the roots of the zero polynomial");
  fmpz_poly_primitive_part(out.p, out.p);
}

void primitive_integer_poly(Fmpz_poly& out, const std::vector<Rational>& p)
{
  Fmpq_poly q;
  set_poly(q, p);
  if (fmpq_poly_is_zero(q.p)) throw std::logic_error("Algebraic: the roots of the zero polynomial");
  fmpq_poly_get_numerator(out.p, q.p);
  fmpz_poly_primitive_part(out.p, out.p);
}

} // namespace

// The work on FLINT's types, with Algebraic's representation at hand.
struct Algebraic_access {
  static std::vector<Algebraic> real_roots(const fmpz_poly_struct* f, const Rational& a, const Rational& b);
  static std::vector<Algebraic> quadratic_roots(const fmpz_poly_struct* f, const Rational& a, const Rational& b);
  static void irreducible_roots(const fmpz_poly_struct* g, const Rational& a, const Rational& b,
                                std::vector<Algebraic>& out);
  static Algebraic root_between(const fmpz_poly_struct* f, const Rational& lo, const Rational& hi);
  static CGAL::Sign sign_of(const Algebraic& x, const fmpq_poly_struct* g);
  // The root of one of R's irreducible factors that N(r) / D(r) is.
  static Algebraic root_of_factor(const fmpz_poly_struct* R, const Algebraic& r, const fmpz_poly_struct* n,
                                  const fmpz_poly_struct* d);
};

Algebraic Algebraic::irrational(std::vector<mpz_class> poly, const Rational& lo, const Rational& hi)
{
  auto rep = std::make_shared<Rep>();
  rep->poly = std::move(poly);
  Algebraic x(std::move(rep), lo, hi);
  x.narrow_in_doubles();
  return x;
}

int Algebraic::poly_sign(const Rational& q) const
{
  // d^k m(n / d) in integers (d > 0): Horner with the powers of d.
  mpz_srcptr n = mpq_numref(q.mpq()), d = mpq_denref(q.mpq());
  const std::vector<mpz_class>& m = rep_->poly;
  mpz_class v = 0, dk = 1;
  for (std::size_t i = m.size(); i-- > 0;) {
    v = v * mpz_class(n) + m[i] * dk;
    dk *= mpz_class(d);
  }
  return sgn(v);
}

// The interval narrowed to a few ulps by bisection in doubles, while the
// polynomial's sign at the middle is sure (intervals, rounding upward): a
// sign or comparison then seldom needs the exact bisection of refine().
void Algebraic::narrow_in_doubles() const
{
  using I = CGAL::Interval_nt<false>;
  constexpr int capacity = 7;
  const std::vector<mpz_class>& m = rep_->poly;
  if (m.size() > capacity) return;
  int lower = poly_sign(lo_);
  double a = CGAL::to_interval(lo_).second, b = CGAL::to_interval(hi_).first;
  if (!(a < b) || !std::isfinite(a) || !std::isfinite(b)) return;
  CGAL::Protect_FPU_rounding<true> upward;
  Polynomial<I, capacity> p;
  for (std::size_t i = m.size(); i-- > 0;) p = p * Polynomial<I, capacity>(I(0), I(1)) + Polynomial<I, capacity>(enclosure_of(m[i]));
  auto sign_at = [&](double t) { return Interval_isolation<capacity>::sure_sign(p.at(I(t))); };
  if (sign_at(a) != lower || sign_at(b) != -lower) return;   // the root may lie between lo and a, or b and hi
  for (int i = 0; i < 64; ++i) {
    double mid = a + (b - a) / 2;
    if (!(a < mid && mid < b)) break;
    int s = sign_at(mid);
    if (s != 1 && s != -1) break;
    (s == lower ? a : b) = mid;
  }
  lo_ = Rational(a);
  hi_ = Rational(b);
}

void Algebraic::refine() const
{
  if (is_rational()) return;
  Rational mid = (lo_ + hi_) / 2;
  // The root is simple: the polynomial's sign at every lower end is the
  // same, and differs from its sign at every upper end.
  if (poly_sign(mid) == poly_sign(lo_)) lo_ = mid;
  else hi_ = mid;
}

void Algebraic::exclude(const Rational& q) const
{
  while (lo_ < q && q < hi_) refine();
}

std::vector<Algebraic> Algebraic::real_roots(const std::vector<Rational>& p, const Rational& a, const Rational& b)
{
  Fmpz_poly f;
  primitive_integer_poly(f, p);
  return Algebraic_access::real_roots(f.p, a, b);
}

std::vector<Algebraic> Algebraic::real_roots(const std::vector<mpz_class>& p, const Rational& a, const Rational& b)
{
  Fmpz_poly f;
  primitive_integer_poly(f, p);
  return Algebraic_access::real_roots(f.p, a, b);
}

std::vector<Algebraic> Algebraic::real_roots_rational_first(const std::vector<mpz_class>& p, const Rational& a,
                                                            const Rational& b)
{
  Fmpz_poly f;
  primitive_integer_poly(f, p);
  if (fmpz_poly_degree(f.p) == 2) return Algebraic_access::quadratic_roots(f.p, a, b);
  if (auto rational = rational_roots(f.p, a, b)) return *rational;
  return Algebraic_access::real_roots(f.p, a, b);
}

// f = c2 t^2 + c1 t + c0 with D = c1^2 - 4 c0 c2: no real root when D < 0;
// rational roots (-c1 +- sqrt D) / (2 c2) when D is a square (an exact
// integer root); otherwise f has no rational root, so it is irreducible
// over Q and its roots are isolated as any irreducible factor's. A
// turning pair's critical times are mostly such roots; no factoring, and
// no rational tried first.
std::vector<Algebraic> Algebraic_access::quadratic_roots(const fmpz_poly_struct* f, const Rational& a,
                                                         const Rational& b)
{
  mpz_class c[3];
  for (int i = 0; i < 3; ++i) fmpz_get_mpz(c[i].get_mpz_t(), f->coeffs + i);
  mpz_class D = c[1] * c[1] - 4 * c[0] * c[2];
  std::vector<Algebraic> out;
  if (sgn(D) < 0) return out;
  if (!mpz_perfect_square_p(D.get_mpz_t())) {
    irreducible_roots(f, a, b, out);
    return out;
  }
  mpz_class root;
  mpz_sqrt(root.get_mpz_t(), D.get_mpz_t());
  for (int s : {-1, 1}) {
    Rational x = quotient_of_integers(-c[1] + s * root, 2 * c[2]);
    if (!(x < a) && !(b < x) && (out.empty() || out.back().rational() != x)) out.emplace_back(x);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The roots in [a, b] of g, irreducible of degree 2 or more, ascending:
// isolated in doubles where that certifies them, else by Arb.
void Algebraic_access::irreducible_roots(const fmpz_poly_struct* g, const Rational& a, const Rational& b,
                                         std::vector<Algebraic>& out)
{
  std::vector<mpz_class> poly = normal_coefficients(g);
  auto isolated = isolate_in_doubles(g, a, b);
  if (!isolated) isolated = isolate_real_roots(g);
  for (const auto& [lo, hi] : isolated->intervals) {
    Algebraic x = Algebraic::irrational(poly, lo, hi);
    if (compare(x, a) >= 0 && compare(x, b) <= 0) out.push_back(std::move(x));
  }
}

std::vector<Algebraic> Algebraic_access::real_roots(const fmpz_poly_struct* f, const Rational& a, const Rational& b)
{
  fmpz_poly_factor_t fac;
  fmpz_poly_factor_init(fac);
  fmpz_poly_factor(fac, f);
  std::vector<Algebraic> out;
  for (slong i = 0; i < fac->num; ++i) {
    const fmpz_poly_struct* g = fac->p + i;
    slong deg = fmpz_poly_degree(g);
    if (deg == 1) {
      Rational root = linear_root(g);
      if (!(root < a) && !(b < root)) out.emplace_back(root);
      continue;
    }
    irreducible_roots(g, a, b, out);
  }
  fmpz_poly_factor_clear(fac);
  std::sort(out.begin(), out.end());
  return out;
}

Algebraic Algebraic::root_between(const std::vector<Rational>& p, const Rational& lo, const Rational& hi)
{
  Fmpz_poly f;
  primitive_integer_poly(f, p);
  return Algebraic_access::root_between(f.p, lo, hi);
}

Algebraic Algebraic::root_between(const std::vector<mpz_class>& p, const Rational& lo, const Rational& hi)
{
  Fmpz_poly f;
  primitive_integer_poly(f, p);
  return Algebraic_access::root_between(f.p, lo, hi);
}

Algebraic Algebraic_access::root_between(const fmpz_poly_struct* f, const Rational& lo, const Rational& hi)
{
  fmpz_poly_factor_t fac;
  fmpz_poly_factor_init(fac);
  fmpz_poly_factor(fac, f);
  // p has one simple root in (lo, hi) and none at the ends: exactly one
  // factor changes sign there, and it holds that root.
  for (slong i = 0; i < fac->num; ++i) {
    Fmpq_poly g;
    fmpq_poly_set_fmpz_poly(g.p, fac->p + i);
    if (sign_at_rational(g.p, lo) * sign_at_rational(g.p, hi) >= 0) continue;
    Algebraic x;
    if (fmpz_poly_degree(fac->p + i) == 1) {
      x = Algebraic(linear_root(fac->p + i));
    } else {
      x = Algebraic::irrational(normal_coefficients(fac->p + i), lo, hi);
    }
    fmpz_poly_factor_clear(fac);
    return x;
  }
  fmpz_poly_factor_clear(fac);
  throw std::logic_error("Algebraic::root_between: no sign change in the interval");
}

bool Algebraic::is_root_of(const std::vector<mpz_class>& p) const { return root_divided_out(p).has_value(); }

std::optional<std::vector<mpz_class>> Algebraic::root_divided_out(const std::vector<mpz_class>& p) const
{
  if (sign_in_doubles(p, lower(), upper()) != 2) return std::nullopt;
  std::size_t length = p.size();
  while (length > 0 && p[length - 1] == 0) --length;
  std::vector<mpz_class> rest = without_root(p);
  if (rest.size() == length) return std::nullopt;   // no power divides: not a root
  return rest;
}

std::vector<mpz_class> Algebraic::without_root(const std::vector<mpz_class>& p) const
{
  Fmpz_poly f, m, q;
  for (std::size_t i = 0; i < p.size(); ++i) fmpz_poly_set_coeff_mpz(f.p, static_cast<slong>(i), p[i].get_mpz_t());
  if (fmpz_poly_is_zero(f.p)) throw std::logic_error("Algebraic: a root divided out of the zero polynomial");
  if (is_rational()) {   // b t - a for a / b in lowest terms
    fmpz_poly_set_coeff_mpz(m.p, 1, mpq_denref(value_.mpq()));
    mpz_class a(mpq_numref(value_.mpq()));
    a = -a;
    fmpz_poly_set_coeff_mpz(m.p, 0, a.get_mpz_t());
  } else {
    for (std::size_t i = 0; i < rep_->poly.size(); ++i)
      fmpz_poly_set_coeff_mpz(m.p, static_cast<slong>(i), rep_->poly[i].get_mpz_t());
  }
  while (fmpz_poly_length(f.p) >= fmpz_poly_length(m.p) && fmpz_poly_divides(q.p, f.p, m.p)) fmpz_poly_swap(f.p, q.p);
  std::vector<mpz_class> out(static_cast<std::size_t>(fmpz_poly_length(f.p)));
  for (std::size_t i = 0; i < out.size(); ++i) fmpz_poly_get_coeff_mpz(out[i].get_mpz_t(), f.p, static_cast<slong>(i));
  return out;
}

CGAL::Sign Algebraic::sign_of(const std::vector<Rational>& g) const
{
  if (!is_rational())
    if (int s = sign_in_doubles(g, lo_, hi_); s != 2) return CGAL::Sign(s);
  Fmpq_poly G;
  set_poly(G, g);
  return Algebraic_access::sign_of(*this, G.p);
}

CGAL::Sign Algebraic::sign_of(const std::vector<mpz_class>& g) const
{
  if (!is_rational())
    if (int s = sign_in_doubles(g, lo_, hi_); s != 2) return CGAL::Sign(s);
  Fmpq_poly G;
  set_poly(G, g);
  return Algebraic_access::sign_of(*this, G.p);
}

CGAL::Sign Algebraic_access::sign_of(const Algebraic& x, const fmpq_poly_struct* g)
{
  const Algebraic::Rep* rep_ = x.rep_.get();
  if (x.is_rational()) return CGAL::Sign(sign_at_rational(g, x.value_));
  // g(r) = 0 exactly when the minimal polynomial divides g.
  Fmpq_poly m, rem;
  set_poly(m, rep_->poly);
  fmpq_poly_rem(rem.p, g, m.p);
  if (fmpq_poly_is_zero(rem.p)) return CGAL::ZERO;
  // Otherwise g(r) != 0: an enclosure of g over the interval excludes zero
  // once the interval is narrow enough.
  Fmpz_poly num;
  fmpq_poly_get_numerator(num.p, rem.p);   // the same sign at r (a positive denominator; r a root of m)
  Arb at, y;
  Arf lo, hi;
  for (slong prec = 64;; prec += 32) {
    to_arf(lo.x, x.lo_);
    to_arf(hi.x, x.hi_);
    arb_set_interval_arf(at.x, lo.x, hi.x, prec);
    arb_fmpz_poly_evaluate_arb(y.x, num.p, at.x, prec);
    if (arb_is_positive(y.x)) return CGAL::POSITIVE;
    if (arb_is_negative(y.x)) return CGAL::NEGATIVE;
    for (int i = 0; i < 8; ++i) x.refine();
  }
}

Algebraic Algebraic_access::root_of_factor(const fmpz_poly_struct* R, const Algebraic& r, const fmpz_poly_struct* n,
                                           const fmpz_poly_struct* d)
{
  fmpz_poly_factor_t fac;
  fmpz_poly_factor_init(fac);
  fmpz_poly_factor(fac, R);
  Algebraic x = r;   // refined on a copy
  // Each round narrows r's interval 256-fold, alpha's enclosure with it,
  // until one factor's root is alone there; past the cap (far beyond any
  // separation of roots of these degrees) something is wrong.
  for (int round = 0;; ++round) {
    if (round == 200) throw std::logic_error("Algebraic::quotient_at: no factor isolates the quotient");
    auto [lo, hi] = quotient_enclosure(x, n, d, 128 + 8 * round);
    // alpha lies in [lo, hi] and is a root of one factor: when exactly one
    // factor may have a root there, that is its minimal polynomial, and its
    // root there is alpha once certified alone.
    const fmpz_poly_struct* hit = nullptr;
    int hits = 0;
    for (slong i = 0; lo <= hi && i < fac->num; ++i) {
      const fmpz_poly_struct* g = fac->p + i;
      bool maybe = fmpz_poly_degree(g) == 1 ? lo <= linear_root(g) && linear_root(g) <= hi : !surely_no_root(g, lo, hi);
      if (maybe) ++hits, hit = g;
    }
    if (hits == 1 && (fmpz_poly_degree(hit) == 1 || single_root(hit, lo, hi))) {
      Algebraic out = fmpz_poly_degree(hit) == 1 ? Algebraic(linear_root(hit))
                                                 : Algebraic::irrational(normal_coefficients(hit), lo, hi);
      fmpz_poly_factor_clear(fac);
      return out;
    }
    for (int i = 0; i < 8; ++i) x.refine();
  }
}

std::vector<Rational> Algebraic::field_element(const Algebraic& r, const std::vector<Rational>& num,
                                               const std::vector<Rational>& den)
{
  Fmpq_poly N, D;
  set_poly(N, num);
  set_poly(D, den);
  if (r.is_rational()) {
    Fmpq x(r.value_), nv, dv;
    fmpq_poly_evaluate_fmpq(nv.q, N.p, x.q);
    fmpq_poly_evaluate_fmpq(dv.q, D.p, x.q);
    if (fmpq_is_zero(dv.q)) throw std::logic_error("Algebraic::field_element: a zero denominator");
    fmpq_div(nv.q, nv.q, dv.q);
    return {from_fmpq(nv.q)};
  }
  Fmpq_poly m, alpha, g, s, t;
  set_poly(m, r.rep_->poly);
  fmpq_poly_rem(N.p, N.p, m.p);
  fmpq_poly_rem(D.p, D.p, m.p);
  if (fmpq_poly_is_zero(D.p)) throw std::logic_error("Algebraic::field_element: a zero denominator");
  // 1 = s D + t m (m irreducible, D not a multiple): 1 / D(r) = s(r).
  fmpq_poly_xgcd(g.p, s.p, t.p, D.p, m.p);
  mul_mod(alpha.p, N.p, s.p, m.p);
  std::vector<Rational> out(static_cast<std::size_t>(std::max<slong>(fmpq_poly_length(alpha.p), 1)));
  for (std::size_t i = 0; i < out.size(); ++i) {
    Fmpq c;
    fmpq_poly_get_coeff_fmpq(c.q, alpha.p, static_cast<slong>(i));
    out[i] = from_fmpq(c.q);
  }
  return out;
}

// alpha = N(r) / D(r) for r irrational. Its conjugates are N(r_i) / D(r_i)
// over m's roots r_i, so R(X) = Res_t(m(t), D(t) X - N(t)), a polynomial of
// degree d = deg m in Z[X] (D(r_i) != 0: m is irreducible and does not
// divide D), vanishes at alpha, and alpha's minimal polynomial is one of
// R's irreducible factors. R is interpolated from its values at
// X = 0 .. d (one integer resultant each: FLINT's fmpz_poly_resultant, no
// rational arithmetic), factored (fmpz_poly_factor), and the factor and
// root are the one alpha's enclosure (Arb, over r's interval) meets alone,
// certified: a sign change across the enclosure and a derivative whose
// enclosure excludes zero. A quadratic r takes no resultant: alpha is
// read off Q(r) (Quadratic_element, linear_image).
Algebraic Algebraic::quotient_at(const Algebraic& r, const std::vector<Rational>& num, const std::vector<Rational>& den)
{
  if (r.is_rational()) return Algebraic(field_element(r, num, den)[0]);
  if (r.rep_->poly.size() == 3) {
    Quadratic_element field(r);
    return (field.at(num) / field.at(den)).value();
  }
  // num and den over one common denominator: integers, the same quotient.
  std::vector<Rational> both = num;
  both.insert(both.end(), den.begin(), den.end());
  Fmpq_poly joint;
  set_poly(joint, both);
  mpz_class l;
  fmpz_get_mpz(l.get_mpz_t(), fmpq_poly_denref(joint.p));
  auto scaled = [&](const std::vector<Rational>& p) {
    std::vector<mpz_class> out;
    for (const Rational& c : p) out.push_back(mpz_class(Rational(c * Rational(l.get_mpz_t())).numerator().mpz()));
    return out;
  };
  return quotient_at(r, scaled(num), scaled(den));
}

// alpha = a + b r, b != 0, r quadratic with minimal polynomial m: alpha
// has the minimal polynomial b^2 m((X - a) / b), of degree 2 and
// irreducible as m is, and the open interval a + b (lo, hi) of r's
// isolating interval holds alpha and not its conjugate a + b r' (X = a + b
// t is one to one and r' is outside (lo, hi)), with rational ends that
// are no roots. No resultant is made or factored: a contact coordinate at
// a quadratic t* is one such (quotient_at).
Algebraic Algebraic::linear_image(const Algebraic& r, const Rational& a, const Rational& b)
{
  if (CGAL::is_zero(b)) return Algebraic(a);
  if (r.is_rational() || r.rep_->poly.size() != 3) throw std::logic_error("Algebraic::linear_image: r is not a quadratic irrational");
  const std::vector<mpz_class>& m = r.rep_->poly;
  Rational c0(m[0].get_mpz_t()), c1(m[1].get_mpz_t()), c2(m[2].get_mpz_t());
  // b^2 m((X - a) / b) = c2 (X - a)^2 + c1 b (X - a) + c0 b^2.
  std::vector<Rational> p = {c2 * a * a - c1 * b * a + c0 * b * b, c1 * b - Rational(2) * a * c2, c2};
  Fmpz_poly P;
  primitive_integer_poly(P, p);
  Rational lo = a + b * r.lo_, hi = a + b * r.hi_;
  if (CGAL::sign(b) == CGAL::NEGATIVE) std::swap(lo, hi);
  return Algebraic::irrational(normal_coefficients(P.p), lo, hi);
}

Algebraic Algebraic::quotient_at(const Algebraic& r, const std::vector<mpz_class>& num, const std::vector<mpz_class>& den)
{
  // A rational r: one number. A quadratic one: a + b r, made in Q(r)
  // (Quadratic_element). Other degrees take the resultant below: for the
  // CCD queries' cubic times the field element would be a cost first.
  if (r.is_rational()) {
    std::vector<Rational> n(num.size()), d(den.size());
    for (std::size_t i = 0; i < num.size(); ++i) n[i] = Rational(num[i].get_mpz_t());
    for (std::size_t i = 0; i < den.size(); ++i) d[i] = Rational(den[i].get_mpz_t());
    return Algebraic(field_element(r, n, d)[0]);
  }
  if (r.rep_->poly.size() == 3) {
    Quadratic_element field(r);
    return (field.at(num) / field.at(den)).value();
  }
  Fmpz_poly n, d_, m;
  for (std::size_t i = 0; i < num.size(); ++i) fmpz_poly_set_coeff_mpz(n.p, static_cast<slong>(i), num[i].get_mpz_t());
  for (std::size_t i = 0; i < den.size(); ++i) fmpz_poly_set_coeff_mpz(d_.p, static_cast<slong>(i), den[i].get_mpz_t());
  for (std::size_t i = 0; i < r.rep_->poly.size(); ++i)
    fmpz_poly_set_coeff_mpz(m.p, static_cast<slong>(i), r.rep_->poly[i].get_mpz_t());
  // The points X avoid the one where D X - N drops below its degree in t
  // (the resultant's value there is not R's).
  slong degree = fmpz_poly_degree(m.p), k = std::max(fmpz_poly_degree(n.p), fmpz_poly_degree(d_.p));
  std::vector<fmpz> xs(static_cast<std::size_t>(degree + 1)), ys(xs.size());
  slong x = 0;
  for (slong j = 0; j <= degree; ++j, ++x) {
    Fmpz_poly g;
    for (;; ++x) {
      fmpz_poly_scalar_mul_si(g.p, d_.p, x);
      fmpz_poly_sub(g.p, g.p, n.p);
      if (fmpz_poly_degree(g.p) == k) break;
    }
    fmpz_init_set_si(&xs[j], x);
    fmpz_init(&ys[j]);
    fmpz_poly_resultant(&ys[j], m.p, g.p);
  }
  Fmpz_poly resultant;
  fmpz_poly_interpolate_fmpz_vec(resultant.p, xs.data(), ys.data(), degree + 1);
  for (slong j = 0; j <= degree; ++j) fmpz_clear(&xs[j]), fmpz_clear(&ys[j]);
  return Algebraic_access::root_of_factor(resultant.p, r, n.p, d_.p);
}

int compare(const Algebraic& a, const Rational& q)
{
  if (a.is_rational()) return CGAL::compare(a.value_, q);
  if (!(a.lo_ < q)) return 1;
  if (!(q < a.hi_)) return -1;
  // q inside the interval, and not the root (a rational): the root lies
  // on the side of q where the polynomial changes sign.
  return a.poly_sign(q) == a.poly_sign(a.lo_) ? 1 : -1;
}

int compare(const Algebraic& a, const Algebraic& b)
{
  if (b.is_rational()) return compare(a, b.value_);
  if (a.is_rational()) return -compare(b, a.value_);
  if (a.rep_->poly == b.rep_->poly) {
    // One minimal polynomial: its roots are simple, so the intersection of
    // the two intervals holds a root (then both numbers are it) exactly
    // when the polynomial changes sign across it.
    Rational lo = std::max(a.lo_, b.lo_), hi = std::min(a.hi_, b.hi_);
    if (lo < hi && a.poly_sign(lo) != a.poly_sign(hi)) return 0;
    if (lo < hi) {   // no root in [lo, hi]: each number lies outside it
      a.exclude(lo), a.exclude(hi), b.exclude(lo), b.exclude(hi);
    }
  }
  // Distinct numbers: refined apart.
  for (;;) {
    if (!(a.lo_ < b.hi_)) return 1;
    if (!(b.lo_ < a.hi_)) return -1;
    a.refine();
    b.refine();
  }
}

double Algebraic::to_double() const
{
  if (is_rational()) return round_to_nearest(value_);
  Algebraic x = *this;   // refine a copy: this interval stays as it is
  for (;;) {
    double lo = round_to_nearest(x.lo_), hi = round_to_nearest(x.hi_);
    if (lo == hi) return lo;
    x.refine();
  }
}

CGAL::Interval_nt<false> Algebraic::to_interval() const
{
  auto lo = CGAL::to_interval(lower()), hi = CGAL::to_interval(upper());
  return CGAL::Interval_nt<false>(lo.first, hi.second);
}

std::string Algebraic::approx() const
{
  char buffer[64];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, to_double());
  return std::string(buffer, result.ptr);
}

std::pair<Rational, Rational> Algebraic::short_interval() const
{
  // A function of the number alone (not of how it was made): its
  // neighbours among the minimal polynomial's real roots bound it.
  std::vector<Rational> p(rep_->poly.size());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = Rational(rep_->poly[i].get_mpz_t());
  Fmpz_poly g;
  primitive_integer_poly(g, p);
  Rational bound = root_bound(g.p);
  std::vector<Algebraic> roots = real_roots(p, -bound, bound);
  const Algebraic *below = nullptr, *above = nullptr;
  for (const Algebraic& r : roots) {
    int c = compare(r, *this);
    if (c < 0) below = &r;
    if (c > 0 && !above) above = &r;
  }
  Algebraic x = *this;
  for (Rational scale = 1;; scale *= 10) {
    // floor(x * scale), once the interval no longer holds a multiple of 1 / scale.
    for (;;) {
      mpz_class flo, fhi;
      Rational l = x.lo_ * scale, h = x.hi_ * scale;
      mpz_fdiv_q(flo.get_mpz_t(), mpq_numref(l.mpq()), mpq_denref(l.mpq()));
      mpz_fdiv_q(fhi.get_mpz_t(), mpq_numref(h.mpq()), mpq_denref(h.mpq()));
      if (flo == fhi) {
        Rational lo = Rational(flo.get_mpz_t()) / scale, hi = Rational(mpz_class(flo + 1).get_mpz_t()) / scale;
        if ((!below || compare(*below, lo) < 0) && (!above || compare(*above, hi) > 0)) return {lo, hi};
        break;
      }
      x.refine();
    }
  }
}

std::string Algebraic::to_text() const
{
  if (is_rational()) return to_string(value_);
  std::string poly;
  for (std::size_t i = 0; i < rep_->poly.size(); ++i) poly += (i ? ", " : "") + rep_->poly[i].get_str();
  auto [lo, hi] = short_interval();
  return "root of [" + poly + "] in (" + to_string(lo) + ", " + to_string(hi) + ") ~ " + approx();
}

bool farther_than(const Algebraic& a, const Algebraic& b, const Rational& bound)
{
  if (a.is_rational() && b.is_rational()) return CGAL::abs(a.rational() - b.rational()) > bound;
  if (b.is_rational()) return compare(a, b.rational() + bound) > 0 || compare(a, b.rational() - bound) < 0;
  if (a.is_rational()) return farther_than(b, a, bound);
  for (int i = 0; i < 2000; ++i, a.refine(), b.refine()) {
    Rational lo = a.lower() - b.upper(), hi = a.upper() - b.lower();   // a - b lies strictly between
    if (lo >= bound || hi <= -bound) return true;
    if (lo >= -bound && hi <= bound) return false;
  }
  return false;
}

} // namespace clash4d
