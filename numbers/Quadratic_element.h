// An element of the field Q(r), r an irrational root of a quadratic
// c2 X^2 + c1 X + c0 (an Algebraic of degree 2, integer coefficients,
// c2 > 0), held in integers: (A + B s) / d with s = c2 r, a root of
// X^2 + c1 X + c0 c2, so that s^2 = -c1 s - c0 c2 and a product makes no
// fraction to reduce. A turning pair's irrational t* is mostly such a root
// (the reach of a turning vertex is quadratic in t: docs/rotation.md), and
// a point read at t* (Cramer's quotients of three planes) is a few integer
// products and one conjugate here, where the quotients as polynomials
// are minors of degree 6, each read at t* by an extended gcd in FLINT
// (Algebraic::field_element). Algebraic::quotient_at at a quadratic root
// is made here too.
#ifndef CLASH4D_NUMBERS_QUADRATIC_ELEMENT_H
#define CLASH4D_NUMBERS_QUADRATIC_ELEMENT_H

#include "numbers/Algebraic.h"
#include "numbers/Rational.h"

#include <gmpxx.h>
#include <memory>
#include <vector>

namespace clash4d {

class Quadratic_element {
public:
  // 0 of no field yet: it takes its field from the element it meets in an
  // operation (so arrays of elements can be made, then assigned).
  Quadratic_element() = default;
  // The field of r, r irrational of degree 2; the element 0.
  explicit Quadratic_element(const Algebraic& r);
  // g(r) (coefficients constant first), by Horner in s on c2^k g(r) =
  // sum g_i c2^(k - i) s^i, k = deg g.
  Quadratic_element at(const std::vector<Rational>& g) const;
  Quadratic_element at(const std::vector<mpz_class>& g) const;
  // The same on g[0 .. n).
  Quadratic_element at(const Rational* g, std::size_t n) const;

  bool is_zero() const { return A_ == 0 && B_ == 0; }   // r is irrational
  // The element as a number: the rational a when it is one, else the root
  // of b^2 m((X - a) / b) that a + b r is (Algebraic::linear_image), with
  // a = A / d and b = B c2 / d.
  Algebraic value() const;

  Quadratic_element operator-() const { return {field_, -A_, -B_, d_}; }
  friend Quadratic_element operator+(const Quadratic_element& x, const Quadratic_element& y) { return sum(x, y, 1); }
  friend Quadratic_element operator-(const Quadratic_element& x, const Quadratic_element& y) { return sum(x, y, -1); }
  // (A + B s)(C + D s) = AC - BD c0 c2 + (AD + BC - BD c1) s.
  friend Quadratic_element operator*(const Quadratic_element& x, const Quadratic_element& y);
  // 1 / y = d (C + D s') / N, y = (C + D s) / d != 0, with s' = -c1 - s
  // the conjugate and N = (C + D s)(C + D s') = C^2 - c1 C D + c0 c2 D^2,
  // not 0 as y is not.
  Quadratic_element inverse() const;
  friend Quadratic_element operator/(const Quadratic_element& x, const Quadratic_element& y) { return x * y.inverse(); }

private:
  struct Field {
    Algebraic r;
    mpz_class c0, c1, c2;
    mpz_class c0_c2;   // c0 c2: s^2 = -c1 s - c0 c2
  };
  Quadratic_element(std::shared_ptr<const Field> field, mpz_class A, mpz_class B, mpz_class d)
    : field_(std::move(field)), A_(std::move(A)), B_(std::move(B)), d_(std::move(d)) {}
  static const std::shared_ptr<const Field>& field_of(const Quadratic_element& x, const Quadratic_element& y)
  {
    return x.field_ ? x.field_ : y.field_;
  }
  const Field& field() const;   // throws on an element of no field
  static Quadratic_element sum(const Quadratic_element& x, const Quadratic_element& y, int sign);
  // g(r) L for the integers g[0 .. n) (g over its common denominator L),
  // by Horner.
  Quadratic_element horner(const mpz_srcptr* g, std::size_t n, const mpz_class& L) const;

  std::shared_ptr<const Field> field_;
  mpz_class A_ = 0, B_ = 0, d_ = 1;   // d != 0
};

} // namespace clash4d

#endif
