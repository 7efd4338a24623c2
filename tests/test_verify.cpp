// The independent certificate checker (verify/, docs/certificate-format.md)
// on hand-made scenes and certificates. Every certificate's correctness is
// derived by hand in its comment; literals [a,b,c,e_t,e] read
// a x + b y + c z + e_t t + e < 0.
#define BOOST_TEST_MODULE verify
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>

#include "cli/Verify_command.h"
#include "support/Cli_run.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include "verify/Certificate_checker.h"
#include <fstream>
#include <random>
#include <sstream>

using namespace clash4d;
using namespace clash4d::verifier;

namespace {

std::string block(const char* name, const std::string& min, const std::string& max, const char* motion = nullptr)
{
  std::string s = R"({"name":")" + std::string(name) + R"(","shape":{"block":{"min":)" + min + R"(,"max":)" + max + "}}";
  return s + (motion ? R"(,"motion":")" + std::string(motion) + "\"}" : "}");
}

std::string scene(const std::string& objects, const char* time = "[0,10]")
{
  return R"({"format":"clash4d-scene/1","time":)" + std::string(time) + R"(,"objects":[)" + objects + "]}";
}

Json cert(const char* semantics, bool collide, bool earliest, bool all, const std::string& pairs, const char* time = R"(["0","10"])")
{
  Json c = Json::parse(std::string(R"({"format":"clash4d-certificate/1","scene":"test","time":)") + time + ",\"pairs\":" + pairs + "}");
  c["semantics"] = semantics;
  c["claim"] = {{"collide", collide}, {"earliest", earliest}, {"all_pairs", all}};
  return c;
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

void expect_rejected(const Verify_result& r, const std::string& where, const std::string& reason, int exit_code = 1,
                     bool past_step_limit = false)
{
  BOOST_TEST(!r.ok);
  BOOST_TEST(r.exit_code == exit_code);
  BOOST_TEST(r.past_step_limit == past_step_limit);
  BOOST_TEST(r.where == where);
  BOOST_TEST(r.reason.find(reason) != std::string::npos, r.reason);
}

// A = [0,1]^3, B = [2,3]x[0,1]^2, at rest. One term: A's six atoms and B's.
// x - 1 < 0 (A) and 2 - x < 0 (B) with lambda 1, 1: x cancels, constants
// -1 + 2 = 1 >= 0: no point has both (regularised).
const std::string apart_scene = scene(block("A", "[0,0,0]", "[1,1,1]") + "," + block("B", "[2,0,0]", "[3,1,1]"));
const std::string apart_pairs = R"([{"objects":["A","B"],"collide":false,"apart":{"until":"10","pieces":[
  {"t":["0","10"],"proof":{"conflicts":[{"literals":[["1","0","0","0","-1"],["-1","0","0","0","2"]],"lambda":["1","1"]}]}}]}}])";
const std::string leaf = "pairs[0].apart.pieces[0].proof";

} // namespace

BOOST_AUTO_TEST_CASE(two_blocks_apart)
{
  expect_ok(verify(apart_scene, cert("regularised", false, false, false, apart_pairs)),
            "verified: no collision in [0, 10] (regularised): 1 pair apart");
  // Literals are matched in coprime form, multipliers apply as written:
  // 2x - 2 with lambda 1/2 is the same conflict.
  Json c = cert("regularised", false, false, false, apart_pairs);
  Json& conflict = c["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"][0];
  conflict["literals"][0] = {"2", "0", "0", "0", "-2"};
  conflict["lambda"][0] = "1/2";
  BOOST_TEST(verify(apart_scene, c).ok);
  // Closed semantics: the constants sum to 1 > 0, so the closures are apart too.
  expect_ok(verify(apart_scene, cert("closed", false, false, false, apart_pairs)),
            "verified: no collision in [0, 10] (closed): 1 pair apart");
}

BOOST_AUTO_TEST_CASE(rejections_of_the_apart_proof)
{
  Json c = cert("regularised", false, false, false, apart_pairs);
  Json flipped = c;   // lambda -1: not positive
  flipped["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"][0]["lambda"][1] = "-1";
  expect_rejected(verify(apart_scene, flipped), leaf + ".conflicts[0].lambda[1]", "lambda must be positive");
  Json unbalanced = c;   // lambda 2 on 2 - x: x no longer cancels
  unbalanced["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"][0]["lambda"][1] = "2";
  expect_rejected(verify(apart_scene, unbalanced), leaf + ".conflicts[0]", "x coefficients is -1, not 0");
  Json dropped = c;   // no conflict: the one term is open
  dropped["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"] = Json::array();
  expect_rejected(verify(apart_scene, dropped), leaf, "[1,0,0,0,-1] (A), [-1,0,0,0,0] (A)");
  Json gap = c;   // the piece ends at 9: [9, 10] is not covered
  gap["pairs"][0]["apart"]["pieces"][0]["t"][1] = "9";
  expect_rejected(verify(apart_scene, gap), "pairs[0].apart.until", "the pieces end at 9, not at until = 10");
  Json none = c;  // no piece at all
  none["pairs"][0]["apart"]["pieces"] = Json::array();
  expect_rejected(verify(apart_scene, none), "pairs[0].apart.until", "the pieces end at 0, not at until = 10");
  Json claim = c;  // collide true, but no PAIR collides
  claim["claim"]["collide"] = true;
  expect_rejected(verify(apart_scene, claim), "claim.collide", "no PAIR collides");
  Json unknown = c;
  unknown["comment"] = "hi";
  expect_rejected(verify(apart_scene, unknown), "comment", "unknown key 'comment'");
  Json unknown_deep = c;
  unknown_deep["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"][0]["weight"] = "1";
  expect_rejected(verify(apart_scene, unknown_deep), leaf + ".conflicts[0].weight", "unknown key 'weight'");
  Json literal_a_number = c;   // section 1: numbers are strings
  literal_a_number["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"][0]["lambda"][0] = 1;
  expect_rejected(verify(apart_scene, literal_a_number), leaf + ".conflicts[0].lambda[0]", "expected a number as a string", 2);
  Json format = c;
  format["format"] = "clash4d-certificate/2";
  expect_rejected(verify(apart_scene, format), "format", "expected \"clash4d-certificate/1\"", 2);
  Json time = c;   // the scene's span is [0, 10]
  time["time"][1] = "11";
  expect_rejected(verify(apart_scene, time), "time[1]", "the scene's span ends at 10");
  Json twice = c;  // rule 1
  twice["pairs"].push_back(c["pairs"][0]);
  twice["pairs"][1]["objects"] = {"B", "A"};
  expect_rejected(verify(apart_scene, twice), "pairs[1].objects", "appears twice");
}

