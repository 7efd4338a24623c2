// Self-tests of the independent CCD oracle (tests/support/Ccd_oracle.h) on
// hand-derived cases: every expected answer below is derived in its comment
// from the contract of docs/ccd-queries.md, not computed by any decider.
// Then randomised checks against a second, differently written static test
// (Cramer on a non-zero 2x2 minor, segment containment when the rank drops)
// and invariances of the first time.
#define BOOST_TEST_MODULE ccd_oracle
#include <boost/test/unit_test.hpp>

#include "support/Ccd_oracle.h"

#include <random>
#include <string>
#include <vector>

using namespace clash4d::ccd_oracle;

namespace {

// gmpxx keeps a fraction as written ("2/4", or (k, 16)), and GMP's
// arithmetic and == want lowest terms: each one made here is reduced.
mpq_class Qn(const char* s)
{
  mpq_class q(s);
  q.canonicalize();
  return q;
}

Point3 P(const mpq_class& x, const mpq_class& y, const mpq_class& z) { return {x, y, z}; }

// Rows: the 4 vertices at t = 0, then at t = 1 (vertex-face: p, a, b, c;
// edge-edge: a0, a1, b0, b1).
Query make(const Point3& v0, const Point3& v1, const Point3& v2, const Point3& v3, const Point3& w0,
           const Point3& w1, const Point3& w2, const Point3& w3)
{
  return {v0, v1, v2, v3, w0, w1, w2, w3};
}
// The same vertex positions at both times (a static configuration).
Query still(const Point3& v0, const Point3& v1, const Point3& v2, const Point3& v3)
{
  return make(v0, v1, v2, v3, v0, v1, v2, v3);
}

Real rat(const mpq_class& x)
{
  Real r;
  r.is_rational = true;
  r.value = x;
  return r;
}
Real root(const std::vector<mpq_class>& poly, const mpq_class& lo, const mpq_class& hi)
{
  Real r;
  r.is_rational = false;
  r.poly = poly;
  r.lo = lo;
  r.hi = hi;
  return r;
}

void expect_miss(Type type, const Query& q, const mpq_class& D = 0)
{
  Answer a = solve(type, q, D);
  BOOST_CHECK_MESSAGE(!a.collide, "expected no collision, got t* = " << describe(a.t_star));
}
Answer expect_hit(Type type, const Query& q, const Real& t_expected, const mpq_class& D = 0)
{
  Answer a = solve(type, q, D);
  BOOST_CHECK_MESSAGE(a.collide, "expected a collision at " << describe(t_expected));
  if (a.collide)
    BOOST_CHECK_MESSAGE(compare(a.t_star, t_expected) == 0,
                        "t* = " << describe(a.t_star) << ", expected " << describe(t_expected));
  return a;
}

const Type VF = Type::vertex_face;
const Type EE = Type::edge_edge;

// The unit triangle a = (0,0,0), b = (1,0,0), c = (0,1,0) used throughout
// (fixed unless said otherwise).
const Point3 A0 = P(0, 0, 0), B0 = P(1, 0, 0), C0 = P(0, 1, 0);
// The fixed edge a0 = (0,0,0), a1 = (1,0,0) used throughout for edge-edge.
const Point3 E0 = P(0, 0, 0), E1 = P(1, 0, 0);

// (5 - sqrt 14) / 11 ~ 0.11439: 11 r - 5 = -sqrt 14, (11 r - 5)^2 = 14,
// 121 r^2 - 110 r + 11 = 0, i.e. 11 r^2 - 10 r + 1 = 0 (roots (5 +- sqrt 14)/11,
// ~0.11439 and ~0.79470). At 1/10: 0.11 - 1 + 1 > 0, at 1/5: 0.44 - 2 + 1 < 0.
Real r_5_minus_sqrt14_over_11() { return root({1, -10, 11}, Qn("1/10"), Qn("1/5")); }

}  // namespace

// ============================================================== vertex-face

BOOST_AUTO_TEST_CASE(vf_clear_miss)
{
  // p(t) = (5, 5, 1 - 2t) meets the plane z = 0 only at t = 1/2, at (5,5,0),
  // where x + y = 10 > 1: outside the triangle. Never in the plane otherwise.
  expect_miss(VF, make(P(5, 5, 1), A0, B0, C0, P(5, 5, -1), A0, B0, C0));
}

BOOST_AUTO_TEST_CASE(vf_clear_hit_rational)
{
  // The doc's example: p(t) = (t/4, t/4, 1 - 2t); z = 0 at t = 1/2, where
  // p = (1/8, 1/8, 0) = a + 1/8 (b - a) + 1/8 (c - a), inside. t* = 1/2.
  Query q = make(P(0, 0, 1), A0, B0, C0, P(Qn("1/4"), Qn("1/4"), -1), A0, B0, C0);
  Answer a = expect_hit(VF, q, rat(Qn("1/2")));
  BOOST_CHECK(a.t_star.is_rational);
  // is_contact: (1/8, 1/8) is the contact at 1/2; (1/8, 1/4) is not; the
  // right (u, v) at a wrong time (1/4, p_z = 1/2) is not either.
  BOOST_CHECK(is_contact(VF, q, rat(Qn("1/2")), {Qn("1/8")}, {Qn("1/8")}));
  BOOST_CHECK(!is_contact(VF, q, rat(Qn("1/2")), {Qn("1/8")}, {Qn("1/4")}));
  BOOST_CHECK(!is_contact(VF, q, rat(Qn("1/4")), {Qn("1/8")}, {Qn("1/8")}));
  // As polynomials in t: u = v = t/4 are the in-plane coordinates of p(t),
  // so they are a contact at 1/2 too.
  BOOST_CHECK(is_contact(VF, q, rat(Qn("1/2")), {0, Qn("1/4")}, {0, Qn("1/4")}));
}

