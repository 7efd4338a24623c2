// The exact number type of the toolkit and its text conversions.
#ifndef CLASH4D_EXACT_RATIONAL_H
#define CLASH4D_EXACT_RATIONAL_H

#include <CGAL/Gmpq.h>
#include <string>

namespace clash4d {

// CGAL's exact rational over GMP. CGAL::Exact_rational is Gmpq or mpq_class
// depending on how CGAL was configured; we pin Gmpq so the exact type does not
// change with the build and carries no expression templates into generic code.
using Rational = CGAL::Gmpq;

// "p/q" in lowest terms, or "p" when q = 1 (the spec's output form).
std::string to_string(const Rational& q);

// The double nearest to q (ties to even), via MPFR: Gmpq's own to_double
// truncates, which would make the double instantiation read a different scene
// than "the nearest double" the spec promises. Returns +-inf on overflow.
double round_to_nearest(const Rational& q);

// The largest multiple of 2^-bits at or below q (bits >= 0).
Rational floor_to_grid(const Rational& q, int bits);

// 2^e, exactly.
Rational power_of_two(int e);

// The least k with 2^-k <= q, for q > 0 (that is, -floor(log2 q)).
int grid_exponent(const Rational& q);

} // namespace clash4d

#endif
