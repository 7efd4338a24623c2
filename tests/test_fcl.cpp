#define BOOST_TEST_MODULE fcl
#include <boost/test/unit_test.hpp>

#include "cli/Commands.h"
#include "compare/Comparer.h"
#include "compare/Fcl_subject.h"
#include "compare/Fuzz_campaign.h"
#include "compare/Report_writer.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace clash4d;
using json = nlohmann::ordered_json;
namespace fs = std::filesystem;

// Only built with FCL (tests/CMakeLists.txt); without it the subject is
// skipped as "fcl: not built in" and this suite does not exist.

static Scene fixture(const std::string& entry) { return read_scene_file(std::string(CLASH4D_FIXTURES) + "/" + entry); }
static Scene scene_text(const std::string& text) { return read_scene(read_json_text(text)); }

static json compare_with_fcl(const Scene& scene, const std::string& name, bool earliest = true)
{
  Compare_options o;
  o.fcl = true;
  o.earliest = earliest;
  return compare_scene(scene, name, o).to_json();
}

static const json& subject(const json& c, const std::string& name)
{
  for (const auto& s : c["subjects"])
    if (s["subject"] == name) return s;
  BOOST_FAIL("no subject " << name);
  return c;
}

static bool disagrees_as(const json& c, const std::string& subject_name, const std::string& cause)
{
  for (const auto& d : c["disagreements"])
    if (d["subject"] == subject_name && d["cause"] == cause) return true;
  return false;
}

static bool fcl_disagrees(const json& c)
{
  for (const auto& d : c["disagreements"])
    if (d["subject"] == "fcl") return true;
  return false;
}

// FCL's conservative advancement stops once its next safe step is below
// 1e-4 of the span; when the objects close head-on at the speed it bounds
// with, the time left is below that, so t* is within 1e-4 (tH - tL).
static double fcl_t_star(const json& c) { return std::stod(subject(c, "fcl")["earliest"]["t"].get<std::string>()); }

BOOST_AUTO_TEST_CASE(built_in)
{
  BOOST_TEST(Fcl_subject::built_in());
}

// ------------------------------------------------------------------ clear cases: FCL agrees with exact

BOOST_AUTO_TEST_CASE(clear_collision_head_on_agrees)
{
  // a's x max 1 + t meets b's x min 5 - t at t = 2 (y, z equal), then they
  // overlap: a collision with t* = 2 (fixtures/contact/expected.json).
  json c = compare_with_fcl(fixture("contact/clear_collision_head_on.json"), "head-on");
  const json& f = subject(c, "fcl");
  BOOST_TEST(f["skipped"].is_null());
  BOOST_TEST(f["collide"] == true);
  BOOST_TEST(f["agrees"] == true);
  BOOST_TEST(f["witness"]["objects"] == json::array({"a", "b"}));
  BOOST_TEST(f["witness"]["point"].is_null());      // FCL gives no point inside both
  BOOST_TEST(f["witness_valid"].is_null());
  BOOST_TEST(std::abs(fcl_t_star(c) - 2) <= 1e-4 * 10);
  BOOST_TEST(!fcl_disagrees(c));
}

BOOST_AUTO_TEST_CASE(time_of_contact_is_a_fraction_of_the_span)
{
  // The same scene: contact at t = 2 of [0, 10] is 1/5 of the way.
  Fcl_subject fcl(fixture("contact/clear_collision_head_on.json"));
  BOOST_TEST_REQUIRE(fcl.expressible());
  std::optional<double> toc = fcl.time_of_contact(0, 1);
  BOOST_TEST_REQUIRE(toc.has_value());
  BOOST_TEST(std::abs(*toc - 0.2) <= 1e-4);
}

BOOST_AUTO_TEST_CASE(clear_miss_agrees)
{
  // a has y in [0, 1] and b y in [2, 3] at all times: 1 apart, no collision,
  // and not near contact either, so FCL's tolerances do not matter.
  json c = compare_with_fcl(fixture("contact/clear_miss_parallel.json"), "miss");
  BOOST_TEST(subject(c, "exact")["collide"] == false);
  BOOST_TEST(subject(c, "fcl")["collide"] == false);
  BOOST_TEST(subject(c, "fcl")["agrees"] == true);
  BOOST_TEST(!fcl_disagrees(c));
}