BOOST_AUTO_TEST_CASE(vf_hit_irrational)
{
  // a = (0,0,0), c = (0,1,0) fixed, b(t) = (1, 0, 11 t),
  // p(t) = (t, 1/4, -1 + 10 t)   [p: (0,1/4,-1) -> (1,1/4,9), b: (1,0,0) -> (1,0,11)].
  // The triangle's xy-shadow is the fixed unit triangle, so the only
  // candidate is u = p_x = t, v = p_y = 1/4, and the contact needs
  // p_z = a_z + u (b_z - a_z) + v (c_z - a_z) = 11 t^2, i.e.
  // h(t) = 11 t^2 - 10 t + 1 = 0 (= -det[b-a, c-a, p-a], the coplanarity
  // polynomial, here of degree 2). h(0) = 1 > 0, so no contact before the
  // first root r = (5 - sqrt 14)/11 ~ 0.1144, where (u, v) = (r, 1/4) is
  // inside (u + v ~ 0.364). t* = r, irrational.
  Query q = make(P(0, Qn("1/4"), -1), A0, B0, C0, P(1, Qn("1/4"), 9), A0, P(1, 0, 11), C0);
  Real r = r_5_minus_sqrt14_over_11();
  Answer a = expect_hit(VF, q, r);
  BOOST_CHECK(!a.t_star.is_rational);
  BOOST_CHECK(compare(a.t_star, rat(Qn("1/9"))) > 0);  // 0.1111 < r < 0.125
  BOOST_CHECK(compare(a.t_star, rat(Qn("1/8"))) < 0);
  // The same number through a non-minimal polynomial and a wide interval:
  // (11x^2 - 10x + 1)(x - 3) = 11x^3 - 43x^2 + 31x - 3, whose only root in
  // (0, 1/2) is r (the others are ~0.7947 and 3).
  BOOST_CHECK_EQUAL(compare(a.t_star, root({-3, 31, -43, 11}, 0, Qn("1/2"))), 0);
  // is_contact in Q(r): u = t, v = 1/4 is the contact; u = t + 1/100 is not.
  BOOST_CHECK(is_contact(VF, q, r, {0, 1}, {Qn("1/4")}));
  BOOST_CHECK(!is_contact(VF, q, r, {Qn("1/100"), 1}, {Qn("1/4")}));
  // At the other root (5 + sqrt 14)/11 ~ 0.7947 (in (7/10, 4/5): h(7/10) =
  // -0.61, h(4/5) = 0.04), p is in the plane but u + v ~ 1.045 > 1.
  BOOST_CHECK(!is_contact(VF, q, root({1, -10, 11}, Qn("7/10"), Qn("4/5")), {0, 1}, {Qn("1/4")}));
}

BOOST_AUTO_TEST_CASE(vf_touch_at_t1)
{
  // p(t) = (1/4, 1/4, 1 - t): in the plane z = 0 only at t = 1, inside. t* = 1.
  expect_hit(VF, make(P(Qn("1/4"), Qn("1/4"), 1), A0, B0, C0, P(Qn("1/4"), Qn("1/4"), 0), A0, B0, C0), rat(1));
  // p(t) = (1, 0, 1 - t) reaches the corner b exactly at t = 1.
  expect_hit(VF, make(P(1, 0, 1), A0, B0, C0, P(1, 0, 0), A0, B0, C0), rat(1));
}

BOOST_AUTO_TEST_CASE(vf_contact_at_t0)
{
  // p(0) = (1/4, 1/4, 0) is inside; it leaves upward. t* = 0.
  expect_hit(VF, make(P(Qn("1/4"), Qn("1/4"), 0), A0, B0, C0, P(Qn("1/4"), Qn("1/4"), 1), A0, B0, C0), rat(0));
  // p(0) = b exactly, then p(t) = (1 + t, 0, t) leaves. t* = 0.
  expect_hit(VF, make(P(1, 0, 0), A0, B0, C0, P(2, 0, 1), A0, B0, C0), rat(0));
}

BOOST_AUTO_TEST_CASE(vf_coplanar_throughout)
{
  // Everything stays in z = 0: det[b-a, c-a, p-a] is identically zero.
  // Hit: p(t) = (2 - 4t, 1/4, 0) is in the triangle iff x >= 0 and
  // x + y <= 1: 2 - 4t + 1/4 <= 1 <=> t >= 5/16, and t <= 1/2. t* = 5/16
  // (p on the edge bc there).
  expect_hit(VF, make(P(2, Qn("1/4"), 0), A0, B0, C0, P(-2, Qn("1/4"), 0), A0, B0, C0), rat(Qn("5/16")));
  // Miss: the triangle translates by (t, 0, 0) in its plane, p = (5,5,0)
  // fixed; its y = 5 exceeds every y of the triangle (<= 1).
  expect_miss(VF, make(P(5, 5, 0), A0, B0, C0, P(5, 5, 0), P(1, 0, 0), P(2, 0, 0), P(1, 1, 0)));
}

BOOST_AUTO_TEST_CASE(vf_vertex_through_edge_and_corner)
{
  // p(t) = (1/2, 0, 1 - 2t) crosses z = 0 at t = 1/2 at (1/2, 0, 0), the
  // midpoint of edge ab (u = 1/2, v = 0). t* = 1/2.
  Query q = make(P(Qn("1/2"), 0, 1), A0, B0, C0, P(Qn("1/2"), 0, -1), A0, B0, C0);
  expect_hit(VF, q, rat(Qn("1/2")));
  BOOST_CHECK(is_contact(VF, q, rat(Qn("1/2")), {Qn("1/2")}, {}));
  BOOST_CHECK(!is_contact(VF, q, rat(Qn("1/2")), {Qn("1/2")}, {Qn("-1/100")}));  // v < 0
  // p(t) = (0, 0, 1 - 2t) passes through the corner a at t = 1/2.
  expect_hit(VF, make(P(0, 0, 1), A0, B0, C0, P(0, 0, -1), A0, B0, C0), rat(Qn("1/2")));
  // Just outside the edge: p(t) = (1/2, -1/100, 1 - 2t) is in the plane only
  // at t = 1/2, at y = -1/100 < 0. Miss.
  expect_miss(VF, make(P(Qn("1/2"), Qn("-1/100"), 1), A0, B0, C0, P(Qn("1/2"), Qn("-1/100"), -1), A0, B0, C0));
}

