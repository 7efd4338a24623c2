#define BOOST_TEST_MODULE ccd
// CCD queries (docs/ccd-queries.md): hand-derived cases for each degenerate
// kind of both primitives, the exact answers of the filtered kernel against
// the rational kernel on seeded campaigns of the fuzz families (with floors
// on how often the intervals decide alone, and how often they hand a sign to
// rationals), the readers' errors, and the command line.
//
// CLASH4D_SEED overrides the campaign seed, CLASH4D_CCD_CASES the number of
// cases.
#include <boost/test/unit_test.hpp>

#include "ccd/Ccd_families.h"
#include "ccd/Ccd_reader.h"
#include "exact/Ccd_filtered_kernel.h"
#include "exact/Ccd_instantiation.h"
#include "numbers/Quadratic_element.h"
#include "float/Ccd_double_instantiation.h"
#include "scene/Input_error.h"
#include "scene/Number_text.h"
#include "scene/Random_draw.h"
#include <nlohmann/json.hpp>
#include "support/Ccd_oracle.h"
#include "support/Cli_run.h"
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace clash4d;

namespace {

std::uint64_t env_number(const char* name, std::uint64_t fallback)
{
  const char* v = std::getenv(name);
  return v && *v ? std::strtoull(v, nullptr, 10) : fallback;
}

using Rows = Ccd_query::Rows;

// Rows from text: the four vertices at t = 0, then at t = 1.
Ccd_query query(Ccd_type type, std::initializer_list<std::array<const char*, 3>> rows)
{
  Rows r;
  std::size_t i = 0;
  for (const auto& row : rows) {
    for (std::size_t k = 0; k < 3; ++k) r[i][k] = parse_number_text(row[k], true).value;
    ++i;
  }
  BOOST_REQUIRE_EQUAL(i, 8u);
  return Ccd_query(type, r);
}

Ccd_answer earliest(const Ccd_query& q, bool filtered = true)
{
  Ccd_options o;
  o.earliest = true;
  return filtered ? ccd_exact(q, o) : ccd_rational(q, o);
}

const Algebraic& exact(const Ccd_number& x) { return std::get<Algebraic>(x); }
Algebraic rational(const char* q) { return Algebraic(Rational(q)); }

// The contact's own check, in Q(t*): the primitives' points at (u, v) agree
// and (u, v) lies in the parameter domain (docs/ccd-queries.md).
void check_contact(const Ccd_query& q, const Ccd_answer& a)
{
  BOOST_REQUIRE(a.collide && a.earliest && a.earliest->uv);
  const Algebraic &t = exact(a.earliest->t), &u = exact(a.earliest->u), &v = exact(a.earliest->v);
  const Ccd_uv_fraction<Rational>& f = *a.earliest->uv;
  BOOST_TEST((compare(u, Rational(0)) >= 0 && compare(v, Rational(0)) >= 0));
  if (q.type() == Ccd_type::vertex_face) {   // 1 - u - v = (ud vd - un vd - vn ud) / (ud vd) >= 0
    Polynomial<Rational> den = f.u_den * f.v_den, num = den - f.u_num * f.v_den - f.v_num * f.u_den;
    BOOST_TEST(t.sign_of(num.coefficients()) * t.sign_of(den.coefficients()) >= 0);
  } else {
    BOOST_TEST((compare(u, Rational(1)) <= 0 && compare(v, Rational(1)) <= 0));
  }
  // Each coordinate of the difference of the two points, a polynomial in t
  // once multiplied by u's and v's denominators, vanishes at t*.
  for (std::size_t k = 0; k < 3; ++k) {
    auto x = [&](int i) { return Polynomial<Rational>(q.row(i)[k], q.row(i + 4)[k] - q.row(i)[k]); };
    Polynomial<Rational> diff;
    if (q.type() == Ccd_type::vertex_face)   // (p - a) u_den v_den - (b - a) u_num v_den - (c - a) v_num u_den
      diff = (x(0) - x(1)) * f.u_den * f.v_den - (x(2) - x(1)) * f.u_num * f.v_den - (x(3) - x(1)) * f.v_num * f.u_den;
    else   // (a0 - b0) u_den v_den + (a1 - a0) u_num v_den - (b1 - b0) v_num u_den
      diff = (x(0) - x(2)) * f.u_den * f.v_den + (x(1) - x(0)) * f.u_num * f.v_den - (x(3) - x(2)) * f.v_num * f.u_den;
    BOOST_TEST(t.sign_of(diff.coefficients()) == CGAL::ZERO, "coordinate " << k << " of the contact");
  }
}

// Exact (filtered) and rational agree, t* and (u, v) included; returns the
// filtered answer.
Ccd_answer agreed(const Ccd_query& q)
{
  Ccd_answer e = earliest(q, true), r = earliest(q, false);
  BOOST_REQUIRE_EQUAL(e.collide, r.collide);
  if (e.collide) {
    BOOST_TEST((exact(e.earliest->t) == exact(r.earliest->t)));
    BOOST_TEST((exact(e.earliest->u) == exact(r.earliest->u)));
    BOOST_TEST((exact(e.earliest->v) == exact(r.earliest->v)));
    check_contact(q, e);
  }
  return e;
}

void expect_hit(const Ccd_query& q, const Algebraic& t, const Algebraic& u, const Algebraic& v)
{
  Ccd_answer a = agreed(q);
  BOOST_REQUIRE(a.collide);
  BOOST_TEST(exact(a.earliest->t).to_text() == t.to_text());
  BOOST_TEST((exact(a.earliest->t) == t));
  BOOST_TEST((exact(a.earliest->u) == u));
  BOOST_TEST((exact(a.earliest->v) == v));
}

void expect_miss(const Ccd_query& q) { BOOST_TEST(!agreed(q).collide); }

} // namespace

// The triangle a = (0,0,0), b = (1,0,0), c = (0,1,0) at rest in z = 0 unless
// said otherwise; P = p - a, N = (0,0,1), so F = N . P = p_z(t).
BOOST_AUTO_TEST_SUITE(vertex_face)