BOOST_AUTO_TEST_CASE(penetrating_hulls_agree)
{
  // Two octahedra |x| + |y| + |z| <= 1 as hulls of their 6 vertices, b's
  // centre at (5 - t, 0, 0): the x extents [-1, 1] and [4 - t, 6 - t]
  // overlap for t > 3, and then the segment between the centres lies in both
  // interiors near its middle, so they collide with t* = 3 (vertex meets
  // vertex at t = 3), and b goes right through a.
  const std::string octahedron = "{\"hull\":[[1,0,0],[-1,0,0],[0,1,0],[0,-1,0],[0,0,1],[0,0,-1]]}";
  Scene s = scene_text("{\"format\":\"clash4d-scene/1\",\"time\":[0,10],\"objects\":["
                       "{\"name\":\"a\",\"shape\":" + octahedron + "},"
                       "{\"name\":\"b\",\"shape\":{\"translate\":[5,0,0],\"solid\":" + octahedron + "},\"motion\":\"vel -1 0 0\"}]}");
  json c = compare_with_fcl(s, "octahedra");
  BOOST_TEST(subject(c, "exact")["collide"] == true);
  BOOST_TEST(subject(c, "exact")["earliest"]["t"] == "3");
  BOOST_TEST(subject(c, "fcl")["collide"] == true);
  BOOST_TEST(subject(c, "fcl")["agrees"] == true);
  BOOST_TEST(std::abs(fcl_t_star(c) - 3) <= 1e-4 * 10);
}

BOOST_AUTO_TEST_CASE(hulls_overlapping_from_the_start_agree)
{
  // The cube [1/4, 3/4]^3 (a hull of its 8 corners) and the tetrahedron
  // x, y, z >= 0, x + y + z <= 2, at rest: the cube's centre (1/2, 1/2, 1/2)
  // has coordinate sum 3/2 < 2 and is strictly inside both, so they collide
  // from the start, t* = tL = 0.
  const std::string cube = "{\"hull\":[[\"1/4\",\"1/4\",\"1/4\"],[\"3/4\",\"1/4\",\"1/4\"],[\"1/4\",\"3/4\",\"1/4\"],"
                           "[\"3/4\",\"3/4\",\"1/4\"],[\"1/4\",\"1/4\",\"3/4\"],[\"3/4\",\"1/4\",\"3/4\"],"
                           "[\"1/4\",\"3/4\",\"3/4\"],[\"3/4\",\"3/4\",\"3/4\"]]}";
  Scene s = scene_text("{\"format\":\"clash4d-scene/1\",\"time\":[0,1],\"objects\":["
                       "{\"name\":\"tet\",\"shape\":{\"hull\":[[0,0,0],[2,0,0],[0,2,0],[0,0,2]]}},"
                       "{\"name\":\"cube\",\"shape\":" + cube + "}]}");
  json c = compare_with_fcl(s, "overlapping");
  BOOST_TEST(subject(c, "exact")["collide"] == true);
  BOOST_TEST(subject(c, "fcl")["collide"] == true);
  BOOST_TEST(subject(c, "fcl")["earliest"]["t"] == "0");
  BOOST_TEST(subject(c, "fcl")["agrees"] == true);
}

BOOST_AUTO_TEST_CASE(rotated_and_translated_pieces_are_placed_exactly)
{
  // The block [0,2] x [0,1] x [0,1] rotated by the quaternion (1,0,0,1)
  // (a quarter turn about z: (x, y) -> (-y, x)) occupies [-1,0] x [0,2] x
  // [0,1]; translated by (3,0,0) it is [2,3] x [0,2] x [0,1]. The unit
  // block at (1/2, 1/2, 0) moving +x at speed 1 reaches x = 2 with its face
  // x max = 3/2 + t at t = 1/2: collision, t* = 1/2. Unrotated, the block
  // would be [3,5] x [0,1] x [0,1] and met at t = 3/2, so the rotation shows.
  Scene s = scene_text("{\"format\":\"clash4d-scene/1\",\"time\":[0,10],\"objects\":["
                       "{\"name\":\"wall\",\"shape\":{\"translate\":[3,0,0],\"solid\":{\"rotate\":[1,0,0,1],\"solid\":"
                       "{\"block\":{\"min\":[0,0,0],\"max\":[2,1,1]}}}}},"
                       "{\"name\":\"ram\",\"shape\":{\"block\":{\"min\":[\"1/2\",\"1/2\",0],\"max\":[\"3/2\",\"3/2\",1]}},"
                       "\"motion\":\"vel 1 0 0\"}]}");
  json c = compare_with_fcl(s, "rotated");
  BOOST_TEST(subject(c, "exact")["earliest"]["t"] == "1/2");
  BOOST_TEST(subject(c, "fcl")["agrees"] == true);
  BOOST_TEST(std::abs(fcl_t_star(c) - 0.5) <= 1e-4 * 10);
}

