// An independent, brute-force exact oracle for the CCD queries of
// docs/ccd-queries.md ("The contract": vertex-face and edge-edge under linear
// vertex motion, first time t*, minimum separation D). Tests only.
//
// It shares nothing with the production decider: standard library and GMP's
// C++ classes (mpq_class) only, its own polynomial arithmetic, its own Sturm
// sequences, its own real algebraic numbers. No floating point decides
// anything (doubles appear only in describe(), for messages).
//
// Method.
//
// 1. Static test at one time t, as a distance test. With the vertex positions
//    at time t, the query "collides at t" (separation D >= 0) iff
//        min over the closed parameter domain of |X(u, v)|^2 <= D^2,
//    where X(u, v) = a + u (b - a) + v (c - a) - p on the triangle
//    u, v >= 0, u + v <= 1 (vertex-face), and
//    X(u, v) = a0 + u (a1 - a0) - b0 - v (b1 - b0) on the square [0,1]^2
//    (edge-edge). With D = 0 this is exactly the contract's equation (the
//    minimum is attained: the domain is compact). |X|^2 is a convex
//    quadratic in (u, v) with Gram matrix G (positive semidefinite), so its
//    minimum over the convex polygon is attained
//      - either at a point of the polygon's relative interior, where the
//        gradient vanishes: then it is the unconstrained minimum. If
//        det G > 0 that is the unique critical point (Cramer on G);
//        if det G = 0 the set of unconstrained minimisers is an affine set of
//        dimension >= 1 through that point, which leaves the bounded polygon,
//        so the same value is also attained on the polygon's boundary;
//      - or on the boundary: the three sides of the triangle (segments ab,
//        ac, bc in space), resp. the four sides of the square (a0 vs segment
//        b, a1 vs segment b, b0 vs segment a, b1 vs segment a).
//    Hence  dist <= D  iff
//        [det G > 0, critical point in the closed domain, value <= D^2]
//        or some boundary point-segment distance <= D,
//    and point-segment (w = p - q0, d = q1 - q0, s in [0,1]) likewise:
//        |p - q0|^2 <= D^2  or  |p - q1|^2 <= D^2  or
//        [d.d > 0, 0 <= w.d <= d.d, (w.w)(d.d) - (w.d)^2 <= D^2 (d.d)].
//    Degenerate triangles (collinear corners, all equal) and zero-length
//    edges need no special branch: det G = 0 (resp. d.d = 0) switches the
//    interior clause off and the boundary clauses cover them. Every
//    condition is the sign (>= 0 or > 0) of a polynomial in the coordinates,
//    with divisions cleared by the positive denominators det G and d.d.
//
// 2. So the static answer at time t is a fixed boolean formula (an OR of
//    ANDs) of sign conditions on a fixed, finite list of polynomials in t
//    (the "atoms", degree <= 6), built once per query. There is no other
//    branching. On every open interval between consecutive real roots of
//    the non-zero atoms, every atom has a constant sign, so the answer is
//    constant. The collision set S = {t in [0,1] : dist(t) <= D} is closed
//    (dist is continuous in t). Hence: if t in S is not a critical point
//    (a root of an atom in [0,1], or 0, or 1), the whole open interval
//    around it between critical points is in S, and so is its left end.
//    So S is non-empty iff it contains a critical point, and t* is the
//    least critical point in S.
//
// 3. Critical points: for each atom, its squarefree part, Sturm sequence,
//    root isolation in [0,1] by bisection. Sorted exactly (compare()), the
//    formula is evaluated at each in increasing order, exactly: at a
//    rational point by evaluation, at an irrational root r of squarefree P
//    isolated in (lo, hi) by sign_at(): g(r) = 0 iff gcd(g, P) has a root in
//    (lo, hi) (Sturm count), otherwise bisect until an exact interval
//    evaluation of g on [lo, hi] excludes 0 (tried first for a few
//    bisections before the gcd, as a shortcut: an enclosure without 0 is a
//    proof of the sign on its own).
//
// Speed only (no effect on the answers): every atom and every Sturm member
// is replaced by a POSITIVE rational multiple with coprime integer
// coefficients (same sign everywhere), and signs at rationals and interval
// enclosures are computed in integers over a common denominator.
#ifndef CLASH4D_TESTS_SUPPORT_CCD_ORACLE_H
#define CLASH4D_TESTS_SUPPORT_CCD_ORACLE_H

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace clash4d {
namespace ccd_oracle {

enum class Type { vertex_face, edge_edge };
using Point3 = std::array<mpq_class, 3>;
// Rows in the CSV order of docs/ccd-queries.md: the 4 vertices at t = 0,
// then the same 4 at t = 1.
using Query = std::array<Point3, 8>;

// An exact real number: rational, or the unique root of a squarefree
// polynomial `poly` (rational coefficients, constant term first, degree >= 2)
// in the OPEN interval (lo, hi), lo < hi rational.
struct Real {
  bool is_rational = true;
  mpq_class value;              // when rational
  std::vector<mpq_class> poly;  // otherwise
  mpq_class lo, hi;
};
struct Answer {
  bool collide = false;
  Real t_star;  // meaningful when collide
};

namespace detail {

// ---------------------------------------------------------------- polynomials
// Constant term first; normalised: no trailing zero, the zero polynomial is
// empty (degree -1).
using Poly = std::vector<mpq_class>;

inline int sign_of(const mpq_class& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }
inline int sign_of(const mpz_class& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

inline Poly& trim(Poly& p)
{
  while (!p.empty() && p.back() == 0) p.pop_back();
  return p;
}
inline Poly trimmed(Poly p) { return std::move(trim(p)); }
inline int deg(const Poly& p) { return static_cast<int>(p.size()) - 1; }

inline Poly constant(const mpq_class& c) { return trimmed(Poly{c}); }

inline Poly add(const Poly& a, const Poly& b)
{
  Poly r(std::max(a.size(), b.size()));
  for (std::size_t i = 0; i < a.size(); ++i) r[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) r[i] += b[i];
  return trimmed(std::move(r));
}
inline Poly neg(const Poly& a)
{
  Poly r(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) r[i] = -a[i];
  return r;
}
inline Poly sub(const Poly& a, const Poly& b) { return add(a, neg(b)); }
inline Poly mul(const Poly& a, const Poly& b)
{
  if (a.empty() || b.empty()) return Poly();
  Poly r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return trimmed(std::move(r));
}
inline Poly scale(const Poly& a, const mpq_class& c)
{
  Poly r(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) r[i] = a[i] * c;
  return trimmed(std::move(r));
}

// a = q b + r, deg r < deg b; b non-zero.
inline void divmod(const Poly& a, const Poly& b, Poly& q, Poly& r)
{
  if (b.empty()) throw std::domain_error("ccd_oracle: polynomial division by zero");
  r = a;
  trim(r);
  q.clear();
  if (deg(r) < deg(b)) return;
  q.assign(r.size() - b.size() + 1, mpq_class(0));
  const mpq_class& lead = b.back();
  while (!r.empty() && deg(r) >= deg(b)) {
    std::size_t shift = r.size() - b.size();
    mpq_class c = r.back() / lead;
    q[shift] = c;
    for (std::size_t i = 0; i < b.size(); ++i) r[shift + i] -= c * b[i];
    r.back() = 0;  // exact anyway; guards against a non-zero residue
    trim(r);
  }
  trim(q);
}
inline Poly rem(const Poly& a, const Poly& b)
{
  Poly q, r;
  divmod(a, b, q, r);
  return r;
}
inline Poly quo_exact(const Poly& a, const Poly& b)
{
  Poly q, r;
  divmod(a, b, q, r);
  if (!r.empty()) throw std::logic_error("ccd_oracle: inexact polynomial division");
  return q;
}
inline Poly derivative(const Poly& a)
{
  Poly r;
  for (std::size_t i = 1; i < a.size(); ++i) r.push_back(a[i] * static_cast<unsigned long>(i));
  return trimmed(std::move(r));
}
inline Poly monic(const Poly& a)
{
  if (a.empty()) return a;
  return scale(a, 1 / a.back());
}
// p times a POSITIVE rational such that the coefficients are coprime
// integers: same sign as p at every point (keeps the numbers small).
inline Poly positive_primitive(const Poly& p0)
{
  Poly p = trimmed(p0);
  if (p.empty()) return p;
  mpz_class l = 1, g = 0;
  for (const auto& c : p) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  for (const auto& c : p) {
    mpz_class n = c.get_num() * (l / c.get_den());
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), n.get_mpz_t());
  }
  return scale(p, mpq_class(l) / mpq_class(g));  // g > 0: p is non-zero
}
// Monic gcd; gcd(0, 0) = 0. (Remainders rescaled: the gcd is defined up to a constant.)
inline Poly gcd(Poly a, Poly b)
{
  a = positive_primitive(trimmed(a));
  b = positive_primitive(trimmed(b));
  while (!b.empty()) {
    Poly r = positive_primitive(rem(a, b));
    a = std::move(b);
    b = std::move(r);
  }
  return monic(a);
}
// The squarefree part p / gcd(p, p'), monic (same distinct roots).
inline Poly squarefree(const Poly& p)
{
  if (deg(p) < 1) return monic(p);
  return monic(quo_exact(p, gcd(p, derivative(p))));
}
inline mpq_class eval(const Poly& p, const mpq_class& x)
{
  mpq_class r = 0;
  for (std::size_t i = p.size(); i-- > 0;) r = r * x + p[i];
  return r;
}
// p / (x - c) for a root c of p.
inline Poly deflate(const Poly& p, const mpq_class& c) { return quo_exact(p, Poly{-c, mpq_class(1)}); }

// Integer polynomial with the same roots (positive leading coefficient).
inline std::vector<mpz_class> integer_primitive(const Poly& p)
{
  mpz_class l = 1;
  for (const auto& c : p) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  std::vector<mpz_class> z(p.size());
  mpz_class g = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    mpq_class v = p[i] * l;
    z[i] = v.get_num();
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), z[i].get_mpz_t());
  }
  if (g != 0)
    for (auto& c : z) c /= g;
  if (!z.empty() && z.back() < 0)
    for (auto& c : z) c = -c;
  return z;
}
// The same with the SIGN of p kept everywhere (a positive multiple of p).
inline std::vector<mpz_class> integer_same_sign(const Poly& p)
{
  Poly q = positive_primitive(p);
  std::vector<mpz_class> z(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) z[i] = q[i].get_num();  // integers already
  return z;
}
// Sign of an integer polynomial at n/d (d > 0): sign of d^k z(n/d) =
// sum z_i n^i d^(k-i) (Horner: acc <- acc n + z_i d^(k-i)).
inline int sign_at_rational(const std::vector<mpz_class>& z, const mpq_class& x)
{
  if (z.empty()) return 0;
  const mpz_class& n = x.get_num();
  const mpz_class& d = x.get_den();
  mpz_class acc = z.back();
  mpz_class dp = 1;
  for (std::size_t i = z.size() - 1; i-- > 0;) {
    dp *= d;
    acc = acc * n + z[i] * dp;
  }
  return sign_of(acc);
}
// Over the whole interval [lo, hi]: 1 if z > 0 there, -1 if z < 0 there, 0
// when the interval bound does not decide. With a common denominator d > 0,
// x = y/d, y in [Nlo, Nhi] (integers), d^k z(x) = sum z_i y^i d^(k-i): the
// same Horner scheme in exact integer interval arithmetic encloses it.
inline int interval_sign(const std::vector<mpz_class>& z, const mpq_class& lo, const mpq_class& hi)
{
  if (z.empty()) return 0;
  mpz_class d;
  mpz_lcm(d.get_mpz_t(), lo.get_den_mpz_t(), hi.get_den_mpz_t());
  mpz_class Nlo = lo.get_num() * (d / lo.get_den()), Nhi = hi.get_num() * (d / hi.get_den());
  mpz_class alo = z.back(), ahi = z.back(), dp = 1;
  for (std::size_t i = z.size() - 1; i-- > 0;) {
    dp *= d;
    mpz_class p1 = alo * Nlo, p2 = alo * Nhi, p3 = ahi * Nlo, p4 = ahi * Nhi;
    mpz_class mn = p1, mx = p1;
    for (const mpz_class* p : {&p2, &p3, &p4}) {
      if (*p < mn) mn = *p;
      if (*p > mx) mx = *p;
    }
    mpz_class c = z[i] * dp;
    alo = mn + c;
    ahi = mx + c;
  }
  if (alo > 0) return 1;
  if (ahi < 0) return -1;
  return 0;
}

