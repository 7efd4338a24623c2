// The checker of certificates of turning scenes (verify/, format
// clash4d-certificate/turning-1, docs/certificate-format.md, section 8), on
// certificates written by hand from the worked example of 8.6: the block
// [-1, 1]^3 turning about z with q(t) = (1, 0, 0, t) into the slab x >= 6/5.
// Its three literals and multipliers give sum lambda e = (1 + t^2)(11 t^2 -
// 10 t + 1), positive before t* = (5 - sqrt 14)/11 ~ 0.1144, zero at t* and
// at (5 + sqrt 14)/11 ~ 0.795, negative between.
#define BOOST_TEST_MODULE verify_turning
#include <boost/test/unit_test.hpp>

#include "support/Cli_run.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include "verify/Certificate_checker.h"
#include "verify/Real_time.h"
#include <fstream>
#include <algorithm>
#include <functional>
#include <random>
#include <sstream>

using namespace clash4d;
using namespace clash4d::verifier;

namespace {

Rational_poly poly(std::initializer_list<const char*> c)
{
  std::vector<mpq_class> v;
  for (const char* s : c) v.emplace_back(s);
  for (mpq_class& q : v) q.canonicalize();
  return Rational_poly(v);
}

// t* = (5 - sqrt 14)/11 and the other root (5 + sqrt 14)/11.
const Rational_poly quad = poly({"1", "-10", "11"});
Real_time t_star() { return Real_time(quad, mpq_class(1, 10), mpq_class(1, 8)); }
Real_time t_other() { return Real_time(quad, mpq_class(3, 4), mpq_class(4, 5)); }
Real_time at(const char* q) { mpq_class v(q); v.canonicalize(); return Real_time(v); }

std::string file_text(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

const std::string fixtures = CLASH4D_FIXTURES;
const std::string full_scene = file_text(fixtures + "/rotation/square_into_slab.json");
const std::string short_scene = file_text(fixtures + "/../tests/data/turning/square_into_slab_short.json");

// The scene with the slab 1e-9 closer: its min x is 6/5 - 10^-9.
std::string slab_closer(const std::string& scene)
{
  std::string s = scene;
  s.replace(s.find("\"6/5\""), 5, "\"1199999999/1000000000\"");
  return s;
}

// The one conflict of 8.6: the square's x - 1 and -y - 1, the slab's 6/5 - x.
const char* conflict_86 = R"({"literals": [
     [["1","0","-1"], ["0","2"], ["0"], ["-1","0","-1"]],
     [["0","2"], ["-1","0","1"], ["0"], ["-1","0","-1"]],
     [["-5"], ["0"], ["0"], ["6"]]],
   "lambda": [["5","0","-5"], ["0","10"], ["1","0","2","0","1"]]})";

Json cert(const char* semantics, bool collide, const std::string& time, const Json& pair)
{
  Json c = {{"format", "clash4d-certificate/turning-1"}, {"scene", "test"}, {"semantics", semantics}};
  c["time"] = Json::array({"0", time});
  c["claim"] = {{"collide", collide}, {"earliest", false}, {"all_pairs", false}};
  c["pairs"] = Json::array({pair});
  return c;
}

// "no collision" until `until`, one piece [0, until] with the conflict of 8.6.
Json apart(const Json& until)
{
  Json piece = {{"t", Json::array({"0", until})}, {"proof", {{"conflicts", Json::array({Json::parse(conflict_86)})}}}};
  Json a = {{"until", until}, {"pieces", Json::array({piece})}};
  return {{"objects", {"square", "slab"}}, {"collide", false}, {"apart", a}};
}

Json time_json(const char* lo, const char* hi, std::vector<const char*> p = {"1", "-10", "11"})
{
  return {{"poly", p}, {"between", {lo, hi}}, {"approx", "0.114394783"}};
}

Verify_result verify(const std::string& scene_text, const Json& c)
{
  return verify_certificate(read_scene(read_json_text(scene_text)), c);
}

void expect_ok(const Verify_result& r, const std::string& claim)
{
  BOOST_TEST(r.ok, r.where + ": " + r.reason);
  BOOST_TEST(r.claim == claim);
}

void expect_rejected(const Verify_result& r, const std::string& where, const std::string& reason, int exit_code = 1)
{
  BOOST_TEST(!r.ok);
  BOOST_TEST(!r.past_step_limit);   // every rejection here refutes a step
  BOOST_TEST(r.exit_code == exit_code, r.exit_code << " " << r.where << ": " << r.reason);
  BOOST_TEST(r.where == where, r.where << ": " << r.reason);
  BOOST_TEST(r.reason.find(reason) != std::string::npos, r.reason);
}

const std::string piece0 = "pairs[0].apart.pieces[0]";
const std::string conflict0 = piece0 + ".proof.conflicts[0]";

} // namespace

// ---------------------------------------------------------------- Rational_poly

BOOST_AUTO_TEST_CASE(sturm_counts_distinct_roots)
{
  Rational_poly two = poly({"-2", "0", "1"});   // t^2 - 2
  BOOST_TEST(count_roots(two, mpq_class(0), mpq_class(2)) == 1);
  BOOST_TEST(count_roots(two, mpq_class(-2), mpq_class(2)) == 2);
  BOOST_TEST(count_roots(two * two, mpq_class(-2), mpq_class(2)) == 2);   // a double root counts once
  BOOST_TEST(count_roots(two, mpq_class(3, 2), mpq_class(2)) == 0);
  // Roots at the ends are divided out: t (t - 1)(t - 2) in (0, 2) has only 1.
  Rational_poly cubic = poly({"0", "1"}) * poly({"-1", "1"}) * poly({"-2", "1"});
  BOOST_TEST(count_roots(cubic, mpq_class(0), mpq_class(2)) == 1);
  BOOST_TEST(count_roots(cubic * cubic, mpq_class(0), mpq_class(2)) == 1);
  BOOST_TEST(count_roots(quad, mpq_class(0), mpq_class(1, 10)) == 0);
  BOOST_TEST(count_roots(quad, mpq_class(1, 10), mpq_class(1, 8)) == 1);
  BOOST_TEST(count_roots(quad, mpq_class(0), mpq_class(1)) == 2);
  BOOST_TEST(count_roots(poly({"1", "0", "1"}), mpq_class(-100), mpq_class(100)) == 0);
}

BOOST_AUTO_TEST_CASE(polynomial_arithmetic)
{
  Rational_poly a = poly({"-2", "0", "1"}), b = poly({"5", "1"});
  Rational_poly q, r;
  divmod(a * b + poly({"3"}), b, q, r);
  BOOST_TEST((q == a));
  BOOST_TEST((r == poly({"3"})));
  BOOST_TEST((exact_div(a * b, a) == b));
  BOOST_TEST((gcd(a * b, a * poly({"1", "1"})) == a));   // monic
  BOOST_TEST((a.derivative() == poly({"0", "2"})));
  BOOST_TEST(a(mpq_class(3)) == 7);
  // Yun: (t^2 - 2) (t + 5)^2 (t - 1)^3: factors of multiplicity 1, 2, 3.
  Rational_poly l = poly({"-1", "1"});
  std::vector<Rational_poly> f = square_free_factors(mpq_class(3) * a * b * b * l * l * l);
  BOOST_TEST(f.size() == 3u);
  BOOST_TEST((f[0] == a && f[1] == b && f[2] == l));
  BOOST_TEST((odd_part(mpq_class(3) * a * b * b * l * l * l) == mpq_class(3) * a * l));
}

BOOST_AUTO_TEST_CASE(odd_part_positivity_with_a_double_root)
{
  Rational_poly p = quad * quad;   // (11 t^2 - 10 t + 1)^2: double roots in [0, 1]
  BOOST_TEST(nonnegative_on(p, at("0"), at("1")));
  BOOST_TEST(!nonnegative_on(p * poly({"-1/2", "1"}), at("0"), at("1")));   // changes sign at 1/2
  BOOST_TEST(!nonnegative_on(-p, at("0"), at("1")));                          // only <= 0
  BOOST_TEST(nonnegative_on(Rational_poly(), at("0"), at("1")));              // zero: >= 0
  BOOST_TEST(!positive_on(p, at("0"), at("1")));                               // its roots
  BOOST_TEST(positive_on(p, at("0"), at("1/10")));
}

