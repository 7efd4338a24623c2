// The exact number type of the toolkit and its text conversions.
#ifndef CLASH4D_NUMBERS_RATIONAL_H
#define CLASH4D_NUMBERS_RATIONAL_H

#include <CGAL/Gmpq.h>
#include <gmpxx.h>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

namespace clash4d {

// CGAL's exact rational over GMP. CGAL::Exact_rational is Gmpq or mpq_class
// depending on how CGAL was configured; we pin Gmpq so the exact type does not
// change with the build and carries no expression templates into generic code.
using Rational = CGAL::Gmpq;

// "p/q" in lowest terms, or "p" when q = 1 (the spec's output form).
std::string to_string(const Rational& q);

// The inverse of to_string, for text this program printed: "p" or "p/q"
// with q > 0, of any length (input goes through scene/Number_text.h, with
// its limits, instead). Throws std::invalid_argument on other text.
Rational rational_from_string(const std::string& text);

// A finite double x as the rational it is, made from its bits (x = m 2^e,
// m odd): Gmpq(double)'s number (mpq_set_d) without its general path's
// reallocation. How point intervals become the rational run's numbers.
Rational exact_rational(double x);

// The double nearest to q (ties to even), via MPFR: Gmpq's own to_double
// truncates, which would make the double instantiation read a different scene
// than "the nearest double" the spec promises. Returns +-inf on overflow.
double round_to_nearest(const Rational& q);

// z as a double when it has at most 53 bits (then exactly): the quick
// path of the kernels' reading of rationals, read off GMP's single limb.
inline bool small_double(mpz_srcptr z, double& out)
{
  static_assert(GMP_LIMB_BITS == 64, "one limb is taken to hold 53 bits");
  if (z->_mp_size == 0) return out = 0, true;
  if (z->_mp_size != 1 && z->_mp_size != -1) return false;
  mp_limb_t m = z->_mp_d[0];
  if (m >> 53) return false;
  out = z->_mp_size > 0 ? static_cast<double>(m) : -static_cast<double>(m);
  return true;
}

// The double nearest to q, as round_to_nearest, with the quick path for a
// numerator and denominator of at most 53 bits (exact doubles, whose IEEE
// quotient is the nearest double when the rounding mode is to nearest, as
// the caller must make it). How the double instantiation reads a scene.
inline double nearest_double(const Rational& q)
{
  double n = 0, d = 0;
  if (small_double(mpq_numref(q.mpq()), n) && small_double(mpq_denref(q.mpq()), d)) return n / d;
  return round_to_nearest(q);
}

// Whether q is an integer (GMP's canonical form: denominator 1).
inline bool is_integer(const Rational& q) { return mpz_cmp_ui(mpq_denref(q.mpq()), 1) == 0; }

// An interval of doubles that surely holds q, read under upward rounding
// (the interval filters' guard, CGAL::Protect_FPU_rounding<true>): with a
// numerator and denominator of at most 53 bits (exact doubles), their
// quotient rounded down and up, which is as tight as the general
// conversion and q itself when q is a double; else CGAL's (MPFR), which
// the quick path spares the filters on nearly every number of a scene.
inline std::pair<double, double> enclosing_interval(const Rational& q)
{
  double n = 0, d = 0;
  if (!small_double(mpq_numref(q.mpq()), n) || !small_double(mpq_denref(q.mpq()), d)) return CGAL::to_interval(q);
  // d > 0 (GMP's canonical form); rounding upward, -(-n / d) rounds down.
  return {-(-n / d), n / d};
}

// An interval of doubles that surely holds the integer z, in any rounding
// mode: z itself when it has at most 53 bits, else CGAL's enclosure.
inline std::pair<double, double> enclosing_interval(const mpz_class& z)
{
  double d = 0;
  if (small_double(z.get_mpz_t(), d)) return {d, d};
  return CGAL::to_interval(Rational(z.get_mpz_t()));
}

// 2^e as a double, made from its bits in the normal range (no libm call:
// the grid roundings of the search take it on every comparison).
inline double power_of_two_double(int e)
{
  if (e < -1022 || e > 1023) return std::ldexp(1.0, e);
  std::uint64_t bits = static_cast<std::uint64_t>(1023 + e) << 52;
  double out;
  std::memcpy(&out, &bits, sizeof out);
  return out;
}

// Scales the numbers by one positive factor so that they become coprime
// integers (all zero: unchanged). Used on hyperplane coefficients, which
// this leaves the same hyperplane with the same sides.
void scale_to_coprime_integers(Rational* x, std::size_t n);

// The same coprime integers, as GMP integers in out[0..n): their products
// and sums need no gcd and no shared representation (the rational kernel's
// ring, Rational_kernel::RT).
void coprime_integers(const Rational* x, std::size_t n, mpz_class* out);

// The solution x[0..n) of the regular n x n system whose augmented rows
// [M | rhs] are m[i * (n + 1) .. (i + 1) * (n + 1)), in lowest terms:
// Bareiss's fraction-free elimination on the rows scaled to coprime
// integers (the same solution), with one division by the determinant per
// coordinate at the end, where rational elimination takes a gcd per
// operation. Throws std::logic_error when the matrix is singular.
void solve_regular(const Rational* m, std::size_t n, Rational* x);

// The same solution when the rows' numbers fit in a long and the
// elimination in 128-bit integers (every product checked): true, x
// written; otherwise false, x untouched (n at most 6). solve_regular takes
// it first; most of the toolkit's systems (scene numbers of a few digits)
// fit, and it needs no allocation but the answer's.
bool solve_regular_small(const Rational* m, std::size_t n, Rational* x);

// num / den in lowest terms (den not zero, of either sign).
Rational quotient_of_integers(const mpz_class& num, const mpz_class& den);

// sum a[i] b[i], exactly. mpq_mul and mpq_add take gcds to keep each
// partial result in lowest terms, most of a rational dot product's cost;
// here the products and sums are kept as unreduced fractions of GMP
// integers (one common denominator while the terms share it, as a rotated
// or scaled vector's coordinates do) and reduced once at the end.
// With plus: sum a[i] b[i] + *plus, reduced once (a plane's value n.p + c).
Rational sum_of_products(const Rational* a, const Rational* b, std::size_t n, const Rational* plus = nullptr);
// *c - sum a[i] b[i] (c null: 0), reduced once (a plane's extruded
// offset d - n.o and time coefficient -n.v).
Rational difference_of_products(const Rational* c, const Rational* a, const Rational* b, std::size_t n);
// The sign of that sum, without reducing it (the common denominator is
// positive): a side of a plane without making its value.
int sign_of_sum_of_products(const Rational* a, const Rational* b, std::size_t n, const Rational* plus = nullptr);

// x[0..n) as X[i] / d, d > 0 the lcm of their denominators (a gcd only
// where the lcm does not already hold a denominator, as in
// coprime_integers): the same numbers over integer numerators, for
// formulas linear in each vector (geometry/kernel_ft4.h, determinants).
void over_common_denominator(const Rational* x, std::size_t n, mpz_class* X, mpz_class& d);

// The largest multiple of 2^-bits at or below q (bits >= 0).
Rational floor_to_grid(const Rational& q, int bits);

// Whether q is a multiple of 2^-bits that a double holds exactly.
bool is_exact_dyadic(const Rational& q, int bits);

// 2^e, exactly.
Rational power_of_two(int e);

// The least k with 2^-k <= q, for q > 0 (that is, -floor(log2 q)).
int grid_exponent(const Rational& q);

// The rational q with lo < q < hi (lo < hi) that has the least denominator
// (Stern-Brocot, by continued fractions): sample times that read as a
// person would write them (rotation/Simplest_rational.h), and the fraction
// a certified double enclosure of a rational root holds.
Rational simplest_between(const Rational& lo, const Rational& hi);

} // namespace clash4d

#endif