// Touching blocks A = [0,1]^3, B = [1,2]x[0,1]^2. Regularised: x - 1 < 0 and
// 1 - x < 0 sum to 0 >= 0 (all strict): apart. Closed: the same sum 0 is not
// > 0 and no literal is strict, so that conflict proves nothing; the touch
// c = (1, 1/2, 1/2, 5) has generic witnesses (1/2, 1/2, 1/2, 5) in A and
// (3/2, 1/2, 1/2, 5) in B (every literal zero at c, or of the witness's sign).
const std::string touching_scene = scene(block("A", "[0,0,0]", "[1,1,1]") + "," + block("B", "[1,0,0]", "[2,1,1]"));
const std::string touching_apart = R"([{"objects":["A","B"],"collide":false,"apart":{"until":"10","pieces":[
  {"t":["0","10"],"proof":{"conflicts":[{"literals":[["1","0","0","0","-1"],["-1","0","0","0","1"]],"lambda":["1","1"]}]}}]}}])";

BOOST_AUTO_TEST_CASE(touching_blocks_apart_regularised_and_touching_closed)
{
  expect_ok(verify(touching_scene, cert("regularised", false, false, false, touching_apart)),
            "verified: no collision in [0, 10] (regularised): 1 pair apart");
  expect_rejected(verify(touching_scene, cert("closed", false, false, false, touching_apart)), leaf + ".conflicts[0]",
                  "constants is 0, not > 0");
  std::string touch = R"([{"objects":["A","B"],"collide":true,"touch":{"point":["1","1/2","1/2","5"],
    "inside":[["1/2","1/2","1/2","5"],["3/2","1/2","1/2","5"]]}}])";
  expect_ok(verify(touching_scene, cert("closed", true, false, false, touch)),
            "verified: collision (closed): A and B at (1, 1/2, 1/2, 5)");
  // WA inside B instead: not strictly inside A.
  Json bad = cert("closed", true, false, false, touch);
  bad["pairs"][0]["touch"]["inside"][0] = {"3/2", "1/2", "1/2", "5"};
  expect_rejected(verify(touching_scene, bad), "pairs[0].touch.inside[0]", "not strictly inside A");
  // A contact off the face: x - 1 is 1/4 > 0 at c but < 0 at WA.
  bad = cert("closed", true, false, false, touch);
  bad["pairs"][0]["touch"]["point"][0] = "5/4";
  expect_rejected(verify(touching_scene, bad), "pairs[0].touch.inside[0]", "with a sign other than here");
  // A touch is no regularised proof.
  expect_rejected(verify(touching_scene, cert("regularised", true, false, false, touch)), "pairs[0].touch",
                  "for closed semantics");
}

// ram [3,4] moves at -1 until t = 2 and stops, its face x = 1 on the box's:
// the touch at t = 2, a velocity change of ram. A generic witness at that
// very time is fine (either segment's literals have the same signs there),
// and so is one at t = 3 (no change strictly between 2 and 3). One at t = 1 from before, with c at t = 5/2 after
// the stop, has the change t = 2 strictly between: rejected.
BOOST_AUTO_TEST_CASE(a_generic_witness_may_sit_at_a_velocity_change)
{
  std::string stop = scene(block("A", "[0,0,0]", "[1,1,1]") + "," +
                           block("B", "[3,0,0]", "[4,1,1]", "rest until 0 vel -1 0 0 until 2 rest"));
  std::string touch = R"([{"objects":["A","B"],"collide":true,"touch":{"point":["1","1/2","1/2","2"],
    "inside":[["1/2","1/2","1/2","2"],["3/2","1/2","1/2","2"]]}}])";
  expect_ok(verify(stop, cert("closed", true, false, false, touch)), "verified: collision (closed): A and B at (1, 1/2, 1/2, 2)");
  Json later = cert("closed", true, false, false, touch);
  later["pairs"][0]["touch"]["inside"][1] = {"3/2", "1/2", "1/2", "3"};
  expect_ok(verify(stop, later), "verified: collision (closed): A and B at (1, 1/2, 1/2, 2)");
  Json across = cert("closed", true, false, false, touch);
  across["pairs"][0]["touch"]["point"] = {"1", "1/2", "1/2", "5/2"};
  across["pairs"][0]["touch"]["inside"][0] = {"1/2", "1/2", "1/2", "5/2"};
  across["pairs"][0]["touch"]["inside"][1] = {"5/2", "1/2", "1/2", "1"};
  expect_rejected(verify(stop, across), "pairs[0].touch.inside[1][3]", "lies between the contact's time and this one");
}

