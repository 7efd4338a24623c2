// A TIME of docs/certificate-format.md, section 8.1: a rational, or the one
// real root of a polynomial in an open interval with rational ends. Signs,
// comparisons and positivity on intervals, all exact (Sturm and gcds).
#ifndef CLASH4D_VERIFY_REAL_TIME_H
#define CLASH4D_VERIFY_REAL_TIME_H

#include "verify/Rational_poly.h"

namespace clash4d::verifier {

class Real_time {
public:
  Real_time() = default;
  explicit Real_time(const mpq_class& q) : exact_(true), value_(q) {}
  // The root of poly in (lo, hi); the caller has checked section 8.1's
  // conditions (valid_root below).
  Real_time(const Rational_poly& poly, const mpq_class& lo, const mpq_class& hi);

  bool exact() const { return exact_; }        // its value known as a rational
  const mpq_class& value() const { return value_; }   // when exact
  const Rational_poly& poly() const { return sqfree_; }
  const mpq_class& lo() const { return lo_; }
  const mpq_class& hi() const { return hi_; }
  // The ends of the isolating interval (closed when exact, open otherwise).
  const mpq_class& lower() const { return exact_ ? value_ : lo_; }
  const mpq_class& upper() const { return exact_ ? value_ : hi_; }
  // Halve the interval, keeping the root (a midpoint that is the root
  // makes the time exact).
  void refine();

private:
  bool exact_ = false;
  mpq_class value_, lo_, hi_;
  Rational_poly sqfree_;   // the square-free part: simple roots, a sign change
};

// Section 8.1's conditions on a TIME {"poly", "between"} but lo < hi and
// poly != 0 (checked first): "" when they hold, else what fails.
enum class Root_check { ok, root_at_lo, root_at_hi, not_one_root };
Root_check valid_root(const Rational_poly& poly, const mpq_class& lo, const mpq_class& hi);

int sign_at(const Rational_poly& p, const Real_time& r);
bool equal(const Real_time& a, const Real_time& b);
bool less(const Real_time& a, const Real_time& b);
inline bool less_equal(const Real_time& a, const Real_time& b) { return !less(b, a); }
// A rational strictly between a < b.
mpq_class rational_between(Real_time a, Real_time b);
// Distinct real roots of f (not zero) in the open interval (a, b), a < b.
long count_roots(const Rational_poly& f, Real_time a, Real_time b);

// The three predicates of section 8.1, for a < b.
bool nonnegative_on(const Rational_poly& p, const Real_time& a, const Real_time& b);       // p >= 0 on [a, b]
bool positive_on(const Rational_poly& p, const Real_time& a, const Real_time& b);          // p > 0 on [a, b]
bool positive_on_half_open(const Rational_poly& p, const Real_time& a, const Real_time& b);   // p > 0 on [a, b)

} // namespace clash4d::verifier

#endif
