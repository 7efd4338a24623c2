#include "exact/Number_field_kernel.h"
#include <e-antic/renf.h>
#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>
#include <arb.h>
#include <stdexcept>

namespace clash4d {

namespace {

mpq_class to_mpq(const Rational& q) { return mpq_class(q.mpq()); }
Rational from_mpq(const mpq_class& q) { return Rational(q.get_mpq_t()); }
// The rational value of an element that is rational (is_rational()).
Rational rational_value(const Field_number::Element& e) { return from_mpq(static_cast<mpq_class>(e)); }

// The rational an arf holds (finite: the ends of a ball made from two).
Rational rational_of(const arf_t x)
{
  fmpz_t m, e;
  fmpz_init(m);
  fmpz_init(e);
  arf_get_fmpz_2exp(m, e, x);
  mpz_class M, E;
  fmpz_get_mpz(M.get_mpz_t(), m);
  fmpz_get_mpz(E.get_mpz_t(), e);
  fmpz_clear(m);
  fmpz_clear(e);
  Rational q = quotient_of_integers(M, mpz_class(1));
  return q * power_of_two(static_cast<int>(E.get_si()));
}

// A ball around r's isolating interval; the interval is halved until the
// ball's own ends hold no other real root of r's minimal polynomial (the
// ball may be wider than the interval by its radius's rounding).
void isolating_ball(const Algebraic& r, arb_t ball, slong prec)
{
  for (;;) {
    fmpq_t lo, hi;
    fmpq_init(lo);
    fmpq_init(hi);
    fmpq_set_mpq(lo, r.lower().mpq());
    fmpq_set_mpq(hi, r.upper().mpq());
    arb_t b;
    arb_init(b);
    arb_set_fmpq(ball, lo, prec);
    arb_set_fmpq(b, hi, prec);
    arb_union(ball, ball, b, prec);
    arb_clear(b);
    fmpq_clear(lo);
    fmpq_clear(hi);
    arf_t l, u;
    arf_init(l);
    arf_init(u);
    arb_get_lbound_arf(l, ball, prec);
    arb_get_ubound_arf(u, ball, prec);
    std::size_t roots = Algebraic::real_roots(r.polynomial(), rational_of(l), rational_of(u)).size();
    arf_clear(l);
    arf_clear(u);
    if (roots == 1) return;
    r.refine();
  }
}

} // namespace

Field_number::Field_number(double d) : x_(to_mpq(exact_rational(d))) {}

Number_field_kernel::Number_field_kernel(const Algebraic& r) : r_(r)
{
  if (r.is_rational()) return;   // Q
  constexpr slong prec = 64;
  fmpq_poly_t p;
  fmpq_poly_init(p);
  const std::vector<mpz_class>& m = r.polynomial();
  for (std::size_t i = 0; i < m.size(); ++i) fmpq_poly_set_coeff_mpz(p, static_cast<slong>(i), m[i].get_mpz_t());
  arb_t ball;
  arb_init(ball);
  isolating_ball(r, ball, prec);
  renf_t nf;
  renf_init(nf, p, ball, prec);
  field_ = eantic::renf_class::make(nf, "r");
  renf_clear(nf);
  arb_clear(ball);
  fmpq_poly_clear(p);
}

Field_number Number_field_kernel::generator() const
{
  return field_ ? FT(field_->gen()) : from_rational(r_.rational());
}

Field_number Number_field_kernel::from_rational(const Rational& q) const
{
  return FT(field_ ? Field_number::Element(*field_, to_mpq(q)) : Field_number::Element(to_mpq(q)));
}

Field_number Number_field_kernel::at(const std::vector<Rational>& g) const
{
  FT r = generator(), y = from_rational(Rational(0));
  for (std::size_t i = g.size(); i-- > 0;) y = y * r + from_rational(g[i]);
  return y;
}

std::vector<Rational> Number_field_kernel::coefficients(const FT& x) const
{
  const Field_number::Element& e = x.element();
  if (e.is_rational()) return {rational_value(e)};
  std::vector<mpz_class> num = e.num_vector();
  mpz_class den = e.den();
  std::vector<Rational> out;
  for (const mpz_class& c : num) out.push_back(quotient_of_integers(c, den));
  return out;
}

Rational Number_field_kernel::floor_on_grid(const FT& x, int bits) const
{
  mpz_class f = (x * from_rational(clash4d::power_of_two(bits))).element().floor();
  return quotient_of_integers(f, mpz_class(1)) * clash4d::power_of_two(-bits);
}

Field_number Number_field_kernel::floor_to_grid(const FT& x, int bits) const
{
  return from_rational(floor_on_grid(x, bits));
}

int Number_field_kernel::grid_exponent(const FT& x) const
{
  if (sign(x) != CGAL::POSITIVE) throw std::logic_error("internal error: grid_exponent of a number that is not positive");
  if (x.element().is_rational()) return clash4d::grid_exponent(rational_value(x.element()));
  // x's floor on a grid of 2^-bits, made finer until it is not zero; then
  // x lies in [f, f + 2^-bits), and x is irrational, so it is never f nor a
  // power of two: the exponent of f decides unless f + 2^-bits passes the
  // next power of two, where one comparison settles it.
  for (int bits = 8;; bits *= 2) {
    Rational f = floor_on_grid(x, bits);
    if (f == 0) continue;
    int e = clash4d::grid_exponent(f);   // 2^-e <= f < x
    return x < from_rational(clash4d::power_of_two(1 - e)) ? e : e - 1;
  }
}

std::string Number_field_kernel::to_text(const FT& x) const
{
  if (x.element().is_rational()) return to_string(rational_value(x.element()));
  return Algebraic::quotient_at(r_, coefficients(x), {Rational(1)}).to_text();
}

Stat_number Number_field_kernel::to_stat(const FT& x) const
{
  if (x.element().is_rational())
    return {Stat_number::Kind::Exact, rational_value(x.element()), 0, 0};
  // x in [f, f + 2^-40]; each end rounded outward, so the doubles still
  // enclose x (an Enclosure is read as sure bounds).
  Rational f = floor_on_grid(x, 40);
  return {Stat_number::Kind::Enclosure, Rational(0), enclosing_interval(f).first,
          enclosing_interval(f + clash4d::power_of_two(-40)).second};
}

} // namespace clash4d
