#define BOOST_TEST_MODULE numbers
#include <boost/test/unit_test.hpp>

#include "check/Collision_checker.h"
#include "exact/Interval_kernel.h"
#include "exact/Rational_kernel.h"
#include "float/Double_kernel.h"
#include "scene/Number_text.h"
#include <CGAL/FPU.h>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <vector>

using namespace clash4d;

// The kernel concept (geometry/Kernel_concept.h) holds for the three
// kernels and fails for a kernel that lacks one member, here to_stat.
namespace {
struct Missing_to_stat : Kernel_base<Missing_to_stat, double> {
  static constexpr const char* name() { return "incomplete"; }
  static constexpr bool is_exact = false, reads_exact_constructions = false;
  CGAL::Sign sign(double x) const { return CGAL::sign(x); }
  double from_rational(const Rational& r) const { return CGAL::to_double(r); }
  double floor_to_grid(double x, int) const { return x; }
  double power_of_two(int e) const { return std::ldexp(1.0, e); }
  int grid_exponent(double) const { return 0; }
  std::string to_text(double) const { return ""; }
};
struct Complete : Missing_to_stat {
  Stat_number to_stat(double x) const { return {Stat_number::Kind::Double, Rational(), x, x}; }
};
struct Wrong_type : Missing_to_stat {
  int to_stat(double) const { return 0; }
};
static_assert(is_kernel_v<Rational_kernel> && is_kernel_v<Interval_kernel> && is_kernel_v<Double_kernel>);
static_assert(!is_kernel_v<Wrong_type>, "a member of the wrong type must not pass the concept");
static_assert(!is_kernel_v<Missing_to_stat>, "a kernel without to_stat must not pass the concept");
static_assert(is_kernel_v<Complete>, "adding the member makes it a kernel");

// Four seeded random rows of rationals n / d, |n| <= numerators and
// 1 <= d <= denominators, a quarter of the entries zero; the fourth row
// r3 = (3/7) r0 - (5/2) r1 (dependent) when `dependent`.
std::array<Vector4<Rational>, 4> random_rows(std::mt19937_64& rng, long numerators, long denominators, bool dependent)
{
  std::array<Vector4<Rational>, 4> r;
  for (auto& row : r)
    for (auto& v : row) {
      if (rng() % 4 == 0) {
        v = Rational(0);
        continue;
      }
      Rational x(static_cast<long>(rng() % static_cast<unsigned long>(2 * numerators + 1)) - numerators);
      v = x / Rational(static_cast<long>(1 + rng() % static_cast<unsigned long>(denominators)));
    }
  if (dependent)
    for (int j = 0; j < 4; ++j) r[3][j] = Rational(3, 7) * r[0][j] - Rational(5, 2) * r[1][j];
  return r;
}
} // namespace

static Rational q(const std::string& text)
{
  Number_parse p = parse_number_text(text, true);
  BOOST_TEST_REQUIRE(p.ok, text << ": " << p.error);
  return p.value;
}

BOOST_AUTO_TEST_CASE(decimals_are_read_exactly)
{
  BOOST_TEST(q("0.1") == Rational(1, 10));
  BOOST_TEST(q("-2.5e-3") == Rational(-1, 400));
  BOOST_TEST(q("1E2") == Rational(100));
  BOOST_TEST(q("0.1") + q("0.2") == q("0.3"));      // false in doubles
  BOOST_TEST(q("3/6") == Rational(1, 2));
  BOOST_TEST(q("-7/14") == Rational(-1, 2));
  BOOST_TEST(q("123456789012345678901234567890") * Rational(10) == q("1234567890123456789012345678900"));
}

BOOST_AUTO_TEST_CASE(malformed_numbers_are_refused)
{
  for (const char* bad : {"1.2.3", "0x10", "1/2/3", " 1", "1 ", "01", "+1", ".5", "1.", "1e", "NaN", "inf", "", "-", "1/-2", "1/0", "0/0"}) {
    Number_parse p = parse_number_text(bad, true);
    BOOST_TEST(!p.ok, "accepted '" << bad << "'");
    BOOST_TEST(!p.limit);
  }
  BOOST_TEST(parse_number_text("1/0", true).error.find("zero denominator") != std::string::npos);
  BOOST_TEST(!parse_number_text("1/2", false).ok);   // JSON numbers are never fractions
}

BOOST_AUTO_TEST_CASE(absurd_numbers_hit_a_named_limit)
{
  Number_parse p = parse_number_text("1e1000000", true);
  BOOST_TEST(!p.ok);
  BOOST_TEST(p.limit);
  BOOST_TEST(p.error.find("1000") != std::string::npos);
  BOOST_TEST(parse_number_text(std::string(2000, '9'), true).limit);
  BOOST_TEST(parse_number_text("1e1000", true).ok);
}

BOOST_AUTO_TEST_CASE(exact_output_is_lowest_terms)
{
  BOOST_TEST(to_string(Rational(6, 4)) == "3/2");
  BOOST_TEST(to_string(Rational(-5)) == "-5");
  BOOST_TEST(to_string(Rational(0)) == "0");
  BOOST_TEST(to_string(Rational(-2, -4)) == "1/2");
}

// to_string's quick path (parts of one limb) against GMP's own printing,
// mpq_get_str: at the limb's edges (2^64 - 1 and 2^64, in either part,
// with either sign) and on seeded random rationals of 1 to 130 bits a part,
// so both paths and their boundary are taken.
BOOST_AUTO_TEST_CASE(rational_text_is_gmps)
{
  auto gmp_text = [](const Rational& x) {
    std::unique_ptr<char, void (*)(void*)> s(mpq_get_str(nullptr, 10, x.mpq()), std::free);
    return std::string(s.get());
  };
  auto power = [](unsigned e) {
    Rational p(1);
    for (unsigned i = 0; i < e; ++i) p = p * Rational(2);
    return p;
  };
  std::vector<Rational> edges{Rational(0), Rational(1), Rational(-1), Rational(1, 2)};
  for (const Rational& big : {power(64) - Rational(1), power(64), power(64) + Rational(1)})
    for (const Rational& x : {big, -big, Rational(1) / big, Rational(-3) / big, big / Rational(3)}) edges.push_back(x);
  for (const Rational& x : edges) BOOST_TEST(to_string(x) == gmp_text(x));
  std::uint64_t seed = 20261129;
  BOOST_TEST_MESSAGE("rational text: seed " << seed);
  std::mt19937_64 rng(seed);
  auto random_part = [&](unsigned bits) {
    Rational p(0);
    for (unsigned b = 0; b < bits; ++b) p = p * Rational(2) + Rational(b == 0 ? 1 : static_cast<long>(rng() & 1));
    return p;
  };
  for (int i = 0; i < 4000; ++i) {
    unsigned bits_n = 1 + static_cast<unsigned>(rng() % 130), bits_d = 1 + static_cast<unsigned>(rng() % 130);
    Rational x = random_part(bits_n) / random_part(bits_d);
    if (i % 2) x = -x;
    BOOST_TEST(to_string(x) == gmp_text(x));
  }
}