// ---------------------------------------------------------------- Sturm
// p squarefree: p0 = p, p1 = p', p_{k+1} = -rem(p_{k-1}, p_k). For a < b,
// V(a) - V(b) is the number of distinct real roots in (a, b].
// Each member may be replaced by a positive multiple of itself (signs, hence
// variations, unchanged): kept as coprime integers for fast exact signs.
struct Sturm {
  std::vector<std::vector<mpz_class>> seq;
  explicit Sturm(const Poly& p)
  {
    if (p.empty()) return;
    Poly prev = positive_primitive(p);
    seq.push_back(integer_same_sign(prev));
    Poly cur = positive_primitive(derivative(p));
    if (cur.empty()) return;
    seq.push_back(integer_same_sign(cur));
    for (;;) {
      Poly r = positive_primitive(neg(rem(prev, cur)));
      if (r.empty()) break;
      seq.push_back(integer_same_sign(r));
      prev = std::move(cur);
      cur = std::move(r);
    }
  }
  int variations(const mpq_class& x) const
  {
    int v = 0, last = 0;
    for (const auto& q : seq) {
      int s = sign_at_rational(q, x);
      if (s == 0) continue;
      if (last != 0 && s != last) ++v;
      last = s;
    }
    return v;
  }
  // Roots in the open (lo, hi); the ends must not be roots of p.
  int count_open(const mpq_class& lo, const mpq_class& hi) const { return variations(lo) - variations(hi); }
};