BOOST_AUTO_TEST_CASE(a_certificate_on_a_scene_moved_by_1e_9_is_rejected)
{
  // B's min x moves to 1 - 1e-9: its literal is now [-1e9,0,0,0,999999999],
  // not the certificate's 1 - x, so the term is closed off by nothing.
  std::string moved = scene(block("A", "[0,0,0]", "[1,1,1]") + "," + block("B", "[\"999999999/1000000000\",0,0]", "[2,1,1]"));
  expect_rejected(verify(moved, cert("regularised", false, false, false, touching_apart)), leaf,
                  "no conflict closes off the term");
}

// A = [0,1]^3, B = [1/2,3/2]x[0,1]^2 overlap; (3/4, 1/2, 1/2, 5) is strictly
// inside both, and t = 5 is no velocity change.
BOOST_AUTO_TEST_CASE(overlapping_blocks_with_a_witness)
{
  std::string s = scene(block("A", "[0,0,0]", "[1,1,1]") + "," + block("B", "[0.5,0,0]", "[1.5,1,1]"));
  std::string pairs = R"([{"objects":["A","B"],"collide":true,"witness":["3/4","1/2","1/2","5"]}])";
  expect_ok(verify(s, cert("regularised", true, false, false, pairs)),
            "verified: collision (regularised): A and B at (3/4, 1/2, 1/2, 5)");
  Json out = cert("regularised", true, false, false, pairs);
  out["pairs"][0]["witness"][0] = "1/4";   // inside A, outside B
  expect_rejected(verify(s, out), "pairs[0].witness", "not strictly inside B");
  out["pairs"][0]["witness"] = {"3/4", "1/2", "1/2", "10"};   // at tH
  expect_rejected(verify(s, out), "pairs[0].witness[3]", "strictly inside (tL, tH)");
  Json no_pairs = cert("regularised", false, false, false, "[]");   // rule 3
  expect_rejected(verify(s, no_pairs), "pairs", "no PAIR for A/B");
}

// The scene format's example: box = [0,1]^3, ram = [3,4]x[0,1]^2 moving at
// -1 in x from 0 to 5, so its x range is [3 - t, 4 - t] and t* = 2.
// Contact C = (1, 1/2, 1/2, 2); W = (3/4, 1/2, 1/2, 5/2) is inside both
// (ram's x range is [1/2, 3/2] then) and every literal zero at C or of W's
// sign: box x - 1 is 0 at C; ram's 3 - x - t is 0 at C; the others < 0 at both.
// Apart on [0, 2]: x - 1 (box), -x - t + 3 (ram), t - 2 (slab), lambda 1, 1, 1:
// x and t cancel, constants -1 + 3 - 2 = 0 >= 0.
const std::string ram_scene = scene(block("box", "[0,0,0]", "[1,1,1]") + "," +
                                    block("ram", "[3,0,0]", "[4,1,1]", "rest until 0 vel -1 0 0 until 5 rest"));
const std::string ram_pairs = R"([{"objects":["box","ram"],"collide":true,
  "earliest":{"t":"2","point":["1","1/2","1/2","2"],"inside":[["3/4","1/2","1/2","5/2"]]},
  "apart":{"until":"2","pieces":[{"t":["0","2"],"proof":{"conflicts":[
    {"literals":[["1","0","0","0","-1"],["-1","0","0","-1","3"],["0","0","0","1","-2"]],"lambda":["1","1","1"]}]}}]}}])";

BOOST_AUTO_TEST_CASE(a_block_moving_into_another_earliest)
{
  expect_ok(verify(ram_scene, cert("regularised", true, true, false, ram_pairs)),
            "verified: earliest collision (regularised): box and ram at t* = 2, contact (1, 1/2, 1/2, 2)");
  // t* earlier by 1e-9, everything else made to fit: the apart proof holds
  // (the constants sum to 1e-9 > 0), but ram's 3 - x - t is 1e-9 > 0 at the
  // contact and < 0 at W: the contact is not in the closure.
  Json early = cert("regularised", true, true, false, ram_pairs);
  Json& p = early["pairs"][0];
  p["earliest"]["t"] = "1999999999/1000000000";
  p["earliest"]["point"][3] = "1999999999/1000000000";
  p["apart"]["until"] = "1999999999/1000000000";
  p["apart"]["pieces"][0]["t"][1] = "1999999999/1000000000";
  p["apart"]["pieces"][0]["proof"]["conflicts"][0]["literals"][2] = {"0", "0", "0", "1000000000", "-1999999999"};
  p["apart"]["pieces"][0]["proof"]["conflicts"][0]["lambda"][2] = "1/1000000000";
  expect_rejected(verify(ram_scene, early), "pairs[0].earliest.inside[0]", "a literal of ram is non-zero at the contact");
  // The apart part must reach t*.
  Json short_apart = cert("regularised", true, true, false, ram_pairs);
  short_apart["pairs"][0]["apart"]["until"] = "1";
  short_apart["pairs"][0]["apart"]["pieces"][0]["t"][1] = "1";
  short_apart["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"][0]["literals"][2] = {"0", "0", "0", "1", "-1"};
  expect_rejected(verify(ram_scene, short_apart), "pairs[0].apart.until", "must end at t* = 2");
  // Claim earliest, but a plain witness.
  std::string witness = R"([{"objects":["box","ram"],"collide":true,"witness":["3/4","1/2","1/2","5/2"]}])";
  expect_rejected(verify(ram_scene, cert("regularised", true, true, false, witness)), "pairs[0]", "needs an earliest proof");
  expect_ok(verify(ram_scene, cert("regularised", true, false, false, witness)),
            "verified: collision (regularised): box and ram at (3/4, 1/2, 1/2, 5/2)");
}