BOOST_AUTO_TEST_CASE(double_reading_rounds_to_nearest)
{
  Double_kernel k;
  BOOST_TEST(k.from_rational(q("0.1")) == 0.1);
  BOOST_TEST(k.from_rational(q("1/3")) == 1.0 / 3.0);
  // 2^53 + 1 is a tie: to even, 2^53. 2^53 + 3 ties up to 2^53 + 4.
  BOOST_TEST(k.from_rational(q("9007199254740993")) == 9007199254740992.0);
  BOOST_TEST(k.from_rational(q("9007199254740995")) == 9007199254740996.0);
  // Truncation (what mpq_get_d does) would give the smaller neighbour here.
  Rational just_below_one = Rational(1) - Rational(1, 1) / q("1e30");
  BOOST_TEST(k.from_rational(just_below_one) == 1.0);
  BOOST_CHECK_THROW(k.from_rational(q("1e400")), std::range_error);
}

// The interval kernel's reading of x, under its rounding (upward).
static Interval interval_reading(const Interval_kernel& ik, const Rational& x)
{
  CGAL::Protect_FPU_rounding<true> protect;
  return ik.from_rational(x);
}

// The kernels' quick reading of rationals with small numerators and
// denominators (one division of exact doubles) against MPFR's: the nearest
// double for Double_kernel, the tightest enclosure for Interval_kernel (its
// ends the neighbours of that double, or the double itself when exact), on
// seeded random rationals on both sides of the 53-bit limit.
BOOST_AUTO_TEST_CASE(quick_reading_matches_mpfr)
{
  std::uint64_t seed = 20261125;
  BOOST_TEST_MESSAGE("quick rational reading: seed " << seed);
  std::mt19937_64 rng(seed);
  Double_kernel dk;
  Interval_kernel ik;
  for (int i = 0; i < 20000; ++i) {
    int bits_n = 1 + static_cast<int>(rng() % 60), bits_d = 1 + static_cast<int>(rng() % 60);
    Rational n(static_cast<long>(rng() >> (64 - bits_n))), d(static_cast<long>(rng() >> (64 - bits_d)) + 1);
    Rational x = (i % 2 ? -n : n) / d;
    double nearest = round_to_nearest(x);
    BOOST_TEST(dk.from_rational(x) == nearest, to_string(x));
    Interval e = interval_reading(ik, x);
    BOOST_TEST((Rational(e.inf()) <= x && x <= Rational(e.sup())), to_string(x));
    bool exact = Rational(nearest) == x;
    BOOST_TEST((exact ? e.is_point() : e.inf() == std::nextafter(e.sup(), -HUGE_VAL)), to_string(x));
  }
}

// The reader's approximations (numbers/Approximation.h) are the numbers
// the kernels' own readings make, bit for bit: the interval kernel's
// enclosure (so an interval run reads the same intervals either way) and
// the nearest double (the double kernel, the convex pairs' guide); and an
// approximation is read only for the very number it was made from. On
// seeded random rationals of 1 to 130 bits a part, both sides of the quick
// reading's 53-bit limit, and on doubles and integers.
BOOST_AUTO_TEST_CASE(approximations_are_the_kernels_readings)
{
  std::uint64_t seed = 20261130;
  BOOST_TEST_MESSAGE("approximations: seed " << seed);
  std::mt19937_64 rng(seed);
  Double_kernel dk;
  Interval_kernel ik;
  auto random_integer = [&](int bits) {
    mpz_class z = 0;
    for (int b = 0; b < bits; b += 32) z = (z << 32) + static_cast<unsigned long>(rng() & 0xffffffffu);
    return mpz_class(z >> ((bits + 31) / 32 * 32 - bits));
  };
  for (int i = 0; i < 20000; ++i) {
    int bits_n = 1 + static_cast<int>(rng() % 130), bits_d = 1 + static_cast<int>(rng() % 130);
    mpq_class v(random_integer(bits_n), random_integer(bits_d) + 1);
    v.canonicalize();
    if (i % 3 == 1) v = mpq_class(static_cast<double>(rng() >> 11) * std::ldexp(1.0, static_cast<int>(rng() % 80) - 60));
    if (i % 2) v = -v;
    Rational x(v.get_mpq_t());
    Approximation a(x);
    Interval e = interval_reading(ik, x), f;
    {
      CGAL::Protect_FPU_rounding<true> protect;
      f = ik.from_approximation(a);
    }
    BOOST_TEST((a.enclosure.inf() == e.inf() && a.enclosure.sup() == e.sup()), to_string(x));
    BOOST_TEST((f.inf() == e.inf() && f.sup() == e.sup()), to_string(x));
    BOOST_TEST(a.nearest == round_to_nearest(x), to_string(x));
    BOOST_TEST(dk.from_approximation(a) == dk.from_rational(x), to_string(x));
    Rational copy = x;
    BOOST_TEST((a.of(x) && a.of(copy)), to_string(x));
    BOOST_TEST(!a.of(Rational(v.get_mpq_t())), "an equal number made again is another number: " << to_string(x));
  }
  Approximation far(q("1e400"));
  BOOST_CHECK_THROW(dk.from_approximation(far), std::range_error);
}

BOOST_AUTO_TEST_CASE(double_output_is_shortest_round_trip)
{
  Double_kernel k;
  BOOST_TEST(k.to_text(0.1) == "0.1");
  BOOST_TEST(k.to_text(0.1 + 0.2) == "0.30000000000000004");
  BOOST_TEST(k.to_text(2.0) == "2");
  BOOST_TEST(std::stod(k.to_text(1.0 / 3.0)) == 1.0 / 3.0);
}