BOOST_AUTO_TEST_CASE(vf_degenerate_triangle)
{
  // Collinear corners a = (1,0,0), b = (0,0,0), c = (2,0,0): the triangle is
  // the segment [0, 2] on the x axis. p(t) = (3/2, 0, 1 - 2t) is on it at
  // t = 1/2 only. t* = 1/2.
  const Point3 a = P(1, 0, 0), b = P(0, 0, 0), c = P(2, 0, 0);
  expect_hit(VF, make(P(Qn("3/2"), 0, 1), a, b, c, P(Qn("3/2"), 0, -1), a, b, c), rat(Qn("1/2")));
  // p(t) = (5/2, 0, 1 - 2t): on the x axis at t = 1/2 but at x = 5/2 > 2. Miss.
  expect_miss(VF, make(P(Qn("5/2"), 0, 1), a, b, c, P(Qn("5/2"), 0, -1), a, b, c));
  // All corners equal (1,1,1): the triangle is that point. p(t) = (2t,2t,2t)
  // is there at t = 1/2.
  const Point3 o = P(1, 1, 1);
  expect_hit(VF, make(P(0, 0, 0), o, o, o, P(2, 2, 2), o, o, o), rat(Qn("1/2")));
  // p(t) = (2t, 2t, 3t) would need t = 1/2 and t = 1/3 at once. Miss.
  expect_miss(VF, make(P(0, 0, 0), o, o, o, P(2, 2, 3), o, o, o));
  // A triangle flattening through a segment: a = (0,0,0), b = (2,0,0) fixed,
  // c(t) = (1, s, s) with s = 1 - 2t (degenerate at t = 1/2), p = (1, -1/2,
  // -1/2) fixed. a + u(b-a) + v(c-a) = (2u + v, v s, v s) = p needs v s = -1/2,
  // so s < 0 and v = -1/(2s) <= 1 <=> s <= -1/2 <=> t >= 3/4; then
  // u = (1 - v)/2 >= 0 and u + v = (1 + v)/2 <= 1. t* = 3/4 (p = c there).
  const Point3 p = P(1, Qn("-1/2"), Qn("-1/2"));
  expect_hit(VF, make(p, P(0, 0, 0), P(2, 0, 0), P(1, 1, 1), p, P(0, 0, 0), P(2, 0, 0), P(1, -1, -1)),
             rat(Qn("3/4")));
}

BOOST_AUTO_TEST_CASE(vf_separation)
{
  // p(t) = (4t - 1, 1/4, 1) over the unit triangle. For x < 0 the nearest
  // point is on edge ac, (0, 1/4, 0): distance sqrt(x^2 + 1) > 1. For
  // 0 <= x <= 3/4 the foot (x, 1/4, 0) is inside: distance exactly 1.
  const Query q = make(P(-1, Qn("1/4"), 1), A0, B0, C0, P(3, Qn("1/4"), 1), A0, B0, C0);
  // D = 1: reached exactly, first at x = 0, t = 1/4.
  expect_hit(VF, q, rat(Qn("1/4")), 1);
  // D = 99/100: the distance is >= |p_z| = 1 > D throughout. Miss.
  expect_miss(VF, q, Qn("99/100"));
  // Plain contract: p_z = 1 always. Miss.
  expect_miss(VF, q);
  // An irrational first time: p(t) = (4t - 4, -1, 0), x <= 0, y = -1: the
  // nearest point is the corner a (x <= 0, y <= 0 is a's normal cone), at
  // distance sqrt(x^2 + 1) <= 2 <=> x >= -sqrt 3 <=> t >= 1 - sqrt(3)/4 ~
  // 0.5670, the root of 16(1 - t)^2 = 3, i.e. 16t^2 - 32t + 13, in (1/2, 3/5)
  // (values 1 and -0.44 there).
  const Query q2 = make(P(-4, -1, 0), A0, B0, C0, P(0, -1, 0), A0, B0, C0);
  Answer a = expect_hit(VF, q2, root({13, -32, 16}, Qn("1/2"), Qn("3/5")), 2);
  BOOST_CHECK(!a.t_star.is_rational);
  expect_miss(VF, q2);  // y = -1: never on the triangle
  BOOST_CHECK_THROW(solve(VF, q2, -1), std::invalid_argument);
}

// ============================================================== edge-edge

BOOST_AUTO_TEST_CASE(ee_clear_miss)
{
  // b(t) = {(1/2, y, 1 + t) : -1 <= y <= 1}: always at z >= 1 above the edge on the x axis.
  expect_miss(EE, make(E0, E1, P(Qn("1/2"), -1, 1), P(Qn("1/2"), 1, 1), E0, E1, P(Qn("1/2"), -1, 2),
                       P(Qn("1/2"), 1, 2)));
}