// Rule 4 with a third object "far" = [10,11]x[0,1]^2: the other pairs need
// only be apart until t* = 2. box/far: x - 1 and 10 - x, constants 9.
// ram/far on [0, 2]: ram's x + t - 4, far's 10 - x and the slab's -t (0 - t),
// lambda 1 each: x and t cancel, constants 6.
BOOST_AUTO_TEST_CASE(earliest_needs_the_others_apart_until_t_star)
{
  std::string s = scene(block("box", "[0,0,0]", "[1,1,1]") + "," +
                        block("ram", "[3,0,0]", "[4,1,1]", "rest until 0 vel -1 0 0 until 5 rest") + "," +
                        block("far", "[10,0,0]", "[11,1,1]"));
  Json c = cert("regularised", true, true, false, ram_pairs);
  c["pairs"].push_back(Json::parse(R"({"objects":["box","far"],"collide":false,"apart":{"until":"2","pieces":[{"t":["0","2"],
    "proof":{"conflicts":[{"literals":[["1","0","0","0","-1"],["-1","0","0","0","10"]],"lambda":["1","1"]}]}}]}})"));
  c["pairs"].push_back(Json::parse(R"({"objects":["ram","far"],"collide":false,"apart":{"until":"2","pieces":[{"t":["0","2"],
    "proof":{"conflicts":[{"literals":[["1","0","0","1","-4"],["-1","0","0","0","10"],["0","0","0","-1","0"]],"lambda":["1","1","1"]}]}}]}})"));
  expect_ok(verify(s, c), "verified: earliest collision (regularised): box and ram at t* = 2, contact (1, 1/2, 1/2, 2)");
  Json short_of = c;   // box/far only until 1 < t*
  short_of["pairs"][1]["apart"]["until"] = "1";
  short_of["pairs"][1]["apart"]["pieces"][0]["t"][1] = "1";
  expect_rejected(verify(s, short_of), "pairs[1].apart.until", "before t* = 2");
  Json all = c;   // all_pairs: the others must reach tH
  all["claim"]["all_pairs"] = true;
  expect_rejected(verify(s, all), "pairs[1].apart.until", "not until tH = 10");
  Json missing = c;   // rule 4: every pair not ignored has a PAIR
  missing["pairs"].erase(2);
  expect_rejected(verify(s, missing), "pairs", "no PAIR for ram/far");
}

// Closed: the ram first touches the box at t* = 2 too; the slab's end t = 2
// is then strict, so the same conflict (constants sum 0) holds through the
// strict t - 2. WA = (1/2, 1/2, 1/2, 3) is in the box, WB = (3/2, 1/2, 1/2, 1)
// in the ram (x range [2, 3] at t = 1) with ram's 3 - x - t zero at C.
BOOST_AUTO_TEST_CASE(closed_earliest_uses_the_strict_end)
{
  Json c = cert("closed", true, true, false, ram_pairs);
  c["pairs"][0]["earliest"]["inside"] = Json::parse(R"([["1/2","1/2","1/2","3"],["5/2","1/2","1/2","1"]])");
  // Without open_end, t - 2 <= 0 is non-strict: the sum 0 proves nothing
  // (the blocks do touch at t = 2).
  expect_rejected(verify(ram_scene, c), leaf + ".conflicts[0]", "no strict literal has lambda > 0");
  c["pairs"][0]["apart"]["open_end"] = true;
  expect_ok(verify(ram_scene, c), "verified: earliest collision (closed): box and ram at t* = 2, contact (1, 1/2, 1/2, 2)");
  // Without the strict t - 2 the sum 0 proves nothing.
  Json& conflict = c["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"][0];
  conflict["literals"][2] = {"0", "0", "0", "-1", "0"};   // -t < 0, not a literal of the leaf (and t cannot cancel)
  expect_rejected(verify(ram_scene, c), leaf + ".conflicts[0]", "t coefficients is -2, not 0");
}

// A = [0,2]x[0,1]^2 minus T1 = [1/2,1]x[-1,2]^2 minus T2 = [1,3/2]x[-1,2]^2:
// two blocks [0,1/2] and [3/2,2] with a dangling face at x = 1 (1 - x <= 0
// from NOT T1 and x - 1 <= 0 from NOT T2). B = [3/4,5/4]x[0,1]^2 meets only
// that face, so closed: apart. TA's 36 terms: S's atoms, one atom of NOT T1
// (1-x, x-1/2, 2-y, 1+y, 2-z, 1+z), one of NOT T2 (3/2-x, x-1, 2-y, ...).
// Empty ones ("of": "A", strict): {1-x, x-1}; {y-1, 2-y}; {-y, 1+y}; z
// likewise; {x-1/2, 3/2-x}. Non-empty ones: x > 3/2 against B's x - 5/4
// (lambda 2, 1: constants 6 - 5 = 1 > 0), x < 1/2 against B's 3/4 - x
// (lambda 2, 1: constants -2 + 3 = 1 > 0).
const std::string dangling_scene = scene(
    R"({"name":"A","shape":{"difference":[{"block":{"min":[0,0,0],"max":[2,1,1]}},
       {"block":{"min":[0.5,-1,-1],"max":[1,2,2]}},{"block":{"min":[1,-1,-1],"max":[1.5,2,2]}}]}},)" +
    block("B", "[0.75,0,0]", "[1.25,1,1]"));