// ---------------------------------------------------------------- algebraic numbers
// Rational q, or the unique root of squarefree P (degree >= 2) in the open
// (lo, hi), P(lo) != 0 != P(hi). Z is P as a primitive integer polynomial
// (fast exact signs), s_lo the sign of P at lo.
struct Alg {
  bool rat = true;
  mpq_class q;
  Poly P;
  std::vector<mpz_class> Z;
  mpq_class lo, hi;
  int s_lo = 0;
};

inline Alg rational_alg(const mpq_class& x)
{
  Alg a;
  a.rat = true;
  a.q = x;
  return a;
}
// Requires: P squarefree, ends not roots, exactly one root in (lo, hi).
inline Alg make_alg(const Poly& P, const mpq_class& lo, const mpq_class& hi)
{
  if (deg(P) == 1) return rational_alg(-P[0] / P[1]);
  Alg a;
  a.rat = false;
  a.P = monic(P);
  a.Z = integer_primitive(a.P);
  a.lo = lo;
  a.hi = hi;
  a.s_lo = sign_at_rational(a.Z, lo);
  if (a.s_lo == 0 || sign_at_rational(a.Z, hi) != -a.s_lo)
    throw std::logic_error("ccd_oracle: bad isolating interval");
  return a;
}
// Halve the isolating interval (the root is simple and unique in it, so P
// changes sign exactly across the half that holds it).
inline void refine(Alg& a)
{
  if (a.rat) return;
  mpq_class mid = (a.lo + a.hi) / 2;
  int s = sign_at_rational(a.Z, mid);
  if (s == 0) {
    a = rational_alg(mid);
  } else if (s == a.s_lo) {
    a.lo = mid;
  } else {
    a.hi = mid;
  }
}