BOOST_AUTO_TEST_CASE(union_pieces_and_ignored_pairs)
{
  // Three objects: u is the union of [0,1]^3 and [1,2] x [0,1] x [0,1]
  // (the bar [0,2] x [0,1] x [0,1] in two pieces); v = [3/2, 5/2] x
  // [0,1] x [0,1] overlaps u's second piece at rest; w overlaps v at rest but
  // the pair (v, w) is ignored. So only (u, v) collides (spec: ignored pairs
  // are never tested), and FCL must find it through u's second piece.
  Scene s = scene_text("{\"format\":\"clash4d-scene/1\",\"time\":[0,1],\"objects\":["
                       "{\"name\":\"u\",\"shape\":{\"union\":[{\"block\":{\"min\":[0,0,0],\"max\":[1,1,1]}},"
                       "{\"block\":{\"min\":[1,0,0],\"max\":[2,1,1]}}]}},"
                       "{\"name\":\"v\",\"shape\":{\"block\":{\"min\":[\"3/2\",0,0],\"max\":[\"5/2\",1,1]}}},"
                       "{\"name\":\"w\",\"shape\":{\"block\":{\"min\":[\"5/2\",\"1/2\",0],\"max\":[3,1,1]}}}],"
                       "\"ignore\":[[\"v\",\"w\"]]}");
  Fcl_subject fcl(s);
  BOOST_TEST_REQUIRE(fcl.expressible());
  Check_options all;
  all.all_pairs = true;
  Check_answer a = fcl.check(all);
  BOOST_TEST_REQUIRE(a.pairs.size() == 1u);
  BOOST_TEST(a.pairs[0].a == "u");
  BOOST_TEST(a.pairs[0].b == "v");
  BOOST_TEST(!fcl.time_of_contact(0, 2).has_value());   // u = [0,2] and w = [5/2,3] in x: 1/2 apart
}

// ------------------------------------------------------------------ touching: right in FCL's own terms

BOOST_AUTO_TEST_CASE(face_touch_is_an_agreement_in_closed_semantics)
{
  // The tetrahedron x + y + z <= 1 (and x, y, z >= 0) and the cap over its
  // face share exactly that face: the closed sets meet, the interiors do
  // not (fixtures/contact/expected.json, both semantics). FCL decides
  // closed sets and reports the contact as a collision: right in its own
  // terms (issue 14), so no disagreement.
  json c = compare_with_fcl(fixture("contact/hull_face_touch.json"), "face");
  BOOST_TEST(subject(c, "exact")["collide"] == false);
  BOOST_TEST(subject(c, "exact closed")["collide"] == true);
  BOOST_TEST(c["closed_touch"] == true);
  BOOST_TEST(subject(c, "fcl")["semantics"] == "closed");
  BOOST_TEST(subject(c, "fcl")["collide"] == true);
  BOOST_TEST(subject(c, "fcl")["agrees"] == true);
  BOOST_TEST(!fcl_disagrees(c));
}

BOOST_AUTO_TEST_CASE(instant_touch_is_an_agreement_in_closed_semantics)
{
  // a leaves b's column exactly when b arrives in a's row: the closed boxes
  // touch at t = 4 only (fixtures/contact/expected.json: closed first
  // contact 4). FCL's advancement reaches distance zero at t = 4 and stops
  // there; its t* is held against the closed one.
  json c = compare_with_fcl(fixture("contact/crossing_paths_touch_instant.json"), "instant");
  BOOST_TEST(subject(c, "exact")["collide"] == false);
  BOOST_TEST(subject(c, "exact closed")["earliest"]["t"] == "4");
  BOOST_TEST(subject(c, "fcl")["collide"] == true);
  BOOST_TEST(!fcl_disagrees(c));
  BOOST_TEST(std::abs(fcl_t_star(c) - 4) <= 1e-4 * 10);
  BOOST_TEST(std::stod(subject(c, "fcl")["t_error"].get<std::string>()) <= 1e-3);
}

