// The rational time kernel of the CCD sweep (ccd/Ccd_sweep.h): the named
// polynomials exactly, times as real algebraic numbers (numbers/
// Algebraic.h), every sign exact. The reference the filtered kernel
// (Ccd_filtered_kernel.h) answers as, and the one it asks where an interval
// leaves a sign in doubt.
//
// The query's numbers are scaled by one positive integer L (the least
// common multiple of their denominators and the separation's), so every
// named polynomial has integer coefficients: each is a homogeneous form of
// some degree k in the coordinates (and D), so scaling multiplies it by
// L^k > 0 and keeps every sign and root, and the quotients that give (u, v)
// are unchanged. GMP integers need no gcd per operation, as rationals do.
#ifndef CLASH4D_EXACT_CCD_RATIONAL_KERNEL_H
#define CLASH4D_EXACT_CCD_RATIONAL_KERNEL_H

#include "ccd/Ccd_polynomials.h"
#include "ccd/Ccd_query.h"
#include "ccd/Ccd_sweep.h"
#include "ccd/Swept_boxes.h"
#include "numbers/Algebraic.h"
#include <array>
#include <gmpxx.h>
#include <optional>
#include <vector>

namespace clash4d {

class Ccd_rational_kernel {
public:
  using FT = mpz_class;
  using Time = Algebraic;
  using Poly = Polynomial<mpz_class>;
  static constexpr bool is_exact = true;

  // separation: the minimum separation D (0: the plain question).
  explicit Ccd_rational_kernel(const Ccd_query& q, const Rational& separation = Rational(0));

  Ccd_type type() const { return p_.type(); }
  bool separated() const { return p_.separated(); }
  Ccd_polynomials<mpz_class>& polynomials() { return p_; }

  // Apart by more than the separation on some axis.
  bool swept_boxes_apart() const;

  Time zero() const { return Algebraic(Rational(0)); }
  bool is_end(const Time& t) const { return t.is_rational() && t.rational() == 1; }
  int sign_at(int name, const Time& t) { return sign_of(p_(name), t); }
  // The sign on (t, t + e): of the polynomial at t, or else of its first
  // derivative not zero at t (a polynomial not identically zero has one).
  int sign_after(int name, const Time& t);
  Time next_time(const Ccd_path& names, const Time& t);

  // The distinct roots in [0, 1] of a named polynomial (none when it is
  // identically zero), ascending; made once.
  const std::vector<Algebraic>& roots(int name);
  static int sign_of(const Poly& g, const Time& t);

private:
  struct Scaled {
    std::array<Vector3<mpz_class>, 8> rows;
    mpz_class separation;
  };
  static Scaled scaled(const Ccd_query& q, const Rational& separation);

  Scaled s_;
  Ccd_polynomials<mpz_class> p_;
  std::array<std::optional<std::vector<Algebraic>>, ccd_name::max_count> roots_;
};

} // namespace clash4d

#endif
