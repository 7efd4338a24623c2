#include "exact/Ccd_rational_kernel.h"

namespace clash4d {

Ccd_rational_kernel::Scaled Ccd_rational_kernel::scaled(const Ccd_query& q, const Rational& separation)
{
  mpz_class l = 1;
  auto take = [&](const Rational& x) { mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), mpq_denref(x.mpq())); };
  for (const auto& row : q.rows())
    for (const Rational& x : row) take(x);
  take(separation);
  auto scale = [&](const Rational& x) {
    mpz_class out;
    mpz_divexact(out.get_mpz_t(), l.get_mpz_t(), mpq_denref(x.mpq()));
    out *= mpz_class(mpq_numref(x.mpq()));
    return out;
  };
  Scaled s;
  for (std::size_t i = 0; i < 8; ++i)
    for (std::size_t k = 0; k < 3; ++k) s.rows[i][k] = scale(q.rows()[i][k]);
  s.separation = scale(separation);
  return s;
}

Ccd_rational_kernel::Ccd_rational_kernel(const Ccd_query& q, const Rational& separation)
  : s_(scaled(q, separation)),
    p_(q.type(), s_.rows,
       sgn(s_.separation) > 0 ? std::optional<mpz_class>(s_.separation * s_.separation) : std::nullopt)
{
}

bool Ccd_rational_kernel::swept_boxes_apart() const
{
  const mpz_class& d = s_.separation;
  return clash4d::swept_boxes_apart(type(), s_.rows, [&d](const mpz_class& a, const mpz_class& b) { return a + d < b; });
}

int Ccd_rational_kernel::sign_after(int name, const Time& t)
{
  Poly g = p_(name);
  for (int order = 0; order < Poly::capacity; ++order, g = g.derivative())
    if (int s = sign_of(g, t)) return s;
  return 0;
}

Ccd_rational_kernel::Time Ccd_rational_kernel::next_time(const Ccd_path& names, const Time& t)
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

const std::vector<Algebraic>& Ccd_rational_kernel::roots(int name)
{
  auto& r = roots_[static_cast<std::size_t>(name)];
  if (!r) {
    std::vector<mpz_class> c = p_(name).coefficients();
    bool zero = true;
    for (const mpz_class& x : c) zero = zero && sgn(x) == 0;
    r = zero ? std::vector<Algebraic>() : Algebraic::real_roots(c, Rational(0), Rational(1));
  }
  return *r;
}

// At a rational t = n / d (d > 0): the sign of d^k g(n / d), in integers.
int Ccd_rational_kernel::sign_of(const Poly& g, const Time& t)
{
  if (!t.is_rational()) return t.sign_of(g.coefficients());
  mpz_srcptr n = mpq_numref(t.rational().mpq()), d = mpq_denref(t.rational().mpq());
  mpz_class v = 0, dk = 1;
  for (int i = g.size() - 1; i >= 0; --i) {
    v = v * mpz_class(n) + g[i] * dk;
    dk *= mpz_class(d);
  }
  return sgn(v);
}

} // namespace clash4d