// ---------------------------------------------------------------- Real_time

BOOST_AUTO_TEST_CASE(signs_at_algebraic_numbers)
{
  Real_time sqrt2(poly({"-2", "0", "1"}), mpq_class(1), mpq_class(2));
  BOOST_TEST(sign_at(poly({"-141421356237/100000000000", "1"}), sqrt2) > 0);   // sqrt 2 > 1.41421356237
  BOOST_TEST(sign_at(poly({"-1414213562374/1000000000000", "1"}), sqrt2) < 0); // < 1.414213562374
  BOOST_TEST(sign_at(poly({"-2", "0", "1"}), sqrt2) == 0);
  BOOST_TEST(sign_at(poly({"-2", "0", "1"}) * poly({"7", "1"}), sqrt2) == 0);
  BOOST_TEST(sign_at(poly({"-3", "0", "1"}), sqrt2) < 0);
  BOOST_TEST(sign_at(Rational_poly(), sqrt2) == 0);
  // The same number by another polynomial and interval.
  Real_time again(poly({"-2", "0", "1"}) * poly({"5", "1"}), mpq_class(0), mpq_class(3));
  BOOST_TEST(equal(sqrt2, again));
  BOOST_TEST(!less(sqrt2, again));
  BOOST_TEST(!less(again, sqrt2));
  Real_time sqrt3(poly({"-3", "0", "1"}), mpq_class(1), mpq_class(2));
  BOOST_TEST(!equal(sqrt2, sqrt3));
  BOOST_TEST(less(sqrt2, sqrt3));
  BOOST_TEST(!less(sqrt3, sqrt2));
  BOOST_TEST(less(at("141421356237/100000000000"), sqrt2));
  BOOST_TEST(less(sqrt2, at("3/2")));
  // A rational given as a root is that rational.
  Real_time half(poly({"-3", "2"}), mpq_class(1), mpq_class(2));
  BOOST_TEST(equal(half, at("3/2")));
  BOOST_TEST(equal(at("3/2"), half));
  BOOST_TEST(!equal(half, at("7/5")));
  BOOST_TEST(less(at("7/5"), half));
  // A root of even multiplicity: P = (t^2 - 2)^2 has no sign change.
  Real_time twice(poly({"-2", "0", "1"}) * poly({"-2", "0", "1"}), mpq_class(1), mpq_class(2));
  BOOST_TEST(equal(twice, sqrt2));
  BOOST_TEST(sign_at(poly({"-141421356237/100000000000", "1"}), twice) > 0);
  BOOST_TEST((valid_root(poly({"-2", "0", "1"}), mpq_class(1), mpq_class(2)) == Root_check::ok));
  BOOST_TEST((valid_root(poly({"-2", "0", "1"}), mpq_class(-2), mpq_class(2)) == Root_check::not_one_root));
  BOOST_TEST((valid_root(poly({"-1", "0", "1"}), mpq_class(1), mpq_class(2)) == Root_check::root_at_lo));
}

BOOST_AUTO_TEST_CASE(positivity_up_to_an_algebraic_time)
{
  Rational_poly sum = poly({"1", "0", "1"}) * quad;   // sum lambda e of 8.6
  BOOST_TEST(nonnegative_on(sum, at("0"), t_star()));
  BOOST_TEST(positive_on_half_open(sum, at("0"), t_star()));
  BOOST_TEST(!positive_on(sum, at("0"), t_star()));   // zero at t*
  BOOST_TEST(!nonnegative_on(sum, at("0"), at("1/8")));
  BOOST_TEST(!nonnegative_on(sum, at("0"), t_other()));
  BOOST_TEST(nonnegative_on(sum, t_other(), at("1")));
  BOOST_TEST(!nonnegative_on(sum, t_star(), t_other()));
  BOOST_TEST(nonnegative_on(-sum, t_star(), t_other()));
  BOOST_TEST(count_roots(quad, at("0"), t_star()) == 0);
  BOOST_TEST(count_roots(quad, at("0"), t_other()) == 1);
  BOOST_TEST(count_roots(quad, t_star(), t_other()) == 0);
  BOOST_TEST(count_roots(quad, t_star(), at("1")) == 1);
  BOOST_TEST(count_roots(quad * poly({"-1/2", "1"}), t_star(), t_other()) == 1);
  BOOST_TEST(less(t_star(), t_other()));
  BOOST_TEST(equal(t_star(), Real_time(quad * poly({"5", "1"}), mpq_class(0), mpq_class(1, 8))));
  BOOST_TEST(rational_between(t_star(), t_other()) > mpq_class(1, 8));
}

// ---------------------------------------------------------------- certificates

// 8.6: on the scene cut to [0, 1/10] the one conflict is the whole proof.
BOOST_AUTO_TEST_CASE(turning_square_no_collision)
{
  expect_ok(verify(short_scene, cert("regularised", false, "1/10", apart("1/10"))),
            "verified: no collision in [0, 1/10] (regularised): 1 pair apart");
  expect_ok(verify(short_scene, cert("closed", false, "1/10", apart("1/10"))),
            "verified: no collision in [0, 1/10] (closed): 1 pair apart");
  // Through the text reader too (numbers are strings).
  Json c = cert("regularised", false, "1/10", apart("1/10"));
  expect_ok(verify(short_scene, parse_certificate(c.dump())), "verified: no collision in [0, 1/10] (regularised): 1 pair apart");
  // Two pieces, [0, 1/20] and [1/20, 1/10], the second piece's end written
  // as an algebraic TIME that is 1/10: 10 t - 1 in (0, 1).
  Json two = cert("regularised", false, "1/10", apart("1/10"));
  Json& pieces = two["pairs"][0]["apart"]["pieces"];
  pieces.push_back(pieces[0]);
  pieces[0]["t"][1] = "1/20";
  pieces[1]["t"] = {"1/20", {{"poly", {"-1", "10"}}, {"between", {"0", "1"}}}};
  expect_ok(verify(short_scene, two), "verified: no collision in [0, 1/10] (regularised): 1 pair apart");
  // A piece dropped: the pieces end at 1/20, not at until.
  Json dropped = two;
  dropped["pairs"][0]["apart"]["pieces"].erase(1);
  expect_rejected(verify(short_scene, dropped), "pairs[0].apart.until", "the pieces end at 1/20");
  // A piece's end moved: a gap between 1/20 and 1/30.
  Json moved = two;
  moved["pairs"][0]["apart"]["pieces"][1]["t"][0] = "1/30";
  expect_rejected(verify(short_scene, moved), "pairs[0].apart.pieces[1].t[0]", "not at 1/20");
}

