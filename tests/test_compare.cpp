#define BOOST_TEST_MODULE compare
#include <boost/test/unit_test.hpp>

#include "compare/Comparer.h"
#include "scene/Input_error.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include <filesystem>

using namespace clash4d;
using json = nlohmann::ordered_json;

static json compare_fixture(const std::string& entry, bool earliest = false)
{
  Compare_options o;
  o.earliest = earliest;
  return compare_scene(read_scene_file(std::string(CLASH4D_FIXTURES) + "/" + entry), entry, o).to_json();
}

static const json& subject(const json& c, const std::string& name)
{
  for (const auto& s : c["subjects"])
    if (s["subject"] == name) return s;
  BOOST_FAIL("no subject " << name);
  return c;
}

BOOST_AUTO_TEST_CASE(decimal_sums_that_miss_are_input_rounding)
{
  // 0.1 + 0.2 > 0.3 in doubles: the rounded scene itself overlaps.
  json c = compare_fixture("contact/sliding_contact_decimal.json");
  BOOST_TEST(subject(c, "exact")["collide"] == false);
  BOOST_TEST(subject(c, "exact-rounded")["collide"] == true);
  BOOST_TEST(subject(c, "exact-rounded")["cause"] == "input rounding");
  BOOST_TEST(subject(c, "double")["collide"] == true);
  BOOST_TEST(subject(c, "double")["cause"] == "input rounding");
}

BOOST_AUTO_TEST_CASE(integer_contact_is_agreed_by_everyone)
{
  // Integers are exact in doubles and every sum here is too.
  json c = compare_fixture("contact/face_touch_static.json");
  BOOST_TEST(c["disagreements"].empty());
  for (const auto& s : c["subjects"]) BOOST_TEST(s["collide"] == false);
}

// Each cause as defined in compare/Comparer.h, checked on every fixture.
BOOST_AUTO_TEST_CASE(causes_follow_their_definitions_on_all_fixtures)
{
  std::size_t disagreements = 0;
  for (const char* family : {"contact", "paper"})
    for (const auto& f : std::filesystem::directory_iterator(std::string(CLASH4D_FIXTURES) + "/" + family)) {
      std::string name = f.path().filename().string();
      if (name == "expected.json" || name.find("skewed") != std::string::npos) continue;   // skewed: slow exact run
      json c = compare_fixture(std::string(family) + "/" + name, true);
      const json& exact = subject(c, "exact");
      BOOST_TEST(exact["agrees"] == true);
      if (exact["collide"] == true) BOOST_TEST(exact["witness_valid"] == true, name);
      const json& rounded = subject(c, "exact-rounded");
      for (const auto& s : c["subjects"]) {
        if (s["cause"].is_null()) continue;
        ++disagreements;
        std::string cause = s["cause"];
        if (cause == "invalid witness") {
          BOOST_TEST(s["collide"] == exact["collide"], name);
          BOOST_TEST(s["witness_valid"] == false, name);
        } else {
          BOOST_TEST(s["collide"] != exact["collide"], name);
        }
        if (cause == "input rounding") BOOST_TEST((rounded["ok"] == false || rounded["collide"] != exact["collide"]), name);
        if (cause == "contact") BOOST_TEST(c["near_contact"] == true, name);
        if (cause == "arithmetic") {
          BOOST_TEST(rounded["collide"] == exact["collide"], name);
          BOOST_TEST(c["near_contact"] == false, name);
        }
      }
      BOOST_TEST(c["disagreements"].size() <= c["subjects"].size() - 1);
    }
  BOOST_TEST(disagreements > 0u);   // the fixtures do make float code err
}

BOOST_AUTO_TEST_CASE(rounding_can_make_a_scene_invalid)
{
  Scene s = read_scene(read_json_text(R"({"format":"clash4d-scene/1","time":[0,1],"objects":[
    {"name":"thin","shape":{"block":{"min":[1,0,0],"max":["1.00000000000000000001",1,1]}}},
    {"name":"b","shape":{"block":{"min":[0,0,0],"max":[2,1,1]}}}]})"));
  BOOST_CHECK_THROW(rounded_scene(s), Input_error);
  json c = compare_scene(s, "thin", Compare_options()).to_json();
  BOOST_TEST(subject(c, "exact")["collide"] == true);
  BOOST_TEST(subject(c, "exact-rounded")["ok"] == false);
  BOOST_TEST(subject(c, "exact-rounded")["error"].get<std::string>().find("min must be less than max") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(earliest_error_is_reported_for_double)
{
  // t* = 1.99999999 exactly; the double run computes it with rounding error.
  json c = compare_fixture("contact/approach_stop_decimal_overlap_1e-9.json", true);
  BOOST_TEST(subject(c, "exact")["earliest"]["t"] == "199999999/100000000");
  BOOST_TEST(subject(c, "exact")["t_error"] == "0.000e+00");
  BOOST_TEST(!subject(c, "double")["t_error"].is_null());
}