BOOST_AUTO_TEST_CASE(ee_clear_hit_rational)
{
  // b(t) = {(1/2, y, 1 - 2t)}: crosses the x axis at t = 1/2 at (1/2,0,0),
  // u = 1/2 on a, v = 1/2 on b. t* = 1/2.
  Query q = make(E0, E1, P(Qn("1/2"), -1, 1), P(Qn("1/2"), 1, 1), E0, E1, P(Qn("1/2"), -1, -1),
                 P(Qn("1/2"), 1, -1));
  Answer a = expect_hit(EE, q, rat(Qn("1/2")));
  BOOST_CHECK(a.t_star.is_rational);
  BOOST_CHECK(is_contact(EE, q, rat(Qn("1/2")), {Qn("1/2")}, {Qn("1/2")}));
  BOOST_CHECK(!is_contact(EE, q, rat(Qn("1/2")), {Qn("1/2")}, {Qn("1/3")}));
  BOOST_CHECK(!is_contact(EE, q, rat(Qn("1/4")), {Qn("1/2")}, {Qn("1/2")}));  // b is at z = 1/2 then
  BOOST_CHECK(!is_contact(EE, q, rat(Qn("3/2")), {Qn("1/2")}, {Qn("1/2")}));  // t outside [0, 1]
}

BOOST_AUTO_TEST_CASE(ee_hit_irrational)
{
  // a on the x axis from 0 to 1; b0(t) = (1/2, -1, 11t - 10), b1(t) = (1/2, t, 1)
  // [b0: (1/2,-1,-10) -> (1/2,-1,1), b1: (1/2,0,1) -> (1/2,1,1)]. b lies in
  // the plane x = 1/2, which meets a only at (1/2, 0, 0) (u = 1/2), so the
  // question is whether the yz-segment from (-1, 11t - 10) to (t, 1) holds
  // the origin: collinear iff z0 y1 - y0 z1 = (11t - 10) t + 1 = 11t^2 - 10t + 1
  // = 0 (positive at t = 0, so no contact before the first root r =
  // (5 - sqrt 14)/11), and then y = -1 + v (t + 1) = 0 gives v = 1/(1 + r)
  // ~ 0.897 in [0, 1]. t* = r.
  Query q = make(E0, E1, P(Qn("1/2"), -1, -10), P(Qn("1/2"), 0, 1), E0, E1, P(Qn("1/2"), -1, 1),
                 P(Qn("1/2"), 1, 1));
  Real r = r_5_minus_sqrt14_over_11();
  Answer a = expect_hit(EE, q, r);
  BOOST_CHECK(!a.t_star.is_rational);
  // is_contact with v given as a polynomial that equals 1/(1 + t) only in
  // Q(r): (1 + r)(21/22 - r/2) = 1 - (11 r^2 - 10 r + 1)/22 = 1. So
  // v = 21/22 - t/2 is the contact at r (and not at other t), v = 9/10 is not.
  BOOST_CHECK(is_contact(EE, q, r, {Qn("1/2")}, {Qn("21/22"), Qn("-1/2")}));
  BOOST_CHECK(!is_contact(EE, q, r, {Qn("1/2")}, {Qn("9/10")}));
  BOOST_CHECK(!is_contact(EE, q, rat(Qn("1/8")), {Qn("1/2")}, {Qn("21/22"), Qn("-1/2")}));
}

BOOST_AUTO_TEST_CASE(ee_touch_at_t1_and_contact_at_t0)
{
  // b(t) = {(1/2, y, 1 - t)}: reaches the x axis exactly at t = 1.
  expect_hit(EE, make(E0, E1, P(Qn("1/2"), -1, 1), P(Qn("1/2"), 1, 1), E0, E1, P(Qn("1/2"), -1, 0),
                      P(Qn("1/2"), 1, 0)),
             rat(1));
  // b(t) = {(1/2, y, t)}: crosses a at t = 0, then leaves. t* = 0.
  expect_hit(EE, make(E0, E1, P(Qn("1/2"), -1, 0), P(Qn("1/2"), 1, 0), E0, E1, P(Qn("1/2"), -1, 1),
                      P(Qn("1/2"), 1, 1)),
             rat(0));
}

BOOST_AUTO_TEST_CASE(ee_coplanar_throughout)
{
  // All in z = 0 (the coplanarity polynomial is identically zero).
  // Hit: b(t) = {(1/2, y, 0) : 1 - 2t <= y <= 2 - 2t} holds (1/2, 0, 0) iff t >= 1/2.
  expect_hit(EE, make(E0, E1, P(Qn("1/2"), 1, 0), P(Qn("1/2"), 2, 0), E0, E1, P(Qn("1/2"), -1, 0),
                      P(Qn("1/2"), 0, 0)),
             rat(Qn("1/2")));
  // Miss: b slides along x at y between 1 and 2, never on y = 0.
  expect_miss(EE, make(E0, E1, P(Qn("1/2"), 1, 0), P(Qn("1/2"), 2, 0), E0, E1, P(Qn("3/2"), 1, 0),
                       P(Qn("3/2"), 2, 0)));
}

BOOST_AUTO_TEST_CASE(ee_endpoints)
{
  // b(t) = {(1/2, 0, z) : 1 - 2t <= z <= 2 - 2t}: its end b0 reaches the
  // interior of a at t = 1/2 (v = 0, u = 1/2).
  Query q = make(E0, E1, P(Qn("1/2"), 0, 1), P(Qn("1/2"), 0, 2), E0, E1, P(Qn("1/2"), 0, -1),
                 P(Qn("1/2"), 0, 0));
  expect_hit(EE, q, rat(Qn("1/2")));
  BOOST_CHECK(is_contact(EE, q, rat(Qn("1/2")), {Qn("1/2")}, {0}));
  // The same at x = 1: b0 meets the end a1 = (1,0,0) at t = 1/2.
  expect_hit(EE, make(E0, E1, P(1, 0, 1), P(1, 0, 2), E0, E1, P(1, 0, -1), P(1, 0, 0)), rat(Qn("1/2")));
  // At x = 101/100 it misses a (whose x <= 1).
  expect_miss(EE, make(E0, E1, P(Qn("101/100"), 0, 1), P(Qn("101/100"), 0, 2), E0, E1, P(Qn("101/100"), 0, -1),
                       P(Qn("101/100"), 0, 0)));
  // The end a1 passes through the interior of b: b(t) = {(1, y, 1 - 2t) :
  // -1 <= y <= 1} holds (1,0,0) at t = 1/2.
  expect_hit(EE, make(E0, E1, P(1, -1, 1), P(1, 1, 1), E0, E1, P(1, -1, -1), P(1, 1, -1)), rat(Qn("1/2")));
}

