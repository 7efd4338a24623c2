// The interval kernel: the approximate half of the filtered exact kernel.
// Numbers are CGAL::Interval_nt<false> (the rounding mode must be upward
// while it computes: the filtered runner holds CGAL::Protect_FPU_rounding),
// each enclosing the rational the same formula gives in exact arithmetic. A
// sign is returned only when the interval excludes the other signs; otherwise
// CGAL::Uncertain_conversion_exception is thrown and the filtered runner
// redoes the work in rationals, as CGAL's Filtered_predicate does.
#ifndef CLASH4D_EXACT_INTERVAL_KERNEL_H
#define CLASH4D_EXACT_INTERVAL_KERNEL_H

#include "geometry/Kernel_base.h"
#include "geometry/Kernel_concept.h"
#include "numbers/Number_ops.h"
#include "numbers/Rational.h"
#include "numbers/Stat_number.h"
#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>
#include <algorithm>
#include <cmath>
#include <charconv>
#include <cstdio>
#include <optional>
#include <string>

namespace clash4d {

using Interval = CGAL::Interval_nt<false>;

// Enclosures of min, max and |a|, no decision (see numbers/Number_ops.h).
template <>
struct Number_ops<Interval> {
  static Interval lower(const Interval& a, const Interval& b) { return CGAL::min(a, b); }
  static Interval upper(const Interval& a, const Interval& b) { return CGAL::max(a, b); }
  static Interval magnitude(const Interval& a) { return CGAL::abs(a); }
  static bool same(const Interval& a, const Interval& b) { return a.is_same(b); }
};

class Interval_kernel : public Kernel_base<Interval_kernel, Interval> {
public:
  static constexpr const char* name() { return "interval"; }
  using Protector = CGAL::Protect_FPU_rounding<true>;   // the rounding its arithmetic needs
  static constexpr bool reads_exact_constructions = true;   // tight enclosures, exact zeros (model/Model_builder.h)
  static constexpr bool is_exact = false;

  // Whether this machine rounds as the Protector asks: an interval encloses
  // its rational only if the FPU honours the upward rounding mode. Under
  // valgrind (every SSE operation rounded to nearest) or an emulator that
  // ignores the mode, it does not, and a sign given here could be wrong:
  // the filtered runner then answers in rationals alone (exact/
  // Filtered_runner.h, prepare). Measured once per process: 1/3 rounded up
  // must exceed 1/3 rounded down (the -(-a / b) of CGAL's lower ends).
  static bool encloses_here()
  {
    static const bool upward = [] {
      Protector protect;
      // volatile: read after the mode is set and written before it is
      // restored (plain locals, GCC moves the divisions past the restore,
      // -frounding-math or not), and never folded.
      volatile double one = 1.0, three = 3.0;
      volatile double up = one / three, down = -(-one / three);
      return up > down;
    }();
    return upward;
  }
  // b > 0: a / b is monotone in a, and its ends divide by b's far or near
  // end as a's ends are positive or negative (rounding upward; -(-x / y)
  // rounds down).
  FT quotient(const FT& a, const FT& b, CGAL::Sign sb) const
  {
    if (sb == CGAL::NEGATIVE) return quotient(-a, -b, CGAL::POSITIVE);
    // Opaque operands and results (CGAL::IA_opacify, as in CGAL's own
    // interval operations): each division is made under the caller's
    // Protector, never folded or moved past its restore (encloses_here
    // measured GCC doing both to plain divisions).
    using CGAL::IA_opacify;
    double lo = -IA_opacify(IA_opacify(-a.inf()) / IA_opacify(a.inf() >= 0 ? b.sup() : b.inf()));
    double hi = IA_opacify(IA_opacify(a.sup()) / IA_opacify(a.sup() >= 0 ? b.inf() : b.sup()));
    return FT(lo, hi);
  }

  // Near ties need no certificate here (Kernel_base::largest_component):
  // compared by the enclosures' upper ends.
  template <std::size_t N>
  int largest_component(const std::array<FT, N>& v) const
  {
    int k = 0;
    for (int q = 1; q < static_cast<int>(N); ++q)
      if (CGAL::abs(v[k]).sup() < CGAL::abs(v[q]).sup()) k = q;
    return k;
  }