// Exact sign of g at the number a (refines a in place).
inline int sign_at(const Poly& g0, Alg& a)
{
  if (g0.empty()) return 0;
  if (a.rat) return sign_of(eval(g0, a.q));
  Poly g = rem(g0, a.P);  // g(r) = (g mod P)(r) since P(r) = 0
  if (g.empty()) return 0;
  if (deg(g) == 0) return sign_of(g[0]);
  std::vector<mpz_class> z = integer_same_sign(g);
  // Cheap first: an enclosure of g over the isolating interval that excludes
  // 0 decides the sign (r is inside). Only when it does not, ask the gcd.
  for (int i = 0; i < 8; ++i) {
    int s = interval_sign(z, a.lo, a.hi);
    if (s != 0) return s;
    refine(a);
    if (a.rat) return sign_at_rational(z, a.q);
  }
  Poly G = gcd(g, a.P);
  if (deg(G) >= 1) {
    // G | P, so lo and hi are not roots of G; G is squarefree.
    if (Sturm(G).count_open(a.lo, a.hi) >= 1) return 0;  // the root of P in (lo,hi) is a root of g
  }
  for (;;) {  // g(r) != 0: terminates
    int s = interval_sign(z, a.lo, a.hi);
    if (s != 0) return s;
    refine(a);
    if (a.rat) return sign_at_rational(z, a.q);
  }
}