const std::string dangling_pairs = R"([{"objects":["A","B"],"collide":false,"apart":{"until":"10","pieces":[
  {"t":["0","10"],"proof":{"conflicts":[
    {"literals":[["-1","0","0","0","1"],["1","0","0","0","-1"]],"lambda":["1","1"],"of":"A"},
    {"literals":[["0","1","0","0","-1"],["0","-1","0","0","2"]],"lambda":["1","1"],"of":"A"},
    {"literals":[["0","-1","0","0","0"],["0","1","0","0","1"]],"lambda":["1","1"],"of":"A"},
    {"literals":[["0","0","1","0","-1"],["0","0","-1","0","2"]],"lambda":["1","1"],"of":"A"},
    {"literals":[["0","0","-1","0","0"],["0","0","1","0","1"]],"lambda":["1","1"],"of":"A"},
    {"literals":[["2","0","0","0","-1"],["-2","0","0","0","3"]],"lambda":["1","1"],"of":"A"},
    {"literals":[["-2","0","0","0","3"],["4","0","0","0","-5"]],"lambda":["2","1"]},
    {"literals":[["2","0","0","0","-1"],["-4","0","0","0","3"]],"lambda":["2","1"]}]}}]}}])";

BOOST_AUTO_TEST_CASE(a_dangling_face_is_not_in_the_closed_object)
{
  expect_ok(verify(dangling_scene, cert("closed", false, false, false, dangling_pairs)),
            "verified: no collision in [0, 10] (closed): 1 pair apart");
  // Regularised: the same conflicts hold (strict, constants >= 0).
  BOOST_TEST(verify(dangling_scene, cert("regularised", false, false, false, dangling_pairs)).ok);
  // The face term {1-x, x-1} with "of": "both" is non-strict: 0 is not > 0.
  Json both = cert("closed", false, false, false, dangling_pairs);
  both["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"][0].erase("of");
  expect_rejected(verify(dangling_scene, both), leaf + ".conflicts[0]", "constants is 0, not > 0");
  // Without it the face term is open: closed has no literal-and-negation rule.
  Json dropped = cert("closed", false, false, false, dangling_pairs);
  dropped["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"].erase(0);
  expect_rejected(verify(dangling_scene, dropped), leaf, "[-1,0,0,0,1] (A), [1,0,0,0,-1] (A)");
  // Regularised has it: the face term is closed off by 1 - x and x - 1.
  dropped["semantics"] = "regularised";
  BOOST_TEST(verify(dangling_scene, dropped).ok);
}

// B = [2,3]x[0,1]^2 moves at -1 in x from 0 on, time [0,1]: its 2 - x
// becomes -x - t + 2 < 0. Split on t - 1/2: below, x - 1 (A), -x - t + 2 (B)
// and the path's 2t - 1, lambda 1, 1, 1/2: constants -1 + 2 - 1/2 >= 0.
// Above (1 - 2t < 0): the slab's t - 1 with lambda 1: constants 0 >= 0.
const std::string split_scene =
    scene(block("A", "[0,0,0]", "[1,1,1]") + "," + block("B", "[2,0,0]", "[3,1,1]", "rest until 0 vel -1 0 0"), "[0,1]");
const std::string split_pairs = R"([{"objects":["A","B"],"collide":false,"apart":{"until":"1","pieces":[
  {"t":["0","1"],"proof":{"split":["0","0","0","2","-1"],
    "below":{"conflicts":[{"literals":[["1","0","0","0","-1"],["-1","0","0","-1","2"],["0","0","0","2","-1"]],"lambda":["1","1","1/2"]}]},
    "above":{"conflicts":[{"literals":[["1","0","0","0","-1"],["-1","0","0","-1","2"],["0","0","0","1","-1"]],"lambda":["1","1","1"]}]}}}]}}])";

BOOST_AUTO_TEST_CASE(a_split_node)
{
  expect_ok(verify(split_scene, cert("regularised", false, false, false, split_pairs, R"(["0","1"])")),
            "verified: no collision in [0, 1] (regularised): 1 pair apart");
  // Above may not use the below side's 2t - 1.
  Json wrong = cert("regularised", false, false, false, split_pairs, R"(["0","1"])");
  wrong["pairs"][0]["apart"]["pieces"][0]["proof"]["above"] = wrong["pairs"][0]["apart"]["pieces"][0]["proof"]["below"];
  expect_rejected(verify(split_scene, wrong), leaf + ".above", "no conflict closes off the term");
  // A split on a constant would make both sides empty.
  wrong = cert("regularised", false, false, false, split_pairs, R"(["0","1"])");
  wrong["pairs"][0]["apart"]["pieces"][0]["proof"]["split"] = {"0", "0", "0", "0", "1"};
  expect_rejected(verify(split_scene, wrong), leaf + ".split", "non-zero coefficient");
}