// The piece [0, t*] with t* algebraic is proved; the claim rules then ask
// for apart until tH = 1 (rule 5: without an earliest claim).
BOOST_AUTO_TEST_CASE(apart_until_the_algebraic_contact_time)
{
  Json c = cert("regularised", false, "1", apart(time_json("1/10", "1/8")));
  expect_rejected(verify(full_scene, c), "pairs[0].apart.until", "not until tH = 1");
  // Closed: sum lambda e > 0 only on [0, t*): with open_end the piece holds,
  // then rule 5 (apart until tH); without it, the piece fails at t*.
  Json closed = cert("closed", false, "1", apart(time_json("1/10", "1/8")));
  expect_rejected(verify(full_scene, closed), conflict0, "is not > 0 on the piece");
  closed["pairs"][0]["apart"]["open_end"] = true;
  expect_rejected(verify(full_scene, closed), "pairs[0].apart.until", "not until tH = 1");
  // until moved past t*: sum lambda e < 0 on (t*, 1/8].
  expect_rejected(verify(full_scene, cert("regularised", false, "1", apart("1/8"))), conflict0, "is not >= 0 on the piece");
  // The TIME's interval moved onto the other root (5 + sqrt 14)/11: the
  // sum is negative between the roots.
  expect_rejected(verify(full_scene, cert("regularised", false, "1", apart(time_json("3/4", "4/5")))), conflict0,
                  "is not >= 0 on the piece");
  // A poly with two roots in the interval is no TIME.
  expect_rejected(verify(full_scene, cert("regularised", false, "1", apart(time_json("0", "1")))), "pairs[0].apart.until",
                  "2 distinct roots in (0, 1)");
  Json two_roots = cert("regularised", false, "1", apart(time_json("1/10", "1/8")));
  two_roots["pairs"][0]["apart"]["pieces"][0]["t"][1] = time_json("0", "1");
  expect_rejected(verify(full_scene, two_roots), piece0 + ".t[1]", "not exactly one");
  // Other failures of a TIME at their place.
  Json at_end = cert("regularised", false, "1", apart(time_json("1/10", "1/8")));
  at_end["pairs"][0]["apart"]["until"]["between"][0] = "0";
  at_end["pairs"][0]["apart"]["until"]["poly"] = {"0", "-1", "11"};   // t (11 t - 1): a root at 0
  expect_rejected(verify(full_scene, at_end), "pairs[0].apart.until.between[0]", "zero at 0");
  Json zero = cert("regularised", false, "1", apart(time_json("1/10", "1/8", {"0", "0"})));
  expect_rejected(verify(full_scene, zero), "pairs[0].apart.until.poly", "zero polynomial");
  Json backwards = cert("regularised", false, "1", apart(time_json("1/8", "1/10")));
  expect_rejected(verify(full_scene, backwards), "pairs[0].apart.until.between", "lo < hi");
  Json fraction = cert("regularised", false, "1", apart(time_json("1/10", "1/8", {"1", "-10", "11/2"})));
  expect_rejected(verify(full_scene, fraction), "pairs[0].apart.until.poly[2]", "integer", 2);
}

BOOST_AUTO_TEST_CASE(tampered_conflicts_are_rejected)
{
  auto tampered = [](const std::function<void(Json&)>& change) {
    Json c = cert("regularised", false, "1/10", apart("1/10"));
    change(c["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"][0]);
    return verify(short_scene, c);
  };
  // A lambda coefficient changed: the identity fails.
  expect_rejected(tampered([](Json& c) { c["lambda"][0][2] = "-4"; }), conflict0, "the sum of lambda times the x polynomials is [0, 0, 1, 0, -1]");
  expect_rejected(tampered([](Json& c) { c["lambda"][1] = {"0", "9"}; }), conflict0, "x polynomials is [0, 0, -2]");
  // A lambda negative on the piece.
  expect_rejected(tampered([](Json& c) { c["lambda"][1] = {"-1", "10"}; }), conflict0 + ".lambda[1]", ">= 0 on the piece");
  // All lambdas zero: the identity holds, but nothing is proved.
  expect_rejected(tampered([](Json& c) { c["lambda"] = {{"0"}, {"0"}, {"0"}}; }), conflict0 + ".lambda", "zero polynomial");
  // A literal the term does not hold: the slab's atom moved.
  expect_rejected(tampered([](Json& c) { c["literals"][2] = {{"-5"}, {"0"}, {"0"}, {"7"}}; }), piece0 + ".proof", "no conflict closes off");
  // Literals are matched in coprime form, multipliers apply as written.
  expect_ok(tampered([](Json& c) {
              c["literals"][2] = {{"-10"}, {"0"}, {"0"}, {"12"}};
              c["lambda"][2] = {"1/2", "0", "1", "0", "1/2"};
            }),
            "verified: no collision in [0, 1/10] (regularised): 1 pair apart");
  // A LIT with no x, y or z, and shapes that are unreadable (2).
  expect_rejected(tampered([](Json& c) { c["literals"][0] = {{"0"}, {"0"}, {"0"}, {"1"}}; }), conflict0 + ".literals[0]", "non-zero polynomial");
  expect_rejected(tampered([](Json& c) { c["lambda"][0] = {5, 0, -5}; }), conflict0 + ".lambda[0][0]", "as a string", 2);
  expect_rejected(tampered([](Json& c) { c["lambda"][0] = Json::array(); }), conflict0 + ".lambda[0]", "at least one", 2);
  expect_rejected(tampered([](Json& c) { c["literals"][0].erase(3); }), conflict0 + ".literals[0]", "4 elements", 2);
  expect_rejected(tampered([](Json& c) { c["lambda"].erase(2); }), conflict0 + ".lambda", "one polynomial per literal");
  // A split is an unknown key of a turning-1 proof.
  Json split = cert("regularised", false, "1/10", apart("1/10"));
  split["pairs"][0]["apart"]["pieces"][0]["proof"]["split"] = {"1", "0", "0", "0", "0"};
  expect_rejected(verify(short_scene, split), piece0 + ".proof.split", "unknown key");
}

// The same proof on the scene with the slab 1e-9 closer proves nothing:
// its literal is another one. With that literal (and lambda scaled to it),
// the sum lambda e is negative at t*: the contact comes earlier.
BOOST_AUTO_TEST_CASE(slab_moved_closer)
{
  expect_rejected(verify(slab_closer(short_scene), cert("regularised", false, "1/10", apart("1/10"))), piece0 + ".proof",
                  "no conflict closes off");
  Json c = cert("regularised", false, "1", apart(time_json("1/10", "1/8")));
  Json& conflict = c["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"][0];
  conflict["literals"][2] = {{"-1000000000"}, {"0"}, {"0"}, {"1199999999"}};   // 2e8 (-5 x + 6 - 5e-9)
  conflict["lambda"][2] = {"1/200000000", "0", "1/100000000", "0", "1/200000000"};
  expect_rejected(verify(slab_closer(full_scene), c), conflict0, "is not >= 0 on the piece");
  // On the scene as it was, every conflict's arithmetic is checked first.
  expect_rejected(verify(full_scene, c), conflict0, "is not >= 0 on the piece");
}

// A collision: a witness at t = 1/2, and a touch at t* with FIELD
// coordinates. At t*, the square's corner (1, -1) is at x = 6/5 and
// y = (t^2 + 2t - 1)/(1 + t^2), which is -1 + 11/5 t modulo 11 t^2 - 10 t + 1.
BOOST_AUTO_TEST_CASE(turning_square_collides)
{
  Json witness = {{"objects", {"square", "slab"}}, {"collide", true}, {"witness", {"13/10", "1/5", "0", "1/2"}}};
  expect_ok(verify(full_scene, cert("regularised", true, "1", witness)),
            "verified: collision (regularised): square and slab at (13/10, 1/5, 0, 1/2)");
  witness["witness"][1] = "1/2";   // outside the square: l1 = 3/4 (13/10) + 1/2 - 5/4 > 0
  expect_rejected(verify(full_scene, cert("regularised", true, "1", witness)), "pairs[0].witness", "not strictly inside square");
  witness["witness"] = {"13/10", "1/5", "0", "1"};   // t = 1 is a breakpoint (and tH)
  expect_rejected(verify(full_scene, cert("regularised", true, "1", witness)), "pairs[0].witness[3]", "strictly inside (tL, tH)");

  Json y = {{"at_t", {"-1", "11/5"}}};
  Json c_point = {"6/5", y, "0", time_json("1/10", "1/8")};
  Json wa = {"0", "0", "0", time_json("0", "1/8", {"5", "-49", "45", "11"})};   // t* as a root of (11t^2 - 10t + 1)(t + 5)
  Json wb = {"2", "0", "0", time_json("1/10", "1/8")};
  Json touch = {{"objects", {"square", "slab"}}, {"collide", true}, {"touch", {{"point", c_point}, {"inside", {wa, wb}}}}};
  expect_ok(verify(full_scene, cert("closed", true, "1", touch)),
            "verified: collision (closed): square and slab at (6/5, [-1, 11/5](t), 0, root of [1, -10, 11] in (1/10, 1/8))");
  // The contact's y moved: the square's face -y - 1 is positive there.
  Json off = touch;
  off["touch"]["point"][1]["at_t"][1] = "2";
  expect_rejected(verify(full_scene, cert("closed", true, "1", off)), "pairs[0].touch.inside[0]", "sign other than here");
  // A witness at another time.
  Json late = touch;
  late["touch"]["inside"][1][3] = "1/8";
  expect_rejected(verify(full_scene, cert("closed", true, "1", late)), "pairs[0].touch.inside[1][3]", "equal the contact's time");
  // The same point at the other root (5 + sqrt 14)/11 ~ 0.795 is a touch
  // too: the corner leaves the slab's face there (y = -1 + 11/5 t holds at
  // both roots).
  Json other = touch;
  other["touch"]["point"][3]["between"] = {"3/4", "4/5"};
  for (int k : {0, 1}) other["touch"]["inside"][k][3] = time_json("3/4", "4/5");
  expect_ok(verify(full_scene, cert("closed", true, "1", other)),
            "verified: collision (closed): square and slab at (6/5, [-1, 11/5](t), 0, root of [1, -10, 11] in (3/4, 4/5))");
  // Between the roots, at t = 1/2, (6/5, 1/10, 0) is inside the square
  // (l1 = -1/4, l2 = -1/8) and on the slab's face: a touch as well. At
  // x = 11/10 it is outside the slab (6/5 - x > 0 there, < 0 at WB).
  Json mid = touch;
  mid["touch"]["point"][3] = "1/2";
  for (int k : {0, 1}) mid["touch"]["inside"][k][3] = "1/2";
  expect_ok(verify(full_scene, cert("closed", true, "1", mid)),
            "verified: collision (closed): square and slab at (6/5, [-1, 11/5](t), 0, 1/2)");
  mid["touch"]["point"][0] = "11/10";
  expect_rejected(verify(full_scene, cert("closed", true, "1", mid)), "pairs[0].touch.inside[1]", "sign other than here");
}

