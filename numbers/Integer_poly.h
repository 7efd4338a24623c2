// A polynomial in one variable with integer coefficients, on FLINT's
// fmpz_poly: a coefficient that fits in a word is kept in the word (GMP's
// mpz allocates for every non-zero one), and one array holds them all. The
// exact time slices make their rows and minors in it (rotation/Moving_planes.h,
// Critical_times.cpp): on a turning box pair, allocation was a quarter of
// a query when each coefficient was an mpz_class.
//
// The interface is the one rotation/'s generic code asks of Polynomial<FT>:
// size(), reading a coefficient, +, -, *, and a scalar times a polynomial;
// and the exact division, primitive part and square root that
// Critical_times.cpp takes a turning object's scale out of a minor with.
// size() is the degree plus one (FLINT keeps no leading zero); 0 for the
// zero polynomial.
#ifndef CLASH4D_NUMBERS_INTEGER_POLY_H
#define CLASH4D_NUMBERS_INTEGER_POLY_H

#include <gmpxx.h>

#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>

#include <optional>
#include <utility>
#include <vector>

namespace clash4d {

class Integer_poly {
public:
  Integer_poly() { fmpz_poly_init(p_); }
  // c[0] + c[1] t + ...
  explicit Integer_poly(const std::vector<mpz_class>& c)
  {
    fmpz_poly_init2(p_, static_cast<slong>(c.size()));
    for (std::size_t i = c.size(); i-- > 0;) fmpz_poly_set_coeff_mpz(p_, static_cast<slong>(i), c[i].get_mpz_t());
  }
  Integer_poly(const Integer_poly& o)
  {
    fmpz_poly_init(p_);
    fmpz_poly_set(p_, o.p_);
  }
  Integer_poly(Integer_poly&& o) noexcept
  {
    fmpz_poly_init(p_);
    fmpz_poly_swap(p_, o.p_);
  }
  Integer_poly& operator=(const Integer_poly& o)
  {
    fmpz_poly_set(p_, o.p_);
    return *this;
  }
  Integer_poly& operator=(Integer_poly&& o) noexcept
  {
    fmpz_poly_swap(p_, o.p_);
    return *this;
  }
  ~Integer_poly() { fmpz_poly_clear(p_); }

  int size() const { return static_cast<int>(fmpz_poly_length(p_)); }
  // The coefficient of t^i, 0 <= i < size().
  mpz_class operator[](int i) const
  {
    mpz_class c;
    fmpz_poly_get_coeff_mpz(c.get_mpz_t(), p_, i);
    return c;
  }
  // Sets the coefficient of t^i to c.
  void set_coefficient(int i, mpz_srcptr c) { fmpz_poly_set_coeff_mpz(p_, static_cast<slong>(i), c); }
  // The coefficient of t^i written into x (no number made).
  void coefficient_into(int i, mpz_ptr x) const { fmpz_poly_get_coeff_mpz(x, p_, i); }
  std::vector<mpz_class> coefficients() const
  {
    std::vector<mpz_class> c(size());
    for (int i = 0; i < size(); ++i) fmpz_poly_get_coeff_mpz(c[i].get_mpz_t(), p_, i);
    return c;
  }

  friend Integer_poly operator+(const Integer_poly& a, const Integer_poly& b)
  {
    return made([&](fmpz_poly_t r) { fmpz_poly_add(r, a.p_, b.p_); });
  }
  friend Integer_poly operator-(const Integer_poly& a, const Integer_poly& b)
  {
    return made([&](fmpz_poly_t r) { fmpz_poly_sub(r, a.p_, b.p_); });
  }
  friend Integer_poly operator-(const Integer_poly& a)
  {
    return made([&](fmpz_poly_t r) { fmpz_poly_neg(r, a.p_); });
  }
  friend Integer_poly operator*(const Integer_poly& a, const Integer_poly& b)
  {
    return made([&](fmpz_poly_t r) { fmpz_poly_mul(r, a.p_, b.p_); });
  }
  friend Integer_poly operator*(const mpz_class& s, const Integer_poly& a)
  {
    return made([&](fmpz_poly_t r) { fmpz_poly_scalar_mul_mpz(r, a.p_, s.get_mpz_t()); });
  }
  // The quotient by d (not zero) when d divides this exactly, else none.
  std::optional<Integer_poly> divided_by(const Integer_poly& d) const
  {
    Integer_poly q;
    if (!fmpz_poly_divides(q.p_, p_, d.p_)) return std::nullopt;
    return q;
  }
  // This over the gcd of its coefficients, the leading one positive.
  Integer_poly primitive_part() const
  {
    return made([&](fmpz_poly_t r) { fmpz_poly_primitive_part(r, p_); });
  }
  // The polynomial whose square this is, when there is one.
  std::optional<Integer_poly> square_root() const
  {
    Integer_poly r;
    if (!fmpz_poly_sqrt(r.p_, p_)) return std::nullopt;
    return r;
  }

  Integer_poly& operator+=(const Integer_poly& b)
  {
    fmpz_poly_add(p_, p_, b.p_);
    return *this;
  }
  Integer_poly& operator-=(const Integer_poly& b)
  {
    fmpz_poly_sub(p_, p_, b.p_);
    return *this;
  }

private:
  template <class Op>
  static Integer_poly made(Op op)
  {
    Integer_poly r;
    op(r.p_);
    return r;
  }

  fmpz_poly_t p_;
};

} // namespace clash4d

#endif