// rotate (1,0,0,1) is a quarter turn about z (n = 2, R = [[0,-1,0],[1,0,0],
// [0,0,1]]): [0,2]x[0,1]^2 becomes [-1,0]x[0,2]x[0,1], whose atom x <= 0 is
// the image of -y <= 0. B = [1/2,1]x[0,1]^2: x < 0 (A) and 1 - 2x < 0 (B),
// lambda 2, 1: constants 1 >= 0. The transposed rotation would put A at
// x in [0,1] and have no atom x.
BOOST_AUTO_TEST_CASE(a_rotated_solid)
{
  std::string s = scene(R"({"name":"A","shape":{"rotate":[1,0,0,1],"solid":{"block":{"min":[0,0,0],"max":[2,1,1]}}}},)" +
                        block("B", "[0.5,0,0]", "[1,1,1]"));
  std::string pairs = R"([{"objects":["A","B"],"collide":false,"apart":{"until":"10","pieces":[
    {"t":["0","10"],"proof":{"conflicts":[{"literals":[["1","0","0","0","0"],["-2","0","0","0","1"]],"lambda":["2","1"]}]}}]}}])";
  expect_ok(verify(s, cert("regularised", false, false, false, pairs)), "verified: no collision in [0, 10] (regularised): 1 pair apart");
  // (-1/2, 3/2, 1/2, 1) is inside the turned A (and in C = [-1,0]x[1,2]x[0,1]).
  std::string s2 = scene(R"({"name":"A","shape":{"rotate":[1,0,0,1],"solid":{"block":{"min":[0,0,0],"max":[2,1,1]}}}},)" +
                         block("C", "[-1,1,0]", "[0,2,1]"));
  expect_ok(verify(s2, cert("regularised", true, false, false, R"([{"objects":["A","C"],"collide":true,"witness":["-1/2","3/2","1/2","1"]}])")),
            "verified: collision (regularised): A and C at (-1/2, 3/2, 1/2, 1)");
}

// hull of the corner tetrahedron plus a point inside and one on the face
// z = 0 (that plane is found by several triples, one atom). Its atom
// x + y + z - 1 and B = [1,2]^3's 1 - x, 1 - y, 1 - z, lambda 1 each:
// constants -1 + 3 = 2 >= 0.
BOOST_AUTO_TEST_CASE(a_hull)
{
  std::string s = scene(R"({"name":"A","shape":{"hull":[[0,0,0],[1,0,0],[0,1,0],[0,0,1],[0.1,0.1,0.1],[0.5,0.25,0]]}},)" +
                        block("B", "[1,1,1]", "[2,2,2]"));
  std::string pairs = R"([{"objects":["A","B"],"collide":false,"apart":{"until":"10","pieces":[
    {"t":["0","10"],"proof":{"conflicts":[{"literals":[["1","1","1","0","-1"],["-1","0","0","0","1"],["0","-1","0","0","1"],["0","0","-1","0","1"]],
     "lambda":["1","1","1","1"]}]}}]}}])";
  expect_ok(verify(s, cert("regularised", false, false, false, pairs)), "verified: no collision in [0, 10] (regularised): 1 pair apart");
  // A witness on the hull's far side of x + y + z = 1 is outside it.
  std::string s2 = scene(R"({"name":"A","shape":{"hull":[[0,0,0],[1,0,0],[0,1,0],[0,0,1]]}},)" + block("B", "[0,0,0]", "[1,1,1]"));
  expect_rejected(verify(s2, cert("regularised", true, false, false, R"([{"objects":["A","B"],"collide":true,"witness":["1/2","1/2","1/4","1"]}])")),
                  "pairs[0].witness", "not strictly inside A");
}

// B = [3,4]x[0,1]^2, velocity -1/2 in x until 2, then +1: D = -t/2, then
// t - 3 (D(2) = -1 either way). Its 3 - x is -x - t/2 + 3 before 2 (coprime
// [-2,0,0,-1,6]) and -x + t after. [0,2]: x - 1, -2x - t + 6, t - 2 with
// lambda 2, 1, 1: constants -2 + 6 - 2 = 2. [2,4]: x - 1, t - x, 2 - t
// with lambda 1, 1, 1: constants 1.
const std::string turn_scene =
    scene(block("A", "[0,0,0]", "[1,1,1]") + "," + block("B", "[3,0,0]", "[4,1,1]", "vel -1/2 0 0 until 2 vel 1 0 0"), "[0,4]");
const std::string turn_pairs = R"([{"objects":["A","B"],"collide":false,"apart":{"until":"4","pieces":[
  {"t":["0","2"],"proof":{"conflicts":[{"literals":[["1","0","0","0","-1"],["-2","0","0","-1","6"],["0","0","0","1","-2"]],"lambda":["2","1","1"]}]}},
  {"t":["2","4"],"proof":{"conflicts":[{"literals":[["1","0","0","0","-1"],["-1","0","0","1","0"],["0","0","0","-1","2"]],"lambda":["1","1","1"]}]}}]}}])";

BOOST_AUTO_TEST_CASE(a_velocity_change_splits_the_pieces)
{
  expect_ok(verify(turn_scene, cert("regularised", false, false, false, turn_pairs, R"(["0","4"])")),
            "verified: no collision in [0, 4] (regularised): 1 pair apart");
  Json moved = cert("regularised", false, false, false, turn_pairs, R"(["0","4"])");
  moved["pairs"][0]["apart"]["pieces"][0]["t"][1] = "3";
  moved["pairs"][0]["apart"]["pieces"][1]["t"][0] = "3";
  expect_rejected(verify(turn_scene, moved), "pairs[0].apart.pieces[0].t", "a velocity change of B lies inside the piece");
  Json dropped = cert("regularised", false, false, false, turn_pairs, R"(["0","4"])");
  dropped["pairs"][0]["apart"]["pieces"].erase(0);
  expect_rejected(verify(turn_scene, dropped), "pairs[0].apart.pieces[0].t[0]", "the piece starts at 2, not at 0 (tL)");
}