// -1, 0, 1 (refines both in place).
inline int compare_alg(Alg& a, Alg& b)
{
  if (a.rat && b.rat) return a.q < b.q ? -1 : (a.q > b.q ? 1 : 0);
  if (a.rat) return -compare_alg(b, a);
  if (b.rat) {  // a irrational-form, b = x rational
    const mpq_class& x = b.q;
    if (x <= a.lo) return 1;
    if (x >= a.hi) return -1;
    int s = sign_at_rational(a.Z, x);
    if (s == 0) return 0;  // the unique root of P in (lo, hi)
    // The root is in (lo, x) iff P changes sign there.
    return s != a.s_lo ? -1 : 1;
  }
  // Both irrational-form. Equal iff gcd(Pa, Pb) has a root in the
  // intersection of the intervals (its ends are ends of one of the two
  // intervals, so not roots of the gcd).
  {
    mpq_class lo = std::max(a.lo, b.lo), hi = std::min(a.hi, b.hi);
    if (lo < hi) {
      Poly G = gcd(a.P, b.P);
      if (deg(G) >= 1 && Sturm(G).count_open(lo, hi) >= 1) return 0;
    }
  }
  for (;;) {  // distinct: separate by bisection
    if (a.rat || b.rat) return compare_alg(a, b);
    if (a.hi <= b.lo) return -1;
    if (b.hi <= a.lo) return 1;
    refine(a);
    refine(b);
  }
}

// Validate and normalise a Real.
inline Alg to_alg(const Real& r)
{
  if (r.is_rational) return rational_alg(r.value);
  Poly P = r.poly;
  trim(P);
  if (deg(P) < 1) throw std::invalid_argument("ccd_oracle::Real: polynomial of degree < 1");
  if (!(r.lo < r.hi)) throw std::invalid_argument("ccd_oracle::Real: interval with lo >= hi");
  P = squarefree(P);
  // The open interval: drop roots at its ends.
  if (eval(P, r.lo) == 0) P = deflate(P, r.lo);
  if (deg(P) >= 1 && eval(P, r.hi) == 0) P = deflate(P, r.hi);
  int n = deg(P) >= 1 ? Sturm(P).count_open(r.lo, r.hi) : 0;
  if (n != 1)
    throw std::invalid_argument("ccd_oracle::Real: the polynomial has " + std::to_string(n) +
                                " distinct roots in the open interval, not 1");
  return make_alg(P, r.lo, r.hi);
}
inline Real to_real(const Alg& a)
{
  Real r;
  r.is_rational = a.rat;
  if (a.rat) {
    r.value = a.q;
    return r;
  }
  for (const auto& c : a.Z) r.poly.push_back(mpq_class(c));
  r.lo = a.lo;
  r.hi = a.hi;
  return r;
}

// The rational with the least denominator in the open (lo, hi), lo < hi.
inline mpq_class simplest_between(const mpq_class& lo, const mpq_class& hi)
{
  mpz_class fl;
  mpz_fdiv_q(fl.get_mpz_t(), lo.get_num_mpz_t(), lo.get_den_mpz_t());
  mpq_class next(fl + 1);
  if (next < hi) return next;  // an integer strictly inside
  // (lo, hi) is inside [fl, fl + 1]: recurse on the reciprocals of the fractional parts.
  mpq_class x = lo - fl, y = hi - fl;  // 0 <= x < y <= 1
  mpq_class inv_y = 1 / y;
  mpq_class inner;
  if (x == 0) {
    mpz_class f;
    mpz_fdiv_q(f.get_mpz_t(), inv_y.get_num_mpz_t(), inv_y.get_den_mpz_t());
    inner = mpq_class(f + 1);
  } else {
    inner = simplest_between(inv_y, 1 / x);
  }
  return mpq_class(fl) + 1 / inner;
}