// Section 8: each format on its kind of scene only.
BOOST_AUTO_TEST_CASE(formats_and_kinds_of_scene)
{
  Json c = cert("regularised", false, "1/10", apart("1/10"));
  c["format"] = "clash4d-certificate/1";
  expect_rejected(verify(short_scene, c), "format", "clash4d-certificate/turning-1");
  Json piece = {{"t", {"0", "1/10"}}, {"proof", {{"conflicts", Json::array()}}}};
  Json still = R"({"format":"clash4d-scene/1","time":[0,"1/10"],"objects":[
    {"name":"square","shape":{"block":{"min":[-1,-1,-1],"max":[1,1,1]}},"motion":{"poses":[{"t":0},{"t":1,"rotate":[2,0,0,0]}]}},
    {"name":"slab","shape":{"block":{"min":["6/5",-1,-1],"max":[3,1,1]}}}]})"_json;
  expect_rejected(verify(still.dump(), cert("regularised", false, "1/10", apart("1/10"))), "format", "no object of the scene turns");
  c["format"] = "clash4d-certificate/2";
  expect_rejected(verify(short_scene, c), "format", "expected", 2);
  // An earliest claim of no collision: rule 4 asks nothing more.
  Json early = cert("regularised", false, "1/10", apart("1/10"));
  early["claim"]["earliest"] = true;
  expect_ok(verify(short_scene, early), "verified: no collision in [0, 1/10] (regularised): 1 pair apart");
  Json with_earliest = cert("regularised", false, "1/10", apart("1/10"));
  with_earliest["pairs"][0]["earliest"] = Json::object();
  expect_rejected(verify(short_scene, with_earliest), "pairs[0]", "holds apart and nothing else");
}

// A ROBMOD object in a turning scene: q = (1, 0, 0, 0), c(t) = D(t), its
// `until` times its breakpoints (8.2). The ram [5, 6] x [-1, 1]^2 moves
// with velocity -10 in x until t = 1/2, so it spans x in [2, 3] at t = 3/10.
BOOST_AUTO_TEST_CASE(a_robmod_object_in_a_turning_scene)
{
  Json scene = Json::parse(full_scene);
  scene["objects"].push_back(R"({"name":"ram","shape":{"block":{"min":[5,-1,-1],"max":[6,1,1]}},"motion":"vel -10 0 0 until 1/2 vel 0 0 0"})"_json);
  std::string text = scene.dump();
  Json pair = {{"objects", {"ram", "slab"}}, {"collide", true}, {"witness", {"5/2", "0", "0", "3/10"}}};
  expect_ok(verify(text, cert("regularised", true, "1", pair)), "verified: collision (regularised): ram and slab at (5/2, 0, 0, 3/10)");
  pair["witness"][3] = "1/10";   // the ram spans [4, 5] then
  expect_rejected(verify(text, cert("regularised", true, "1", pair)), "pairs[0].witness", "not strictly inside ram");
  pair["witness"] = {"-1", "0", "0", "1/2"};
  expect_rejected(verify(text, cert("regularised", true, "1", pair)), "pairs[0].witness[3]", "breakpoint of ram");
  // Apart on [0, 1/5]: the slab's x - 3 and the ram's 5 - 10 t - x (its
  // literal [[-1], [0], [0], [5, -10]]), lambda 1, 1: x cancels, e = 2 - 10 t
  // >= 0 on [0, 1/5] only. The piece holds; the claim then needs every pair
  // (rule 3) and apart until tH (rule 5).
  Json conflict = R"({"literals": [[["1"], ["0"], ["0"], ["-3"]], [["-1"], ["0"], ["0"], ["5", "-10"]]], "lambda": [["1"], ["1"]]})"_json;
  Json piece = {{"t", {"0", "1/5"}}, {"proof", {{"conflicts", {conflict}}}}};
  Json a = {{"until", "1/5"}, {"pieces", {piece}}};
  Json apart_pair = {{"objects", {"slab", "ram"}}, {"collide", false}, {"apart", a}};
  expect_rejected(verify(text, cert("regularised", false, "1", apart_pair)), "pairs", "no PAIR for square/slab");
  apart_pair["apart"]["until"] = "1/4";
  apart_pair["apart"]["pieces"][0]["t"][1] = "1/4";
  expect_rejected(verify(text, cert("regularised", false, "1", apart_pair)), conflict0, "is not >= 0 on the piece");
  apart_pair["apart"]["until"] = "1";
  apart_pair["apart"]["pieces"][0]["t"][1] = "1";
  expect_rejected(verify(text, cert("regularised", false, "1", apart_pair)), piece0 + ".t", "a breakpoint of ram lies inside the piece");
}

std::string temp_file(const std::string& name, const std::string& text)
{
  std::string path = "/tmp/clash4d_test_verify_turning_" + name;
  std::ofstream(path) << text;
  return path;
}

BOOST_AUTO_TEST_CASE(cli_exit_codes)
{
  std::string s = fixtures + "/../tests/data/turning/square_into_slab_short.json";
  Cli_run r = run_clash4d({"verify", s, temp_file("good.json", cert("regularised", false, "1/10", apart("1/10")).dump())});
  BOOST_TEST(r.status == 0, r.err);
  BOOST_TEST(r.out == "verified: no collision in [0, 1/10] (regularised): 1 pair apart\n");
  Json old = cert("regularised", false, "1/10", apart("1/10"));
  old["format"] = "clash4d-certificate/1";
  r = run_clash4d({"verify", s, temp_file("old.json", old.dump())});
  BOOST_TEST(r.status == 1);
  BOOST_TEST(r.err.find("format: object square turns") != std::string::npos, r.err);
  std::string number = cert("regularised", false, "1/10", apart("1/10")).dump();
  number.replace(number.find("[\"5\",\"0\",\"-5\"]"), 13, "[5,\"0\",\"-5\"]");
  r = run_clash4d({"verify", s, temp_file("number.json", number)});
  BOOST_TEST(r.status == 2, r.err);
}