// Answers kept in point intervals (exact/Filtered_result.h) and statistics
// print exact doubles as rationals without GMP: the text GMP gives for the
// same rational (Rational(d) is exact: mpq_set_d), on chosen doubles and on
// seeded random bit patterns over every exponent, subnormals included.
BOOST_AUTO_TEST_CASE(dyadic_text_is_the_exact_rational)
{
  for (double d : {0.0, -0.0, 1.0, -3.0, 0.5, -0.375, 1e-10, 12345.6789, 1048575.0 / 1048576.0, 1e20, -7e-300,
                   9007199254740992.0, (std::ldexp(1.0, 53) - 1) / 4, std::ldexp(1.0, -62), std::ldexp(1.0, -63),
                   std::ldexp(-3.0, -61), 5e-324, -std::numeric_limits<double>::max()})
    BOOST_TEST(Interval_kernel::dyadic_text(d) == to_string(Rational(d)), d);
  std::uint64_t seed = 20261130;
  BOOST_TEST_MESSAGE("dyadic text: seed " << seed);
  std::mt19937_64 rng(seed);
  int checked = 0, without_gmp = 0;
  for (int i = 0; i < 20000; ++i) {
    std::uint64_t bits = rng();
    if (i % 2) bits = (bits & ~(std::uint64_t{0x7ff} << 52)) | (std::uint64_t(1023 + int(rng() % 140) - 70) << 52);
    double d = 0;
    std::memcpy(&d, &bits, sizeof d);
    if (!std::isfinite(d)) continue;
    ++checked;
    std::string want = to_string(Rational(d));
    BOOST_TEST(Interval_kernel::dyadic_text(d) == want, d);
    // 2^-10 <= |d| < 2^53: d = num / 2^shift with 0 <= shift <= 62, printed without GMP
    without_gmp += std::abs(d) >= std::ldexp(1.0, -10) && std::abs(d) < std::ldexp(1.0, 53);
  }
  BOOST_TEST(checked > 19000);
  BOOST_TEST(without_gmp > 1000);   // both paths are taken
}

// The interval kernel's division by an interval of known sign against
// CGAL's general division: the same enclosure, on seeded random intervals.
BOOST_AUTO_TEST_CASE(quotient_of_known_sign_is_cgal_division)
{
  std::uint64_t seed = 20261125;
  BOOST_TEST_MESSAGE("interval quotient: seed " << seed);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-4, 4);
  Interval_kernel ik;
  CGAL::Protect_FPU_rounding<true> protect;
  for (int i = 0; i < 20000; ++i) {
    double a0 = u(rng), a1 = i % 3 ? u(rng) : a0, b0 = std::abs(u(rng)) + 1e-3, b1 = i % 5 ? b0 + std::abs(u(rng)) : b0;
    Interval a(std::min(a0, a1), std::max(a0, a1)), b(b0, b1);
    if (i % 2) b = -b;
    Interval q = ik.quotient(a, b, i % 2 ? CGAL::NEGATIVE : CGAL::POSITIVE), r = a / b;
    BOOST_TEST((q.inf() == r.inf() && q.sup() == r.sup()), i);
  }
}

// uncertain_sign: the interval kernel's sign without a throw, indeterminate
// exactly where sign() throws (an interval holding 0 and another number);
// certain for a point 0 and for intervals of one sign. Exact kernels: sign.
BOOST_AUTO_TEST_CASE(uncertain_sign_is_indeterminate_where_sign_throws)
{
  Interval_kernel ik;
  Interval_kernel::Protector protect;
  using I = Interval_kernel::FT;
  const I tenth = ik.from_rational(q("1/10"));
  const I around_zero = tenth - tenth;   // [-e, e]: 1/10 - 1/10 only enclosed
  BOOST_TEST(!CGAL::is_certain(ik.uncertain_sign(around_zero)));
  BOOST_CHECK_THROW(ik.sign(around_zero), CGAL::Uncertain_conversion_exception);
  BOOST_TEST(!CGAL::is_certain(ik.uncertain_sign(I(0, 1))));   // [0, 1]: zero or positive
  BOOST_TEST((CGAL::get_certain(ik.uncertain_sign(I(0))) == CGAL::ZERO));
  BOOST_TEST((CGAL::get_certain(ik.uncertain_sign(tenth)) == CGAL::POSITIVE));
  BOOST_TEST((CGAL::get_certain(ik.uncertain_sign(-tenth)) == CGAL::NEGATIVE));
  Rational_kernel rk;
  BOOST_TEST((CGAL::get_certain(rk.uncertain_sign(q("1/10") - q("1/10"))) == CGAL::ZERO));
  BOOST_TEST((CGAL::get_certain(rk.uncertain_sign(mpz_class(-3))) == CGAL::NEGATIVE));   // the ring too
}

// Time_span::lo_on_grid (model/Scene_model.h): a multiple of 2^-bits that a
// double holds, decided on the rational; at the edges of both conditions.
BOOST_AUTO_TEST_CASE(exact_dyadics_at_their_edges)
{
  BOOST_TEST(is_exact_dyadic(q("0"), 20));
  BOOST_TEST(is_exact_dyadic(q("-3"), 20));
  BOOST_TEST(is_exact_dyadic(q("5/1048576"), 20));        // 5 * 2^-20
  BOOST_TEST(!is_exact_dyadic(q("5/2097152"), 20));       // 5 * 2^-21: off the grid
  BOOST_TEST(!is_exact_dyadic(q("3/10"), 20));            // not dyadic
  BOOST_TEST(!is_exact_dyadic(q("1/3"), 20));
  BOOST_TEST(is_exact_dyadic(q("9007199254740991"), 20));  // 2^53 - 1
  BOOST_TEST(!is_exact_dyadic(q("9007199254740993"), 20)); // 2^53 + 1: no double holds it
}