// p = (1/4, 1/4, 1 - 2t): F = 1 - 2t, t* = 1/2, inside at u = v = 1/4.
BOOST_AUTO_TEST_CASE(through_the_interior)
{
  expect_hit(query(Ccd_type::vertex_face, {{"1/4", "1/4", "1"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"},
                                           {"1/4", "1/4", "-1"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"}}),
             rational("1/2"), rational("1/4"), rational("1/4"));
}

// p = (2, 2, 1 - 2t) meets the plane at t = 1/2 at u = v = 2: outside.
BOOST_AUTO_TEST_CASE(clear_miss)
{
  expect_miss(query(Ccd_type::vertex_face, {{"2", "2", "1"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"},
                                            {"2", "2", "-1"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"}}));
}

// p = (1/4, 1/4, 1 - t): F = 1 - t is zero only at t = 1, where p is inside:
// touching exactly at the end of the span counts.
BOOST_AUTO_TEST_CASE(touching_at_t_one)
{
  expect_hit(query(Ccd_type::vertex_face, {{"1/4", "1/4", "1"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"},
                                           {"1/4", "1/4", "0"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"}}),
             rational("1"), rational("1/4"), rational("1/4"));
}

// p = (1/4, 1/4, t): on the triangle at t = 0, leaving it.
BOOST_AUTO_TEST_CASE(contact_at_t_zero)
{
  expect_hit(query(Ccd_type::vertex_face, {{"1/4", "1/4", "0"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"},
                                           {"1/4", "1/4", "1"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"}}),
             rational("0"), rational("1/4"), rational("1/4"));
}

// p = (1/2, 0, 1 - 2t) crosses the plane at (1/2, 0, 0): on edge ab,
// u = 1/2, v = 0. The vertex passes exactly through the edge.
BOOST_AUTO_TEST_CASE(through_an_edge)
{
  expect_hit(query(Ccd_type::vertex_face, {{"1/2", "0", "1"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"},
                                           {"1/2", "0", "-1"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"}}),
             rational("1/2"), rational("1/2"), rational("0"));
}

// p = (0, 0, 1 - 2t) through the corner a: u = v = 0.
BOOST_AUTO_TEST_CASE(through_a_corner)
{
  expect_hit(query(Ccd_type::vertex_face, {{"0", "0", "1"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"},
                                           {"0", "0", "-1"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"}}),
             rational("1/2"), rational("0"), rational("0"));
}

// The same 1e-15 outside edge ab (y = -1e-15): it misses. The double
// instantiation, on doubles that keep the offset, misses too; with a
// tolerance of 1e-9 it calls it a contact.
BOOST_AUTO_TEST_CASE(near_miss_outside_an_edge)
{
  Ccd_query q = query(Ccd_type::vertex_face,
                      {{"1/2", "-1e-15", "1"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"},
                       {"1/2", "-1e-15", "-1"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"}});
  expect_miss(q);
  Ccd_options o;
  BOOST_TEST(!ccd_double(q, o).collide);
  o.tolerance = 1e-9;
  BOOST_TEST(ccd_double(q, o).collide);
}

// Everything in z = 0 (F = 0 for all t): p = (2 - 3t, 2 - 3t, 0) enters the
// triangle where x + y = 1, 4 - 6t = 1, t* = 1/2, on the hypotenuse
// u = v = 1/2.
BOOST_AUTO_TEST_CASE(coplanar_sliding_hit)
{
  expect_hit(query(Ccd_type::vertex_face, {{"2", "2", "0"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"},
                                           {"-1", "-1", "0"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"}}),
             rational("1/2"), rational("1/2"), rational("1/2"));
}

// p = (2, 2 - 3t, 0): x = 2 > 1 throughout, never in the triangle.
BOOST_AUTO_TEST_CASE(coplanar_sliding_miss)
{
  expect_miss(query(Ccd_type::vertex_face, {{"2", "2", "0"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"},
                                            {"2", "-1", "0"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"}}));
}

// The triangle a = (0,0,0), b = (2,0,0), c = (1,0,0) is the segment [0, 2]
// of the x axis; p = (1, 1 - 2t, 0) meets it at t = 1/2. N = 0, so the
// contact is p on [a, b] at sigma = 1/2: u = 1/2, v = 0.
BOOST_AUTO_TEST_CASE(degenerate_triangle)
{
  expect_hit(query(Ccd_type::vertex_face, {{"1", "1", "0"}, {"0", "0", "0"}, {"2", "0", "0"}, {"1", "0", "0"},
                                           {"1", "-1", "0"}, {"0", "0", "0"}, {"2", "0", "0"}, {"1", "0", "0"}}),
             rational("1/2"), rational("1/2"), rational("0"));
}

// All three corners at the origin: p = (1 - 2t)(1, 1, 1) passes through it
// at t = 1/2 (a point segment: u = v = 0).
BOOST_AUTO_TEST_CASE(triangle_that_is_a_point)
{
  expect_hit(query(Ccd_type::vertex_face, {{"1", "1", "1"}, {"0", "0", "0"}, {"0", "0", "0"}, {"0", "0", "0"},
                                           {"-1", "-1", "-1"}, {"0", "0", "0"}, {"0", "0", "0"}, {"0", "0", "0"}}),
             rational("1/2"), rational("0"), rational("0"));
}

// An irrational t*. a = (0,0,0), b = (1,0,0) at rest, c = (0, 1, 2t - 1),
// p = (1/8, t, 1/4 - t). N = E1 x E2 = (0, 1 - 2t, 1), F = N . P =
// (1 - 2t) t + 1/4 - t = 1/4 - 2t^2 > 0 before t* = 1/(2 sqrt 2), the root
// of 8t^2 - 1. There p = u b + v c with u = 1/8 (x) and v = t (y), and z
// agrees: t (2t - 1) = 2t^2 - t = 1/4 - t. So (u, v) = (1/8, t*), inside.
BOOST_AUTO_TEST_CASE(irrational_first_time)
{
  Ccd_query q = query(Ccd_type::vertex_face, {{"1/8", "0", "1/4"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "-1"},
                                              {"1/8", "1", "-3/4"}, {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "1"}});
  auto roots = Algebraic::real_roots({Rational(-1), Rational(0), Rational(8)}, Rational(0), Rational(1));
  BOOST_REQUIRE_EQUAL(roots.size(), 1u);
  expect_hit(q, roots[0], rational("1/8"), roots[0]);
  Ccd_answer a = earliest(q);
  BOOST_TEST(!exact(a.earliest->t).is_rational());
  BOOST_TEST(exact(a.earliest->t).approx() == "0.3535533905932738");
}

BOOST_AUTO_TEST_SUITE_END()

// Edge a along x from (-1,0,.) to (1,0,.), edge b along y at rest unless
// said otherwise.
BOOST_AUTO_TEST_SUITE(edge_edge)

// a at z = 1 - 2t crosses b = (0, +-1, 0) at t = 1/2, at the middles.
BOOST_AUTO_TEST_CASE(crossing)
{
  expect_hit(query(Ccd_type::edge_edge, {{"-1", "0", "1"}, {"1", "0", "1"}, {"0", "-1", "0"}, {"0", "1", "0"},
                                         {"-1", "0", "-1"}, {"1", "0", "-1"}, {"0", "-1", "0"}, {"0", "1", "0"}}),
             rational("1/2"), rational("1/2"), rational("1/2"));
}

// b moved to x = 2: the lines meet at x = 2, beyond a's end.
BOOST_AUTO_TEST_CASE(lines_meet_beyond_an_end)
{
  expect_miss(query(Ccd_type::edge_edge, {{"-1", "0", "1"}, {"1", "0", "1"}, {"2", "-1", "0"}, {"2", "1", "0"},
                                          {"-1", "0", "-1"}, {"1", "0", "-1"}, {"2", "-1", "0"}, {"2", "1", "0"}}));
}

// a = [(0,y,0), (2,y,0)] with y = 1 - 2t, b = [(1,0,0), (3,0,0)]: parallel,
// collinear at t = 1/2 with overlap [1, 2]; b0 lies on a at u = 1/2.
BOOST_AUTO_TEST_CASE(parallel_overlapping)
{
  expect_hit(query(Ccd_type::edge_edge, {{"0", "1", "0"}, {"2", "1", "0"}, {"1", "0", "0"}, {"3", "0", "0"},
                                         {"0", "-1", "0"}, {"2", "-1", "0"}, {"1", "0", "0"}, {"3", "0", "0"}}),
             rational("1/2"), rational("1/2"), rational("0"));
}

// The same with b = [(3,0,0), (4,0,0)]: collinear at t = 1/2, disjoint.
BOOST_AUTO_TEST_CASE(collinear_disjoint)
{
  expect_miss(query(Ccd_type::edge_edge, {{"0", "1", "0"}, {"2", "1", "0"}, {"3", "0", "0"}, {"4", "0", "0"},
                                          {"0", "-1", "0"}, {"2", "-1", "0"}, {"3", "0", "0"}, {"4", "0", "0"}}));
}

// Parallel in planes 1e-9 apart (b at z = 1e-9): never meet.
BOOST_AUTO_TEST_CASE(parallel_near_miss)
{
  expect_miss(query(Ccd_type::edge_edge, {{"0", "1", "0"}, {"2", "1", "0"}, {"1", "0", "1e-9"}, {"3", "0", "1e-9"},
                                          {"0", "-1", "0"}, {"2", "-1", "0"}, {"1", "0", "1e-9"}, {"3", "0", "1e-9"}}));
}

// a = [(-2,0,1-t), (0,0,1-t)] reaches z = 0 at t = 1, where its end a1 =
// (0,0,0) lies on b at v = 1/2: touching exactly at t = 1, u = 1.
BOOST_AUTO_TEST_CASE(endpoint_touch_at_t_one)
{
  expect_hit(query(Ccd_type::edge_edge, {{"-2", "0", "1"}, {"0", "0", "1"}, {"0", "-1", "0"}, {"0", "1", "0"},
                                         {"-2", "0", "0"}, {"0", "0", "0"}, {"0", "-1", "0"}, {"0", "1", "0"}}),
             rational("1"), rational("1"), rational("1/2"));
}

// a is the point (0, 0, 1 - 2t) (zero length) through b = [(-1,0,0),
// (1,0,0)] at t = 1/2, v = 1/2.
BOOST_AUTO_TEST_CASE(zero_length_edge)
{
  expect_hit(query(Ccd_type::edge_edge, {{"0", "0", "1"}, {"0", "0", "1"}, {"-1", "0", "0"}, {"1", "0", "0"},
                                         {"0", "0", "-1"}, {"0", "0", "-1"}, {"-1", "0", "0"}, {"1", "0", "0"}}),
             rational("1/2"), rational("0"), rational("1/2"));
}

// Both edges are points: t (1,1,1) and (1 - t)(1,1,1) meet at t = 1/2.
BOOST_AUTO_TEST_CASE(two_points)
{
  expect_hit(query(Ccd_type::edge_edge, {{"0", "0", "0"}, {"0", "0", "0"}, {"1", "1", "1"}, {"1", "1", "1"},
                                         {"1", "1", "1"}, {"1", "1", "1"}, {"0", "0", "0"}, {"0", "0", "0"}}),
             rational("1/2"), rational("0"), rational("0"));
}

// In z = 0 throughout: a = [(0,0,0), (1,0,0)] at rest, b = [(2-2t, -1, 0),
// (2-2t, 1, 0)] sweeps to x = 0; it reaches a1 at t = 1/2 (u = 1, v = 1/2).
BOOST_AUTO_TEST_CASE(coplanar_sweep)
{
  expect_hit(query(Ccd_type::edge_edge, {{"0", "0", "0"}, {"1", "0", "0"}, {"2", "-1", "0"}, {"2", "1", "0"},
                                         {"0", "0", "0"}, {"1", "0", "0"}, {"0", "-1", "0"}, {"0", "1", "0"}}),
             rational("1/2"), rational("1"), rational("1/2"));
}

// An irrational t*. a = [(0,0,0), (1,t,0)], b = [(1/2,-1,-1/4-t),
// (1/2,1,-1/4+t)]: A = (1,t,0), B = (0,2,2t), D = (1/2,-1,-1/4-t), and
// F = A . (B x D) = (z0 + z1) + t (z1 - z0)/2 = -1/2 + t^2: negative before
// t* = 1/sqrt 2, the root of 2t^2 - 1. There u = 1/2 (x), and y: t/2 =
// -1 + 2v gives v = 1/2 + t/4, in [0, 1]; z: -1/4 - t + 2t v = -1/4 + t^2/2
// = 0. v = 1/2 + sqrt(2)/8 is the root of 32v^2 - 32v + 7 near 0.677.
BOOST_AUTO_TEST_CASE(irrational_first_time)
{
  Ccd_query q = query(Ccd_type::edge_edge, {{"0", "0", "0"}, {"1", "0", "0"}, {"1/2", "-1", "-1/4"}, {"1/2", "1", "-1/4"},
                                            {"0", "0", "0"}, {"1", "1", "0"}, {"1/2", "-1", "-5/4"}, {"1/2", "1", "3/4"}});
  auto t = Algebraic::real_roots({Rational(-1), Rational(0), Rational(2)}, Rational(0), Rational(1));
  auto v = Algebraic::real_roots({Rational(7), Rational(-32), Rational(32)}, Rational(1, 2), Rational(1));
  BOOST_REQUIRE(t.size() == 1 && v.size() == 1);
  expect_hit(q, t[0], rational("1/2"), v[0]);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(campaigns)

// Every fuzz family, seeded: the filtered kernel's answers are the rational
// kernel's (t* and (u, v) included) and every contact checks in Q(t*). The
// floors hold the filter to its job: most cases decided by intervals alone,
// and some signs handed to rationals (the ties the families are made of).
BOOST_AUTO_TEST_CASE(filtered_equals_rational_on_the_families)
{
  std::uint64_t seed = env_number("CLASH4D_SEED", 20261202), cases = env_number("CLASH4D_CCD_CASES", 1200);
  BOOST_TEST_MESSAGE("ccd campaign: seed " << seed << ", " << cases << " cases (CLASH4D_SEED, CLASH4D_CCD_CASES)");
  std::size_t intervals_alone = 0, handed = 0, collide = 0;
  for (std::uint64_t i = 0; i < cases; ++i) {
    Ccd_case c = make_ccd_case(seed, i);
    BOOST_TEST_CONTEXT("case " << i << " (" << c.family << "), seed " << seed)
    {
      collide += agreed(c.query).collide;
      Ccd_filtered_kernel::Protector protect;
      Ccd_filtered_kernel k(c.query);
      ccd_sweep(k);
      (k.exact_questions() == 0 ? intervals_alone : handed) += 1;
    }
  }
  BOOST_TEST_MESSAGE("  " << collide << " collide; intervals alone " << intervals_alone << ", rationals asked " << handed);
  BOOST_TEST(intervals_alone >= cases / 5);
  BOOST_TEST(handed >= cases / 5);
  BOOST_TEST(collide >= cases / 2);
  BOOST_TEST(collide < cases);
}

// The simulation-like mix of the benchmark: mostly clear misses, decided by
// the swept boxes in intervals.
BOOST_AUTO_TEST_CASE(filtered_equals_rational_on_the_simulation_mix)
{
  std::uint64_t seed = env_number("CLASH4D_SEED", 20261202);
  BOOST_TEST_MESSAGE("simulation mix: seed " << seed);
  Random_draw draw(seed);
  std::size_t near_count = 0;
  for (int i = 0; i < 400; ++i) {
    bool near = false, degenerate = false;
    Ccd_query q = make_simulation_query(i % 2 ? Ccd_type::edge_edge : Ccd_type::vertex_face, draw, near, degenerate);
    near_count += near;
    BOOST_TEST_CONTEXT("query " << i << ", seed " << seed) { agreed(q); }
  }
  BOOST_TEST(near_count > 0u);
}

// Against the brute-force oracle (tests/support/Ccd_oracle.h: written from
// docs/ccd-queries.md alone, its own Sturm sequences and distance test):
// the verdict, t* compared exactly, and (u, v) checked in Q(t*) by the
// oracle's own arithmetic; with a separation, the verdict and t*.
namespace oracle = clash4d::ccd_oracle;

namespace {

oracle::Query oracle_query(const Ccd_query& q)
{
  oracle::Query out;
  for (std::size_t i = 0; i < 8; ++i)
    for (std::size_t k = 0; k < 3; ++k) out[i][k] = mpq_class(q.rows()[i][k].mpq());
  return out;
}

oracle::Real oracle_real(const Algebraic& x)
{
  oracle::Real r;
  r.is_rational = x.is_rational();
  if (r.is_rational) {
    r.value = mpq_class(x.rational().mpq());
    return r;
  }
  for (const mpz_class& c : x.polynomial()) r.poly.push_back(mpq_class(c));
  r.lo = mpq_class(x.lower().mpq());
  r.hi = mpq_class(x.upper().mpq());
  return r;
}

std::vector<mpq_class> oracle_poly(const std::vector<Rational>& p)
{
  std::vector<mpq_class> out;
  for (const Rational& c : p) out.push_back(mpq_class(c.mpq()));
  return out;
}

// A query of small integer coordinates over 2: many degenerate
// configurations (collinear, coplanar, parallel) by chance.
Ccd_query small_grid_query(Random_draw& d)
{
  Ccd_query::Rows r;
  for (auto& row : r)
    for (auto& x : row) x = Rational(static_cast<int>(d.range(-2, 2)), 2);
  return Ccd_query(d.percent(50) ? Ccd_type::vertex_face : Ccd_type::edge_edge, r);
}

void check_against_oracle(const Ccd_query& q, const Rational& separation)
{
  Ccd_options o;
  o.earliest = true;
  o.separation = separation;
  Ccd_answer a = ccd_exact(q, o), r = ccd_rational(q, o);
  oracle::Type type = q.type() == Ccd_type::vertex_face ? oracle::Type::vertex_face : oracle::Type::edge_edge;
  oracle::Answer truth = oracle::solve(type, oracle_query(q), mpq_class(separation.mpq()));
  BOOST_REQUIRE_EQUAL(a.collide, truth.collide);
  BOOST_REQUIRE_EQUAL(r.collide, truth.collide);
  if (!a.collide) return;
  const Algebraic& t = exact(a.earliest->t);
  BOOST_TEST(oracle::compare(truth.t_star, oracle_real(t)) == 0,
             "t* " << t.to_text() << " against the oracle's " << oracle::describe(truth.t_star));
  BOOST_TEST((t == exact(r.earliest->t)));
  if (CGAL::is_positive(separation)) return;
  const Ccd_uv_fraction<Rational>& f = *a.earliest->uv;
  auto u = Algebraic::field_element(t, f.u_num.coefficients(), f.u_den.coefficients());
  auto v = Algebraic::field_element(t, f.v_num.coefficients(), f.v_den.coefficients());
  BOOST_TEST(oracle::is_contact(type, oracle_query(q), oracle_real(t), oracle_poly(u), oracle_poly(v)));
}

} // namespace

BOOST_AUTO_TEST_CASE(the_oracle_agrees)
{
  std::uint64_t seed = env_number("CLASH4D_SEED", 20261202), cases = env_number("CLASH4D_CCD_ORACLE_CASES", 240);
  BOOST_TEST_MESSAGE("oracle campaign: seed " << seed << ", " << cases
                                              << " cases of each kind (CLASH4D_SEED, CLASH4D_CCD_ORACLE_CASES)");
  Random_draw draw(seed);
  for (std::uint64_t i = 0; i < cases; ++i) {
    Ccd_case c = make_ccd_case(seed + 1, i);
    BOOST_TEST_CONTEXT("family case " << i << " (" << c.family << "), seed " << seed) { check_against_oracle(c.query, 0); }
    Ccd_query g = small_grid_query(draw);
    BOOST_TEST_CONTEXT("grid query " << i << ", seed " << seed) { check_against_oracle(g, 0); }
    Rational separation(static_cast<int>(draw.range(1, 4)), 4);
    if (i % 3 == 0)
      BOOST_TEST_CONTEXT("grid query " << i << " with separation " << separation << ", seed " << seed)
      {
        check_against_oracle(g, separation);
      }
  }
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(reading)

namespace {

// The through_the_interior query as CSV rows (label 1) and a miss (label 0).
const char* const hit_rows =
    "1,4,1,4,1,1,1\n0,1,0,1,0,1,1\n1,1,0,1,0,1,1\n0,1,1,1,0,1,1\n"
    "1,4,1,4,-1,1,1\n0,1,0,1,0,1,1\n1,1,0,1,0,1,1\n0,1,1,1,0,1,1\n";
const char* const miss_rows =
    "2,1,2,1,1,1,0\n0,1,0,1,0,1,0\n1,1,0,1,0,1,0\n0,1,1,1,0,1,0\n"
    "2,1,2,1,-1,1,0\n0,1,0,1,0,1,0\n1,1,0,1,0,1,0\n0,1,1,1,0,1,0\n";

std::vector<Ccd_query> read_text(const std::string& text, Ccd_reader::Format f, std::optional<Ccd_type> type)
{
  std::istringstream in(text);
  Ccd_reader reader(in, f, type);
  std::vector<Ccd_query> out;
  while (reader.read(3, out) > 0) {}
  return out;
}

// The error a text gives: "place: message" (exit code in *code).
std::string error_of(const std::string& text, Ccd_reader::Format f, std::optional<Ccd_type> type, int* code = nullptr)
{
  try {
    read_text(text, f, type);
  } catch (const Input_error& e) {
    if (code) *code = e.exit_code();
    return e.place() + ": " + e.what();
  }
  return "no error";
}

std::string temp_file(const std::string& name, const std::string& text)
{
  auto dir = std::filesystem::temp_directory_path() / ("clash4d-ccd-test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir / "vertex-face");
  auto path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

} // namespace

BOOST_AUTO_TEST_CASE(csv_queries_exactly)
{
  std::string crlf;   // the second query's rows end in "\r\n"
  for (char c : std::string(miss_rows)) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  auto qs = read_text(std::string(hit_rows) + crlf, Ccd_reader::Format::csv, Ccd_type::vertex_face);
  BOOST_REQUIRE_EQUAL(qs.size(), 2u);
  BOOST_TEST(qs[0].row(0)[0] == Rational(1, 4));
  BOOST_TEST(qs[0].row(4)[2] == Rational(-1));
  BOOST_TEST(*qs[0].label);
  BOOST_TEST(!*qs[1].label);
  BOOST_TEST(qs[1].line == 9u);
}

BOOST_AUTO_TEST_CASE(csv_errors_name_line_and_column)
{
  auto csv = Ccd_reader::Format::csv;
  std::string rows = hit_rows;
  BOOST_TEST(error_of(rows.substr(0, rows.size() - 14), csv, Ccd_type::vertex_face).find("line 8") == 0);
  BOOST_TEST(error_of("1,4,1,4,1,1\n", csv, Ccd_type::vertex_face) ==
             "line 1: expected 7 comma-separated integers (x, y and z as numerator, denominator; a 0/1 label), found 6 "
             "fields");
  BOOST_TEST(error_of("1,4,x,4,1,1,1\n", csv, Ccd_type::vertex_face) ==
             "line 1, column 5: the y numerator is not an integer: 'x'");
  BOOST_TEST(error_of("1,4,1,0,1,1,1\n", csv, Ccd_type::vertex_face) == "line 1, column 7: the y denominator is zero");
  BOOST_TEST(error_of("1,4,1,4,1,1,2\n", csv, Ccd_type::vertex_face) ==
             "line 1, column 13: the label is not 0 or 1: '2'");
  std::string mixed = rows;
  mixed[mixed.size() - 2] = '0';   // the last row's label
  BOOST_TEST(error_of(mixed, csv, Ccd_type::vertex_face).find("line 8: the label differs") == 0);
  BOOST_TEST(error_of(std::string(hit_rows).insert(14, "\n"), csv, Ccd_type::vertex_face).find("line 2: a blank line") == 0);
  int code = 0;
  BOOST_TEST(error_of("1" + std::string(1200, '0') + ",1,1,1,1,1,1\n", csv, Ccd_type::vertex_face, &code)
                 .find("more than 1000 digits") != std::string::npos);
  BOOST_TEST(code == CLASH4D_EXIT_LIMIT);
  // A line over the limit is refused as such (exit 3), a bad row before it first.
  std::string long_line = std::string(hit_rows) + std::string(CLASH4D_MAX_CCD_LINE + 1, '1') + "\n";
  BOOST_TEST(error_of(long_line, csv, Ccd_type::vertex_face, &code).find("line 9: longer than the limit") == 0);
  BOOST_TEST(code == CLASH4D_EXIT_LIMIT);
  BOOST_TEST(error_of("1,4,1,4,1,1,x\n" + std::string(CLASH4D_MAX_CCD_LINE + 1, '1') + "\n", csv, Ccd_type::vertex_face)
                 .find("line 1, column 13") == 0);
  std::istringstream in(hit_rows);
  BOOST_CHECK_THROW(Ccd_reader(in, csv, std::nullopt), Input_error);   // CSV needs a type
}

BOOST_AUTO_TEST_CASE(json_lines)
{
  auto json = Ccd_reader::Format::json_lines;
  auto qs = read_text("{\"type\": \"edge-edge\", \"t0\": [[0,0,0],[1,0,0],[\"1/2\",-1,1],[0.5,1,1]], "
                      "\"t1\": [[0,0,0],[1,0,0],[\"1/2\",-1,-1],[0.5,1,-1]], \"label\": 1}\n\n",
                      json, std::nullopt);
  BOOST_REQUIRE_EQUAL(qs.size(), 1u);
  BOOST_TEST((qs[0].type() == Ccd_type::edge_edge));
  BOOST_TEST(qs[0].row(3)[0] == Rational(1, 2));
  BOOST_TEST(*qs[0].label);
  Ccd_options o;
  o.earliest = true;
  BOOST_TEST((exact(ccd_exact(qs[0], o).earliest->t) == rational("1/2")));
  BOOST_TEST(error_of("{\"t0\": [], \"t1\": []}\n", json, Ccd_type::vertex_face) ==
             "line 1: t0: expected the 4 vertices, found 0");
  BOOST_TEST(error_of("{\"type\": \"vf\", \"t0\": [[0,0,0],[1,0,0],[0,1],[0,0,1]], \"t1\": []}\n", json, std::nullopt) ==
             "line 1: t0[2]: expected 3 numbers, found 2");
  BOOST_TEST(error_of("\n{\"type\": \"edge-edge\", \"t0\": [], \"t1\": []}\n", json, Ccd_type::vertex_face) ==
             "line 2: type: \"edge-edge\" differs from --type vertex-face");
  BOOST_TEST(error_of("{\"tO\": 1}\n", json, Ccd_type::vertex_face).find("line 1: unknown key \"tO\"") == 0);
  BOOST_TEST(error_of("{\"t0\": [1,\n", json, Ccd_type::vertex_face).find("line 1, column") == 0);
  BOOST_TEST(error_of("{\"t0\": []}\n", json, std::nullopt).find("the query type is not known") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_command_line)
{
  std::string file = temp_file("vertex-face/two.csv", std::string(hit_rows) + miss_rows);
  Cli_run r = run_clash4d({"ccd", file});
  BOOST_TEST(r.status == 1, r.err);   // a query collides
  BOOST_TEST(r.out.find("two.csv: 2 queries, 1 collide (exact, closed)") != std::string::npos, r.out);
  r = run_clash4d({"ccd", file, "--json", "--earliest", "--labels"});
  BOOST_TEST(r.status == 0);   // both answers agree with their labels
  BOOST_TEST(r.out == "{\"index\":0,\"collide\":true,\"t\":\"1/2\",\"uv\":[\"1/4\",\"1/4\"],\"label\":true,\"agree\":true}\n"
                      "{\"index\":1,\"collide\":false,\"t\":null,\"label\":false,\"agree\":true}\n");
  BOOST_TEST(r.err.find("labels: 2 agree, 0 disagree") != std::string::npos, r.err);
  r = run_clash4d({"ccd", file, "--number", "double", "--json", "--earliest"});
  BOOST_TEST(r.out.find("\"t\":\"0.5\",\"uv\":[\"0.25\",\"0.25\"]") != std::string::npos, r.out);
  // A wrong label: exit 1, the query named.
  std::string wrong = std::string(hit_rows);
  for (std::size_t at = wrong.find(",1\n"); at != std::string::npos; at = wrong.find(",1\n", at)) wrong[at + 1] = '0';
  std::string wrong_file = temp_file("vertex-face/wrong.csv", wrong);
  r = run_clash4d({"ccd", wrong_file, "--labels"});
  BOOST_TEST(r.status == 1);
  BOOST_TEST(r.out.find("query 0 (line 1): collides, labelled 0") != std::string::npos, r.out);
  // Bad input: exit 2, the file and place named, no answer printed.
  std::string bad = temp_file("vertex-face/bad.csv", std::string(hit_rows) + "1,2,3\n");
  r = run_clash4d({"ccd", file, bad, "--json"});
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.out.empty());
  BOOST_TEST(r.err.find("bad.csv: line 9: expected 7 comma-separated integers") != std::string::npos, r.err);
  std::string untyped = temp_file("q.csv", hit_rows);
  r = run_clash4d({"ccd", untyped});
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.err.find("the query type is not known") != std::string::npos, r.err);
  BOOST_TEST(run_clash4d({"ccd", untyped, "--type", "vf"}).status == 1);
  r = run_clash4d({"ccd", std::filesystem::path(file).parent_path().string()});
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.err.find("is a folder") != std::string::npos, r.err);
  // With a separation of 2, the miss's vertex (distance 3 sqrt(2) / 2 > 2)
  // still misses; with 3 it is within reach from the start.
  BOOST_TEST(run_clash4d({"ccd", file, "--separation", "2", "--json"}).out.find("\"index\":1,\"collide\":false") !=
             std::string::npos);
  BOOST_TEST(run_clash4d({"ccd", file, "--separation", "3", "--json"}).out.find("\"index\":1,\"collide\":true") !=
             std::string::npos);
  BOOST_TEST(run_clash4d({"ccd", file, "--separation", "x"}).status == 2);
  BOOST_TEST(run_clash4d({"ccd", file, "--tolerance", "1e-9"}).status == 2);   // double only
}

BOOST_AUTO_TEST_SUITE_END()

// The fixtures (fixtures/ccd/TYPE/hand-derived.csv and .jsonl, the same
// queries): each answer of `clash4d ccd --earliest --json --labels` in both
// exact kernels is the one expected.json derives by hand, numbers as the
// spec prints them (an irrational t* as its minimal polynomial, the
// coarsest decimal interval and the nearest double).
BOOST_AUTO_TEST_CASE(fixtures_answer_as_derived)
{
  namespace fs = std::filesystem;
  for (const char* type : {"vertex-face", "edge-edge"}) {
    fs::path dir = fs::path(CLASH4D_FIXTURES) / "ccd" / type;
    auto expected = nlohmann::json::parse(std::ifstream(dir / "expected.json"));
    for (const char* file : {"hand-derived.csv", "hand-derived.jsonl"})
      for (const char* number : {"exact", "rational"}) {
        Cli_run r = run_clash4d({"ccd", (dir / file).string(), "--earliest", "--json", "--labels", "--number", number});
        BOOST_TEST_CONTEXT(type << "/" << file << " --number " << number)
        {
          BOOST_TEST(r.status == 0, r.err);   // every label (the expected verdict) agrees
          std::istringstream lines(r.out);
          std::string line;
          std::size_t i = 0;
          for (; std::getline(lines, line); ++i) {
            const auto& want = expected["queries"].at(i);
            auto got = nlohmann::json::parse(line);
            BOOST_TEST_CONTEXT("query " << i << " (" << want["name"].get<std::string>() << ")")
            {
              BOOST_TEST(got["collide"] == want["collide"]);
              if (want["collide"].get<bool>()) {
                BOOST_TEST(got["t"] == want["t"], got["t"].dump() << " != " << want["t"].dump());
                BOOST_TEST(got["uv"] == want["uv"], got["uv"].dump() << " != " << want["uv"].dump());
              }
            }
          }
          BOOST_TEST(i == expected["queries"].size());
        }
      }
  }
}

namespace {
// A polynomial of this degree with small random rational coefficients
// (numerators in [-9, 9], denominators in [1, 4]).
std::vector<Rational> small_rational_poly(Random_draw& draw, int degree)
{
  std::vector<Rational> p;
  for (int i = 0; i <= degree; ++i) p.emplace_back(static_cast<int>(draw.range(-9, 9)), static_cast<int>(draw.range(1, 4)));
  return p;
}
} // namespace

// Algebraic::quotient_at (the printed u and v, and a turning pair's
// contact point at a quadratic t*): on seeded cubic and quadratic roots r
// and quotients alpha = N(r) / D(r), its minimal polynomial mu has
// mu(alpha) = 0 in Q(r) (mu evaluated at alpha's polynomial in r, reduced
// modulo r's minimal polynomial, is 0), of r's degree when alpha is
// irrational (2 and 3 are prime), and it is alpha and not a conjugate:
// its double is alpha's, evaluated in long double at r's, and mu changes
// sign across its interval. And a quotient that is a rational c by
// construction, (c D + m L) / D, is c.
BOOST_AUTO_TEST_CASE(quotients_at_a_root_are_those_numbers)
{
  std::uint64_t seed = env_number("CLASH4D_SEED", 20261202);
  BOOST_TEST_MESSAGE("quotients at roots: seed " << seed);
  Random_draw draw(seed);
  auto small_poly = [&](int degree) { return small_rational_poly(draw, degree); };
  auto remainder = [](std::vector<Rational> a, const std::vector<Rational>& m) {   // a mod m, m's leading term non-zero
    while (a.size() >= m.size()) {
      Rational f = a.back() / m.back();
      for (std::size_t i = 0; i < m.size(); ++i) a[a.size() - m.size() + i] -= f * m[i];
      a.pop_back();
    }
    return a;
  };
  int irrational = 0, quadratic = 0, disguised_rationals = 0;
  for (int i = 0; i < 300; ++i) {
    auto roots = Algebraic::real_roots(small_poly(i % 3 == 2 ? 2 : 3), Rational(-8), Rational(8));
    for (const Algebraic& r : roots) {
      if (r.is_rational()) continue;
      std::vector<Rational> num = small_poly(2), den = small_poly(2);
      if (r.sign_of(den) == CGAL::ZERO) continue;
      Algebraic q = Algebraic::quotient_at(r, num, den);
      std::vector<Rational> alpha = Algebraic::field_element(r, num, den), m;
      for (const mpz_class& c : r.polynomial()) m.emplace_back(c.get_mpz_t());
      // mu(alpha) by Horner in Q[t] / (m).
      std::vector<Rational> value{Rational(0)};
      std::vector<mpz_class> mu = q.is_rational() ? std::vector<mpz_class>{} : q.polynomial();
      if (q.is_rational()) mu = {mpz_class(-mpz_class(q.rational().numerator().mpz())), mpz_class(q.rational().denominator().mpz())};
      for (std::size_t k = mu.size(); k-- > 0;) {
        std::vector<Rational> product(value.size() + alpha.size() - 1, Rational(0));
        for (std::size_t a = 0; a < value.size(); ++a)
          for (std::size_t b = 0; b < alpha.size(); ++b) product[a + b] += value[a] * alpha[b];
        product[0] += Rational(mu[k].get_mpz_t());
        value = remainder(product, m);
      }
      bool zero = true;
      for (const Rational& c : value) zero = zero && CGAL::is_zero(c);
      BOOST_TEST_CONTEXT("root " << r.to_text() << ", quotient " << q.to_text())
      {
        BOOST_TEST(zero);
        long double t = r.to_double(), n = 0, d = 0;
        for (std::size_t k = num.size(); k-- > 0;) n = n * t + CGAL::to_double(num[k]);
        for (std::size_t k = den.size(); k-- > 0;) d = d * t + CGAL::to_double(den[k]);
        BOOST_TEST(std::abs(q.to_double() - static_cast<double>(n / d)) <= 1e-9 * (1 + std::abs(static_cast<double>(n / d))));
        BOOST_TEST(q.is_rational() == (alpha.size() == 1));
        if (!q.is_rational()) {
          BOOST_TEST(mu.size() == r.polynomial().size());
          auto mu_at = [&](const Rational& x) {
            Rational v = 0;
            for (std::size_t k = mu.size(); k-- > 0;) v = v * x + Rational(mu[k].get_mpz_t());
            return CGAL::sign(v);
          };
          BOOST_TEST(mu_at(q.lower()) * mu_at(q.upper()) < 0);
        }
      }
      irrational += !q.is_rational();
      quadratic += !q.is_rational() && r.polynomial().size() == 3;
      // A rational made to look otherwise: (c D + m L)(r) / D(r) = c, since
      // m(r) = 0 (for a quadratic r the field element is the constant c,
      // read off without a resultant: Algebraic_access::linear_image; for
      // a cubic, the resultant's linear factor).
      Rational c(static_cast<int>(draw.range(-9, 9)), static_cast<int>(draw.range(1, 4)));
      std::vector<Rational> l = small_poly(1), disguised(std::max(den.size(), m.size() + l.size() - 1), Rational(0));
      for (std::size_t k = 0; k < den.size(); ++k) disguised[k] += c * den[k];
      for (std::size_t a = 0; a < m.size(); ++a)
        for (std::size_t b = 0; b < l.size(); ++b) disguised[a + b] += m[a] * l[b];
      Algebraic same = Algebraic::quotient_at(r, disguised, den);
      BOOST_TEST((same.is_rational() && same.rational() == c), "root " << r.to_text() << ": " << same.to_text() << " != " << c);
      ++disguised_rationals;
    }
  }
  BOOST_TEST(irrational > 50);
  BOOST_TEST(quadratic > 20);
  BOOST_TEST(disguised_rationals > 50);
}

// Quadratic_element (numbers/Quadratic_element.h: Q(r) for a quadratic r,
// in integers) against FLINT's field arithmetic (Algebraic::field_element:
// an extended gcd modulo r's minimal polynomial m): on seeded quadratic
// roots r and polynomials g, h, the element g(r) / h(r) is the number
// a + b r of field_element's (a, b); g(r) h(r) and g(r) - h(r) are those
// of the polynomials g h and g - h; m(r) is 0, and a default element is
// 0 in any field.
BOOST_AUTO_TEST_CASE(quadratic_elements_are_flints_field_elements)
{
  std::uint64_t seed = env_number("CLASH4D_SEED", 20261206);
  BOOST_TEST_MESSAGE("quadratic elements: seed " << seed);
  Random_draw draw(seed);
  auto small_poly = [&](int degree) { return small_rational_poly(draw, degree); };
  auto number = [](const Algebraic& r, const std::vector<Rational>& e) {
    return e.size() == 1 ? Algebraic(e[0]) : Algebraic::linear_image(r, e[0], e[1]);
  };
  int irrational = 0, checked = 0;
  for (int i = 0; i < 200; ++i) {
    for (const Algebraic& r : Algebraic::real_roots(small_poly(2), Rational(-8), Rational(8))) {
      if (r.is_rational()) continue;
      Quadratic_element field(r);
      std::vector<Rational> g = small_poly(static_cast<int>(draw.range(0, 6))), h = small_poly(static_cast<int>(draw.range(0, 6)));
      std::vector<Rational> product(g.size() + h.size() - 1, Rational(0)), difference(std::max(g.size(), h.size()), Rational(0));
      for (std::size_t a = 0; a < g.size(); ++a)
        for (std::size_t b = 0; b < h.size(); ++b) product[a + b] += g[a] * h[b];
      for (std::size_t a = 0; a < g.size(); ++a) difference[a] += g[a];
      for (std::size_t b = 0; b < h.size(); ++b) difference[b] -= h[b];
      std::vector<Rational> m;
      for (const mpz_class& c : r.polynomial()) m.emplace_back(c.get_mpz_t());
      BOOST_TEST_CONTEXT("root " << r.to_text())
      {
        BOOST_TEST(field.at(m).is_zero());
        BOOST_TEST(field.at(r.polynomial()).is_zero());
        BOOST_TEST(((field.at(g) * field.at(h)).value() == number(r, Algebraic::field_element(r, product, {Rational(1)}))));
        BOOST_TEST(((field.at(g) - field.at(h)).value() == number(r, Algebraic::field_element(r, difference, {Rational(1)}))));
        BOOST_TEST(((Quadratic_element() + field.at(g)).value() == field.at(g).value()));
        if (r.sign_of(h) != CGAL::ZERO) {
          std::vector<Rational> e = Algebraic::field_element(r, g, h);
          Algebraic q = (field.at(g) / field.at(h)).value();
          BOOST_TEST((q == number(r, e)), q.to_text() << " != " << number(r, e).to_text());
          irrational += !q.is_rational();
          ++checked;
        }
      }
    }
  }
  BOOST_TEST(checked > 100);
  BOOST_TEST(irrational > 80);
}