// Formulas of more than one term (8.3's leaves as section 4's): the slab
// joined with a far block [10, 11] x [-1, 1]^2 needs a second conflict, the
// square's l1, l2 and the far block's 10 - x with lambda (1 - t^2, 2 t,
// (1 + t^2)^2): x and y cancel, e = (1 + t^2)(11 t^2 - 2 t + 9) > 0.
BOOST_AUTO_TEST_CASE(terms_of_a_union_and_a_literal_with_its_negation)
{
  Json scene = Json::parse(short_scene);
  scene["objects"][1]["shape"] = R"({"union": [{"block": {"min": ["6/5", -1, -1], "max": [3, 1, 1]}},
                                              {"block": {"min": [10, -1, -1], "max": [11, 1, 1]}}]})"_json;
  std::string text = scene.dump();
  Json c = cert("regularised", false, "1/10", apart("1/10"));
  expect_rejected(verify(text, c), piece0 + ".proof", "no conflict closes off the term");
  Json far = R"({"literals": [
     [["1","0","-1"], ["0","2"], ["0"], ["-1","0","-1"]],
     [["0","2"], ["-1","0","1"], ["0"], ["-1","0","-1"]],
     [["-1"], ["0"], ["0"], ["10"]]],
   "lambda": [["1","0","-1"], ["0","2"], ["1","0","2","0","1"]]})"_json;
  c["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"].push_back(far);
  expect_ok(verify(text, c), "verified: no collision in [0, 1/10] (regularised): 1 pair apart");
  c["semantics"] = "closed";
  expect_ok(verify(text, c), "verified: no collision in [0, 1/10] (closed): 1 pair apart");

  // x - 2 <= 0 and 2 - x <= 0: the one term holds a literal and its
  // negation. Regularised, that closes it off with no conflict; closed, a
  // conflict "of": "B" (lambda 1, 1, e = 0 >= 0) shows its open set empty.
  scene["objects"][1]["shape"] = R"({"intersection": [{"halfspace": [1, 0, 0, -2]}, {"halfspace": [-1, 0, 0, 2]}]})"_json;
  text = scene.dump();
  Json flat = cert("regularised", false, "1/10", apart("1/10"));
  flat["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"] = Json::array();
  expect_ok(verify(text, flat), "verified: no collision in [0, 1/10] (regularised): 1 pair apart");
  flat["semantics"] = "closed";
  expect_rejected(verify(text, flat), piece0 + ".proof", "no conflict closes off the term");
  flat["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"] =
      R"([{"literals": [[["1"], ["0"], ["0"], ["-2"]], [["-2"], ["0"], ["0"], ["4"]]], "lambda": [["2"], ["1"]], "of": "B"}])"_json;
  expect_ok(verify(text, flat), "verified: no collision in [0, 1/10] (closed): 1 pair apart");
  // "of": "A" ranges over the square's term only, which is not empty.
  flat["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"][0]["of"] = "A";
  expect_rejected(verify(text, flat), piece0 + ".proof", "no conflict closes off the term");
}

// Random polynomials with known rational roots (and multiplicities), and
// TIMEs given as roots of products: Sturm counts, signs and comparisons
// against the answers known by construction.
BOOST_AUTO_TEST_CASE(random_roots_against_construction)
{
  std::mt19937 rng(20261203);
  auto rational = [&](int range) { mpq_class q(long(rng() % (2 * range + 1)) - range, long(rng() % 4 + 1)); q.canonicalize(); return q; };
  for (int round = 0; round < 200; ++round) {
    std::vector<mpq_class> roots;
    mpq_class lead(long(rng() % 5) + 1, 3);
    lead.canonicalize();
    Rational_poly p = Rational_poly::constant(rng() % 2 ? lead : mpq_class(-lead));
    for (int k = 0, n = int(rng() % 4) + 1; k < n; ++k) {
      mpq_class r = rational(6);
      roots.push_back(r);
      for (int m = 0, mult = int(rng() % 3) + 1; m < mult; ++m) p = p * Rational_poly::linear(-r, 1);
    }
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    mpq_class x = rational(7), y = rational(7);
    if (x == y) continue;
    if (y < x) std::swap(x, y);
    long expected = std::count_if(roots.begin(), roots.end(), [&](const mpq_class& r) { return x < r && r < y; });
    BOOST_TEST(count_roots(p, x, y) == expected);
    BOOST_TEST(count_roots(p, Real_time(x), Real_time(y)) == expected);
    // Each root r as a TIME: a root of p * (t^2 - 2) isolated around r.
    Rational_poly q = p * poly({"-2", "0", "1"});
    for (const mpq_class& r : roots) {
      mpq_class lo = r - mpq_class(1, 1000), hi = r + mpq_class(1, 1000);
      if (valid_root(q, lo, hi) != Root_check::ok) continue;
      Real_time t(q, lo, hi);
      BOOST_TEST(equal(t, Real_time(r)));
      BOOST_TEST(sign_at(p, t) == 0);
      BOOST_TEST(sign_at(Rational_poly::linear(-x, 1), t) == sgn(r - x));
      BOOST_TEST(less(t, Real_time(r + mpq_class(1, 1000000))));
      BOOST_TEST(!less(t, Real_time(r)));
      long between = std::count_if(roots.begin(), roots.end(), [&](const mpq_class& s) { return r < s && s < y; });
      if (r < y) BOOST_TEST(count_roots(p, t, Real_time(y)) == between);
    }
  }
}

// Random products of (t - r)^m and (t^2 - c)^k with c > 0 not a square of
// a rational (roots +-sqrt c, irrational), negative leads and mixed
// scales: the Sturm count of distinct roots in (x, y) against the roots
// known by construction (sqrt c lies in (x, y) exactly when x < sqrt c,
// by squares, and sqrt c < y). The sequences here take more remainder
// steps than the rational-root products above.
BOOST_AUTO_TEST_CASE(random_irrational_roots_against_construction)
{
  std::mt19937 rng(20261204);
  BOOST_TEST_MESSAGE("irrational roots: seed 20261204");
  auto rational = [&](int range, int den) {
    mpq_class q(long(rng() % (2 * range + 1)) - range, long(rng() % den + 1));
    q.canonicalize();
    return q;
  };
  auto below_root = [](const mpq_class& x, const mpq_class& c) { return x < 0 || x * x < c; };   // x < sqrt c
  for (int round = 0; round < 300; ++round) {
    Rational_poly p = Rational_poly::constant(rational(5, 7) + mpq_class(11, 2));
    if (rng() % 2) p = mpq_class(-1) * p;
    std::vector<mpq_class> squares;   // c of each (t^2 - c) factor: roots -sqrt c, sqrt c
    std::vector<mpq_class> roots;
    for (int k = 0, n = int(rng() % 3) + 1; k < n; ++k) {
      // (3k + 2) / 1 or / 9: in lowest terms, with a numerator 2 mod 3, never a square.
      mpq_class c(2 + 3 * long(rng() % 7), rng() % 2 ? 1 : 9);
      if (std::find(squares.begin(), squares.end(), c) == squares.end()) squares.push_back(c);
      for (int m = 0, mult = int(rng() % 2) + 1; m < mult; ++m) p = p * Rational_poly({-c, 0, 1});
    }
    for (int k = 0, n = int(rng() % 3); k < n; ++k) {
      mpq_class r = rational(4, 5);
      if (std::find(roots.begin(), roots.end(), r) == roots.end()) roots.push_back(r);
      for (int m = 0, mult = int(rng() % 3) + 1; m < mult; ++m) p = p * Rational_poly::linear(-r, 1);
    }
    mpq_class x = rational(5, 6), y = rational(5, 6);
    if (x == y) continue;
    if (y < x) std::swap(x, y);
    long expected = std::count_if(roots.begin(), roots.end(), [&](const mpq_class& r) { return x < r && r < y; });
    for (const mpq_class& c : squares) {
      expected += below_root(x, c) && !below_root(y, c);            // sqrt c in (x, y)
      expected += below_root(-y, c) && !below_root(-x, c);          // -sqrt c in (x, y): -y < sqrt c < -x
    }
    BOOST_TEST(count_roots(p, x, y) == expected, "round " << round);
    BOOST_TEST(Sturm_sequence(p).count(x, y) == expected, "round " << round);
    BOOST_TEST(count_roots(p, Real_time(x), Real_time(y)) == expected, "round " << round);
  }
}