// sum_of_products (the rational dot product over unreduced fractions) is
// the sum of products made one gcd at a time by GMP's mpq arithmetic: by
// hand on a rotation row (shared denominators), zeros, cancellation to 0
// and to an integer; then on seeded random rationals of 1 to 120 bits, with
// shared and different denominators and zero terms, its result in lowest
// terms (a Gmpq compared with == must be canonical). The same with a
// constant added, and the sign of either without reducing it; and the sum
// subtracted from a constant (difference_of_products).
BOOST_AUTO_TEST_CASE(sum_of_products_is_the_exact_dot_product)
{
  auto dot = [](std::vector<Rational> a, std::vector<Rational> b) { return sum_of_products(a.data(), b.data(), a.size()); };
  BOOST_TEST(to_string(dot({q("-7/25"), q("24/25"), q("0")}, {q("1"), q("1"), q("5")})) == "17/25");
  BOOST_TEST(to_string(dot({q("1/3"), q("2/3")}, {q("3"), q("-3/2")})) == "0");
  BOOST_TEST(to_string(dot({q("1/6"), q("5/6")}, {q("3"), q("3")})) == "3");
  BOOST_TEST(to_string(dot({q("0"), q("0")}, {q("7"), q("1/9")})) == "0");
  BOOST_TEST(to_string(dot({q("-1/4")}, {q("2/3")})) == "-1/6");
  std::uint64_t seed = 20261127;
  BOOST_TEST_MESSAGE("sum_of_products: seed " << seed);
  std::mt19937_64 rng(seed);
  auto random_rational = [&](const Rational& den) {
    int bits = 1 + static_cast<int>(rng() % 120);
    Rational x(static_cast<long>(rng() >> (64 - std::min(bits, 62))));
    for (int b = 62; b < bits; b += 62) x = x * Rational(static_cast<long>(1) << 62) + Rational(static_cast<long>(rng() >> 2));
    if (rng() % 2) x = -x;
    return rng() % 5 == 0 ? Rational(0) : x / den;
  };
  int zeros = 0;
  for (int i = 0; i < 5000; ++i) {
    std::size_t n = 1 + rng() % 5;
    Rational shared(static_cast<long>(1 + rng() % 1000));
    std::vector<Rational> a, b;
    for (std::size_t k = 0; k < n; ++k) {
      bool same = rng() % 2;
      a.push_back(random_rational(same ? shared : Rational(static_cast<long>(1 + rng() % 100000))));
      b.push_back(random_rational(same ? Rational(1) : Rational(static_cast<long>(1 + rng() % 100000))));
    }
    Rational expected(0);
    for (std::size_t k = 0; k < n; ++k) expected += a[k] * b[k];
    Rational got = sum_of_products(a.data(), b.data(), n);
    BOOST_TEST(got == expected, i << ": " << to_string(got) << " against " << to_string(expected));
    mpz_class g;
    mpz_gcd(g.get_mpz_t(), mpq_numref(got.mpq()), mpq_denref(got.mpq()));
    BOOST_TEST((g == 1 && mpz_sgn(mpq_denref(got.mpq())) > 0), i);
    // With a constant added (a plane's value n.p + c), a quarter of them
    // the sum's negation, so that the value is exactly 0; and its sign.
    Rational c = i % 4 == 0 ? -expected : random_rational(Rational(static_cast<long>(1 + rng() % 100000)));
    Rational plus = sum_of_products(a.data(), b.data(), n, &c);
    BOOST_TEST(plus == expected + c, i << ": " << to_string(plus) << " against " << to_string(expected + c));
    mpz_gcd(g.get_mpz_t(), mpq_numref(plus.mpq()), mpq_denref(plus.mpq()));
    BOOST_TEST((g == 1 && mpz_sgn(mpq_denref(plus.mpq())) > 0), i);
    int s = sign_of_sum_of_products(a.data(), b.data(), n, &c);
    BOOST_TEST(s == static_cast<int>(CGAL::sign(expected + c)), i);
    BOOST_TEST(sign_of_sum_of_products(a.data(), b.data(), n) == static_cast<int>(CGAL::sign(expected)), i);
    zeros += s == 0;
    // And subtracted from a constant (an extruded offset d - n.o), or from
    // none (-n.v); with c = expected, exactly 0.
    Rational from = i % 4 == 0 ? expected : c, less = difference_of_products(&from, a.data(), b.data(), n);
    BOOST_TEST(less == from - expected, i << ": " << to_string(less) << " against " << to_string(from - expected));
    mpz_gcd(g.get_mpz_t(), mpq_numref(less.mpq()), mpq_denref(less.mpq()));
    BOOST_TEST((g == 1 && mpz_sgn(mpq_denref(less.mpq())) > 0), i);
    BOOST_TEST(difference_of_products(nullptr, a.data(), b.data(), n) == -expected, i);
  }
  BOOST_TEST(zeros >= 1250);   // every fourth, and the terms that are all zero
}

// The rational kernel's compare (mpq_cmp, without making a - b) is the sign
// of a - b: hand-worked cases (equal values in different spellings, signs,
// near denominators) and seeded random pairs, against the subtraction.
BOOST_AUTO_TEST_CASE(rational_compare_is_the_sign_of_the_difference)
{
  Rational_kernel k;
  BOOST_TEST(k.compare(q("2/4"), q("1/2")) == CGAL::ZERO);
  BOOST_TEST(k.compare(q("-1/3"), q("-1/4")) == CGAL::NEGATIVE);
  BOOST_TEST(k.compare(q("1000001/1000000"), q("1000000/999999")) == CGAL::NEGATIVE);
  BOOST_TEST(k.compare(q("0"), q("-1/1000000000000000000000")) == CGAL::POSITIVE);
  BOOST_TEST((k.less(q("7/25"), q("24/25")) && !k.less(q("24/25"), q("24/25"))));
  std::uint64_t seed = 20261128;
  BOOST_TEST_MESSAGE("rational compare: seed " << seed);
  std::mt19937_64 rng(seed);
  auto random_rational = [&] {
    Rational x(static_cast<long>(rng() % 2001) - 1000);
    return x / Rational(static_cast<long>(1 + rng() % 12));
  };
  for (int i = 0; i < 5000; ++i) {
    Rational a = random_rational(), b = i % 3 == 0 ? a * Rational(static_cast<long>(1 + rng() % 3)) : random_rational();
    BOOST_TEST(k.compare(a, b) == CGAL::sign(a - b), i << ": " << to_string(a) << " against " << to_string(b));
  }
}