BOOST_AUTO_TEST_CASE(found_fixtures_are_judged_in_fcls_terms)
{
  // fixtures/found/ holds FCL's disagreements found by the fuzzer (README
  // there) when they were judged in regularised terms. Judged in FCL's own
  // (closed) terms against the hand-derived closed verdict of expected.json:
  // where FCL's answer is that verdict it agrees; where not, the cause is
  // contact only on a scene of touching only, else arithmetic. The two real
  // errors, a near miss reported as a collision and a shallow overlap
  // missed, are observations of FCL 0.7 (Debian's) that stay findings.
  std::ifstream in(std::string(CLASH4D_FIXTURES) + "/found/expected.json");
  json expected = json::parse(in);
  BOOST_TEST(expected.size() >= 2u);
  for (const auto& item : expected.items()) {
    const std::string& file = item.key();
    bool closed = item.value()["closed"]["collide"], regularised = item.value()["collide"];
    json c = compare_with_fcl(fixture("found/" + file), file, false);
    const json& f = subject(c, "fcl");
    BOOST_TEST_REQUIRE(f["skipped"].is_null(), file);
    BOOST_TEST(subject(c, "exact closed")["collide"] == closed, file);
    if (f["collide"] == closed) {
      BOOST_TEST(f["agrees"] == true, file);
    } else {
      BOOST_TEST(f["cause"] == (!regularised && closed ? "contact" : "arithmetic"), file);
    }
  }
  for (const char* real : {"fcl_contact_near_miss_reported_as_collision.json", "fcl_contact_shallow_overlap_missed.json"}) {
    json c = compare_with_fcl(fixture(std::string("found/") + real), real, false);
    BOOST_TEST(disagrees_as(c, "fcl", "arithmetic"), real);
  }
}

// ------------------------------------------------------------------ scenes FCL cannot express: skipped

static void expect_skipped(const json& c, const std::string& reason)
{
  const json& f = subject(c, "fcl");
  BOOST_TEST_REQUIRE(f["skipped"].is_string());
  BOOST_TEST(f["skipped"].get<std::string>() == reason);
  BOOST_TEST(f["ok"] == true);
  BOOST_TEST(f["collide"].is_null());
  BOOST_TEST(f["agrees"].is_null());
  BOOST_TEST(f["cause"].is_null());
  BOOST_TEST(!fcl_disagrees(c));
}

BOOST_AUTO_TEST_CASE(a_difference_is_skipped)
{
  // Object d of this fixture is {"difference": [...]} at the top.
  expect_skipped(compare_with_fcl(fixture("contact/difference_dangling_face_touch.json"), "difference"),
                 "not expressible by fcl: object 'd' is a difference");
}

BOOST_AUTO_TEST_CASE(a_nested_difference_is_skipped_with_its_place)
{
  // The vehicle of §5 is a union whose tenth member is a difference.
  expect_skipped(compare_with_fcl(fixture("paper/section5_vehicle_trays.json"), "vehicle", false),
                 "not expressible by fcl: object 'vehicle' contains a difference at objects[0].shape.union[9]");
}

BOOST_AUTO_TEST_CASE(two_velocity_segments_are_skipped)
{
  // b's motion is "vel -1 0 0 until 2 rest" over [0, 10]: it stops at t = 2,
  // inside the span, which one FCL translation cannot describe.
  expect_skipped(compare_with_fcl(fixture("contact/approach_stop_at_contact.json"), "stop"),
                 "not expressible by fcl: object 'b' changes velocity at t = 2, inside the span "
                 "(fcl's translation motion has one constant velocity)");
}

BOOST_AUTO_TEST_CASE(a_half_space_is_skipped)
{
  Scene s = scene_text("{\"format\":\"clash4d-scene/1\",\"time\":[0,1],\"objects\":["
                       "{\"name\":\"floor\",\"shape\":{\"halfspace\":[0,0,1,0]}},"
                       "{\"name\":\"box\",\"shape\":{\"block\":{\"min\":[0,0,1],\"max\":[1,1,2]}}}]}");
  expect_skipped(compare_with_fcl(s, "floor"), "not expressible by fcl: object 'floor' is a half-space (unbounded, not a polyhedron)");
}