// gcd on random products of linear factors and an irreducible quadratic:
// f g and f h, with g's and h's roots apart from each other and from f's,
// have the monic gcd f / lead(f), whatever the scales.
BOOST_AUTO_TEST_CASE(random_gcds_against_construction)
{
  std::mt19937 rng(20261205);
  BOOST_TEST_MESSAGE("gcds: seed 20261205");
  auto product = [&](int first, int count, long scale) {   // roots first, first + 1, ... over 3
    Rational_poly p = Rational_poly::constant(mpq_class(scale, 7));
    for (int k = 0; k < count; ++k) {
      mpq_class root(first + k, 3);
      root.canonicalize();   // 3/3, 6/3: GMP wants lowest terms
      p = p * Rational_poly::linear(-root, 1);
    }
    return p;
  };
  for (int round = 0; round < 200; ++round) {
    long scale = long(rng() % 4) + 1;
    Rational_poly f = product(0, int(rng() % 3), rng() % 2 ? scale : -scale);
    if (rng() % 2) f = f * poly({"3", "0", "1"});   // t^2 + 3: no real root
    Rational_poly g = product(10, int(rng() % 3) + 1, 2), h = product(20, int(rng() % 3), -3);
    BOOST_TEST((gcd(f * g, f * h) == f.monic()), "round " << round);
    BOOST_TEST((gcd(f * h, f * g) == f.monic()), "round " << round);
  }
}

// Shapes and places of the remaining rules of 8.1, 8.3 and 8.4.
BOOST_AUTO_TEST_CASE(more_places_of_failure)
{
  Json late = cert("regularised", false, "1/10", apart("1/10"));
  late["pairs"][0]["apart"]["until"] = time_json("1/10", "1/8");   // t* > tH = 1/10
  expect_rejected(verify(short_scene, late), "pairs[0].apart.until", "after tH");
  Json approx = cert("regularised", false, "1", apart(time_json("1/10", "1/8")));
  approx["pairs"][0]["apart"]["until"]["approx"] = 0.114;
  expect_rejected(verify(full_scene, approx), "pairs[0].apart.until.approx", "string", 2);
  Json unknown = cert("regularised", false, "1", apart(time_json("1/10", "1/8")));
  unknown["pairs"][0]["apart"]["until"]["degree"] = "2";
  expect_rejected(verify(full_scene, unknown), "pairs[0].apart.until.degree", "unknown key");
  Json no_between = cert("regularised", false, "1", apart(time_json("1/10", "1/8")));
  no_between["pairs"][0]["apart"]["until"].erase("between");
  expect_rejected(verify(full_scene, no_between), "pairs[0].apart.until", "missing key 'between'", 2);
  // A witness is rational: a TIME object there is not a number (2).
  Json witness = {{"objects", {"square", "slab"}}, {"collide", true}, {"witness", {"13/10", "1/5", "0", time_json("1/10", "1/8")}}};
  expect_rejected(verify(full_scene, cert("regularised", true, "1", witness)), "pairs[0].witness[3]", "as a string", 2);
  // A FIELD's object holds at_t only.
  Json c_point = {"6/5", {{"at_t", {"-1", "11/5"}}, {"t", "0"}}, "0", time_json("1/10", "1/8")};
  Json touch = {{"objects", {"square", "slab"}}, {"collide", true},
                {"touch", {{"point", c_point}, {"inside", {{"0", "0", "0", "1/2"}, {"2", "0", "0", "1/2"}}}}}};
  expect_rejected(verify(full_scene, cert("closed", true, "1", touch)), "pairs[0].touch.point[1].t", "unknown key");
  // A touch in regularised semantics, a witness in closed.
  touch["touch"]["point"][1].erase("t");
  expect_rejected(verify(full_scene, cert("regularised", true, "1", touch)), "pairs[0].touch", "closed semantics");
  witness["witness"][3] = "1/2";
  expect_rejected(verify(full_scene, cert("closed", true, "1", witness)), "pairs[0].witness", "regularised semantics");
  // A pair named twice, an object the scene does not have.
  Json twice = cert("regularised", false, "1/10", apart("1/10"));
  twice["pairs"].push_back(twice["pairs"][0]);
  twice["pairs"][1]["objects"] = {"slab", "square"};
  expect_rejected(verify(short_scene, twice), "pairs[1].objects", "appears twice");
  Json nobody = cert("regularised", false, "1/10", apart("1/10"));
  nobody["pairs"][0]["objects"][1] = "ram";
  expect_rejected(verify(short_scene, nobody), "pairs[0].objects[1]", "no object named 'ram'");
  // Claims: a collision with no colliding PAIR.
  expect_rejected(verify(short_scene, cert("regularised", true, "1/10", apart("1/10"))), "claim.collide", "no PAIR collides");
}

// An object with a pose motion that does not turn, in a turning scene: its
// pose times are its breakpoints, c(t) interpolates its translations (8.2).
// The slab moves by -1/2 in x over [0, 1], so at t = 1/2 it spans
// [19/20, 11/4]: (11/10, 1/5, 0) is inside it and inside the square
// (l1 = 33/40 + 1/5 - 5/4 < 0, l2 = 11/10 - 3/20 - 5/4 < 0).
BOOST_AUTO_TEST_CASE(a_translating_pose_motion_in_a_turning_scene)
{
  Json scene = Json::parse(full_scene);
  Json witness = {{"objects", {"square", "slab"}}, {"collide", true}, {"witness", {"11/10", "1/5", "0", "1/2"}}};
  expect_rejected(verify(scene.dump(), cert("regularised", true, "1", witness)), "pairs[0].witness", "not strictly inside slab");
  scene["objects"][1]["motion"] = R"({"poses": [{"t": 0}, {"t": 1, "translate": ["-1/2", 0, 0]}]})"_json;
  expect_ok(verify(scene.dump(), cert("regularised", true, "1", witness)),
            "verified: collision (regularised): square and slab at (11/10, 1/5, 0, 1/2)");
  scene["objects"][1]["motion"] = R"({"poses": [{"t": 0}, {"t": "1/2", "translate": ["-1/4", 0, 0]}, {"t": 1, "translate": ["-1/2", 0, 0]}]})"_json;
  expect_rejected(verify(scene.dump(), cert("regularised", true, "1", witness)), "pairs[0].witness[3]", "breakpoint of slab");
  witness["witness"][3] = "49/100";   // the slab spans [0.955, 2.755] then
  expect_ok(verify(scene.dump(), cert("regularised", true, "1", witness)),
            "verified: collision (regularised): square and slab at (11/10, 1/5, 0, 49/100)");
}

// ---------------------------------------------------------------- earliest (8.4)

namespace {

const char* t_star_line = "root of [1, -10, 11] in (1/10, 1/8)";

// The witness path of 8.4 on (t*, 1/8]. The square's corner (1, -1) is at
// P(t) = (1 - t^2 + 2t, t^2 + 2t - 1, 0) / (1 + t^2); W(t) = (1 - s) P(t)
// steps towards the centre by s = -(11 t^2 - 10 t + 1)/10, zero at t* and
// positive on (t*, (5 + sqrt 14)/11): the square's literals x - 1 and
// -y - 1 are -(1 + t^2) s there (times w), the slab's 6/5 - x is
// (11 t^2 - 10 t + 1)(1 - t)^2 / (10 (1 + t^2)): all negative on (t*, 1/8].
// (1 - s) = (11 t^2 - 10 t + 11)/10, so with w = 10 (1 + t^2):
// x = (11 t^2 - 10 t + 11)(1 + 2t - t^2), y = (11 t^2 - 10 t + 11)(t^2 + 2t - 1).
Json path_json(const char* to = "1/8")
{
  return {{"x", {"11", "12", "-20", "32", "-11"}}, {"y", {"-11", "32", "-20", "12", "11"}}, {"z", {"0"}}, {"w", {"10", "0", "10"}}, {"to", to}};
}

// The square/slab PAIR colliding at t*: apart until `until` (8.6's proof on
// [0, until]) and the earliest proof.
Json earliest_pair(const Json& earliest, const Json& until)
{
  Json p = apart(until);
  p["collide"] = true;
  p["earliest"] = earliest;
  return p;
}

Json regularised_earliest(const Json& t = time_json("1/10", "1/8"), const Json& path = path_json())
{
  return {{"t", t}, {"path", path}};
}

Json earliest_cert(const char* semantics, const Json& pair, bool all_pairs = false)
{
  Json c = cert(semantics, true, "1", pair);
  c["claim"]["earliest"] = true;
  c["claim"]["all_pairs"] = all_pairs;
  return c;
}

// t* moved by 10^-19 (later for sign +1): the root of 11 (t - d)^2 - 10 (t - d) + 1, d = sign 10^-19, times 10^38.
Json shifted_t_star(int sign)
{
  mpz_class D = mpz_class("10000000000000000000") * sign;   // 1/d
  mpz_class c0 = 11 + 10 * D + D * D, c1 = -(22 * D + 10 * D * D), c2 = 11 * D * D;
  return {{"poly", {c0.get_str(), c1.get_str(), c2.get_str()}}, {"between", {"1/10", "1/8"}}};
}

const std::string path_at = "pairs[0].earliest.path";

} // namespace