// The rational kernel's fraction-free solve (numbers/Rational.h): a
// hand-worked system whose first pivot is zero (a row swap), then seeded
// random regular systems, each solution checked by substitution (M x =
// rhs exactly) and against Kernel_base's rational elimination; a singular
// matrix is refused, not answered.
BOOST_AUTO_TEST_CASE(fraction_free_solve_is_the_systems_solution)
{
  Rational_kernel k;
  // 0x + y/2 = 1, x/3 + y = 2: y = 2, x = 0.
  std::array<std::array<Rational, 3>, 2> two{{{q("0"), q("1/2"), q("1")}, {q("1/3"), q("1"), q("2")}}};
  std::array<Rational, 2> x2 = k.solve_regular(two);
  BOOST_TEST((x2[0] == q("0") && x2[1] == q("2")));
  // x + y + z = 6, 2y - z = -1/2, x - z/4 = 1/4. From the third,
  // x = 1/4 + z/4; the second, y = z/2 - 1/4; the first, 7z/4 = 6, so
  // z = 24/7, x = 31/28, y = 41/28.
  std::array<std::array<Rational, 4>, 3> three{
      {{q("1"), q("1"), q("1"), q("6")}, {q("0"), q("2"), q("-1"), q("-1/2")}, {q("1"), q("0"), q("-1/4"), q("1/4")}}};
  std::array<Rational, 3> x3 = k.solve_regular(three);
  BOOST_TEST((x3[0] == q("31/28") && x3[1] == q("41/28") && x3[2] == q("24/7")));
  std::array<std::array<Rational, 3>, 2> singular{{{q("1"), q("2"), q("1")}, {q("1/2"), q("1"), q("3")}}};
  BOOST_CHECK_THROW(k.solve_regular(singular), std::logic_error);

  std::uint64_t seed = 20261127;
  BOOST_TEST_MESSAGE("fraction-free solve: seed " << seed);
  std::mt19937_64 rng(seed);
  auto random_rational = [&] {
    if (rng() % 4 == 0) return Rational(0);   // zero pivots and sparse rows
    Rational x(static_cast<long>(rng() % 20001) - 10000);
    return x / Rational(static_cast<long>(1 + rng() % 1000));
  };
  const Kernel_base<Rational_kernel, Rational>& elimination = k;
  int solved = 0;
  for (int i = 0; i < 2000; ++i) {
    std::array<std::array<Rational, 5>, 4> M;
    for (auto& row : M)
      for (auto& v : row) v = random_rational();
    Vector4<Rational> n[4];
    for (int r = 0; r < 4; ++r) n[r] = {M[r][0], M[r][1], M[r][2], M[r][3]};
    if (CGAL::sign(determinant4(n[0], n[1], n[2], n[3])) == CGAL::ZERO) {
      BOOST_CHECK_THROW(k.solve_regular(M), std::logic_error);
      continue;
    }
    ++solved;
    std::array<Rational, 4> x = k.solve_regular(M);
    for (int r = 0; r < 4; ++r)
      BOOST_TEST(M[r][0] * x[0] + M[r][1] * x[1] + M[r][2] * x[2] + M[r][3] * x[3] == M[r][4], "system " << i);
    BOOST_TEST((x == elimination.solve_regular(M)), "system " << i);
  }
  BOOST_TEST(solved > 1000);   // the random systems are mostly regular
}

// proportional_or_unsure (geometry/Hyperplane4.h) on seeded pairs whose
// answer holds by construction: h = lambda g (+1 or -1 by lambda's sign),
// the same with h's offset or one normal coordinate moved by 1 (0), and g
// with zero coordinates. In rationals it is always certain and the answer;
// in intervals, where certain, the answer, where not, proportional throws;
// both outcomes are reached (scaled copies by a lambda like 1/3 are
// undecidable in intervals, moved ones are not).
BOOST_AUTO_TEST_CASE(proportional_or_unsure_is_the_predicate)
{
  Rational_kernel rk;
  Interval_kernel ik;
  CGAL::Protect_FPU_rounding<true> upward;
  std::uint64_t seed = 20261130;
  BOOST_TEST_MESSAGE("proportional: seed " << seed);
  std::mt19937_64 rng(seed);
  auto small = [&] {
    if (rng() % 3 == 0) return Rational(0);
    return Rational(static_cast<long>(rng() % 41) - 20) / Rational(static_cast<long>(1 + rng() % 12));
  };
  auto in_intervals = [&](const Hyperplane4<Rational>& h) {
    return Hyperplane4<Interval_kernel::FT>{
        {ik.from_rational(h.n[0]), ik.from_rational(h.n[1]), ik.from_rational(h.n[2]), ik.from_rational(h.n[3])},
        ik.from_rational(h.c)};
  };
  int unsure = 0, certain = 0;
  for (int i = 0; i < 4000; ++i) {
    Hyperplane4<Rational> g{{small(), small(), small(), small()}, small()};
    int nonzero = 0;
    for (const auto& x : g.n) nonzero += CGAL::sign(x) != CGAL::ZERO;
    if (nonzero < 2) continue;   // a coordinate moved below leaves it not proportional
    Rational lambda = small();
    if (CGAL::sign(lambda) == CGAL::ZERO) lambda = Rational(-7, 3);
    Hyperplane4<Rational> h{{lambda * g.n[0], lambda * g.n[1], lambda * g.n[2], lambda * g.n[3]}, lambda * g.c};
    int expected = CGAL::sign(lambda) == CGAL::POSITIVE ? 1 : -1;
    switch (i % 3) {
      case 1: h.c += 1, expected = 0; break;
      case 2: h.n[rng() % 4] += 1, expected = 0; break;
      default: break;
    }
    CGAL::Uncertain<int> exact = proportional_or_unsure(rk, h, g);
    BOOST_TEST_REQUIRE(CGAL::is_certain(exact));
    BOOST_TEST(CGAL::get_certain(exact) == expected, "pair " << i);
    BOOST_TEST(proportional(rk, h, g) == expected, "pair " << i);
    CGAL::Uncertain<int> approx = proportional_or_unsure(ik, in_intervals(h), in_intervals(g));
    if (CGAL::is_certain(approx)) {
      ++certain;
      BOOST_TEST(CGAL::get_certain(approx) == expected, "pair " << i);
      BOOST_TEST(proportional(ik, in_intervals(h), in_intervals(g)) == expected, "pair " << i);
    } else {
      ++unsure;
      BOOST_CHECK_THROW(proportional(ik, in_intervals(h), in_intervals(g)), CGAL::Uncertain_conversion_exception);
    }
  }
  BOOST_TEST_MESSAGE("proportional: " << certain << " certain in intervals, " << unsure << " not");
  BOOST_TEST(unsure > 100);
  BOOST_TEST(certain > 500);
}

// exact_rational (a double's bits as a rational) is Gmpq(double)'s number
// (GMP's mpq_set_d), in lowest terms, for seeded doubles of every
// exponent, subnormals, signed zeros and integers included, and to_string
// prints each as GMP does (numbers of up to 1,100 digits); a non-finite
// double is refused.
BOOST_AUTO_TEST_CASE(exact_rational_is_the_doubles_number)
{
  std::uint64_t seed = 20261129;
  BOOST_TEST_MESSAGE("exact_rational: seed " << seed);
  std::mt19937_64 rng(seed);
  std::vector<double> xs = {0.0, -0.0, 1.0, -1.0, 0.5, 3.0, 1e-9, -1e300, 4.9e-324, -2.2250738585072014e-308,
                            1.7976931348623157e308, 9007199254740993.0, 0.1};
  for (int i = 0; i < 20000; ++i) {
    std::uint64_t bits = rng();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (std::isfinite(x)) xs.push_back(x);
    xs.push_back(std::ldexp(static_cast<double>(rng() % 100000) - 50000, static_cast<int>(rng() % 80) - 40));
  }
  for (double x : xs) {
    Rational q = exact_rational(x);
    Rational canonical;   // its own representation (Gmpq shares on copy)
    mpq_set(canonical.mpq(), q.mpq());
    mpq_canonicalize(canonical.mpq());
    BOOST_TEST(mpq_equal(q.mpq(), canonical.mpq()), x);   // already in lowest terms
    BOOST_TEST(mpz_sgn(mpq_denref(q.mpq())) > 0, x);
    BOOST_TEST((q == Rational(x)), x);
    // to_string, written into its own string, is GMP's text (its own allocation).
    char* text = mpq_get_str(nullptr, 10, q.mpq());
    BOOST_TEST(to_string(q) == std::string(text), x);
    void (*free_fn)(void*, size_t);
    mp_get_memory_functions(nullptr, nullptr, &free_fn);
    free_fn(text, std::strlen(text) + 1);
  }
  BOOST_CHECK_THROW(exact_rational(HUGE_VAL), std::invalid_argument);
  BOOST_CHECK_THROW(exact_rational(std::nan("")), std::invalid_argument);
}