// Turn an irrational-form number into a rational when it is one. A rational
// root n/d (lowest terms) of the integer polynomial Z has d | lead(Z) =: L.
// Two distinct rationals of denominators <= L differ by >= 1/L^2, so once the
// interval is narrower than that it holds at most one of them; if the root is
// rational it is that one, and the simplest rational in the interval (least
// denominator, hence <= d <= L) is it. Checked exactly.
inline void rationalize(Alg& a)
{
  if (a.rat) return;
  mpz_class L = a.Z.back();
  if (L < 0) L = -L;
  mpq_class bound(1, 1);
  bound /= mpq_class(L * L);
  while (!a.rat && !(a.hi - a.lo < bound)) refine(a);
  if (a.rat) return;
  mpq_class c = simplest_between(a.lo, a.hi);
  if (sign_at_rational(a.Z, c) == 0) a = rational_alg(c);
}

// The roots of P in (lo, hi), isolated by bisection: P squarefree,
// P(lo) != 0 != P(hi), s its Sturm sequence, n the number of its roots in
// (lo, hi). A midpoint that is a root is output as a rational and divided out.
inline void isolate(const Poly& P, const Sturm& s, const mpq_class& lo, const mpq_class& hi, int n,
                    std::vector<Alg>& out)
{
  if (n == 0) return;
  if (n == 1) {
    out.push_back(make_alg(P, lo, hi));
    return;
  }
  mpq_class mid = (lo + hi) / 2;
  if (eval(P, mid) == 0) {
    out.push_back(rational_alg(mid));
    Poly P2 = deflate(P, mid);  // squarefree, P2(mid) != 0
    Sturm s2(P2);
    int vmid = s2.variations(mid);
    isolate(P2, s2, lo, mid, s2.variations(lo) - vmid, out);
    isolate(P2, s2, mid, hi, vmid - s2.variations(hi), out);
  } else {
    int vmid = s.variations(mid);
    isolate(P, s, lo, mid, s.variations(lo) - vmid, out);
    isolate(P, s, mid, hi, vmid - s.variations(hi), out);
  }
}
// All distinct real roots of g in the closed [0, 1] (none if g is constant or zero).
inline void roots_in_unit_interval(const Poly& g, std::vector<Alg>& out)
{
  if (deg(g) < 1) return;
  Poly P = squarefree(g);
  const mpq_class zero(0), one(1);
  if (eval(P, zero) == 0) {
    out.push_back(rational_alg(zero));
    P = deflate(P, zero);
  }
  if (deg(P) >= 1 && eval(P, one) == 0) {
    out.push_back(rational_alg(one));
    P = deflate(P, one);
  }
  if (deg(P) < 1) return;
  Sturm s(P);
  isolate(P, s, zero, one, s.count_open(zero, one), out);
}

// ---------------------------------------------------------------- the static formula
using V3 = std::array<Poly, 3>;

// x_i(t) = x_i(0) + t (x_i(1) - x_i(0)), i.e. (1 - t) x_i(0) + t x_i(1).
inline V3 position(const Query& q, int i)
{
  V3 r;
  for (int k = 0; k < 3; ++k) r[k] = trimmed(Poly{q[i][k], q[i + 4][k] - q[i][k]});
  return r;
}
inline V3 vsub(const V3& a, const V3& b) { return {sub(a[0], b[0]), sub(a[1], b[1]), sub(a[2], b[2])}; }
inline Poly dot(const V3& a, const V3& b) { return add(add(mul(a[0], b[0]), mul(a[1], b[1])), mul(a[2], b[2])); }

enum class Rel { ge0, gt0 };
struct Formula {
  std::vector<Poly> atoms;                                  // polynomials in t
  std::vector<std::vector<std::pair<std::size_t, Rel>>> clauses;  // OR of ANDs
  std::size_t atom(const Poly& p0)
  {
    Poly p = positive_primitive(p0);  // a positive multiple: same sign at every t
    for (std::size_t i = 0; i < atoms.size(); ++i)
      if (atoms[i] == p) return i;
    atoms.push_back(p);
    return atoms.size() - 1;
  }
  void clause(std::initializer_list<std::pair<Poly, Rel>> conds)
  {
    std::vector<std::pair<std::size_t, Rel>> c;
    for (const auto& pr : conds) c.emplace_back(atom(pr.first), pr.second);
    clauses.push_back(std::move(c));
  }
  bool holds(Alg& t) const
  {
    std::vector<int> memo(atoms.size(), 2);
    for (const auto& c : clauses) {
      bool all = true;
      for (const auto& cond : c) {
        int& s = memo[cond.first];
        if (s == 2) s = sign_at(atoms[cond.first], t);
        if (cond.second == Rel::ge0 ? s < 0 : s <= 0) {
          all = false;
          break;
        }
      }
      if (all) return true;
    }
    return false;
  }
};