BOOST_AUTO_TEST_CASE(ee_parallel)
{
  // b parallel to a throughout (both along x).
  // Miss: b(t) = {(x, 1, 1 - 2t) : 0 <= x <= 1} stays at y = 1.
  expect_miss(EE, make(E0, E1, P(0, 1, 1), P(1, 1, 1), E0, E1, P(0, 1, -1), P(1, 1, -1)));
  // Overlapping hit: b(t) = {(x, 0, 1 - 2t) : 1/2 <= x <= 3/2} lies on the x
  // axis at t = 1/2, overlapping a on [1/2, 1]. t* = 1/2.
  expect_hit(EE, make(E0, E1, P(Qn("1/2"), 0, 1), P(Qn("3/2"), 0, 1), E0, E1, P(Qn("1/2"), 0, -1),
                      P(Qn("3/2"), 0, -1)),
             rat(Qn("1/2")));
  // Touching end to end: b = [1, 2] on the axis at t = 1/2 meets a only at (1,0,0).
  expect_hit(EE, make(E0, E1, P(1, 0, 1), P(2, 0, 1), E0, E1, P(1, 0, -1), P(2, 0, -1)), rat(Qn("1/2")));
  // A gap: b = [101/100, 2] at t = 1/2. Miss.
  expect_miss(EE, make(E0, E1, P(Qn("101/100"), 0, 1), P(2, 0, 1), E0, E1, P(Qn("101/100"), 0, -1), P(2, 0, -1)));
}

BOOST_AUTO_TEST_CASE(ee_collinear)
{
  // Both on the x axis throughout: b(t) = [2 - 2t, 3 - 2t] meets [0, 1] iff
  // 2 - 2t <= 1 <=> t >= 1/2.
  expect_hit(EE, make(E0, E1, P(2, 0, 0), P(3, 0, 0), E0, E1, P(0, 0, 0), P(1, 0, 0)), rat(Qn("1/2")));
  // The same with b's ends swapped (same set at every t).
  expect_hit(EE, make(E0, E1, P(3, 0, 0), P(2, 0, 0), E0, E1, P(1, 0, 0), P(0, 0, 0)), rat(Qn("1/2")));
  // b(t) = [2 + t, 3 + t] moves away. Miss.
  expect_miss(EE, make(E0, E1, P(2, 0, 0), P(3, 0, 0), E0, E1, P(3, 0, 0), P(4, 0, 0)));
}

BOOST_AUTO_TEST_CASE(ee_zero_length)
{
  // b is the point (1/4, 0, 1 - 2t): on a at t = 1/2 (u = 1/4, any v).
  Query q = make(E0, E1, P(Qn("1/4"), 0, 1), P(Qn("1/4"), 0, 1), E0, E1, P(Qn("1/4"), 0, -1),
                 P(Qn("1/4"), 0, -1));
  expect_hit(EE, q, rat(Qn("1/2")));
  BOOST_CHECK(is_contact(EE, q, rat(Qn("1/2")), {Qn("1/4")}, {Qn("2/3")}));
  // The point (1/4, 1/100, 1 - 2t) passes beside a. Miss.
  expect_miss(EE, make(E0, E1, P(Qn("1/4"), Qn("1/100"), 1), P(Qn("1/4"), Qn("1/100"), 1), E0, E1,
                       P(Qn("1/4"), Qn("1/100"), -1), P(Qn("1/4"), Qn("1/100"), -1)));
  // Both edges points: the origin, and (2t - 1, 0, 0). Equal at t = 1/2.
  const Point3 o = P(0, 0, 0);
  expect_hit(EE, make(o, o, P(-1, 0, 0), P(-1, 0, 0), o, o, P(1, 0, 0), P(1, 0, 0)), rat(Qn("1/2")));
  // a collapses to a point at t = 1/2 (a1(t) = (1 - 2t, 0, 0)) and b is the
  // point (-1/2, 0, 0) fixed: a(t) = [0, 1 - 2t] (or [1 - 2t, 0]) holds -1/2
  // iff 1 - 2t <= -1/2 <=> t >= 3/4.
  const Point3 m = P(Qn("-1/2"), 0, 0);
  expect_hit(EE, make(o, P(1, 0, 0), m, m, o, P(-1, 0, 0), m, m), rat(Qn("3/4")));
}

BOOST_AUTO_TEST_CASE(ee_separation)
{
  // b(t) = {(4t - 1, y, 2) : -1 <= y <= 1}, parallel to the y axis at height 2.
  // For x in [0, 1] the closest points are (x,0,0) and (x,0,2): distance 2;
  // for x < 0 it is (0,0,0) to (x,0,2): sqrt(x^2 + 4) > 2.
  const Query q = make(E0, E1, P(-1, -1, 2), P(-1, 1, 2), E0, E1, P(3, -1, 2), P(3, 1, 2));
  expect_hit(EE, q, rat(Qn("1/4")), 2);  // exactly D = 2 from x = 0, t = 1/4
  expect_miss(EE, q, Qn("1999/1000"));   // the distance never drops below 2
  expect_miss(EE, q);
  // Crossing b(t) = {(1/2, y, 3 - 4t)}: distance |3 - 4t| <= 1 first at t = 1/2.
  expect_hit(EE, make(E0, E1, P(Qn("1/2"), -1, 3), P(Qn("1/2"), 1, 3), E0, E1, P(Qn("1/2"), -1, -1),
                      P(Qn("1/2"), 1, -1)),
             rat(Qn("1/2")), 1);
  // b the point (4t - 4, 0, 1): distance to a is sqrt(x^2 + 1) for x <= 0,
  // <= 2 iff t >= 1 - sqrt(3)/4 (root of 16t^2 - 32t + 13 in (1/2, 3/5)).
  expect_hit(EE, make(E0, E1, P(-4, 0, 1), P(-4, 0, 1), E0, E1, P(0, 0, 1), P(0, 0, 1)),
             root({13, -32, 16}, Qn("1/2"), Qn("3/5")), 2);
}

