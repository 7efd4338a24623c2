// Polynomials in t as their rational coefficients, constant term first, of
// any degree (numbers/Polynomial.h holds a fixed capacity): what the
// turning certificate's writer builds its paths, witnesses and multipliers
// from before it checks their signs (certify/Positivity.h).
#ifndef CLASH4D_CERTIFY_COEFFICIENTS_H
#define CLASH4D_CERTIFY_COEFFICIENTS_H

#include "numbers/Rational.h"
#include <utility>
#include <vector>

namespace clash4d::coefficients {

using Poly = std::vector<Rational>;

inline Poly add(Poly a, const Poly& b)
{
  if (a.size() < b.size()) a.resize(b.size(), Rational(0));
  for (std::size_t i = 0; i < b.size(); ++i) a[i] += b[i];
  return a;
}

inline Poly mul(const Poly& a, const Poly& b)
{
  if (a.empty() || b.empty()) return {};
  Poly out(a.size() + b.size() - 1, Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) out[i + j] += a[i] * b[j];
  return out;
}

inline Poly scaled(Poly a, const Rational& s)
{
  for (Rational& c : a) c *= s;
  return a;
}

// The value at t, by Horner's rule.
inline Rational at(const Poly& p, const Rational& t)
{
  Rational v(0);
  for (std::size_t i = p.size(); i-- > 0;) v = v * t + p[i];
  return v;
}

inline Poly trimmed(Poly p)
{
  while (!p.empty() && CGAL::sign(p.back()) == CGAL::ZERO) p.pop_back();
  return p;
}

// a = q b + r; returns q, leaves r in a (b not zero).
inline Poly divide(Poly& a, const Poly& b)
{
  a = trimmed(a);
  Poly q(a.size() >= b.size() ? a.size() - b.size() + 1 : 0, Rational(0));
  while (a.size() >= b.size() && !a.empty()) {
    std::size_t shift = a.size() - b.size();
    Rational f = a.back() / b.back();
    q[shift] = f;
    for (std::size_t i = 0; i < b.size(); ++i) a[shift + i] -= f * b[i];
    a = trimmed(a);
  }
  return q;
}

// The greatest common divisor, by Euclid over Q (not made monic).
inline Poly gcd(Poly a, Poly b)
{
  a = trimmed(a), b = trimmed(b);
  while (!b.empty()) {
    divide(a, b);
    std::swap(a, b);
  }
  return a;
}

} // namespace clash4d::coefficients

#endif