// solve_regular's small path (128-bit integers, every operation checked)
// against Kernel_base's rational elimination, over seeded systems:
//  - scene-like numbers (numerators up to 100 over 1, 2, 4 or 10): a row
//    scaled to integers has entries under 2000, so by Hadamard every k x k
//    minor is under k^(k/2) 2000^k (4 x 4: 2.6e14), and every product the
//    elimination makes is under 2^100: the small path must answer each;
//  - numbers of 4 to 20 bits, then 64 to 128: where it answers, the
//    answer is the system's, and it gives up on many (overflow), which
//    solve_regular then solves in GMP integers, also checked here.
BOOST_AUTO_TEST_CASE(small_solve_is_the_elimination_or_gives_up)
{
  Rational_kernel k;
  const Kernel_base<Rational_kernel, Rational>& elimination = k;
  std::uint64_t seed = 20261128;
  BOOST_TEST_MESSAGE("small solve: seed " << seed);
  std::mt19937_64 rng(seed);
  auto part = [&](int b) {   // up to b random bits
    mpz_class z = 0;
    for (int left = 1 + static_cast<int>(rng() % static_cast<unsigned>(b)); left > 0; left -= 32) {
      int take = std::min(left, 32);
      z = (z << take) + static_cast<unsigned long>(rng() >> (64 - take));
    }
    return z;
  };
  // bits 0: a scene-like number; otherwise about `bits` bits over up to `bits`.
  auto random_rational = [&](int bits) {
    if (rng() % 4 == 0) return Rational(0);
    if (bits == 0) {
      const long dens[4] = {1, 2, 4, 10};
      return Rational(static_cast<long>(rng() % 201) - 100) / Rational(dens[rng() % 4]);
    }
    mpz_class num = part(bits), den = part(bits) + 1;
    if (rng() % 2) num = -num;
    return Rational(CGAL::Gmpz(num.get_mpz_t())) / Rational(CGAL::Gmpz(den.get_mpz_t()));
  };
  int scene_like = 0, scene_like_answered = 0, answered = 0, gave_up = 0;
  for (int i = 0; i < 3000; ++i) {
    int bits = i < 1000 ? 0 : i < 2000 ? 4 + static_cast<int>(rng() % 16) : 64 + static_cast<int>(rng() % 64);
    std::array<std::array<Rational, 5>, 4> M;
    for (auto& row : M)
      for (auto& v : row) v = random_rational(bits);
    Vector4<Rational> n[4];
    for (int r = 0; r < 4; ++r) n[r] = {M[r][0], M[r][1], M[r][2], M[r][3]};
    if (CGAL::sign(determinant4(n[0], n[1], n[2], n[3])) == CGAL::ZERO) continue;
    std::array<Rational, 20> flat;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 5; ++c) flat[static_cast<std::size_t>(r * 5 + c)] = M[r][c];
    const std::array<Rational, 4> untouched{Rational(7), Rational(7), Rational(7), Rational(7)};
    std::array<Rational, 4> x = untouched;
    const std::array<Rational, 4> expected = elimination.solve_regular(M);
    scene_like += bits == 0;
    if (solve_regular_small(flat.data(), 4, x.data())) {
      ++answered;
      scene_like_answered += bits == 0;
      BOOST_TEST((x == expected), "system " << i << " (" << bits << " bits)");
    } else {
      ++gave_up;
      BOOST_TEST((x == untouched), "system " << i);
    }
    BOOST_TEST((k.solve_regular(M) == expected), "system " << i << " (" << bits << " bits)");
  }
  BOOST_TEST_MESSAGE("small solve: " << answered << " answered, " << gave_up << " gave up");
  BOOST_TEST(scene_like > 500);
  BOOST_TEST(scene_like_answered == scene_like);
  BOOST_TEST(answered > scene_like + 100);   // some of the 4-20 bit systems too
  BOOST_TEST(gave_up > 800);                 // most of the larger ones
}

// The rational kernel's orientation4 (rows scaled to coprime integers, the
// determinant in GMP integers) is the sign of the determinant itself:
// hand-worked cases, then seeded random rows (some dependent) held to
// determinant4 in rationals (kernel_ft4.h, the generic cofactor expansion).
BOOST_AUTO_TEST_CASE(rational_orientation_is_the_determinants_sign)
{
  Rational_kernel k;
  using V = Vector4<Rational>;
  V e0{q("1"), q("0"), q("0"), q("0")}, e1{q("0"), q("1"), q("0"), q("0")}, e2{q("0"), q("0"), q("1"), q("0")},
      e3{q("0"), q("0"), q("0"), q("1")};
  BOOST_TEST(k.orientation4(e0, e1, e2, e3) == CGAL::POSITIVE);
  BOOST_TEST(k.orientation4(e1, e0, e2, e3) == CGAL::NEGATIVE);   // one swap
  // diag(1/2, 1/3, -1/5, 7): det = -7/30.
  V a{q("1/2"), q("0"), q("0"), q("0")}, b{q("0"), q("1/3"), q("0"), q("0")}, c{q("0"), q("0"), q("-1/5"), q("0")},
      d{q("0"), q("0"), q("0"), q("7")};
  BOOST_TEST(k.orientation4(a, b, c, d) == CGAL::NEGATIVE);
  V sum{q("1/2"), q("1/3"), q("0"), q("0")};   // a + b: dependent
  BOOST_TEST(k.orientation4(a, b, c, sum) == CGAL::ZERO);
  V zero{q("0"), q("0"), q("0"), q("0")};
  BOOST_TEST(k.orientation4(a, zero, c, d) == CGAL::ZERO);

  std::uint64_t seed = 20261128;
  BOOST_TEST_MESSAGE("rational orientation4: seed " << seed);
  std::mt19937_64 rng(seed);
  int signs[3] = {0, 0, 0};
  for (int i = 0; i < 2000; ++i) {
    std::array<V, 4> r = random_rows(rng, 10000, 1000, i % 4 == 0);
    CGAL::Sign expected = CGAL::sign(determinant4(r[0], r[1], r[2], r[3]));
    BOOST_TEST(k.orientation4(r[0], r[1], r[2], r[3]) == expected, "rows " << i);
    ++signs[expected + 1];
  }
  BOOST_TEST((signs[0] > 500 && signs[1] >= 500 && signs[2] > 500));   // each sign met
}

