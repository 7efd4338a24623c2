// Polynomials in t over the rationals (gmpxx), the checker's own: the
// arithmetic of certificates of turning scenes (docs/certificate-format.md,
// section 8.1). No root isolation library: Sturm sequences and gcds only.
#ifndef CLASH4D_VERIFY_RATIONAL_POLY_H
#define CLASH4D_VERIFY_RATIONAL_POLY_H

#include <gmpxx.h>
#include <vector>

namespace clash4d::verifier {

// Coefficients from the constant term up, no trailing zero: the zero
// polynomial has none.
class Rational_poly {
public:
  Rational_poly() = default;
  explicit Rational_poly(std::vector<mpq_class> coefficients);
  static Rational_poly constant(const mpq_class& c) { return Rational_poly({c}); }
  static Rational_poly linear(const mpq_class& c0, const mpq_class& c1) { return Rational_poly({c0, c1}); }

  bool is_zero() const { return c_.empty(); }
  int degree() const { return static_cast<int>(c_.size()) - 1; }   // -1 for zero
  const std::vector<mpq_class>& coefficients() const { return c_; }
  const mpq_class& lead() const { return c_.back(); }   // not for zero
  mpq_class operator()(const mpq_class& t) const;       // Horner
  Rational_poly derivative() const;
  Rational_poly monic() const;                          // zero stays zero
  bool operator==(const Rational_poly& o) const { return c_ == o.c_; }
  bool operator!=(const Rational_poly& o) const { return c_ != o.c_; }

  friend Rational_poly operator+(const Rational_poly& a, const Rational_poly& b);
  friend Rational_poly operator-(const Rational_poly& a, const Rational_poly& b);
  friend Rational_poly operator*(const Rational_poly& a, const Rational_poly& b);
  friend Rational_poly operator*(const mpq_class& k, const Rational_poly& a);
  friend Rational_poly operator-(const Rational_poly& a) { return mpq_class(-1) * a; }

private:
  void trim();
  std::vector<mpq_class> c_;
};

// a = q b + r with deg r < deg b; b not zero.
void divmod(const Rational_poly& a, const Rational_poly& b, Rational_poly& q, Rational_poly& r);
// a / b when b divides a (a flaw of the checker otherwise: std::logic_error).
Rational_poly exact_div(const Rational_poly& a, const Rational_poly& b);
// The monic gcd; gcd(0, 0) = 0.
Rational_poly gcd(const Rational_poly& a, const Rational_poly& b);
// Yun: f = c * prod_i factors[i-1]^i, each factor monic and square-free,
// pairwise coprime (factors[0] is the part of multiplicity 1). f not zero.
std::vector<Rational_poly> square_free_factors(const Rational_poly& f);
// The odd part g = f / s^2 (section 8.1): f = s^2 g, g square-free up to
// its constant, whose roots are f's roots of odd multiplicity; sign(f) =
// sign(g) wherever s != 0. f not zero.
Rational_poly odd_part(const Rational_poly& f);
// The square-free part f / gcd(f, f'): the same distinct roots, all simple.
Rational_poly square_free_part(const Rational_poly& f);
// Distinct real roots of f (not zero) in the open interval (x, y), x < y:
// roots at the ends divided out, then Sturm's V(x) - V(y).
long count_roots(const Rational_poly& f, const mpq_class& x, const mpq_class& y);

// f's Sturm sequence, made once for the many intervals a refinement asks
// about (each halving of an isolating interval asks again).
class Sturm_sequence {
public:
  explicit Sturm_sequence(const Rational_poly& f);   // f not zero
  // count_roots(f, x, y): V(x) - V(y) on the sequence when neither end is
  // a root of f, else count_roots itself (the ends' roots divided out).
  long count(const mpq_class& x, const mpq_class& y) const;

private:
  Rational_poly f_;
  std::vector<std::vector<mpz_class>> seq_;   // positive multiples of its members, integer coefficients
};

} // namespace clash4d::verifier

#endif
