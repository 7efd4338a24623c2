// Real algebraic numbers, exactly: the times (and contact parameters) that
// are roots of polynomials in t, where a rational answer is not enough
// (docs/ccd-queries.md; the scene format's "Exact numbers that are not
// rational"). A number is a Rational, or the one root of its minimal
// polynomial (integer coefficients, irreducible over Q, degree at least 2,
// no common factor, the leading one positive) in an open interval with
// dyadic ends. Minimal polynomials come from FLINT's factoring
// (fmpz_poly_factor), isolating intervals from Arb's certified root
// isolation (arb_fmpz_poly_complex_roots); every sign and comparison is then
// exact: a zero is a divisibility (the minimal polynomial divides g), and any
// other sign is read off an Arb enclosure once the interval is narrow enough.
#ifndef CLASH4D_NUMBERS_ALGEBRAIC_H
#define CLASH4D_NUMBERS_ALGEBRAIC_H

#include "numbers/Rational.h"
#include <CGAL/Interval_nt.h>
#include <CGAL/enum.h>
#include <gmpxx.h>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace clash4d {

class Algebraic {
public:
  Algebraic() : value_(0) {}
  explicit Algebraic(const Rational& q) : value_(q) {}

  // The distinct real roots of p (coefficients from the constant term up,
  // not all zero) in the closed interval [a, b], ascending.
  static std::vector<Algebraic> real_roots(const std::vector<Rational>& p, const Rational& a, const Rational& b);
  static std::vector<Algebraic> real_roots(const std::vector<mpz_class>& p, const Rational& a, const Rational& b);
  // The same, for callers whose roots are often simple fractions (a
  // turning pair's critical times: contacts at t = 1/4): a quadratic by
  // its discriminant (rational roots when it is a square, else p is
  // irreducible); otherwise, when every root near [a, b] is a double or a
  // simple fraction, found without factoring p (isolation in doubles, then
  // exact signs); otherwise as real_roots.
  // Where roots are mostly irrational (the CCD queries' cubics) the first
  // step is a cost: 12% on the CCD bench's rational column.
  static std::vector<Algebraic> real_roots_rational_first(const std::vector<mpz_class>& p, const Rational& a,
                                                          const Rational& b);
  // The one root of p in the open interval (lo, hi), lo < hi dyadic (a
  // double's value), where p is certified to have a single simple root and
  // no root at either end (an interval run's isolation, made exact).
  static Algebraic root_between(const std::vector<Rational>& p, const Rational& lo, const Rational& hi);
  static Algebraic root_between(const std::vector<mpz_class>& p, const Rational& lo, const Rational& hi);
  // num(r) / den(r), den(r) != 0: an element of the field Q(r) as a number
  // of its own (for a quadratic r, a + b r read off the field element;
  // otherwise its minimal polynomial a factor of a resultant, and its root
  // chosen by enclosure: Algebraic.cpp).
  static Algebraic quotient_at(const Algebraic& r, const std::vector<Rational>& num, const std::vector<Rational>& den);
  static Algebraic quotient_at(const Algebraic& r, const std::vector<mpz_class>& num, const std::vector<mpz_class>& den);
  // The same element as a polynomial in r of degree below r's (its
  // coefficients, constant first; one number when it is rational): what a
  // check in Q(r) reads.
  static std::vector<Rational> field_element(const Algebraic& r, const std::vector<Rational>& num,
                                             const std::vector<Rational>& den);
  // a + b r, r an irrational root of a quadratic, as a number of its own:
  // the rational a when b = 0 (numbers/Quadratic_element.h makes such
  // elements).
  static Algebraic linear_image(const Algebraic& r, const Rational& a, const Rational& b);

