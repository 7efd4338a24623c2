#include "numbers/Rational.h"

#include <mpfr.h>
#include <stdexcept>
#include <utility>
#include <vector>

namespace clash4d {

std::string to_string(const Rational& q)
{
  // Gmpq is always canonical (lowest terms, positive denominator), and GMP
  // prints "p" when q = 1 and "p/q" otherwise: exactly the spec's form.
  char* text = mpq_get_str(nullptr, 10, q.mpq());
  std::string out(text);
  void (*free_fn)(void*, size_t);
  mp_get_memory_functions(nullptr, nullptr, &free_fn);
  free_fn(text, out.size() + 1);
  return out;
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

// Bareiss: after step k, row i > k holds (a_kk a_ij - a_ik a_kj) / p, p the
// previous pivot, an exact division (each entry is a minor of the scaled
// matrix); the rows stay combinations of the system's, so the triangle has
// the same solution, and its last pivot D is the determinant up to sign.
// By Cramer, y_i = D x_i is an integer, found from the bottom up as
// (D c_i - sum_j>i u_ij y_j) / u_ii, again exact.
void solve_regular(const Rational* m, std::size_t n, Rational* x)
{
  const std::size_t w = n + 1;
  std::vector<mpz_class> a(n * w);
  for (std::size_t i = 0; i < n; ++i) coprime_integers(m + i * w, w, a.data() + i * w);
  auto at = [&](std::size_t i, std::size_t j) -> mpz_class& { return a[i * w + j]; };
  mpz_class previous = 1;
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    while (p < n && sgn(at(p, k)) == 0) ++p;
    if (p == n) throw std::logic_error("internal error: solve_regular on a singular system");
    if (p != k)
      for (std::size_t j = k; j < w; ++j) std::swap(at(p, j), at(k, j));
    for (std::size_t i = k + 1; i < n; ++i) {
      for (std::size_t j = k + 1; j < w; ++j) {
        at(i, j) = at(k, k) * at(i, j) - at(i, k) * at(k, j);
        mpz_divexact(at(i, j).get_mpz_t(), at(i, j).get_mpz_t(), previous.get_mpz_t());
      }
      at(i, k) = 0;
    }
    previous = at(k, k);
  }
  const mpz_class& d = at(n - 1, n - 1);
  std::vector<mpz_class> y(n);
  for (std::size_t i = n; i-- > 0;) {
    mpz_class s = d * at(i, n);
    for (std::size_t j = i + 1; j < n; ++j) s -= at(i, j) * y[j];
    mpz_divexact(y[i].get_mpz_t(), s.get_mpz_t(), at(i, i).get_mpz_t());
  }
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
} // namespace

Rational sum_of_products(const Rational* a, const Rational* b, std::size_t n)
{
  thread_local Dot_scratch s;
  mpz_set_ui(s.num, 0);
  mpz_set_ui(s.den, 1);
  for (std::size_t i = 0; i < n; ++i) {
    mpz_srcptr an = mpq_numref(a[i].mpq()), bn = mpq_numref(b[i].mpq());
    if (mpz_sgn(an) == 0 || mpz_sgn(bn) == 0) continue;
    mpz_mul(s.pn, an, bn);
    mpz_mul(s.pd, mpq_denref(a[i].mpq()), mpq_denref(b[i].mpq()));
    if (mpz_cmp(s.pd, s.den) == 0) {   // num/den + pn/den
      mpz_add(s.num, s.num, s.pn);
      continue;
    }
    // num/den + pn/pd = (num pd + pn den) / (den pd)
    mpz_mul(s.num, s.num, s.pd);
    mpz_addmul(s.num, s.pn, s.den);
    mpz_mul(s.den, s.den, s.pd);
  }
  Rational out;   // a new representation, not shared: written in place
  mpz_set(mpq_numref(out.mpq()), s.num);
  mpz_set(mpq_denref(out.mpq()), s.den);
  mpq_canonicalize(out.mpq());
  return out;
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

} // namespace clash4d
