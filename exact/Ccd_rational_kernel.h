// The rational time kernel of the CCD sweep (ccd/Ccd_sweep.h): the named
// polynomials in rationals, times as real algebraic numbers
// (numbers/Algebraic.h), every sign exact. The reference the filtered
// kernel (Ccd_filtered_kernel.h) answers as, and the one it asks where an
// interval leaves a sign in doubt.
#ifndef CLASH4D_EXACT_CCD_RATIONAL_KERNEL_H
#define CLASH4D_EXACT_CCD_RATIONAL_KERNEL_H

#include "ccd/Ccd_polynomials.h"
#include "ccd/Ccd_query.h"
#include "ccd/Swept_boxes.h"
#include "numbers/Algebraic.h"
#include <array>
#include <optional>
#include <vector>

namespace clash4d {

class Ccd_rational_kernel {
public:
  using FT = Rational;
  using Time = Algebraic;
  static constexpr bool is_exact = true;

  // separation: the minimum separation D (0: the plain question).
  explicit Ccd_rational_kernel(const Ccd_query& q, const Rational& separation = Rational(0))
    : query_(q), separation_(separation),
      p_(q.type(), q.rows(), CGAL::is_positive(separation) ? std::optional<Rational>(separation * separation) : std::nullopt)
  {
  }

  Ccd_type type() const { return p_.type(); }
  bool separated() const { return p_.separated(); }
  Ccd_polynomials<Rational>& polynomials() { return p_; }

  // Apart by more than the separation on some axis.
  bool swept_boxes_apart() const
  {
    const Rational& d = separation_;
    return clash4d::swept_boxes_apart(type(), query_.rows(), [&d](const Rational& a, const Rational& b) { return a + d < b; });
  }

  Time zero() const { return Algebraic(Rational(0)); }
  bool is_end(const Time& t) const { return t.is_rational() && t.rational() == 1; }

  int sign_at(int name, const Time& t) { return sign_of(p_(name), t); }

  // The sign on (t, t + e): of the polynomial at t, or else of its first
  // derivative not zero at t (a polynomial not identically zero has one).
  int sign_after(int name, const Time& t)
  {
    Polynomial<Rational> g = p_(name);
    for (int order = 0; order < Polynomial<Rational>::capacity; ++order, g = g.derivative())
      if (int s = sign_of(g, t)) return s;
    return 0;
  }

  Time next_time(const Ccd_path& names, const Time& t)
  {
    Time best = Algebraic(Rational(1));
    for (int name : names)
      for (const Algebraic& r : roots(name))
        if (compare(t, r) < 0) {
          if (compare(r, best) < 0) best = r;
          break;
        }
    return best;
  }

  // The distinct roots in [0, 1] of a named polynomial (none when it is
  // identically zero), ascending; made once.
  const std::vector<Algebraic>& roots(int name)
  {
    auto& r = roots_[static_cast<std::size_t>(name)];
    if (!r) {
      std::vector<Rational> c = p_(name).coefficients();
      bool zero = true;
      for (const Rational& x : c) zero = zero && CGAL::is_zero(x);
      r = zero ? std::vector<Algebraic>() : Algebraic::real_roots(c, Rational(0), Rational(1));
    }
    return *r;
  }

  static int sign_of(const Polynomial<Rational>& g, const Time& t)
  {
    if (t.is_rational()) return CGAL::sign(g.at(t.rational()));
    return t.sign_of(g.coefficients());
  }

private:
  const Ccd_query& query_;
  Rational separation_;
  Ccd_polynomials<Rational> p_;
  std::array<std::optional<std::vector<Algebraic>>, ccd_name::max_count> roots_;
};

} // namespace clash4d

#endif