BOOST_AUTO_TEST_CASE(earliest_regularised_by_a_witness_path)
{
  Json good = earliest_cert("regularised", earliest_pair(regularised_earliest(), time_json("1/10", "1/8")));
  const std::string line = std::string("verified: earliest collision (regularised): square and slab at t* = ") + t_star_line;
  expect_ok(verify(full_scene, good), line);
  expect_ok(verify(full_scene, parse_certificate(good.dump())), line);

  // t* on the other root (5 + sqrt 14)/11 ~ 0.795: the path ends before it;
  // ending at 9/10, the step s is negative after that root: W(t) is outside
  // the square (the corner has left the slab: no path exists there).
  Json other = good;
  other["pairs"][0]["earliest"]["t"] = time_json("3/4", "4/5");
  expect_rejected(verify(full_scene, other), path_at + ".to", "must be after t*");
  other["pairs"][0]["earliest"]["path"]["to"] = "9/10";
  expect_rejected(verify(full_scene, other), path_at, "is not strictly inside square");

  // t* 10^-19 later, the apart's last piece end with it: the path holds,
  // the apart's sum lambda e is negative on (t*, t* + 10^-19].
  Json later = good;
  later["pairs"][0]["earliest"]["t"] = shifted_t_star(1);
  later["pairs"][0]["apart"]["until"] = shifted_t_star(1);
  later["pairs"][0]["apart"]["pieces"][0]["t"][1] = shifted_t_star(1);
  expect_rejected(verify(full_scene, later), conflict0, "is not >= 0 on the piece");
  // 10^-19 earlier: the apart holds, the path's literals are zero at t*.
  Json earlier = good;
  earlier["pairs"][0]["earliest"]["t"] = shifted_t_star(-1);
  earlier["pairs"][0]["apart"]["until"] = shifted_t_star(-1);
  earlier["pairs"][0]["apart"]["pieces"][0]["t"][1] = shifted_t_star(-1);
  expect_rejected(verify(full_scene, earlier), path_at, "has a root between t* and T1");
  // t* moved later without the apart (the path holds): the apart must end at t*.
  Json alone = good;
  alone["pairs"][0]["earliest"]["t"] = shifted_t_star(1);
  expect_rejected(verify(full_scene, alone), "pairs[0].apart.until", "must end at t*");

  // T1 before t*, at or after tH, a TIME object.
  Json before = good;
  before["pairs"][0]["earliest"]["path"]["to"] = "1/10";
  expect_rejected(verify(full_scene, before), path_at + ".to", "must be after t*");
  before["pairs"][0]["earliest"]["path"]["to"] = "1";
  expect_rejected(verify(full_scene, before), path_at + ".to", "before tH");
  before["pairs"][0]["earliest"]["path"]["to"] = time_json("1/10", "1/8");
  expect_rejected(verify(full_scene, before), path_at + ".to", "rational");

  // x moved by -3/100 (W by -3/(1000 (1 + t^2))): the slab's literal is
  // positive at t* and still negative at T1, so it crosses zero between.
  Json crossing = good;
  crossing["pairs"][0]["earliest"]["path"]["x"][0] = "1097/100";
  expect_rejected(verify(full_scene, crossing), path_at, "has a root between t* and T1");
  // Moved by -1/2: the slab's literal is positive on the whole path.
  crossing["pairs"][0]["earliest"]["path"]["x"][0] = "21/2";
  expect_rejected(verify(full_scene, crossing), path_at, "is not strictly inside slab");

  // z = 8t w: the point reaches the top face z = 1 at T1 = 1/8 (and stays
  // below it before): the literals z - 1 are zero there.
  Json top = good;
  top["pairs"][0]["earliest"]["path"]["z"] = {"0", "80", "0", "80"};
  expect_rejected(verify(full_scene, top), path_at, "is zero on the path at T1 = 1/8");
  top["pairs"][0]["earliest"]["path"]["z"] = {"0", "70", "0", "70"};   // z = 7t: below the top at 1/8
  expect_ok(verify(full_scene, top), line);

  // w not positive: the same point W(t) with x, y, w negated.
  Json negative = good;
  Json& p = negative["pairs"][0]["earliest"]["path"];
  for (const char* k : {"x", "y", "w"})
    for (Json& c : p[k]) {
      mpq_class n = -mpq_class(c.get<std::string>());
      c = n.get_str();
    }
  expect_rejected(verify(full_scene, negative), path_at + ".w", "must be > 0");
  // w with a root at 3/25 in (t*, 1/8): 10 (1 + t^2)(25 t - 3)^2 scaled
  // into x, y too would keep W, but w = 0 at 3/25 is refused.
  Json root = good;
  root["pairs"][0]["earliest"]["path"]["w"] = {"90", "-1500", "6340", "-1500", "6250"};
  expect_rejected(verify(full_scene, root), path_at + ".w", "must be > 0");

  // A breakpoint inside (t*, 1/8): the square's motion with a pose at 3/25
  // on its line (q(t) = (1, 0, 0, t) unchanged).
  Json scene = Json::parse(full_scene);
  scene["objects"][0]["motion"]["poses"].insert(scene["objects"][0]["motion"]["poses"].begin() + 1,
                                                R"({"t": "3/25", "rotate": [1, 0, 0, "3/25"]})"_json);
  std::string posed = scene.dump();
  expect_rejected(verify(posed, good), path_at + ".to", "a breakpoint of square lies between t* and T1");
  Json at_break = good;
  at_break["pairs"][0]["earliest"]["path"]["to"] = "3/25";
  expect_rejected(verify(posed, at_break), path_at + ".to", "is a breakpoint of square");
  at_break["pairs"][0]["earliest"]["path"]["to"] = "23/200";   // 0.115, before the pose
  expect_ok(verify(posed, at_break), line);

  // t* = tL: the slab from x = 1/2 overlaps the square from the start; the
  // apart has no pieces, the path is the constant point (3/4, 0, 0).
  Json overlap_scene = Json::parse(full_scene);
  overlap_scene["objects"][1]["shape"]["block"]["min"][0] = "1/2";
  Json from_start = good;
  from_start["pairs"][0]["earliest"] = regularised_earliest(Json("0"), {{"x", {"3/4"}}, {"y", {"0"}}, {"z", {"0"}}, {"w", {"1"}}, {"to", "1/10"}});
  from_start["pairs"][0]["apart"] = {{"until", "0"}, {"pieces", Json::array()}};
  expect_ok(verify(overlap_scene.dump(), from_start), "verified: earliest collision (regularised): square and slab at t* = 0");
  from_start["pairs"][0]["earliest"]["t"] = "-1";
  from_start["pairs"][0]["apart"]["until"] = "-1";
  expect_rejected(verify(overlap_scene.dump(), from_start), "pairs[0].earliest.t", "[tL, tH)");

  // Shapes: the regularised earliest holds t and path; closed keys are unknown.
  Json shape = good;
  shape["pairs"][0]["earliest"]["point"] = {"0", "0", "0", "0"};
  expect_rejected(verify(full_scene, shape), "pairs[0].earliest.point", "unknown key");
  shape = good;
  shape["pairs"][0]["earliest"]["path"].erase("w");
  expect_rejected(verify(full_scene, shape), path_at, "missing key 'w'", 2);
  // t* at tH is refused in regularised semantics.
  shape = good;
  shape["pairs"][0]["earliest"]["t"] = "1";
  expect_rejected(verify(full_scene, shape), "pairs[0].earliest.t", "[tL, tH)");
  // An earliest proof without its apart.
  shape = good;
  shape["pairs"][0].erase("apart");
  expect_rejected(verify(full_scene, shape), "pairs[0]", "earliest with apart");
}