// dist(p, segment [q0, q1])^2 <= D2 (see the header comment).
inline void add_point_segment(Formula& f, const V3& p, const V3& q0, const V3& q1, const mpq_class& D2)
{
  Poly d2 = constant(D2);
  V3 w = vsub(p, q0), w1 = vsub(p, q1), d = vsub(q1, q0);
  Poly ww = dot(w, w), w1w1 = dot(w1, w1), dd = dot(d, d), wd = dot(w, d);
  f.clause({{sub(d2, ww), Rel::ge0}});
  f.clause({{sub(d2, w1w1), Rel::ge0}});
  f.clause({{dd, Rel::gt0},
            {wd, Rel::ge0},
            {sub(dd, wd), Rel::ge0},
            {sub(mul(d2, dd), sub(mul(ww, dd), mul(wd, wd))), Rel::ge0}});
}

inline Formula build(Type type, const Query& q, const mpq_class& D2)
{
  Formula f;
  Poly d2 = constant(D2);
  if (type == Type::vertex_face) {
    V3 p = position(q, 0), a = position(q, 1), b = position(q, 2), c = position(q, 3);
    // min over u,v>=0, u+v<=1 of |u e1 + v e2 - w|^2, w = p - a.
    V3 e1 = vsub(b, a), e2 = vsub(c, a), w = vsub(p, a);
    Poly g11 = dot(e1, e1), g12 = dot(e1, e2), g22 = dot(e2, e2);
    Poly we1 = dot(w, e1), we2 = dot(w, e2), ww = dot(w, w);
    Poly det = sub(mul(g11, g22), mul(g12, g12));
    // G (u, v) = (we1, we2): u = Nu / det, v = Nv / det.
    Poly Nu = sub(mul(we1, g22), mul(g12, we2));
    Poly Nv = sub(mul(g11, we2), mul(g12, we1));
    // Minimum value ww - u we1 - v we2, times det.
    Poly val = sub(sub(mul(ww, det), mul(Nu, we1)), mul(Nv, we2));
    f.clause({{det, Rel::gt0},
              {Nu, Rel::ge0},
              {Nv, Rel::ge0},
              {sub(sub(det, Nu), Nv), Rel::ge0},
              {sub(mul(d2, det), val), Rel::ge0}});
    add_point_segment(f, p, a, b, D2);
    add_point_segment(f, p, a, c, D2);
    add_point_segment(f, p, b, c, D2);
  } else {
    V3 a0 = position(q, 0), a1 = position(q, 1), b0 = position(q, 2), b1 = position(q, 3);
    // min over [0,1]^2 of |r + u da - v db|^2, r = a0 - b0.
    V3 da = vsub(a1, a0), db = vsub(b1, b0), r = vsub(a0, b0);
    Poly A = dot(da, da), B = dot(da, db), C = dot(db, db);
    Poly rda = dot(r, da), rdb = dot(r, db), rr = dot(r, r);
    Poly det = sub(mul(A, C), mul(B, B));
    // [A -B; -B C] (u, v) = (-rda, rdb): u = Nu / det, v = Nv / det.
    Poly Nu = sub(mul(B, rdb), mul(rda, C));
    Poly Nv = sub(mul(A, rdb), mul(B, rda));
    // Minimum value rr + u rda - v rdb, times det.
    Poly val = sub(add(mul(rr, det), mul(Nu, rda)), mul(Nv, rdb));
    f.clause({{det, Rel::gt0},
              {Nu, Rel::ge0},
              {sub(det, Nu), Rel::ge0},
              {Nv, Rel::ge0},
              {sub(det, Nv), Rel::ge0},
              {sub(mul(d2, det), val), Rel::ge0}});
    add_point_segment(f, a0, b0, b1, D2);
    add_point_segment(f, a1, b0, b1, D2);
    add_point_segment(f, b0, a0, a1, D2);
    add_point_segment(f, b1, a0, a1, D2);
  }
  return f;
}

// The static answer at one rational time (for tests of the oracle itself).
inline bool collides_at(Type type, const Query& q, const mpq_class& t, const mpq_class& separation = 0)
{
  Alg a = rational_alg(t);
  return build(type, q, separation * separation).holds(a);
}

}  // namespace detail