// ============================================================== compare

BOOST_AUTO_TEST_CASE(compare_reals)
{
  const Real sqrt2 = root({-2, 0, 1}, 1, 2);
  // (x^2 - 2)(x - 3) = x^3 - 3x^2 - 2x + 6: roots -sqrt2, sqrt2, 3; only sqrt2 in (0, 5/2).
  BOOST_CHECK_EQUAL(compare(sqrt2, root({6, -2, -3, 1}, 0, Qn("5/2"))), 0);
  BOOST_CHECK_EQUAL(compare(root({6, -2, -3, 1}, 0, Qn("5/2")), sqrt2), 0);
  // A wide interval: (-1, 100) holds sqrt2 only (-sqrt2 < -1).
  BOOST_CHECK_EQUAL(compare(root({-2, 0, 1}, -1, 100), sqrt2), 0);
  // (x^2 - 2)^2 is not squarefree; its only distinct root in (1, 2) is sqrt2.
  BOOST_CHECK_EQUAL(compare(root({4, 0, -4, 0, 1}, 1, 2), sqrt2), 0);
  // (x - 1)(x^2 - 2) in (1, 2): the root 1 is an end, excluded; sqrt2 remains.
  BOOST_CHECK_EQUAL(compare(root({2, -2, -1, 1}, 1, 2), sqrt2), 0);
  // Against rationals: 7/5 = 1.4 < 1.4142 = 7071/5000 < sqrt2 < 1.4144 < 3/2.
  BOOST_CHECK_EQUAL(compare(sqrt2, rat(Qn("3/2"))), -1);
  BOOST_CHECK_EQUAL(compare(sqrt2, rat(Qn("7/5"))), 1);
  BOOST_CHECK_EQUAL(compare(sqrt2, rat(Qn("7071/5000"))), 1);
  BOOST_CHECK_EQUAL(compare(rat(Qn("7072/5000")), sqrt2), 1);
  // sqrt2 < sqrt3; -sqrt2 < sqrt2.
  BOOST_CHECK_EQUAL(compare(sqrt2, root({-3, 0, 1}, 1, 2)), -1);
  BOOST_CHECK_EQUAL(compare(root({-2, 0, 1}, -2, -1), sqrt2), -1);
  // sqrt2 < sqrt(2 + 10^-20) (they differ by ~3.5e-21).
  mpq_class eps("1/100000000000000000000");
  BOOST_CHECK_EQUAL(compare(sqrt2, root({-2 - eps, 0, 1}, 1, 2)), -1);
  BOOST_CHECK_EQUAL(compare(root({-2 - eps, 0, 1}, 1, 2), sqrt2), 1);
  // A rational given by a polynomial: (x - 1/2)(x^2 - 2) = x^3 - x^2/2 - 2x + 1,
  // whose only root in (0, 1) is 1/2.
  BOOST_CHECK_EQUAL(compare(root({1, -2, Qn("-1/2"), 1}, 0, 1), rat(Qn("1/2"))), 0);
  BOOST_CHECK_EQUAL(compare(rat(Qn("1/3")), rat(Qn("1/2"))), -1);
  BOOST_CHECK_EQUAL(compare(rat(Qn("2/4")), rat(Qn("1/2"))), 0);
  // Malformed: two roots in (-2, 2); no root in (0, 1); lo >= hi.
  BOOST_CHECK_THROW(compare(root({-2, 0, 1}, -2, 2), sqrt2), std::invalid_argument);
  BOOST_CHECK_THROW(compare(root({1, 0, 1}, 0, 1), sqrt2), std::invalid_argument);
  BOOST_CHECK_THROW(compare(root({-2, 0, 1}, 2, 1), sqrt2), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(root_isolation_and_rationalize)
{
  namespace d = clash4d::ccd_oracle::detail;
  // (2t - 1)(4t - 1)(4t - 3)(2t^2 - 1): roots 1/2, 1/4, 3/4 (all bisection
  // midpoints of [0,1]) and sqrt(1/2) ~ 0.7071 in [0, 1] (-0.7071 outside).
  d::Poly g = d::mul(d::mul(d::Poly{-1, 2}, d::Poly{-1, 4}), d::mul(d::Poly{-3, 4}, d::Poly{-1, 0, 2}));
  std::vector<d::Alg> roots;
  d::roots_in_unit_interval(g, roots);
  std::vector<Real> got;
  for (const auto& a : roots) got.push_back(d::to_real(a));
  const std::vector<Real> expected = {rat(Qn("1/4")), rat(Qn("1/2")), root({-1, 0, 2}, Qn("7/10"), Qn("3/4")),
                                      rat(Qn("3/4"))};
  BOOST_REQUIRE_EQUAL(got.size(), expected.size());
  for (const auto& e : expected) {
    int n = 0;
    for (const auto& x : got) n += compare(x, e) == 0;
    BOOST_CHECK_MESSAGE(n == 1, describe(e) << " found " << n << " times");
  }
  // Ends: t (t - 1)(3t - 1) has the roots 0, 1/3, 1.
  roots.clear();
  d::roots_in_unit_interval(d::mul(d::mul(d::Poly{0, 1}, d::Poly{-1, 1}), d::Poly{-1, 3}), roots);
  BOOST_CHECK_EQUAL(roots.size(), 3u);
  // A rational number in irrational form: the root of (3x - 1)(x^2 - 2) in
  // (0, 1) is 1/3; rationalize() finds it. The root of (x^2 - 2)(x - 3) in
  // (1, 2) stays irrational.
  d::Alg third = d::to_alg(root({2, -6, -1, 3}, 0, 1));
  d::rationalize(third);
  BOOST_CHECK(third.rat && third.q == Qn("1/3"));
  d::Alg s2 = d::to_alg(root({6, -2, -3, 1}, 1, 2));
  d::rationalize(s2);
  BOOST_CHECK(!s2.rat);
}

BOOST_AUTO_TEST_CASE(simplest_rational)
{
  using clash4d::ccd_oracle::detail::simplest_between;
  BOOST_CHECK_EQUAL(simplest_between(Qn("0"), Qn("1/2")), Qn("1/3"));
  BOOST_CHECK_EQUAL(simplest_between(Qn("1/3"), Qn("1/2")), Qn("2/5"));
  BOOST_CHECK_EQUAL(simplest_between(Qn("3/10"), Qn("4/10")), Qn("1/3"));
  BOOST_CHECK_EQUAL(simplest_between(Qn("1/2"), Qn("5/2")), Qn("1"));
  BOOST_CHECK_EQUAL(simplest_between(Qn("-7/5"), Qn("-13/10")), Qn("-4/3"));
}

// ============================================================== randomised cross-checks

namespace {

// A second static test, written the other way round: solve the small linear
// system by Cramer on the first non-zero 2x2 minor, check the remaining row
// and the inequalities; when the rank drops, point-in-segment tests.
namespace alt {
using V = std::array<mpq_class, 3>;
V at(const Query& q, int i, const mpq_class& t)
{
  V r;
  for (int k = 0; k < 3; ++k) r[k] = (1 - t) * q[i][k] + t * q[i + 4][k];
  return r;
}
V minus(const V& a, const V& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
bool on_segment(const V& p, const V& q0, const V& q1)
{
  V d = minus(q1, q0), w = minus(p, q0);
  int i = -1;
  for (int k = 0; k < 3 && i < 0; ++k)
    if (d[k] != 0) i = k;
  if (i < 0) return w[0] == 0 && w[1] == 0 && w[2] == 0;
  mpq_class s = w[i] / d[i];
  if (s < 0 || s > 1) return false;
  for (int k = 0; k < 3; ++k)
    if (w[k] != s * d[k]) return false;
  return true;
}
const int pairs[3][3] = {{0, 1, 2}, {0, 2, 1}, {1, 2, 0}};
bool vf(const V& p, const V& a, const V& b, const V& c)
{
  V e1 = minus(b, a), e2 = minus(c, a), w = minus(p, a);
  for (const auto& pr : pairs) {
    int i = pr[0], j = pr[1], k = pr[2];
    mpq_class m = e1[i] * e2[j] - e1[j] * e2[i];
    if (m == 0) continue;
    mpq_class u = (w[i] * e2[j] - w[j] * e2[i]) / m, v = (e1[i] * w[j] - e1[j] * w[i]) / m;
    return u * e1[k] + v * e2[k] == w[k] && u >= 0 && v >= 0 && u + v <= 1;
  }
  return on_segment(p, a, b) || on_segment(p, a, c) || on_segment(p, b, c);
}
bool ee(const V& a0, const V& a1, const V& b0, const V& b1)
{
  // u da - v db = b0 - a0.
  V da = minus(a1, a0), nb = minus(b0, b1), r = minus(b0, a0);
  for (const auto& pr : pairs) {
    int i = pr[0], j = pr[1], k = pr[2];
    mpq_class m = da[i] * nb[j] - da[j] * nb[i];
    if (m == 0) continue;
    mpq_class u = (r[i] * nb[j] - r[j] * nb[i]) / m, v = (da[i] * r[j] - da[j] * r[i]) / m;
    return u * da[k] + v * nb[k] == r[k] && u >= 0 && u <= 1 && v >= 0 && v <= 1;
  }
  // Parallel or zero-length: they meet iff an end of one is on the other.
  return on_segment(a0, b0, b1) || on_segment(a1, b0, b1) || on_segment(b0, a0, a1) || on_segment(b1, a0, a1);
}
bool contact(Type type, const Query& q, const mpq_class& t)
{
  V x0 = at(q, 0, t), x1 = at(q, 1, t), x2 = at(q, 2, t), x3 = at(q, 3, t);
  return type == Type::vertex_face ? vf(x0, x1, x2, x3) : ee(x0, x1, x2, x3);
}
}  // namespace alt

mpq_class pick(std::mt19937& g, const std::vector<mpq_class>& from)
{
  return from[std::uniform_int_distribution<std::size_t>(0, from.size() - 1)(g)];
}
Point3 random_point(std::mt19937& g, int lo, int hi)
{
  std::uniform_int_distribution<int> d(lo, hi);
  int x = d(g), y = d(g), z = d(g);   // in this order: a call's arguments have none
  return P(x, y, z);
}
Point3 plus(const Point3& a, const Point3& b) { return P(a[0] + b[0], a[1] + b[1], a[2] + b[2]); }
Point3 minus(const Point3& a, const Point3& b) { return P(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }
Point3 times(const mpq_class& s, const Point3& a) { return P(s * a[0], s * a[1], s * a[2]); }

bool same_answer(const Answer& x, const Answer& y)
{
  if (x.collide != y.collide) return false;
  return !x.collide || compare(x.t_star, y.t_star) == 0;
}

}  // namespace

BOOST_AUTO_TEST_CASE(static_configurations_against_second_static_test)
{
  // Still configurations from a tiny grid (many collinear / coplanar /
  // coincident cases), half of them with a contact forced on a boundary or
  // just beyond it. The oracle's distance formula and the Cramer test above
  // must agree; solve() must answer t* = 0 exactly when they say contact.
  std::mt19937 g(20240601);
  const std::vector<mpq_class> params = {Qn("-1/2"), 0, Qn("1/3"), Qn("1/2"), 1, Qn("3/2")};
  int contacts[2] = {0, 0}, total = 0;
  for (int n = 0; n < 400; ++n) {
    for (Type type : {VF, EE}) {
      Point3 x0 = random_point(g, -1, 2), x1 = random_point(g, -1, 2), x2 = random_point(g, -1, 2),
             x3 = random_point(g, -1, 2);
      int mode = std::uniform_int_distribution<int>(0, 3)(g);
      if (type == VF && mode >= 2) {  // p = a + u e1 + v e2
        mpq_class u = pick(g, params), v = pick(g, params);
        if (mode == 3) v = 1 - u;  // on the line through b and c
        x0 = plus(x1, plus(times(u, minus(x2, x1)), times(v, minus(x3, x1))));
      } else if (type == EE && mode >= 2) {  // b passes through a0 + u da at its parameter v
        mpq_class u = pick(g, params), v = pick(g, params);
        Point3 X = plus(x0, times(u, minus(x1, x0)));
        Point3 dir = mode == 3 ? times(pick(g, params), minus(x1, x0)) : minus(x3, x2);  // parallel if 3
        x2 = minus(X, times(v, dir));
        x3 = plus(x2, dir);
      }
      Query q = still(x0, x1, x2, x3);
      bool expected = alt::contact(type, q, 0);
      bool got = clash4d::ccd_oracle::detail::collides_at(type, q, 0);
      BOOST_CHECK_MESSAGE(expected == got, "static disagreement, type " << (type == VF ? "vf" : "ee") << " case "
                                                                         << n);
      Answer a = solve(type, q);
      BOOST_CHECK(a.collide == expected);
      if (a.collide) BOOST_CHECK(a.t_star.is_rational && a.t_star.value == 0);
      contacts[type == VF ? 0 : 1] += expected;
      ++total;
    }
  }
  BOOST_TEST_MESSAGE("static configurations: " << total << ", contacts vf " << contacts[0] << ", ee "
                                               << contacts[1]);
  BOOST_CHECK(contacts[0] > 50 && contacts[1] > 50);
}

BOOST_AUTO_TEST_CASE(moving_queries_first_time_and_invariances)
{
  // Random moving queries on a small integer grid. For each:
  //  - at every grid time s = k/16: if the second static test says contact,
  //    the oracle collides with t* <= s; if s < t* it must say no contact;
  //  - a rational t* is a contact for the second static test;
  //  - the answer is the same after relabelling (triangle corners permuted;
  //    edge ends swapped, edges swapped) and after adding a common linear
  //    motion to all four vertices; the verdict is the same under time
  //    reversal.
  std::mt19937 g(7);
  int hits = 0, irrational = 0, total = 0;
  for (int n = 0; n < 150; ++n) {
    for (Type type : {VF, EE}) {
      Query q;
      for (auto& row : q) row = random_point(g, -2, 2);
      mpq_class D = n % 3 == 0 ? mpq_class(1, 2) : mpq_class(0);
      Answer a = solve(type, q, D);
      ++total;
      if (a.collide) {
        ++hits;
        irrational += !a.t_star.is_rational;
        BOOST_CHECK(compare(a.t_star, rat(0)) >= 0 && compare(a.t_star, rat(1)) <= 0);
      }
      if (D == 0) {
        for (int k = 0; k <= 16; ++k) {
          mpq_class s(k, 16);
          s.canonicalize();
          bool c = alt::contact(type, q, s);
          if (c) BOOST_CHECK_MESSAGE(a.collide && compare(a.t_star, rat(s)) <= 0, "case " << n << " s " << s);
          if (a.collide && compare(rat(s), a.t_star) < 0) BOOST_CHECK_MESSAGE(!c, "case " << n << " s " << s);
        }
        if (a.collide && a.t_star.is_rational)
          BOOST_CHECK_MESSAGE(alt::contact(type, q, a.t_star.value), "case " << n);
      }
      // Relabellings.
      std::vector<Query> variants;
      if (type == VF) {
        variants.push_back({q[0], q[2], q[3], q[1], q[4], q[6], q[7], q[5]});  // (a,b,c) -> (b,c,a)
        variants.push_back({q[0], q[1], q[3], q[2], q[4], q[5], q[7], q[6]});  // b <-> c
      } else {
        variants.push_back({q[1], q[0], q[2], q[3], q[5], q[4], q[6], q[7]});  // a0 <-> a1
        variants.push_back({q[0], q[1], q[3], q[2], q[4], q[5], q[7], q[6]});  // b0 <-> b1
        variants.push_back({q[2], q[3], q[0], q[1], q[6], q[7], q[4], q[5]});  // a <-> b
      }
      // A common motion: + c0 at t = 0, + c1 at t = 1.
      Point3 c0 = random_point(g, -3, 3), c1 = random_point(g, -3, 3);
      Query moved = q;
      for (int i = 0; i < 4; ++i) {
        moved[i] = plus(q[i], c0);
        moved[i + 4] = plus(q[i + 4], c1);
      }
      variants.push_back(moved);
      for (const auto& v : variants)
        BOOST_CHECK_MESSAGE(same_answer(a, solve(type, v, D)), "relabelled/moved answer differs, case " << n);
      Query reversed = {q[4], q[5], q[6], q[7], q[0], q[1], q[2], q[3]};
      BOOST_CHECK_MESSAGE(solve(type, reversed, D).collide == a.collide, "time reversal, case " << n);
    }
  }
  BOOST_TEST_MESSAGE("moving queries: " << total << ", collide " << hits << ", irrational t* " << irrational);
  BOOST_CHECK(hits > 20);
}
