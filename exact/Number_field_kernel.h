// The number-field kernel (regularised-semantics.md, fact 12): the static
// question at an irrational critical time r of a turning pair has its
// coefficients in the field Q(r), and this kernel is that field, exactly,
// under the kernel concept, so the static pipeline's stages run on it
// unchanged. Its numbers are e-antic's elements of a real embedded number
// field (Debian's libeantic-dev): a polynomial in r reduced modulo r's
// minimal polynomial, so a zero test is exact (the remainder is 0), and any
// other sign is read off an Arb enclosure that e-antic refines until it is
// sure. Every sign is exact; nothing is rounded.
#ifndef CLASH4D_EXACT_NUMBER_FIELD_KERNEL_H
#define CLASH4D_EXACT_NUMBER_FIELD_KERNEL_H

#include "geometry/Kernel_base.h"
#include "geometry/Kernel_concept.h"
#include "numbers/Algebraic.h"
#include "numbers/Rational.h"
#include "numbers/Stat_number.h"
#include <e-antic/renf_class.hpp>
#include <e-antic/renf_elem_class.hpp>
#include <boost/intrusive_ptr.hpp>
#include <ostream>
#include <string>
#include <vector>

namespace clash4d {

// A number of Q(r): e-antic's element, with what the stages ask of a
// number type besides (search/Convex_pair.h makes its double guesses exact
// numbers: FT(double), the double's exact value).
class Field_number {
public:
  using Element = eantic::renf_elem_class;
  Field_number() : x_(0) {}
  Field_number(int v) : x_(v) {}   // NOLINT: as every FT(int)
  explicit Field_number(double d);
  explicit Field_number(Element x) : x_(std::move(x)) {}
  const Element& element() const { return x_; }

  Field_number operator-() const { return Field_number(-x_); }
  Field_number& operator+=(const Field_number& y) { x_ += y.x_; return *this; }
  Field_number& operator-=(const Field_number& y) { x_ -= y.x_; return *this; }
  Field_number& operator*=(const Field_number& y) { x_ *= y.x_; return *this; }
  Field_number& operator/=(const Field_number& y) { x_ /= y.x_; return *this; }
  friend Field_number operator+(Field_number x, const Field_number& y) { return x += y; }
  friend Field_number operator-(Field_number x, const Field_number& y) { return x -= y; }
  friend Field_number operator*(Field_number x, const Field_number& y) { return x *= y; }
  friend Field_number operator/(Field_number x, const Field_number& y) { return x /= y; }
  // Exact (e-antic refines enclosures until they are sure).
  friend bool operator<(const Field_number& x, const Field_number& y) { return x.x_ < y.x_; }
  friend bool operator==(const Field_number& x, const Field_number& y) { return x.x_ == y.x_; }
  friend bool operator!=(const Field_number& x, const Field_number& y) { return !(x == y); }
  friend std::ostream& operator<<(std::ostream& out, const Field_number& x) { return out << x.x_; }

private:
  Element x_;
};

class Number_field_kernel : public Kernel_base<Number_field_kernel, Field_number> {
public:
  static constexpr const char* name() { return "number field"; }
  static constexpr bool reads_exact_constructions = true;   // the scene's rationals, embedded exactly
  static constexpr bool is_exact = true;

  // Q itself (a kernel the stages default-construct before assigning one).
  Number_field_kernel() = default;
  // Q(r), r irrational: its minimal polynomial, and an Arb ball around its
  // isolating interval that holds no other real root (checked exactly,
  // since e-antic aborts on a ball that does not isolate).
  explicit Number_field_kernel(const Algebraic& r);

  // r itself, as a number of the field.
  FT generator() const;
  // g(r), g's coefficients constant term first.
  FT at(const std::vector<Rational>& g) const;
  // x as a polynomial in r of degree below r's (constant term first): what
  // a caller outside the kernel reads the field's numbers as.
  std::vector<Rational> coefficients(const FT& x) const;

  CGAL::Sign sign(const FT& x) const { return CGAL::Sign(x.element().sgn()); }
  FT from_rational(const Rational& q) const;
  FT floor_to_grid(const FT& x, int bits) const;
  FT power_of_two(int e) const { return from_rational(clash4d::power_of_two(e)); }
  // The e with 2^-e <= x < 2^(1-e), x > 0: from x's floor on a grid fine
  // enough to hold a nonzero multiple below x.
  int grid_exponent(const FT& x) const;
  std::string to_text(const FT& x) const;
  Stat_number to_stat(const FT& x) const;

private:
  // x's floor on the grid of 2^-bits, as a rational.
  Rational floor_on_grid(const FT& x, int bits) const;

  boost::intrusive_ptr<const eantic::renf_class> field_;   // null: Q
  Algebraic r_;
};

static_assert(is_kernel_v<Number_field_kernel>,
              "Number_field_kernel must model the kernel concept (geometry/Kernel_concept.h)");

} // namespace clash4d

#endif