  // Kept small enough to inline everywhere: the throw is out of line.
  CGAL::Sign sign(const FT& x) const
  {
    if (x.inf() > 0) return CGAL::POSITIVE;
    if (x.sup() < 0) return CGAL::NEGATIVE;
    if (x.inf() == 0 && x.sup() == 0) return CGAL::ZERO;
    uncertain();
  }
  [[noreturn]] __attribute__((noinline, cold)) static void uncertain()
  {
    throw CGAL::Uncertain_conversion_exception("a sign an interval cannot certify");
  }
  CGAL::Uncertain<CGAL::Sign> uncertain_sign(const FT& x) const { return CGAL::sign(x); }
  // CGAL's possibly(sign(x) == POSITIVE) and possibly(sign(x) != NEGATIVE)
  // on its ends, without the Uncertain values (the search's inner loop asks
  // them per plane and line): CGAL's sign is certain when inf > 0, sup < 0 or
  // inf == sup (then zero), and indeterminate (any sign) otherwise.
  bool possibly_positive(const FT& x) const { return x.inf() > 0 || (x.sup() >= 0 && x.inf() < x.sup()); }
  bool possibly_nonnegative(const FT& x) const { return x.sup() >= 0; }
  CGAL::Uncertain<bool> is_nonnegative(const FT& x, bool strict) const { return strict ? x > 0 : x >= 0; }
  FT from_rational(const Rational& q) const
  {
    // Rounding upward, as everywhere here (numbers/Rational.h).
    return FT(enclosing_interval(q));
  }
  // The reader's enclosure of a.q: CGAL's, the tightest (tests/
  // test_numbers.cpp holds it equal to from_rational's).
  FT from_approximation(const Approximation& a) const { return a.enclosure; }
  FT power_of_two(int e) const { return FT(power_of_two_double(e)); }
  // Beyond 2^900 a region face times the grid's 2^20 and a plane's
  // coefficients leave the double range: the rational run takes the pair.
  FT far_power_of_two(int e) const
  {
    if (e > 900) throw CGAL::Uncertain_conversion_exception("a far bound beyond the double range");
    return power_of_two(e);
  }
  // The number a point interval is (grid values, snapped witnesses); none
  // for an interval that only encloses one.
  std::optional<Rational> exact_value(const FT& x) const
  {
    if (!has_exact_value(x)) return std::nullopt;
    return exact_rational(x.inf());
  }
  // Whether exact_value(x) has one, without making it (an overflow is no
  // rational).
  bool has_exact_value(const FT& x) const { return x.is_point() && std::isfinite(x.inf()); }
  // Certain only when both bounds round to the same grid point (then a point
  // interval: grid values are exact doubles while bits and x are moderate).
  FT floor_to_grid(const FT& x, int bits) const
  {
    // Scaling by powers of two is exact while nothing overflows or
    // underflows; beyond that the filter fails.
    const double up = power_of_two_double(bits), down = power_of_two_double(-bits);
    double lo = std::floor(x.inf() * up) * down;
    if (bits > 900 || !std::isfinite(lo) || lo != std::floor(x.sup() * up) * down)
      throw CGAL::Uncertain_conversion_exception("a region face between two grid points");
    return FT(lo);
  }
  // Certain when both bounds are positive and give the same exponent.
  int grid_exponent(const FT& x) const
  {
    int lo = 0, hi = 0;
    if (!(x.inf() > 0) || (std::frexp(x.inf(), &lo), std::frexp(x.sup(), &hi), lo != hi))
      throw CGAL::Uncertain_conversion_exception("a witness's room between two powers of two");
    return 1 - lo;
  }
  // Identical enclosures hold values on one side of every grid jump when
  // their grid point is certain; otherwise the grid points decide.
  bool same_on_grid(const FT& a, const FT& b) const
  {
    FT ga = grid_point(a);
    return a.is_same(b) || ga.is_same(grid_point(b));
  }
  // A point interval is an exact number, printed as the rational it is
  // (dyadic_text); otherwise the enclosure "~[inf, sup]", for statistics
  // only. Answers are printed from intervals only when every number is a
  // point (exact/Filtered_result.h). Every sub-span writes its bounds so,
  // --stats or not: kept cheap (no printf, no GMP for the usual short
  // dyadic numbers).
  std::string to_text(const FT& x) const
  {
    if (x.is_point() && std::isfinite(x.inf())) return dyadic_text(x.inf());
    char text[64] = "~[";
    char* end = std::to_chars(text + 2, text + 30, x.inf()).ptr;
    *end++ = ',';
    *end++ = ' ';
    end = std::to_chars(end, text + 60, x.sup()).ptr;
    *end++ = ']';
    return std::string(text, end);
  }

  Stat_number to_stat(const FT& x) const { return {Stat_number::Kind::Enclosure, Rational(), x.inf(), x.sup()}; }

  // A double as the exact rational it is, "p/q" or "p" in lowest terms:
  // to_string(Rational(d)) (tests/test_numbers.cpp,
  // dyadic_text_is_the_exact_rational), an answer's text.
  static std::string dyadic_text(double d)
  {
    if (d == 0) return "0";
    int e = 0;
    double m = std::frexp(d, &e);                  // d = m 2^e, 0.5 <= |m| < 1
    long long num = static_cast<long long>(std::ldexp(m, 53));   // exact: 53 bits
    int shift = 53 - e;                            // d = num / 2^shift
    // Lowest terms: num's factors of two cancelled against the denominator.
    int twos = std::min(shift, __builtin_ctzll(static_cast<unsigned long long>(num)));
    if (twos > 0) num /= 1LL << twos, shift -= twos;   // num a multiple of 2^twos: exact
    if (shift < 0 || shift > 62) return to_string(Rational(d));
    char text[48];
    char* end = std::to_chars(text, text + 24, num).ptr;
    if (shift > 0) {
      *end++ = '/';
      end = std::to_chars(end, text + 48, 1ULL << shift).ptr;
    }
    return std::string(text, end);
  }
};

static_assert(is_kernel_v<Interval_kernel>, "Interval_kernel must model the kernel concept (geometry/Kernel_concept.h)");

} // namespace clash4d

#endif
