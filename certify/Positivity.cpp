#include "certify/Positivity.h"

#include "rotation/Simplest_rational.h"

namespace clash4d {
namespace {

CGAL::Sign sign_at(const std::vector<Rational>& p, const Algebraic& x)
{
  if (!x.is_rational()) return x.sign_of(p);
  Rational v(0);
  for (std::size_t i = p.size(); i-- > 0;) v = v * x.rational() + p[i];
  return CGAL::sign(v);
}

// a, then p's distinct roots strictly between a and b, then b.
std::vector<Algebraic> cuts(const std::vector<Rational>& p, const Algebraic& a, const Algebraic& b)
{
  std::vector<Algebraic> out{a};
  for (Algebraic& r : Algebraic::real_roots(p, a.lower(), b.upper()))
    if (a < r && r < b) out.push_back(std::move(r));
  out.push_back(b);
  return out;
}

// p > 0 at a rational point between each two consecutive cuts: p has no
// root there, so it is positive on the whole open interval.
bool positive_between(const std::vector<Rational>& p, const std::vector<Algebraic>& c)
{
  for (std::size_t i = 0; i + 1 < c.size(); ++i)
    if (sign_at(p, Algebraic(simplest_between(c[i], c[i + 1]))) != CGAL::POSITIVE) return false;
  return true;
}

} // namespace

bool is_zero_polynomial(const std::vector<Rational>& p)
{
  for (const Rational& c : p)
    if (CGAL::sign(c) != CGAL::ZERO) return false;
  return true;
}

bool nonnegative_on(const std::vector<Rational>& p, const Algebraic& a, const Algebraic& b)
{
  if (is_zero_polynomial(p)) return true;
  return positive_between(p, cuts(p, a, b));
}

bool positive_on(const std::vector<Rational>& p, const Algebraic& a, const Algebraic& b, bool closed_end)
{
  if (is_zero_polynomial(p) || sign_at(p, a) != CGAL::POSITIVE) return false;
  if (closed_end && sign_at(p, b) != CGAL::POSITIVE) return false;
  std::vector<Algebraic> c = cuts(p, a, b);
  return c.size() == 2 && positive_between(p, c);
}

bool positive_after(const std::vector<Rational>& p, const Algebraic& a, const Algebraic& b)
{
  if (is_zero_polynomial(p) || sign_at(p, b) != CGAL::POSITIVE) return false;
  return cuts(p, a, b).size() == 2;
}

} // namespace clash4d