// Closed: the touch at t* (the corner on the slab's face), WA and WB beside
// it at t*, and the apart on [0, t*) with open_end: the sum lambda e of 8.6
// is zero at t*, so without open_end the non-strict conflict fails there.
BOOST_AUTO_TEST_CASE(earliest_closed_by_the_touch_at_t_star)
{
  Json y = {{"at_t", {"-1", "11/5"}}};
  Json c_point = {"6/5", y, "0", time_json("1/10", "1/8")};
  Json wa = {"0", "0", "0", time_json("1/10", "1/8")};
  Json wb = {"2", "0", "0", time_json("1/10", "1/8")};
  Json e = {{"t", time_json("1/10", "1/8")}, {"point", c_point}, {"inside", {wa, wb}}};
  Json good = earliest_cert("closed", earliest_pair(e, time_json("1/10", "1/8")));
  good["pairs"][0]["apart"]["open_end"] = true;
  const std::string line = std::string("verified: earliest collision (closed): square and slab at t* = ") + t_star_line +
                           ", contact (6/5, [-1, 11/5](t), 0, " + t_star_line + ")";
  expect_ok(verify(full_scene, good), line);
  Json closed_end = good;
  closed_end["pairs"][0]["apart"]["open_end"] = false;
  expect_rejected(verify(full_scene, closed_end), conflict0, "is not > 0 on the piece");
  // The contact at another time than t*.
  Json other = good;
  other["pairs"][0]["earliest"]["point"][3] = time_json("3/4", "4/5");
  expect_rejected(verify(full_scene, other), "pairs[0].earliest.point[3]", "equal t*");
  // t* and the touch on the other root: a touch, but the apart fails between the roots.
  other["pairs"][0]["earliest"]["t"] = time_json("3/4", "4/5");
  for (int k : {0, 1}) other["pairs"][0]["earliest"]["inside"][k][3] = time_json("3/4", "4/5");
  other["pairs"][0]["apart"]["until"] = time_json("3/4", "4/5");
  other["pairs"][0]["apart"]["pieces"][0]["t"][1] = time_json("3/4", "4/5");
  expect_rejected(verify(full_scene, other), conflict0, "is not > 0 on the piece [lo, hi)");
  // The contact moved off the square.
  Json off = good;
  off["pairs"][0]["earliest"]["point"][1]["at_t"][1] = "2";
  expect_rejected(verify(full_scene, off), "pairs[0].earliest.inside[0]", "sign other than here");
  // t* after tH.
  Json at_end = good;
  at_end["pairs"][0]["earliest"]["t"] = "2";
  expect_rejected(verify(full_scene, at_end), "pairs[0].earliest.t", "[tL, tH]");
  // A path is a regularised proof: unknown in closed semantics.
  Json path = good;
  path["pairs"][0]["earliest"]["path"] = path_json();
  expect_rejected(verify(full_scene, path), "pairs[0].earliest.path", "unknown key");
}

// Claim rules 4 and 5 with TIMEs: a third object "far" [10, 11] x [-1, 1]^2.
// square/far: the square's l1, l2 and far's 10 - x with lambda (1 - t^2,
// 2t, (1 + t^2)^2), e = (1 + t^2)(11 t^2 - 2 t + 9) > 0; slab/far: x - 3
// and 10 - x, e = 7.
BOOST_AUTO_TEST_CASE(earliest_claims_with_other_pairs)
{
  Json scene = Json::parse(full_scene);
  scene["objects"].push_back(R"({"name": "far", "shape": {"block": {"min": [10, -1, -1], "max": [11, 1, 1]}}})"_json);
  std::string text = scene.dump();
  auto far_pair = [](const char* other, const Json& until) {
    Json conflict = std::string(other) == "square"
                        ? R"({"literals": [[["1","0","-1"], ["0","2"], ["0"], ["-1","0","-1"]], [["0","2"], ["-1","0","1"], ["0"], ["-1","0","-1"]],
                               [["-1"], ["0"], ["0"], ["10"]]], "lambda": [["1","0","-1"], ["0","2"], ["1","0","2","0","1"]]})"_json
                        : R"({"literals": [[["1"], ["0"], ["0"], ["-3"]], [["-1"], ["0"], ["0"], ["10"]]], "lambda": [["1"], ["1"]]})"_json;
    Json piece = {{"t", {"0", until}}, {"proof", {{"conflicts", {conflict}}}}};
    return Json{{"objects", {other, "far"}}, {"collide", false}, {"apart", {{"until", until}, {"pieces", {piece}}}}};
  };
  Json hit = earliest_pair(regularised_earliest(), time_json("1/10", "1/8"));
  Json c = earliest_cert("regularised", hit);
  c["pairs"].push_back(far_pair("square", "1/8"));
  c["pairs"].push_back(far_pair("slab", time_json("1/10", "1/8")));   // until t* exactly: enough
  const std::string line = std::string("verified: earliest collision (regularised): square and slab at t* = ") + t_star_line;
  expect_ok(verify(text, c), line);
  // Apart until 1/10 < t* only.
  Json short_apart = c;
  short_apart["pairs"][1] = far_pair("square", "1/10");
  expect_rejected(verify(text, short_apart), "pairs[1].apart.until", "before t*");
  // Until 10^-19 before t*.
  short_apart["pairs"][1] = far_pair("square", shifted_t_star(-1));
  expect_rejected(verify(text, short_apart), "pairs[1].apart.until", "before t*");
  // Rule 4: every pair not ignored has a PAIR.
  Json missing = c;
  missing["pairs"].erase(2);
  expect_rejected(verify(text, missing), "pairs", "no PAIR for slab/far");
  // all_pairs: the others apart until tH.
  Json all = c;
  all["claim"]["all_pairs"] = true;
  expect_rejected(verify(text, all), "pairs[1].apart.until", "not until tH = 1");
  all["pairs"][1] = far_pair("square", "1");
  all["pairs"][2] = far_pair("slab", "1");
  expect_ok(verify(text, all), std::string("verified: colliding pairs (regularised): square/slab at t* = ") + t_star_line + "; 2 other pairs apart");
  // An earliest claim needs an earliest proof of each colliding PAIR.
  Json witness = c;
  witness["pairs"][0] = {{"objects", {"square", "slab"}}, {"collide", true}, {"witness", {"13/10", "1/5", "0", "1/2"}}};
  expect_rejected(verify(text, witness), "pairs[0]", "needs an earliest proof");
  // Without the earliest claim, an earliest PAIR proves a collision; a path
  // names no point, so the line names t*.
  Json plain = all;
  plain["claim"]["earliest"] = false;
  expect_ok(verify(text, plain), "verified: colliding pairs (regularised): square/slab; 2 other pairs apart");
  plain["claim"]["all_pairs"] = false;
  expect_ok(verify(text, plain), std::string("verified: collision (regularised): square and slab at t* = ") + t_star_line);
}

BOOST_AUTO_TEST_CASE(earliest_cli)
{
  Json good = earliest_cert("regularised", earliest_pair(regularised_earliest(), time_json("1/10", "1/8")));
  Cli_run r = run_clash4d({"verify", fixtures + "/rotation/square_into_slab.json", temp_file("earliest.json", good.dump())});
  BOOST_TEST(r.status == 0, r.err);
  BOOST_TEST(r.out == std::string("verified: earliest collision (regularised): square and slab at t* = ") + t_star_line + "\n");
  good["pairs"][0]["earliest"]["path"]["to"] = "1/10";
  r = run_clash4d({"verify", fixtures + "/rotation/square_into_slab.json", temp_file("earliest_bad.json", good.dump())});
  BOOST_TEST(r.status == 1, r.err);
  BOOST_TEST(r.err.find("pairs[0].earliest.path.to") != std::string::npos, r.err);
}