// ---------------------------------------------------------------- the interface

// separation: D >= 0 (0 = the plain contract). Closed semantics.
inline Answer solve(Type type, const Query& q, const mpq_class& separation = 0)
{
  using namespace detail;
  if (separation < 0) throw std::invalid_argument("ccd_oracle::solve: negative separation");
  Formula f = build(type, q, separation * separation);
  std::vector<Alg> crit;
  crit.push_back(rational_alg(0));
  crit.push_back(rational_alg(1));
  for (const auto& g : f.atoms) roots_in_unit_interval(g, crit);
  // Exact insertion sort, then drop duplicates.
  for (std::size_t i = 1; i < crit.size(); ++i)
    for (std::size_t j = i; j > 0 && compare_alg(crit[j - 1], crit[j]) > 0; --j) std::swap(crit[j - 1], crit[j]);
  std::vector<Alg> uniq;
  for (auto& c : crit)
    if (uniq.empty() || compare_alg(uniq.back(), c) != 0) uniq.push_back(std::move(c));
  Answer ans;
  for (auto& c : uniq) {
    if (f.holds(c)) {
      rationalize(c);
      ans.collide = true;
      ans.t_star = to_real(c);
      return ans;
    }
  }
  return ans;
}

// Exact comparison: -1, 0, 1. Throws std::invalid_argument on a malformed Real.
inline int compare(const Real& a, const Real& b)
{
  detail::Alg x = detail::to_alg(a), y = detail::to_alg(b);
  return detail::compare_alg(x, y);
}

// Whether (u, v) is a contact of the query at time t (plain contract), with u
// and v polynomials in t (constant first) evaluated at t; exact in Q(t).
// t must lie in [0, 1].
inline bool is_contact(Type type, const Query& q, const Real& t, const std::vector<mpq_class>& u_poly,
                       const std::vector<mpq_class>& v_poly)
{
  using namespace detail;
  Alg at = to_alg(t);
  {
    Alg zero = rational_alg(0), one = rational_alg(1);
    if (compare_alg(at, zero) < 0 || compare_alg(at, one) > 0) return false;
  }
  Poly u = trimmed(u_poly), v = trimmed(v_poly);
  Poly one = constant(1);
  std::vector<Poly> zeros, nonneg;
  if (type == Type::vertex_face) {
    V3 p = position(q, 0), a = position(q, 1), b = position(q, 2), c = position(q, 3);
    for (int k = 0; k < 3; ++k)
      zeros.push_back(sub(sub(sub(p[k], a[k]), mul(u, sub(b[k], a[k]))), mul(v, sub(c[k], a[k]))));
    nonneg = {u, v, sub(sub(one, u), v)};
  } else {
    V3 a0 = position(q, 0), a1 = position(q, 1), b0 = position(q, 2), b1 = position(q, 3);
    for (int k = 0; k < 3; ++k)
      zeros.push_back(sub(add(a0[k], mul(u, sub(a1[k], a0[k]))), add(b0[k], mul(v, sub(b1[k], b0[k])))));
    nonneg = {u, sub(one, u), v, sub(one, v)};
  }
  for (const auto& z : zeros)
    if (sign_at(z, at) != 0) return false;
  for (const auto& n : nonneg)
    if (sign_at(n, at) < 0) return false;
  return true;
}

// For messages only: "p/q" or "root of [c0, c1, ...] in (lo, hi) ~ 0.1234".
inline std::string describe(const Real& r)
{
  if (r.is_rational) return r.value.get_str();
  std::ostringstream os;
  os << "root of [";
  for (std::size_t i = 0; i < r.poly.size(); ++i) os << (i ? ", " : "") << r.poly[i].get_str();
  os << "] in (" << r.lo.get_str() << ", " << r.hi.get_str() << ")";
  try {  // approximate by exact bisection, printed as a double
    detail::Alg a = detail::to_alg(r);
    for (int i = 0; i < 60 && !a.rat; ++i) detail::refine(a);
    mpq_class m = a.rat ? a.q : (a.lo + a.hi) / 2;
    os << " ~ " << m.get_d();
  } catch (const std::exception&) {
    os << " (malformed)";
  }
  return os.str();
}

}  // namespace ccd_oracle
}  // namespace clash4d

#endif