// Three objects, all pairs: A and B overlap, C far away (x - 1 < 0 from A,
// 5 - x from C; 4 - x from B... B = [1/2,3/2]: x - 3/2 and 5 - x, lambda 2, 2).
BOOST_AUTO_TEST_CASE(all_pairs)
{
  std::string s = scene(block("A", "[0,0,0]", "[1,1,1]") + "," + block("B", "[0.5,0,0]", "[1.5,1,1]") + "," +
                        block("C", "[5,0,0]", "[6,1,1]"));
  std::string pairs = R"([{"objects":["A","B"],"collide":true,"witness":["3/4","1/2","1/2","5"]},
    {"objects":["A","C"],"collide":false,"apart":{"until":"10","pieces":[{"t":["0","10"],"proof":{"conflicts":[
      {"literals":[["1","0","0","0","-1"],["-1","0","0","0","5"]],"lambda":["1","1"]}]}}]}},
    {"objects":["C","B"],"collide":false,"apart":{"until":"10","pieces":[{"t":["0","10"],"proof":{"conflicts":[
      {"literals":[["-1","0","0","0","5"],["2","0","0","0","-3"]],"lambda":["2","1"]}]}}]}}])";
  expect_ok(verify(s, cert("regularised", true, false, true, pairs)),
            "verified: colliding pairs (regularised): A/B; 2 other pairs apart");
  Json missing = cert("regularised", true, false, true, pairs);
  missing["pairs"].erase(2);
  expect_rejected(verify(s, missing), "pairs", "no PAIR for B/C");
}

// A = [0,1]^3 minus 9 small blocks inside: NOT of each is an OR of 6 atoms,
// 6^9 terms of A, and the one conflict needs B's 2 - x, which comes after
// A's term: no pruning, so the enumeration passes its limit.
BOOST_AUTO_TEST_CASE(the_step_limit)
{
  std::string holes;   // x in [(2i+2)/40, (2i+3)/40]
  for (int i = 0; i < 9; ++i)
    holes += R"(,{"block":{"min":[")" + std::to_string(2 * i + 2) + R"(/40",0.25,0.25],"max":[")" + std::to_string(2 * i + 3) + "/40\",0.75,0.75]}}";
  std::string s = scene(R"({"name":"A","shape":{"difference":[{"block":{"min":[0,0,0],"max":[1,1,1]}})" + holes + "]}}," +
                        block("B", "[2,0,0]", "[3,1,1]"));
  // Nothing is refuted there: the result says it is the limit (check then
  // refuses to write such a certificate as too costly, exit 3).
  expect_rejected(verify(s, cert("regularised", false, false, false, apart_pairs)), leaf, "passed 10,000,000 steps", 1, true);
  // With 5 holes (6^5 terms) the same certificate is proved within the limit.
  std::string five = holes.substr(0, holes.find(",{", holes.find(",{", holes.find(",{", holes.find(",{", holes.find(",{", 1) + 1) + 1) + 1) + 1));
  s = scene(R"({"name":"A","shape":{"difference":[{"block":{"min":[0,0,0],"max":[1,1,1]}})" + five + "]}}," +
            block("B", "[2,0,0]", "[3,1,1]"));
  BOOST_TEST(verify(s, cert("regularised", false, false, false, apart_pairs)).ok);
}

namespace {
std::string file(const std::string& name, const std::string& text)
{
  std::string path = "/tmp/clash4d_test_verify_" + name;
  std::ofstream(path) << text;
  return path;
}
} // namespace

BOOST_AUTO_TEST_CASE(cli_exit_codes)
{
  std::string s = file("scene.json", ram_scene);
  std::string good = cert("regularised", true, true, false, ram_pairs).dump();
  Cli_run r = run_clash4d({"verify", s, file("good.json", good)});
  BOOST_TEST(r.status == 0, r.err);
  BOOST_TEST(r.out == "verified: earliest collision (regularised): box and ram at t* = 2, contact (1, 1/2, 1/2, 2)\n");
  Json bad = cert("regularised", true, true, false, ram_pairs);
  bad["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"][0]["lambda"][1] = "-1";
  std::string bad_file = file("bad.json", bad.dump());
  r = run_clash4d({"verify", s, bad_file});
  BOOST_TEST(r.status == 1);
  BOOST_TEST(r.err == "clash4d verify: " + bad_file + ": " + leaf + ".conflicts[0].lambda[1]: lambda must be positive\n");
  std::string cut = file("cut.json", good.substr(0, good.size() / 2));
  r = run_clash4d({"verify", s, cut});
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.err.find(cut + ": line 1, column ") != std::string::npos, r.err);
  BOOST_TEST(r.err.find("[json.exception.parse_error") != std::string::npos, r.err);
  r = run_clash4d({"verify", s, "/tmp/clash4d_test_verify_no_such_file.json"});
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.err.find("cannot open") != std::string::npos, r.err);
  r = run_clash4d({"verify", file("bad_scene.json", "{\"format\":\"clash4d-scene/1\"}"), cut});
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.err.find("bad_scene.json") != std::string::npos, r.err);
}