// generalised_cross and determinant4 in rationals (numbers/Rational.h: each
// vector over its own common denominator, the cross product or determinant
// in integers, reduced once) are the very numbers of the formulas in
// kernel_ft4.h, held to those formulas computed in GMP's mpq_class, a
// second rational type that takes the generic path: hand-worked cases,
// then seeded random vectors, a quarter of them dependent.
BOOST_AUTO_TEST_CASE(rational_cross_and_determinant_are_the_formulas)
{
  using V = Vector4<Rational>;
  using W = Vector4<mpq_class>;
  V a{q("1/2"), q("0"), q("0"), q("0")}, b{q("0"), q("1/3"), q("0"), q("0")}, c{q("0"), q("0"), q("-1/5"), q("0")},
      d{q("0"), q("0"), q("0"), q("7")};
  // g.x = det(a, b, c, x) = (1/2)(1/3)(-1/5) x_3.
  BOOST_TEST((generalised_cross(a, b, c) == V{q("0"), q("0"), q("0"), q("-1/30")}));
  BOOST_TEST(determinant4(a, b, c, d) == q("-7/30"));
  BOOST_TEST(determinant4(b, a, c, d) == q("7/30"));   // one swap
  V sum{q("1/2"), q("1/3"), q("0"), q("0")};           // a + b: dependent
  BOOST_TEST(determinant4(a, b, c, sum) == q("0"));
  BOOST_TEST((generalised_cross(a, b, sum) == V{q("0"), q("0"), q("0"), q("0")}));

  std::uint64_t seed = 20261130;
  BOOST_TEST_MESSAGE("rational cross and determinant: seed " << seed);
  std::mt19937_64 rng(seed);
  auto wide = [](const V& v) {
    W w;
    for (int j = 0; j < 4; ++j) w[j] = mpq_class(v[j].mpq());
    return w;
  };
  int zeros = 0;
  for (int i = 0; i < 2000; ++i) {
    std::array<V, 4> r = random_rows(rng, 1000000, 100000, i % 4 == 0);
    V g = generalised_cross(r[0], r[1], r[2]);
    W h = generalised_cross(wide(r[0]), wide(r[1]), wide(r[2]));
    BOOST_TEST((wide(g) == h), "cross " << i);
    Rational det = determinant4(r[0], r[1], r[2], r[3]);
    BOOST_TEST((mpq_class(det.mpq()) == dot(h, wide(r[3]))), "determinant " << i);
    zeros += det == 0;
  }
  BOOST_TEST(zeros >= 500);   // the dependent rows are found dependent
}

// Pair_minors (kernel_ft4.h), which the search makes once per pair of
// planes for all the lines through them: in doubles and intervals its
// cross product and its minors are bit for bit the per-line formulas the
// search used before (the 3x3 cofactors of the Laplace expansion, and the
// base point's cross(r0, r1) on the three columns left when one is
// dropped), so no answer of any kernel moves; one minors object serves
// many third rows; in rationals the minors are a_i b_j - a_j b_i. Its
// cross product with a region face's normal +-e_a (cross_axis) is the same
// numbers as cross(+-e_a), in every kernel.
// Seeded random rows, a quarter of them dependent.
template <class FT>
Vector4<FT> cofactor_cross(const Vector4<FT>& a, const Vector4<FT>& b, const Vector4<FT>& c)
{
  auto m = [&](int i, int j) { return a[i] * b[j] - a[j] * b[i]; };
  FT M0 = c[1] * m(2, 3) - c[2] * m(1, 3) + c[3] * m(1, 2);
  FT M1 = c[0] * m(2, 3) - c[2] * m(0, 3) + c[3] * m(0, 2);
  FT M2 = c[0] * m(1, 3) - c[1] * m(0, 3) + c[3] * m(0, 1);
  FT M3 = c[0] * m(1, 2) - c[1] * m(0, 2) + c[2] * m(0, 1);
  return {-M0, M1, -M2, M3};
}

template <class FT, class To>
void check_pair_minors(const std::array<Vector4<Rational>, 4>& r, To to, int i)
{
  auto same = [](const FT& x, const FT& y) {
    if constexpr (std::is_same_v<FT, double>) return x == y || (std::isnan(x) && std::isnan(y));
    else return x.inf() == y.inf() && x.sup() == y.sup();
  };
  std::array<Vector4<FT>, 4> v;
  for (int p = 0; p < 4; ++p)
    for (int j = 0; j < 4; ++j) v[p][j] = to(r[p][j]);
  Pair_minors<FT> ab(v[0], v[1]);
  for (int c = 2; c < 4; ++c) {   // one object, two third rows
    Vector4<FT> g = ab.cross(v[c]), h = cofactor_cross(v[0], v[1], v[c]);
    for (int j = 0; j < 4; ++j) BOOST_TEST(same(g[j], h[j]), "cross " << i << " row " << c << " coordinate " << j);
  }
  for (int a = 0; a < 4; ++a)
    for (bool positive : {false, true}) {
      Vector4<FT> e{FT(0), FT(0), FT(0), FT(0)};
      e[a] = FT(positive ? 1 : -1);
      Vector4<FT> g = ab.cross_axis(a, positive), h = ab.cross(e);
      for (int j = 0; j < 4; ++j) BOOST_TEST(same(g[j], h[j]), "face " << i << " axis " << a << " coordinate " << j);
    }
  for (int k = 0; k < 4; ++k) {   // base_point's x01 with column k dropped
    int cols[3], n = 0;
    for (int q = 0; q < 4; ++q)
      if (q != k) cols[n++] = q;
    Vector3<FT> r0{v[0][cols[0]], v[0][cols[1]], v[0][cols[2]]}, r1{v[1][cols[0]], v[1][cols[1]], v[1][cols[2]]};
    Vector3<FT> x = cross(r0, r1);
    Vector3<FT> y{ab.minor(cols[1], cols[2]), -ab.minor(cols[0], cols[2]), ab.minor(cols[0], cols[1])};
    for (int j = 0; j < 3; ++j) BOOST_TEST(same(x[j], y[j]), "x01 " << i << " dropped " << k << " coordinate " << j);
  }
}

