#define BOOST_TEST_MODULE extrusion
#include <boost/test/unit_test.hpp>

#include "exact/Exact_instantiation.h"
#include "float/Double_instantiation.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include <set>

using namespace clash4d;
using json = nlohmann::ordered_json;

// Paper §3: the block -1 <= x,y,z <= 1 moving with velocity (1,1,1) for
// 0 <= t <= 10 and at rest otherwise (span [-5, 15] so all three parts show).
static const char* section3 = R"({"format":"clash4d-scene/1","time":[-5,15],"objects":[
  {"name":"block","shape":{"block":{"min":[-1,-1,-1],"max":[1,1,1]}},"motion":"rest until 0 vel 1 1 1 until 10 rest"},
  {"name":"far","shape":{"block":{"min":[100,100,100],"max":[101,101,101]}}}]})";

static std::set<std::string> halfspaces_of(const json& object)
{
  std::set<std::string> out;
  const json& parts = object["tree"]["intersection"];
  for (const auto& h : parts[0]["halfspaces"]) out.insert(h["text"].get<std::string>());
  for (const auto& h : parts[1]["time"]) out.insert(h["text"].get<std::string>());
  return out;
}

BOOST_AUTO_TEST_CASE(paper_section3_block)
{
  Scene scene = read_scene(read_json_text(section3));
  for (bool exact : {true, false}) {
    json r = exact ? extrude_exact(scene) : extrude_double(scene);
    BOOST_TEST_REQUIRE(r["spans"].size() == 3u);
    // 1. -1 <= x,y,z <= 1 and t <= 0 (and the span's t >= -5).
    std::set<std::string> rest0{"-x - 1 <= 0", "x - 1 <= 0", "-y - 1 <= 0", "y - 1 <= 0", "-z - 1 <= 0", "z - 1 <= 0",
                                "-t - 5 <= 0", "t <= 0"};
    // 2. t - 1 <= x,y,z <= t + 1, t >= 0 and t <= 10.
    std::set<std::string> moving{"-x + t - 1 <= 0", "x - t - 1 <= 0", "-y + t - 1 <= 0", "y - t - 1 <= 0",
                                 "-z + t - 1 <= 0", "z - t - 1 <= 0", "-t <= 0", "t - 10 <= 0"};
    // 3. 9 <= x,y,z <= 11 and t >= 10 (and t <= 15).
    std::set<std::string> rest1{"-x + 9 <= 0", "x - 11 <= 0", "-y + 9 <= 0", "y - 11 <= 0", "-z + 9 <= 0", "z - 11 <= 0",
                                "-t + 10 <= 0", "t - 15 <= 0"};
    BOOST_TEST(halfspaces_of(r["spans"][0]["objects"][0]) == rest0);
    BOOST_TEST(halfspaces_of(r["spans"][1]["objects"][0]) == moving);
    BOOST_TEST(halfspaces_of(r["spans"][2]["objects"][0]) == rest1);
    BOOST_TEST(r["spans"][1]["objects"][0]["velocity"] == json::array({"1", "1", "1"}));
  }
}

BOOST_AUTO_TEST_CASE(spans_split_at_every_velocity_change_of_any_object)
{
  Scene scene = read_scene(read_json_text(R"({"format":"clash4d-scene/1","time":[0,10],"objects":[
    {"name":"a","shape":{"block":{"min":[0,0,0],"max":[1,1,1]}},"motion":"vel 1 0 0 until 2 rest until 20 vel 1 1 1"},
    {"name":"b","shape":{"block":{"min":[5,0,0],"max":[6,1,1]}},"motion":"rest until 0 vel 0 1 0 until 3/2 rest"}]})"));
  json r = extrude_exact(scene);
  // Breakpoints inside (0, 10): 3/2 and 2; 0 and 20 are not inside.
  BOOST_TEST_REQUIRE(r["spans"].size() == 3u);
  BOOST_TEST(r["spans"][0]["t"] == json::array({"0", "3/2"}));
  BOOST_TEST(r["spans"][1]["t"] == json::array({"3/2", "2"}));
  BOOST_TEST(r["spans"][2]["t"] == json::array({"2", "10"}));
  // b on [3/2, 2] is at rest displaced by (0, 3/2, 0): y >= 3/2 + 0.
  std::set<std::string> b_mid = halfspaces_of(r["spans"][1]["objects"][1]);
  BOOST_TEST(b_mid.count("-y + 3/2 <= 0") == 1u);
  BOOST_TEST(b_mid.count("y - 5/2 <= 0") == 1u);
}

BOOST_AUTO_TEST_CASE(rotated_plane_extrudes_with_n_dot_v)
{
  // The half-space x + y <= 1 moving with v = (2, 3, 0): x + y - 5 t - 1 <= 0.
  Scene scene = read_scene(read_json_text(R"({"format":"clash4d-scene/1","time":[0,1],"objects":[
    {"name":"a","shape":{"halfspace":[1,1,0,-1]},"motion":"vel 2 3 0"},
    {"name":"b","shape":{"block":{"min":[5,0,0],"max":[6,1,1]}}}]})"));
  json r = extrude_exact(scene);
  std::set<std::string> a = halfspaces_of(r["spans"][0]["objects"][0]);
  BOOST_TEST(a.count("x + y - 5*t - 1 <= 0") == 1u);
}
