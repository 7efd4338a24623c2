#include "verify/Rational_poly.h"
#include <algorithm>
#include <stdexcept>
#include <utility>

namespace clash4d::verifier {

Rational_poly::Rational_poly(std::vector<mpq_class> coefficients) : c_(std::move(coefficients))
{
  for (mpq_class& c : c_) c.canonicalize();   // GMP's rationals compute right only in lowest terms
  trim();
}

void Rational_poly::trim()
{
  while (!c_.empty() && c_.back() == 0) c_.pop_back();
}

mpq_class Rational_poly::operator()(const mpq_class& t) const
{
  mpq_class v = 0;
  for (auto it = c_.rbegin(); it != c_.rend(); ++it) v = v * t + *it;
  return v;
}

Rational_poly Rational_poly::derivative() const
{
  std::vector<mpq_class> d;
  for (std::size_t i = 1; i < c_.size(); ++i) d.push_back(c_[i] * static_cast<long>(i));
  return Rational_poly(std::move(d));
}

Rational_poly Rational_poly::monic() const
{
  if (is_zero()) return *this;
  return mpq_class(1 / lead()) * *this;
}

Rational_poly operator+(const Rational_poly& a, const Rational_poly& b)
{
  std::vector<mpq_class> s(std::max(a.c_.size(), b.c_.size()), mpq_class(0));
  for (std::size_t i = 0; i < a.c_.size(); ++i) s[i] += a.c_[i];
  for (std::size_t i = 0; i < b.c_.size(); ++i) s[i] += b.c_[i];
  return Rational_poly(std::move(s));
}

Rational_poly operator-(const Rational_poly& a, const Rational_poly& b) { return a + (-b); }

Rational_poly operator*(const Rational_poly& a, const Rational_poly& b)
{
  if (a.is_zero() || b.is_zero()) return {};
  std::vector<mpq_class> p(a.c_.size() + b.c_.size() - 1, mpq_class(0));
  for (std::size_t i = 0; i < a.c_.size(); ++i)
    for (std::size_t j = 0; j < b.c_.size(); ++j) p[i + j] += a.c_[i] * b.c_[j];
  return Rational_poly(std::move(p));
}

Rational_poly operator*(const mpq_class& k, const Rational_poly& a)
{
  std::vector<mpq_class> p(a.c_);
  for (mpq_class& c : p) c *= k;
  return Rational_poly(std::move(p));
}

void divmod(const Rational_poly& a, const Rational_poly& b, Rational_poly& q, Rational_poly& r)
{
  if (b.is_zero()) throw std::logic_error("polynomial division by zero");
  std::vector<mpq_class> rem = a.coefficients(), quo;
  int db = b.degree();
  if (a.degree() >= db) quo.assign(a.degree() - db + 1, mpq_class(0));
  for (int k = a.degree() - db; k >= 0; --k) {
    mpq_class f = rem[k + db] / b.lead();
    quo[k] = f;
    for (int i = 0; i <= db; ++i) rem[k + i] -= f * b.coefficients()[i];
  }
  q = Rational_poly(std::move(quo));
  r = Rational_poly(std::move(rem));
}

Rational_poly exact_div(const Rational_poly& a, const Rational_poly& b)
{
  Rational_poly q, r;
  divmod(a, b, q, r);
  if (!r.is_zero()) throw std::logic_error("inexact polynomial division");
  return q;
}

namespace {

// Remainder sequences (gcds, Sturm) are kept fraction-free: each member
// is a positive multiple of the true one (the same signs everywhere), with
// coprime integer coefficients from the constant term up.
using Integer_poly = std::vector<mpz_class>;

// A positive multiple of p with coprime integer coefficients; p not zero.
Integer_poly primitive_integer(const Rational_poly& p)
{
  mpz_class den = 1, num = 0;
  for (const mpq_class& c : p.coefficients()) {
    mpz_lcm(den.get_mpz_t(), den.get_mpz_t(), c.get_den_mpz_t());
    mpz_gcd(num.get_mpz_t(), num.get_mpz_t(), c.get_num_mpz_t());
  }
  Integer_poly out;
  for (const mpq_class& c : p.coefficients()) out.push_back(c.get_num() * (den / c.get_den()) / num);
  return out;
}

// A positive multiple of the remainder of a by b (deg b >= 0), divided by
// its content: pseudo-division by |lc(b)|, which keeps the sign, with
// deg a - deg b + 1 steps (the remainder of |lc(b)|^(that) a by b).
Integer_poly positive_remainder(Integer_poly r, const Integer_poly& b)
{
  std::size_t db = b.size() - 1;
  mpz_class l = abs(b.back());
  int s = sgn(b.back());
  // Step k cancels the coefficient of t^(k + db), for k = deg r - db down to 0.
  for (std::size_t k = r.size() > db ? r.size() - db : 0; k-- > 0;) {
    mpz_class lead = r[k + db] * s;
    for (mpz_class& c : r) c *= l;
    for (std::size_t i = 0; i <= db; ++i) r[k + i] -= lead * b[i];
  }
  r.resize(std::min(r.size(), db));
  while (!r.empty() && r.back() == 0) r.pop_back();
  mpz_class g = 0;
  for (const mpz_class& c : r) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_mpz_t());
  for (mpz_class& c : r) mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), g.get_mpz_t());
  return r;
}

} // namespace