BOOST_AUTO_TEST_CASE(pair_minors_are_the_per_line_formulas)
{
  std::uint64_t seed = 20261128;
  BOOST_TEST_MESSAGE("pair minors: seed " << seed);
  std::mt19937_64 rng(seed);
  CGAL::Protect_FPU_rounding<true> upward;   // the interval kernel's mode
  for (int i = 0; i < 2000; ++i) {
    std::array<Vector4<Rational>, 4> r = random_rows(rng, 1000000, 100000, i % 4 == 0);
    check_pair_minors<CGAL::Interval_nt<false>>(r, [](const Rational& x) { return CGAL::to_interval(x); }, i);
    {
      CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
      check_pair_minors<double>(r, [](const Rational& x) { return CGAL::to_double(x); }, i);
      Pair_minors<Rational> ab(r[0], r[1]);
      for (int p = 0; p < 4; ++p)
        for (int q = p + 1; q < 4; ++q)
          BOOST_TEST(ab.minor(p, q) == r[0][p] * r[1][q] - r[0][q] * r[1][p], "rational minor " << i);
      for (int a = 0; a < 4; ++a)
        for (bool positive : {false, true}) {
          Vector4<Rational> e{Rational(0), Rational(0), Rational(0), Rational(0)};
          e[a] = Rational(positive ? 1 : -1);
          BOOST_TEST((ab.cross_axis(a, positive) == ab.cross(e)), "rational face " << i << " axis " << a);
        }
    }
  }
}

// coprime_integers (the rational kernel's ring and lowest terms): one
// positive factor makes the numbers coprime integers; hand-worked cases,
// then seeded random ones held to that definition.
BOOST_AUTO_TEST_CASE(coprime_integers_are_one_positive_multiple)
{
  auto coprime = [](std::vector<Rational> x) {
    std::vector<mpz_class> out(x.size());
    coprime_integers(x.data(), x.size(), out.data());
    std::vector<long> v;
    for (const auto& z : out) v.push_back(z.get_si());
    return v;
  };
  BOOST_TEST((coprime({q("1/2"), q("1/3"), q("0"), q("2/6")}) == std::vector<long>{3, 2, 0, 2}));
  BOOST_TEST((coprime({q("2/4"), q("6/4"), q("-4")}) == std::vector<long>{1, 3, -8}));
  BOOST_TEST((coprime({q("6"), q("9"), q("12")}) == std::vector<long>{2, 3, 4}));
  BOOST_TEST((coprime({q("-3/5"), q("6/5")}) == std::vector<long>{-1, 2}));
  BOOST_TEST((coprime({q("0"), q("0")}) == std::vector<long>{0, 0}));

  std::uint64_t seed = 20261129;
  BOOST_TEST_MESSAGE("coprime integers: seed " << seed);
  std::mt19937_64 rng(seed);
  for (int i = 0; i < 3000; ++i) {
    std::vector<Rational> x(5);
    long shared = static_cast<long>(1 + rng() % 30);   // denominators often shared, as a plane's are
    for (auto& v : x) {
      long den = rng() % 2 ? shared : static_cast<long>(1 + rng() % 30);
      v = rng() % 5 == 0 ? Rational(0) : Rational(static_cast<long>(rng() % 2001) - 1000) / Rational(den);
    }
    std::vector<mpz_class> out(5);
    coprime_integers(x.data(), 5, out.data());
    mpz_class g = 0;
    std::optional<Rational> factor;
    for (int j = 0; j < 5; ++j) {
      mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), out[j].get_mpz_t());
      BOOST_TEST((sgn(out[j]) == 0) == (CGAL::sign(x[j]) == CGAL::ZERO), "case " << i);
      if (CGAL::sign(x[j]) == CGAL::ZERO) continue;
      Rational f = Rational(CGAL::Gmpz(out[j].get_mpz_t())) / x[j];
      BOOST_TEST(CGAL::sign(f) == CGAL::POSITIVE, "case " << i);
      if (factor) BOOST_TEST((f == *factor), "case " << i << ": not one factor");
      factor = f;
    }
    BOOST_TEST((g == 1 || g == 0), "case " << i << ": not coprime");
  }
}

// swap_numbers exchanges numbers (rationals by their handles' pointers,
// which no value shows: only the values are held), and a pair's result moved
// into its slot (Pair_result's move assignment, by exchange) arrives with
// every member: a member left out of Pair_result::swap fails here.
BOOST_AUTO_TEST_CASE(swapped_rationals_and_moved_pair_results_keep_every_member)
{
  Rational a = q("1/3"), b = q("-2/7");
  swap_numbers(a, b);
  BOOST_TEST((a == q("-2/7") && b == q("1/3")));
  Vector4<double> x{1, 2, 3, 4}, y{5, 6, 7, 8};
  swap_numbers(x, y);
  BOOST_TEST((x == Vector4<double>{5, 6, 7, 8} && y == Vector4<double>{1, 2, 3, 4}));

  Pair_result<Rational> from;
  from.a = 3;
  from.b = 5;
  from.collide = from.has_witness = from.witness_verified = from.earliest = true;
  from.witness = {q("1/2"), q("1/3"), q("1/5"), q("1/7")};
  from.t_star = q("9/4");
  from.contact = {q("-1/2"), q("-1/3"), q("-1/5"), q("9/4")};
  from.semantics = Semantics::closed;
  from.witness_cells = {{q("1"), q("2"), q("3"), q("4")}, {q("5"), q("6"), q("7"), q("8")}};
  from.contact_cells = {{q("-1"), q("-2"), q("-3"), q("9/4")}, {q("-5"), q("-6"), q("-7"), q("9/4")}};
  const Pair_result<Rational> expected = from;
  Pair_result<Rational> to;
  to = std::move(from);
  BOOST_TEST((to.a == 3 && to.b == 5));
  BOOST_TEST((to.collide && to.has_witness && to.witness_verified && to.earliest));
  BOOST_TEST((to.witness == expected.witness));
  BOOST_TEST((to.t_star == expected.t_star));
  BOOST_TEST((to.contact == expected.contact));
  BOOST_TEST((to.semantics == Semantics::closed));
  BOOST_TEST((to.witness_cells == expected.witness_cells));
  BOOST_TEST((to.contact_cells == expected.contact_cells));
}
