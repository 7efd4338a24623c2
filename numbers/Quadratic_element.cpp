#include "numbers/Quadratic_element.h"

#include <stdexcept>

namespace clash4d {

Quadratic_element::Quadratic_element(const Algebraic& r)
{
  if (r.is_rational() || r.polynomial().size() != 3)
    throw std::logic_error("Quadratic_element: r is not a quadratic irrational");
  const std::vector<mpz_class>& m = r.polynomial();
  field_ = std::make_shared<const Field>(Field{r, m[0], m[1], m[2], m[0] * m[2]});
}

const Quadratic_element::Field& Quadratic_element::field() const
{
  if (!field_) throw std::logic_error("Quadratic_element: an element of no field");
  return *field_;
}

Quadratic_element Quadratic_element::horner(const mpz_srcptr* g, std::size_t n, const mpz_class& L) const
{
  const Field& f = field();
  mpz_class A = 0, B = 0, scale = 1, next_B;   // scale = c2^(k - i)
  for (std::size_t i = n; i-- > 0;) {
    // (A + B s) s = -B c0 c2 + (A - B c1) s, then + g_i c2^(k - i).
    next_B = A - B * f.c1;
    mpz_mul(A.get_mpz_t(), g[i], scale.get_mpz_t());
    A -= B * f.c0_c2;
    B.swap(next_B);
    if (i > 0) scale *= f.c2;
  }
  // Now A + B s = c2^k g(r) L, k = deg g (the last scale, c2^k).
  return {field_, std::move(A), std::move(B), scale * L};
}

Quadratic_element Quadratic_element::at(const std::vector<mpz_class>& g) const
{
  std::vector<mpz_srcptr> G(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) G[i] = g[i].get_mpz_t();
  return horner(G.data(), G.size(), mpz_class(1));
}

Quadratic_element Quadratic_element::at(const Rational* g, std::size_t n) const
{
  // Integers (a turning pair's rows): their numerators, nothing made.
  std::vector<mpz_srcptr> G(n);
  bool integers = true;
  for (std::size_t i = 0; i < n && integers; ++i) {
    G[i] = mpq_numref(g[i].mpq());
    integers = is_integer(g[i]);
  }
  if (integers) return horner(G.data(), n, mpz_class(1));
  mpz_class L = 1;
  for (std::size_t i = 0; i < n; ++i) mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), mpq_denref(g[i].mpq()));
  std::vector<mpz_class> numerators(n);
  for (std::size_t i = 0; i < n; ++i) {
    mpz_divexact(numerators[i].get_mpz_t(), L.get_mpz_t(), mpq_denref(g[i].mpq()));
    numerators[i] *= mpz_class(mpq_numref(g[i].mpq()));
    G[i] = numerators[i].get_mpz_t();
  }
  return horner(G.data(), n, L);
}

Quadratic_element Quadratic_element::at(const std::vector<Rational>& g) const { return at(g.data(), g.size()); }

Algebraic Quadratic_element::value() const
{
  Rational a = quotient_of_integers(A_, d_);
  if (B_ == 0) return Algebraic(a);
  return Algebraic::linear_image(field().r, a, quotient_of_integers(B_ * field().c2, d_));
}

Quadratic_element Quadratic_element::sum(const Quadratic_element& x, const Quadratic_element& y, int sign)
{
  const auto& field = field_of(x, y);
  if (x.d_ == y.d_) return {field, x.A_ + sign * y.A_, x.B_ + sign * y.B_, x.d_};
  return {field, x.A_ * y.d_ + sign * y.A_ * x.d_, x.B_ * y.d_ + sign * y.B_ * x.d_, x.d_ * y.d_};
}

Quadratic_element operator*(const Quadratic_element& x, const Quadratic_element& y)
{
  const auto& field = Quadratic_element::field_of(x, y);
  mpz_class d = x.d_ * y.d_;
  if (x.B_ == 0 || y.B_ == 0) return {field, x.A_ * y.A_, x.A_ * y.B_ + x.B_ * y.A_, d};
  const Quadratic_element::Field& f = *field;
  mpz_class BD = x.B_ * y.B_;
  return {field, x.A_ * y.A_ - BD * f.c0_c2, x.A_ * y.B_ + x.B_ * y.A_ - BD * f.c1, d};
}

Quadratic_element Quadratic_element::inverse() const
{
  if (is_zero()) throw std::logic_error("Quadratic_element: division by zero");
  const Field& f = field();
  mpz_class norm = A_ * A_ - f.c1 * A_ * B_ + f.c0_c2 * B_ * B_;
  return {field_, d_ * (A_ - B_ * f.c1), -d_ * B_, norm};
}

} // namespace clash4d