BOOST_AUTO_TEST_CASE(a_velocity_change_outside_the_span_is_expressible)
{
  // "rest until 0 vel 1 0 0" changes velocity at t = 0 = tL, not inside
  // [0, 10]: on the span it is one segment. a's x max 1 + t reaches b at 5
  // at t = 4: a collision with t* = 4.
  Scene s = scene_text("{\"format\":\"clash4d-scene/1\",\"time\":[0,10],\"objects\":["
                       "{\"name\":\"a\",\"shape\":{\"block\":{\"min\":[0,0,0],\"max\":[1,1,1]}},\"motion\":\"rest until 0 vel 1 0 0\"},"
                       "{\"name\":\"b\",\"shape\":{\"block\":{\"min\":[5,0,0],\"max\":[6,1,1]}}}]}");
  json c = compare_with_fcl(s, "anchored");
  BOOST_TEST(subject(c, "fcl")["skipped"].is_null());
  BOOST_TEST(subject(c, "fcl")["agrees"] == true);
  BOOST_TEST(std::abs(fcl_t_star(c) - 4) <= 1e-4 * 10);
}

// ------------------------------------------------------------------ command line, report, fuzz

static int cli(std::vector<const char*> args, std::string& out_text)
{
  args.insert(args.begin(), "clash4d");
  std::ostringstream out, err;
  int status = run_cli(static_cast<int>(args.size()), args.data(), out, err);
  out_text = out.str() + err.str();
  return status;
}

BOOST_AUTO_TEST_CASE(compare_command_takes_fcl)
{
  std::string out;
  std::string difference = std::string(CLASH4D_FIXTURES) + "/contact/difference_dangling_face_touch.json";
  // Skipped is not a disagreement: every other subject agrees on this fixture.
  BOOST_TEST(cli({"compare", "--fcl", difference.c_str()}, out) == 0);
  BOOST_TEST(out.find("fcl [closed]: skipped: not expressible by fcl: object 'd' is a difference") != std::string::npos, out);
  std::string touch = std::string(CLASH4D_FIXTURES) + "/contact/hull_face_touch.json";
  BOOST_TEST(cli({"compare", "--fcl", touch.c_str()}, out) == 0);
  BOOST_TEST(out.find("fcl [closed]: collision\n") != std::string::npos, out);
  std::string miss = std::string(CLASH4D_FIXTURES) + "/found/fcl_contact_near_miss_reported_as_collision.json";
  BOOST_TEST(cli({"compare", "--fcl", miss.c_str()}, out) == 1);
  BOOST_TEST(out.find("fcl [closed]: collision  <- arithmetic") != std::string::npos, out);
  // Without --fcl there is no fcl subject.
  cli({"compare", touch.c_str()}, out);
  BOOST_TEST(out.find("fcl") == std::string::npos, out);
}