  bool is_rational() const { return !rep_; }
  const Rational& rational() const { return value_; }   // when is_rational()
  // Whether this number is a root of p (integer coefficients, constant
  // first): an enclosure over the isolating interval that excludes 0 says
  // no, else the minimal polynomial's divisibility decides. Unlike sign_of,
  // it refines nothing, so what a later step reads of the interval (a
  // sample between two times) does not depend on having asked.
  bool is_root_of(const std::vector<mpz_class>& p) const;
  // p (integer coefficients, constant first, not zero) divided by the
  // largest power of this number's minimal polynomial that divides it: p
  // itself when this number is no root of p. Exact over the integers (a
  // primitive factor of an integer polynomial divides it over Z).
  std::vector<mpz_class> without_root(const std::vector<mpz_class>& p) const;
  // Both at once: p without the powers of the minimal polynomial when this
  // number is a root of p (is_root_of's filter, then the divisions made
  // once), none when it is not.
  std::optional<std::vector<mpz_class>> root_divided_out(const std::vector<mpz_class>& p) const;
  // The minimal polynomial's coefficients, constant term first (irrational).
  const std::vector<mpz_class>& polynomial() const { return rep_->poly; }
  // The isolating interval: the open interval (lower, upper) holds this
  // number and no other root of polynomial() (irrational); both are the
  // value when rational.
  const Rational& lower() const { return is_rational() ? value_ : lo_; }
  const Rational& upper() const { return is_rational() ? value_ : hi_; }
  // Halves the isolating interval (the number is unchanged).
  void refine() const;
  // Narrows it in doubles as far as sure signs allow (made numbers are).
  void narrow_in_doubles() const;

  // The sign of g (constant term first) at this number.
  CGAL::Sign sign_of(const std::vector<Rational>& g) const;
  CGAL::Sign sign_of(const std::vector<mpz_class>& g) const;

  // The double nearest to the number (ties to even), an enclosure in
  // doubles, and the shortest decimal that reads back to that double.
  double to_double() const;
  CGAL::Interval_nt<false> to_interval() const;
  std::string approx() const;
  // An isolating interval with short decimal ends, for printing (the
  // spec's "between"): the coarsest [n / 10^k, (n + 1) / 10^k] that holds
  // no other root of the minimal polynomial; a function of the number
  // alone. Irrational only.
  std::pair<Rational, Rational> short_interval() const;
  // "p/q" when rational; otherwise "root of POLY in (lo, hi) ~ approx".
  std::string to_text() const;

  friend int compare(const Algebraic& a, const Algebraic& b);
  friend int compare(const Algebraic& a, const Rational& q);
  friend bool operator<(const Algebraic& a, const Algebraic& b) { return compare(a, b) < 0; }
  friend bool operator==(const Algebraic& a, const Algebraic& b) { return compare(a, b) == 0; }
  friend bool operator!=(const Algebraic& a, const Algebraic& b) { return compare(a, b) != 0; }

private:
  friend struct Algebraic_access;   // Algebraic.cpp: the work on FLINT's types

  struct Rep {
    std::vector<mpz_class> poly;   // the minimal polynomial
  };
  Algebraic(std::shared_ptr<const Rep> rep, const Rational& lo, const Rational& hi)
    : rep_(std::move(rep)), lo_(lo), hi_(hi) {}
  static Algebraic irrational(std::vector<mpz_class> poly, const Rational& lo, const Rational& hi);
  // The sign of the minimal polynomial at a rational (never zero).
  int poly_sign(const Rational& q) const;
  // Shrinks the interval to one side of q (q not this number).
  void exclude(const Rational& q) const;

  Rational value_;                  // rational case
  std::shared_ptr<const Rep> rep_;  // irrational case
  mutable Rational lo_, hi_;        // refined in place: the same number
};

// -1, 0 or 1 as a < b, a = b, a > b (exact).
int compare(const Algebraic& a, const Algebraic& b);
int compare(const Algebraic& a, const Rational& q);

// Whether |a - b| > bound, exactly (the comparer's time bound). Irrational
// numbers are refined until their open isolating intervals decide it; past
// the cap their distance is within 2^-2000 of the bound, and a distance
// equal to the bound is not above it.
bool farther_than(const Algebraic& a, const Algebraic& b, const Rational& bound);

} // namespace clash4d

#endif