// The shared conformance corpus (fixtures/certificates/conformance, issue 59
// items 3, 15, 16): every case's exit code as manifest.json gives it from
// docs/certificate-format.md; tests/python/test_verify_py.py runs it too.
namespace {

const std::string conformance = std::string(CLASH4D_FIXTURES) + "/certificates/conformance/";

// The corpus's manifest, or one of its folders' ("scenes/manifest.json").
Json manifest(const std::string& name = "manifest.json")
{
  std::ifstream in(conformance + name);
  return Json::parse(in);
}

std::string slurp(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A generated case: its base text with the edits, in order.
std::string generated_text(const Json& c)
{
  std::string text = slurp(conformance + c["from"].get<std::string>());
  for (const Json& e : c["edits"]) {
    std::string by = e["prefix"].get<std::string>(), unit = e["unit"].get<std::string>();
    for (int i = 0; i < e["count"].get<int>(); ++i) by += unit;
    by += e["suffix"].get<std::string>();
    std::size_t at = text.find(e["replace"].get<std::string>());
    BOOST_REQUIRE(at != std::string::npos);
    text.replace(at, e["replace"].get<std::string>().size(), by);
  }
  return text;
}

struct Conformance_case {
  std::string name, certificate, why;
  int exit;
};
std::ostream& operator<<(std::ostream& o, const Conformance_case& c) { return o << c.name; }

std::vector<Conformance_case> conformance_cases()
{
  std::vector<Conformance_case> out;
  Json m = manifest();
  for (const Json& c : m["cases"])
    out.push_back({c["certificate"], conformance + c["certificate"].get<std::string>(), c["why"], c["exit"]});
  for (const Json& c : m["generated"]) {
    std::string path = "/tmp/clash4d_test_verify_conformance_" + c["name"].get<std::string>() + ".json";
    std::ofstream(path, std::ios::binary) << generated_text(c);
    out.push_back({c["name"], path, c["why"], c["exit"]});
  }
  return out;
}

} // namespace

BOOST_DATA_TEST_CASE(conformance_corpus, boost::unit_test::data::make(conformance_cases()), c)
{
  std::ostringstream out, err;
  int status = run_verify(conformance + manifest()["scene"].get<std::string>(), c.certificate, 256, out, err);
  BOOST_TEST(status == c.exit, c.name << " (" << c.why << "): " << err.str());
  if (status != 0) BOOST_TEST(err.str().find(c.certificate) != std::string::npos, err.str());
}

// The scene documents of the same corpus (conformance/scenes, issue 59 item
// 15): the C++ scene reader (validate) and the verifier's reading of the
// scene, each with the exit code the manifest gives from
// docs/scene-format.md; the Python verifier's test runs them too.
namespace {

struct Scene_document_case {
  std::string name;
  int validate, verify;
  std::string why;
};
std::ostream& operator<<(std::ostream& o, const Scene_document_case& c) { return o << c.name; }

std::vector<Scene_document_case> scene_document_cases()
{
  Json scenes = manifest("scenes/manifest.json");   // kept: a range over a temporary's member would dangle
  std::vector<Scene_document_case> out;
  for (const Json& c : scenes["cases"]) out.push_back({c["scene"], c["validate"], c["verify"], c["why"]});
  return out;
}

} // namespace

BOOST_DATA_TEST_CASE(conformance_scene_documents, boost::unit_test::data::make(scene_document_cases()), c)
{
  std::string scene = conformance + "scenes/" + c.name;
  Cli_run v = run_clash4d({"validate", scene});
  BOOST_TEST(v.status == c.validate, c.name << " (" << c.why << "): " << v.err);
  std::ostringstream out, err;
  int status = run_verify(scene, conformance + "valid.json", 256, out, err);
  BOOST_TEST(status == c.verify, c.name << " (" << c.why << "): " << err.str());
}

// Issue 59 item 4: a 300-point hull on a cube's faces (gift wrapping, not
// the O(n^4) triples) and a 9,999-segment motion (binary search per piece)
// verify within the suite's ordinary time. Hull x - 1000 and the block's
// 1500 - x, lambda 1 and 1: constants 500 >= 0.
BOOST_AUTO_TEST_CASE(a_hull_of_300_points_and_a_long_motion)
{
  unsigned seed = 59;
  BOOST_TEST_MESSAGE("seed " << seed);
  std::mt19937 rnd(seed);
  std::string pts = "[0,0,0],[0,0,1000],[0,1000,0],[0,1000,1000],[1000,0,0],[1000,0,1000],[1000,1000,0],[1000,1000,1000]";
  for (int i = 8; i < 300; ++i) {
    int c[3] = {int(rnd() % 1001), int(rnd() % 1001), int(rnd() % 1001)};
    c[i % 3] = rnd() % 2 ? 1000 : 0;
    pts += ",[" + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]) + "]";
  }
  std::string s = scene(R"({"name":"A","shape":{"hull":[)" + pts + "]}}," + block("B", "[1500,0,0]", "[1600,100,100]"));
  std::string pairs = R"([{"objects":["A","B"],"collide":false,"apart":{"until":"10","pieces":[
    {"t":["0","10"],"proof":{"conflicts":[{"literals":[["1","0","0","0","-1000"],["-1","0","0","0","1500"]],"lambda":["1","1"]}]}}]}}])";
  expect_ok(verify(s, cert("regularised", false, false, false, pairs)), "verified: no collision in [0, 10] (regularised): 1 pair apart");

  std::string motion, pieces;
  for (int k = 1; k <= 9999; ++k) motion += "vel 0 0 0 until " + std::to_string(k) + "/1000 ";
  std::string cuts_prev = "0";
  for (int k = 1; k <= 10000; ++k) {
    std::string cut = k == 10000 ? "10" : std::to_string(k) + "/1000";
    pieces += std::string(k > 1 ? "," : "") + R"({"t":[")" + cuts_prev + R"(",")" + cut +
              R"("],"proof":{"conflicts":[{"literals":[["1","0","0","0","-1"],["-1","0","0","0","2"]],"lambda":["1","1"]}]}})";
    cuts_prev = cut;
  }
  std::string long_scene = scene(block("A", "[0,0,0]", "[1,1,1]") + "," + block("B", "[2,0,0]", "[3,1,1]", (motion + "vel 0 0 0").c_str()));
  expect_ok(verify(long_scene, cert("regularised", false, false, false,
                                    R"([{"objects":["A","B"],"collide":false,"apart":{"until":"10","pieces":[)" + pieces + "]}}]")),
            "verified: no collision in [0, 10] (regularised): 1 pair apart");
}
