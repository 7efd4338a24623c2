#include "numbers/Rational.h"

#include <mpfr.h>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <utility>
#include <vector>

namespace clash4d {

namespace {

// The magnitude of z when it fits one limb (64 bits, or 32 on a 32-bit GMP).
bool one_limb(mpz_srcptr z, std::uint64_t& magnitude)
{
  static_assert(sizeof(mp_limb_t) <= sizeof(std::uint64_t), "a GMP limb of at most 64 bits");
  if (mpz_size(z) > 1) return false;
  magnitude = mpz_size(z) == 0 ? 0 : mpz_getlimbn(z, 0);
  return true;
}

} // namespace

Rational rational_from_string(const std::string& text)
{
  std::size_t slash = text.find('/');
  auto digits = [&](std::size_t from, std::size_t to) {
    return to > from && text.find_first_not_of("0123456789", from) >= to;
  };
  std::size_t start = !text.empty() && text[0] == '-' ? 1 : 0;
  bool ok = slash == std::string::npos ? digits(start, text.size())
                                       : digits(start, slash) && digits(slash + 1, text.size());
  mpq_class q;
  if (!ok || q.set_str(text, 10) != 0 || q.get_den() == 0)
    throw std::invalid_argument("not a rational printed as p or p/q: '" + text.substr(0, 40) + "'");
  q.canonicalize();
  return Rational(q.get_mpq_t());
}

std::string to_string(const Rational& q)
{
  // Gmpq is always canonical (lowest terms, positive denominator), and GMP
  // prints "p" when q = 1 and "p/q" otherwise: exactly the spec's form.
  // Parts of one limb each (a snapped witness's coordinates, the scene's
  // fractions) are printed with std::to_chars in that same form:
  // mpq_get_str costs several times as much, and an answer prints up to
  // 27 numbers.
  std::uint64_t n = 0, d = 0;
  if (one_limb(mpq_numref(q.mpq()), n) && one_limb(mpq_denref(q.mpq()), d)) {
    char text[2 * 20 + 3];   // a sign, two parts of at most 20 digits, the slash
    char* end = text;
    if (mpq_sgn(q.mpq()) < 0) *end++ = '-';
    end = std::to_chars(end, text + sizeof text, n).ptr;
    if (d != 1) {
      *end++ = '/';
      end = std::to_chars(end, text + sizeof text, d).ptr;
    }
    return std::string(text, end);
  }
  // Otherwise written by GMP into the string itself, sized as GMP's manual
  // gives (each part's digits, at most one more than mpz_sizeinbase says,
  // a sign, the slash and the terminator), then cut at the terminator.
  std::string out(mpz_sizeinbase(mpq_numref(q.mpq()), 10) + mpz_sizeinbase(mpq_denref(q.mpq()), 10) + 5, '\0');
  mpq_get_str(out.data(), 10, q.mpq());
  out.resize(std::strlen(out.c_str()));
  return out;
}

Rational exact_rational(double x)
{
  if (!std::isfinite(x)) throw std::invalid_argument("internal error: exact_rational of a non-finite double");
  Rational q;   // a new number, so writing through mpq() touches no other
  if (x == 0) return q;
  int e = 0;
  // x = m 2^e with m an integer of at most 53 bits (ldexp by 53 is exact).
  auto m = static_cast<std::int64_t>(std::ldexp(std::frexp(x, &e), 53));
  e -= 53;
  int zeros = __builtin_ctzll(static_cast<unsigned long long>(m));   // m odd: lowest terms
  m >>= zeros;   // arithmetic shift of a multiple of 2^zeros: exact for negative m too
  e += zeros;
  if (e >= 0 && e < 10) {   // an integer of at most 63 bits (|m| < 2^53): in the numerator's one limb
    mpz_set_si(mpq_numref(q.mpq()), m * (std::int64_t{1} << e));
  } else if (e >= 0) {
    mpz_set_si(mpq_numref(q.mpq()), m);
    mpz_mul_2exp(mpq_numref(q.mpq()), mpq_numref(q.mpq()), static_cast<mp_bitcnt_t>(e));
  } else {
    mpz_set_si(mpq_numref(q.mpq()), m);
    mpz_set_ui(mpq_denref(q.mpq()), 0);
    mpz_setbit(mpq_denref(q.mpq()), static_cast<mp_bitcnt_t>(-e));
  }
  return q;
}

Rational floor_to_grid(const Rational& q, int bits)
{
  mpz_t n;
  mpz_init(n);
  mpz_mul_2exp(n, mpq_numref(q.mpq()), static_cast<mp_bitcnt_t>(bits));
  mpz_fdiv_q(n, n, mpq_denref(q.mpq()));
  mpq_t r;
  mpq_init(r);
  mpq_set_z(r, n);
  mpq_div_2exp(r, r, static_cast<mp_bitcnt_t>(bits));
  Rational out(r);
  mpq_clear(r);
  mpz_clear(n);
  return out;
}

bool is_exact_dyadic(const Rational& q, int bits)
{
  const mpz_srcptr den = mpq_denref(q.mpq()), num = mpq_numref(q.mpq());
  bool power_of_two = mpz_popcount(den) == 1;
  return power_of_two && mpz_sizeinbase(den, 2) <= static_cast<std::size_t>(bits) + 1 &&
         (mpz_sgn(num) == 0 || mpz_sizeinbase(num, 2) <= 53);
}

void over_common_denominator(const Rational* x, std::size_t n, mpz_class* X, mpz_class& d)
{
  // A gcd only where it can change the result: a denominator the lcm
  // already holds (1, or one shared with an earlier number, as a plane's
  // often is) leaves it.
  d = 1;
  for (std::size_t i = 0; i < n; ++i)
    if (!mpz_divisible_p(d.get_mpz_t(), mpq_denref(x[i].mpq())))
      mpz_lcm(d.get_mpz_t(), d.get_mpz_t(), mpq_denref(x[i].mpq()));
  for (std::size_t i = 0; i < n; ++i) {
    if (mpz_cmp(d.get_mpz_t(), mpq_denref(x[i].mpq())) == 0) {   // the factor is 1 (integers: always)
      mpz_set(X[i].get_mpz_t(), mpq_numref(x[i].mpq()));
      continue;
    }
    mpz_divexact(X[i].get_mpz_t(), d.get_mpz_t(), mpq_denref(x[i].mpq()));
    mpz_mul(X[i].get_mpz_t(), X[i].get_mpz_t(), mpq_numref(x[i].mpq()));
  }
}

void coprime_integers(const Rational* x, std::size_t n, mpz_class* out)
{
  mpz_class d, gcd = 0;
  over_common_denominator(x, n, out, d);
  for (std::size_t i = 0; i < n && gcd != 1; ++i) mpz_gcd(gcd.get_mpz_t(), gcd.get_mpz_t(), out[i].get_mpz_t());
  if (sgn(gcd) == 0 || gcd == 1) return;   // once the gcd is 1 it stays 1
  for (std::size_t i = 0; i < n; ++i) mpz_divexact(out[i].get_mpz_t(), out[i].get_mpz_t(), gcd.get_mpz_t());
}

void scale_to_coprime_integers(Rational* x, std::size_t n)
{
  std::vector<mpz_class> z(n);
  coprime_integers(x, n, z.data());
  // New numbers, not writes through mpq(): Gmpq shares its representation.
  for (std::size_t i = 0; i < n; ++i) x[i] = Rational(CGAL::Gmpz(z[i].get_mpz_t()));
}

namespace {

// 128-bit integers with every operation checked: the small path of
// solve_regular, which gives up at the first result that does not fit.
using Wide = __int128;
using Wide_magnitude = unsigned __int128;
// -2^127 is refused wherever a result is made, so that every magnitude
// and every quotient below fits.
constexpr Wide wide_min = static_cast<Wide>(static_cast<Wide_magnitude>(1) << 127);

bool checked_mul(Wide a, Wide b, Wide& out) { return !__builtin_mul_overflow(a, b, &out) && out != wide_min; }

Wide_magnitude magnitude(Wide a) { return a < 0 ? -static_cast<Wide_magnitude>(a) : static_cast<Wide_magnitude>(a); }

// gcd(|a|, |b|), which fits: neither is -2^127.
Wide wide_gcd(Wide a, Wide b)
{
  Wide_magnitude x = magnitude(a), y = magnitude(b);
  while (y != 0) x = std::exchange(y, x % y);
  return static_cast<Wide>(x);
}

void set_wide(mpz_ptr z, Wide v)
{
  Wide_magnitude m = magnitude(v);
  const std::uint64_t limbs[2] = {static_cast<std::uint64_t>(m), static_cast<std::uint64_t>(m >> 64)};
  mpz_import(z, 2, -1, sizeof limbs[0], 0, 0, limbs);
  if (v < 0) mpz_neg(z, z);
}

// The integer arithmetic of bareiss: each operation writes `out` and says
// whether its result fits (GMP's always does; out may alias an argument).
struct Wide_arithmetic {
  static bool is_zero(Wide a) { return a == 0; }
  // out = a b - c d
  static bool det2(Wide a, Wide b, Wide c, Wide d, Wide& out)
  {
    Wide p, q;
    return checked_mul(a, b, p) && checked_mul(c, d, q) && !__builtin_sub_overflow(p, q, &out) && out != wide_min;
  }
  static bool mul(Wide a, Wide b, Wide& out) { return checked_mul(a, b, out); }
  // out -= a b
  static bool sub_mul(Wide a, Wide b, Wide& out)
  {
    Wide t;
    return checked_mul(a, b, t) && !__builtin_sub_overflow(out, t, &out) && out != wide_min;
  }
  static void divexact(Wide& out, Wide a, Wide b) { out = a / b; }   // exact, and a != -2^127
};

struct Gmp_arithmetic {
  static bool is_zero(const mpz_class& a) { return sgn(a) == 0; }
  static bool det2(const mpz_class& a, const mpz_class& b, const mpz_class& c, const mpz_class& d, mpz_class& out)
  {
    out = a * b - c * d;
    return true;
  }
  static bool mul(const mpz_class& a, const mpz_class& b, mpz_class& out) { return out = a * b, true; }
  static bool sub_mul(const mpz_class& a, const mpz_class& b, mpz_class& out) { return out -= a * b, true; }
  static void divexact(mpz_class& out, const mpz_class& a, const mpz_class& b)
  {
    mpz_divexact(out.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  }
};

// Bareiss: after step k, row i > k holds (a_kk a_ij - a_ik a_kj) / p, p the
// previous pivot, an exact division (each entry is a minor of the scaled
// matrix); the rows stay combinations of the system's, so the triangle has
// the same solution, and its last pivot D is the determinant up to sign.
// By Cramer, y_i = D x_i is an integer, found from the bottom up as
// (D c_i - sum_j>i u_ij y_j) / u_ii, again exact.
// a: the n x (n + 1) rows, as integers I in arithmetic A; y and d: the
// solution's numerators over the determinant. False when a result does not
// fit (A refuses it); throws std::logic_error when the matrix is singular.
template <class I, class A>
bool bareiss(I* a, std::size_t n, I* y, I& d)
{
  const std::size_t w = n + 1;
  auto at = [&](std::size_t i, std::size_t j) -> I& { return a[i * w + j]; };
  I previous(1);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    while (p < n && A::is_zero(at(p, k))) ++p;
    if (p == n) throw std::logic_error("internal error: solve_regular on a singular system");
    if (p != k)
      for (std::size_t j = k; j < w; ++j) std::swap(at(p, j), at(k, j));
    for (std::size_t i = k + 1; i < n; ++i) {
      for (std::size_t j = k + 1; j < w; ++j) {
        if (!A::det2(at(k, k), at(i, j), at(i, k), at(k, j), at(i, j))) return false;
        A::divexact(at(i, j), at(i, j), previous);
      }
      at(i, k) = 0;
    }
    previous = at(k, k);
  }
  d = at(n - 1, n - 1);
  for (std::size_t i = n; i-- > 0;) {
    I s;
    if (!A::mul(d, at(i, n), s)) return false;
    for (std::size_t j = i + 1; j < n; ++j)
      if (!A::sub_mul(at(i, j), y[j], s)) return false;
    A::divexact(y[i], s, at(i, i));
  }
  return true;
}

// Row x[0..w) as coprime integers (coprime_integers), when its numerators
// and denominators fit in a long and the common denominator's products fit.
bool small_coprime_row(const Rational* x, std::size_t w, Wide* out)
{
  Wide lcm = 1, gcd = 0;
  for (std::size_t i = 0; i < w; ++i) {
    mpz_srcptr num = mpq_numref(x[i].mpq()), den = mpq_denref(x[i].mpq());
    if (!mpz_fits_slong_p(num) || !mpz_fits_slong_p(den)) return false;
    Wide d = mpz_get_si(den);
    if (!checked_mul(lcm / wide_gcd(lcm, d), d, lcm)) return false;
  }
  for (std::size_t i = 0; i < w; ++i) {
    if (!checked_mul(lcm / mpz_get_si(mpq_denref(x[i].mpq())), mpz_get_si(mpq_numref(x[i].mpq())), out[i]))
      return false;
    gcd = wide_gcd(gcd, out[i]);
  }
  for (std::size_t i = 0; gcd > 1 && i < w; ++i) out[i] /= gcd;
  return true;
}

} // namespace

// The same elimination in 128-bit integers first: the same integers as
// GMP's wherever it goes on, so the same rationals (lowest terms are unique).
bool solve_regular_small(const Rational* m, std::size_t n, Rational* x)
{
  constexpr std::size_t most = 6;
  const std::size_t w = n + 1;
  if (n == 0 || n > most) return false;
  Wide a[most * (most + 1)], y[most], d = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (!small_coprime_row(m + i * w, w, a + i * w)) return false;
  if (!bareiss<Wide, Wide_arithmetic>(a, n, y, d)) return false;
  for (std::size_t i = 0; i < n; ++i) {
    Rational q;   // a new number, so writing through mpq() touches no other
    set_wide(mpq_numref(q.mpq()), y[i]);
    set_wide(mpq_denref(q.mpq()), d);
    mpq_canonicalize(q.mpq());
    x[i] = std::move(q);
  }
  return true;
}

void solve_regular(const Rational* m, std::size_t n, Rational* x)
{
  if (solve_regular_small(m, n, x)) return;
  const std::size_t w = n + 1;
  std::vector<mpz_class> a(n * w), y(n);
  mpz_class d;
  for (std::size_t i = 0; i < n; ++i) coprime_integers(m + i * w, w, a.data() + i * w);
  bareiss<mpz_class, Gmp_arithmetic>(a.data(), n, y.data(), d);
  for (std::size_t i = 0; i < n; ++i) x[i] = quotient_of_integers(y[i], d);
}

Rational quotient_of_integers(const mpz_class& num, const mpz_class& den)
{
  Rational q;   // a new number, so writing through mpq() touches no other
  mpz_set(mpq_numref(q.mpq()), num.get_mpz_t());
  mpz_set(mpq_denref(q.mpq()), den.get_mpz_t());
  mpq_canonicalize(q.mpq());   // lowest terms, the denominator made positive
  return q;
}

namespace {
// Per-thread GMP integers for sum_of_products, kept so that their limbs are
// allocated once per thread, not once per call.
struct Dot_scratch {
  mpz_t num, den, pn, pd;
  Dot_scratch() { mpz_inits(num, den, pn, pd, nullptr); }
  ~Dot_scratch() { mpz_clears(num, den, pn, pd, nullptr); }
};

// num / den = (plus) + sum a[i] b[i], or with subtract (plus) - sum,
// unreduced, den > 0, in s.
void accumulate(Dot_scratch& s, const Rational* a, const Rational* b, std::size_t n, const Rational* plus,
                bool subtract = false)
{
  mpz_set_ui(s.num, 0);
  mpz_set_ui(s.den, 1);
  auto add = [&s](mpz_srcptr pn, mpz_srcptr pd) {   // pn / pd, pd > 0
    if (mpz_cmp(pd, s.den) == 0) {                  // num/den + pn/den
      mpz_add(s.num, s.num, pn);
      return;
    }
    // num/den + pn/pd = (num pd + pn den) / (den pd)
    mpz_mul(s.num, s.num, pd);
    mpz_addmul(s.num, pn, s.den);
    mpz_mul(s.den, s.den, pd);
  };
  for (std::size_t i = 0; i < n; ++i) {
    mpz_srcptr an = mpq_numref(a[i].mpq()), bn = mpq_numref(b[i].mpq());
    if (mpz_sgn(an) == 0 || mpz_sgn(bn) == 0) continue;
    mpz_mul(s.pn, an, bn);
    if (subtract) mpz_neg(s.pn, s.pn);
    mpz_mul(s.pd, mpq_denref(a[i].mpq()), mpq_denref(b[i].mpq()));
    add(s.pn, s.pd);
  }
  if (plus && mpz_sgn(mpq_numref(plus->mpq())) != 0) add(mpq_numref(plus->mpq()), mpq_denref(plus->mpq()));
}

// num / den of s in lowest terms, as a new representation written in place.
Rational reduced(const Dot_scratch& s)
{
  Rational out;
  mpz_set(mpq_numref(out.mpq()), s.num);
  mpz_set(mpq_denref(out.mpq()), s.den);
  mpq_canonicalize(out.mpq());
  return out;
}
} // namespace

Rational sum_of_products(const Rational* a, const Rational* b, std::size_t n, const Rational* plus)
{
  thread_local Dot_scratch s;
  accumulate(s, a, b, n, plus);
  return reduced(s);
}

Rational difference_of_products(const Rational* c, const Rational* a, const Rational* b, std::size_t n)
{
  thread_local Dot_scratch s;
  accumulate(s, a, b, n, c, true);
  return reduced(s);
}

int sign_of_sum_of_products(const Rational* a, const Rational* b, std::size_t n, const Rational* plus)
{
  thread_local Dot_scratch s;
  accumulate(s, a, b, n, plus);
  return mpz_sgn(s.num);   // the denominator is a product of positive ones
}

Rational power_of_two(int e)
{
  mpq_t r;
  mpq_init(r);
  mpq_set_ui(r, 1, 1);
  if (e >= 0) mpq_mul_2exp(r, r, static_cast<mp_bitcnt_t>(e));
  else mpq_div_2exp(r, r, static_cast<mp_bitcnt_t>(-e));
  Rational out(r);
  mpq_clear(r);
  return out;
}

int grid_exponent(const Rational& q)
{
  // floor(log2 q) is e = bits(num) - bits(den) or one less: e holds when
  // num >= den * 2^e.
  const mpz_srcptr num = mpq_numref(q.mpq()), den = mpq_denref(q.mpq());
  long e = static_cast<long>(mpz_sizeinbase(num, 2)) - static_cast<long>(mpz_sizeinbase(den, 2));
  mpz_t a, b;
  mpz_init_set(a, num);
  mpz_init_set(b, den);
  if (e >= 0) mpz_mul_2exp(b, b, static_cast<mp_bitcnt_t>(e));
  else mpz_mul_2exp(a, a, static_cast<mp_bitcnt_t>(-e));
  if (mpz_cmp(a, b) < 0) --e;
  mpz_clear(a);
  mpz_clear(b);
  return static_cast<int>(-e);
}

double round_to_nearest(const Rational& q)
{
  mpfr_t r;
  mpfr_init2(r, 53);
  mpfr_set_q(r, q.mpq(), MPFR_RNDN);
  double d = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  return d;
}

namespace {

Rational floor_of(const Rational& q)
{
  mpz_class n(q.numerator().mpz()), d(q.denominator().mpz()), f;
  mpz_fdiv_q(f.get_mpz_t(), n.get_mpz_t(), d.get_mpz_t());
  return Rational(CGAL::Gmpz(f.get_mpz_t()));
}

// The simplest q with lo < q < hi; hi_infinite: no upper end.
Rational simplest(const Rational& lo, const Rational& hi, bool hi_infinite)
{
  Rational f = floor_of(lo), next = f + 1;
  if (hi_infinite || next < hi) return next;
  // lo and hi lie in [f, f + 1]: continue on the reciprocals of what is left.
  Rational a = hi - f, b = lo - f;   // 0 < a <= 1, 0 <= b < a
  bool b_zero = CGAL::sign(b) == CGAL::ZERO;
  Rational inner = simplest(Rational(1) / a, b_zero ? Rational(0) : Rational(1) / b, b_zero);
  return f + Rational(1) / inner;
}

} // namespace

Rational simplest_between(const Rational& lo, const Rational& hi)
{
  if (!(lo < hi)) throw std::logic_error("simplest_between: an empty interval");
  if (lo < 0 && 0 < hi) return Rational(0);
  if (hi <= 0) return -simplest(-hi, -lo, false);
  return simplest(lo, hi, false);
}

} // namespace clash4d