Rational_poly gcd(const Rational_poly& a, const Rational_poly& b)
{
  if (a.is_zero() || b.is_zero()) return (a.is_zero() ? b : a).monic();
  Integer_poly x = primitive_integer(a), y = primitive_integer(b);
  while (!y.empty()) {   // Euclid on primitive remainders: the numbers stay small
    Integer_poly r = positive_remainder(x, y);
    x = std::move(y), y = std::move(r);
  }
  std::vector<mpq_class> c(x.begin(), x.end());
  return Rational_poly(std::move(c)).monic();
}

std::vector<Rational_poly> square_free_factors(const Rational_poly& f)
{
  std::vector<Rational_poly> out;
  Rational_poly d = f.derivative(), a = gcd(f, d);
  Rational_poly b = exact_div(f, a), c = exact_div(d, a);
  Rational_poly e = c - b.derivative();
  while (b.degree() > 0) {   // Yun's loop
    Rational_poly g = gcd(b, e);
    out.push_back(g);
    b = exact_div(b, g), c = exact_div(e, g);
    e = c - b.derivative();
  }
  return out;
}

Rational_poly odd_part(const Rational_poly& f)
{
  std::vector<Rational_poly> factors = square_free_factors(f);
  Rational_poly s = Rational_poly::constant(1);
  for (std::size_t i = 0; i < factors.size(); ++i)
    for (std::size_t k = 0; k < (i + 1) / 2; ++k) s = s * factors[i];
  return exact_div(f, s * s);
}

Rational_poly square_free_part(const Rational_poly& f) { return exact_div(f, gcd(f, f.derivative())); }

namespace {

// The sign of p at x = n/d (d > 0): of d^deg p(n/d), an integer.
int sign_at(const Integer_poly& p, const mpq_class& x)
{
  mpz_class v = 0, dpow = 1;
  const mpz_class &n = x.get_num(), &d = x.get_den();
  for (std::size_t i = p.size(); i-- > 0;) {
    v = v * n + p[i] * dpow;
    dpow *= d;
  }
  return sgn(v);
}

// Sign changes of the sequence at x, zeros skipped.
long variations(const std::vector<Integer_poly>& seq, const mpq_class& x)
{
  long changes = 0;
  int last = 0;
  for (const Integer_poly& p : seq) {
    int s = sign_at(p, x);
    if (s != 0 && last != 0 && s != last) ++changes;
    if (s != 0) last = s;
  }
  return changes;
}

// f divided by (t - x) as long as it divides.
Rational_poly without_root(Rational_poly f, const mpq_class& x)
{
  Rational_poly q, r, lin = Rational_poly::linear(-x, 1);
  while (f.degree() > 0 && f(x) == 0) {
    divmod(f, lin, q, r);
    f = q;
  }
  return f;
}

// Sturm: f, f', then minus the remainders; a positive scale keeps signs.
// f of degree at least one.
std::vector<Integer_poly> sturm(const Rational_poly& f)
{
  std::vector<Integer_poly> seq{primitive_integer(f), primitive_integer(f.derivative())};
  while (true) {
    Integer_poly r = positive_remainder(seq[seq.size() - 2], seq.back());
    if (r.empty()) break;
    for (mpz_class& c : r) c = -c;
    seq.push_back(std::move(r));
  }
  return seq;
}

} // namespace

long count_roots(const Rational_poly& f0, const mpq_class& x, const mpq_class& y)
{
  if (f0.is_zero()) throw std::logic_error("counting the roots of the zero polynomial");
  Rational_poly f = without_root(without_root(f0, x), y);
  if (f.degree() <= 0) return 0;
  std::vector<Integer_poly> seq = sturm(f);
  return variations(seq, x) - variations(seq, y);
}

Sturm_sequence::Sturm_sequence(const Rational_poly& f) : f_(f)
{
  if (f.is_zero()) throw std::logic_error("counting the roots of the zero polynomial");
  if (f.degree() > 0) seq_ = sturm(f);
}

long Sturm_sequence::count(const mpq_class& x, const mpq_class& y) const
{
  if (f_.degree() <= 0) return 0;
  if (f_(x) == 0 || f_(y) == 0) return count_roots(f_, x, y);
  return variations(seq_, x) - variations(seq_, y);
}

} // namespace clash4d::verifier