BOOST_AUTO_TEST_CASE(report_counts_skipped_apart)
{
  fs::path dir = fs::temp_directory_path() / ("clash4d_test_fcl_report_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  Scene difference = fixture("contact/difference_dangling_face_touch.json");
  Scene touch = fixture("contact/hull_face_touch.json");
  Scene miss = fixture("found/fcl_contact_near_miss_reported_as_collision.json");
  write_report({{"difference.json", difference, Comparison::from_json(compare_with_fcl(difference, "difference.json")), ""},
                {"touch.json", touch, Comparison::from_json(compare_with_fcl(touch, "touch.json")), ""},
                {"miss.json", miss, Comparison::from_json(compare_with_fcl(miss, "miss.json")), ""}},
               dir.string());
  std::ifstream in(dir / "report.json");
  json r = json::parse(in);
  const json& fcl = r["summary"]["by_subject"]["fcl"];
  BOOST_TEST(fcl["skipped"] == 1);        // the difference
  BOOST_TEST(fcl["answers"] == 2);        // the touch and the near miss, answered
  BOOST_TEST(fcl["disagreements"] == 1);  // the touch agrees in FCL's closed terms, the near miss does not
  BOOST_TEST(fcl["by_cause"]["arithmetic"] == 1);
  std::ifstream junit(dir / "junit.xml");
  std::string x((std::istreambuf_iterator<char>(junit)), std::istreambuf_iterator<char>());
  BOOST_TEST(x.find("<skipped message=\"not expressible by fcl: object &#39;d&#39; is a difference\"/>") != std::string::npos);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(fuzz_campaign_records_fcl)
{
  fs::path dir = fs::temp_directory_path() / ("clash4d_test_fcl_fuzz_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  Fuzz_options o;
  o.seed = 7;
  o.cases = 13;             // one case of each family
  o.out = dir.string();
  o.compare.fcl = true;
  o.max_shrink_checks = 4;  // shrinking has its own tests
  std::ostringstream err;
  run_fuzz(o, err);
  std::ifstream in(dir / "campaign.json");
  BOOST_TEST(json::parse(in)["fcl"] == true);
  // Every saved comparison ran the fcl subject (answered or skipped).
  for (const auto& f : fs::directory_iterator(dir / "findings")) {
    std::ifstream in_finding(f.path());
    json finding = json::parse(in_finding);   // kept: the loop walks inside it
    bool has_fcl = false;
    for (const auto& s : finding["meta"]["comparison"]["subjects"]) has_fcl = has_fcl || s["subject"] == "fcl";
    BOOST_TEST(has_fcl, f.path());
  }
  // The same folder without --fcl is another campaign.
  o.compare.fcl = false;
  BOOST_CHECK_THROW(run_fuzz(o, err), std::runtime_error);
  fs::remove_all(dir);
}

// ------------------------------------------------------------------ turning parts (regularised-semantics fact 13)

// The square turning about its fixed centre by q(t) = (1, 0, 0, t), the
// slab at rest: FCL's screw motion passes through the same orientations at
// constant angular velocity, so its verdict compares exactly and its time
// maps through the change of time. Hand-derived: at FCL's fraction tau the
// angle is tau pi/2; the pose reaches angle 2 atan(s), so s = tan(tau pi/4),
// and the exact t* is (5 - sqrt 14)/11 (fixtures/rotation/expected.json).
BOOST_AUTO_TEST_CASE(a_turn_about_a_fixed_point_is_fcl_s_screw_motion)
{
  Scene scene = fixture("rotation/square_into_slab.json");
  Fcl_subject fcl(scene);
  BOOST_TEST_REQUIRE(fcl.expressible(), fcl.reason());
  BOOST_TEST(fcl.motion_law() == "");
  std::optional<double> toc = fcl.time_of_contact(0, 1);
  BOOST_TEST_REQUIRE(toc.has_value());
  double exact = (5 - std::sqrt(14.0)) / 11;
  BOOST_TEST(std::abs(std::tan(*toc * std::atan(1.0)) - exact) <= 1e-3, "tau " << *toc);
  json c = compare_with_fcl(scene, "square into slab");
  BOOST_TEST(subject(c, "fcl")["collide"] == true);
  BOOST_TEST(std::abs(fcl_t_star(c) - exact) <= 1e-3);   // t* through the change of time
  // The verdicts agree; its t* is farther than the default bound 1e-9 from
  // the exact one (measured about 2e-4): a disagreement in time, nothing else.
  BOOST_TEST(std::abs(fcl_t_star(c) - exact) > 1e-9);
  std::vector<std::string> causes;
  for (const auto& d : c["disagreements"])
    if (d["subject"] == "fcl") causes.push_back(d["cause"]);
  BOOST_TEST(causes == std::vector<std::string>{"time"}, boost::test_tools::per_element());
}

// A block that turns while its centre moves: FCL's screw is another path
// through the configurations, so a differing verdict is the motion law's;
// a pose time inside the span is a second motion, which FCL cannot take.
BOOST_AUTO_TEST_CASE(other_turning_motions_are_named)
{
  Fcl_subject moving(fixture("rotation/touch_at_irrational_time.json"));
  BOOST_TEST_REQUIRE(moving.expressible(), moving.reason());
  BOOST_TEST(moving.motion_law().find("'diamond' turns while its origin moves") != std::string::npos, moving.motion_law());
  Fcl_subject door(fixture("rotation/door_against_stop.json"));
  BOOST_TEST(!door.expressible());
  BOOST_TEST(door.reason().find("has a pose at t = 1, inside the span") != std::string::npos, door.reason());
}
