#define BOOST_TEST_MODULE unbounded
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>

// Pairs whose objects are both unbounded along an axis (issue 16): searched
// within the scene's far bound (model/Far_bound.h, search/Span_region.h).
// The scenes of fixtures/unbounded in every kernel, both semantics, with and
// without --earliest and S-bounds; every witness and contact point checked
// exactly against the hand-derived sets of expected.json, whose rows
// (a, b, c, d, e) stand for a x + b y + c z + d t + e: "inside" < 0 (the
// regularised collision region, its closure with <= 0), closed "le" <= 0
// and "eq" = 0 (the closed objects' common points).

#include "exact/Exact_instantiation.h"
#include "float/Double_instantiation.h"
#include "model/Far_bound.h"
#include "scene/Input_error.h"
#include "scene/Json_reader.h"
#include "scene/Number_text.h"
#include "scene/Scene_reader.h"
#include <fstream>
#include <set>

using namespace clash4d;
namespace data = boost::unit_test::data;
using json = nlohmann::json;

static const std::string folder = std::string(CLASH4D_FIXTURES) + "/unbounded/";

static json manifest()
{
  std::ifstream in(folder + "expected.json");
  return json::parse(in);
}

static std::vector<std::string> entries()
{
  std::vector<std::string> out;
  json m = manifest();
  for (const auto& item : m.items()) out.push_back(item.key());
  return out;
}

enum class Number { exact, rational, double_ };
static const char* name(Number n) { return n == Number::exact ? "exact" : n == Number::rational ? "rational" : "double"; }

static Check_answer run(Number n, const Scene& s, const Check_options& o)
{
  if (n == Number::exact) return check_exact(s, o);
  if (n == Number::rational) return check_rational(s, o);
  return check_double(s, 0, o);
}

// A printed coordinate as the number it stands for: "p/q" exactly, a
// double's shortest decimal as that double's exact value.
static Rational value(const std::string& text, Number n)
{
  if (n == Number::double_) return Rational(std::stod(text));
  Number_parse p = parse_number_text(text, true);
  BOOST_TEST_REQUIRE(p.ok, text);
  return p.value;
}

static Rational row_at(const json& row, const std::array<std::string, 4>& p, Number n)
{
  Rational sum(row[4].get<long>());
  for (int i = 0; i < 4; ++i) sum += Rational(row[i].get<long>()) * value(p[i], n);
  return sum;
}

// sign: -1 every row < 0, 0 every row <= 0; eq rows = 0.
static bool in_set(const json& rows, int strict, const json& eq, const std::array<std::string, 4>& p, Number n)
{
  for (const auto& r : rows)
    if (strict ? !(row_at(r, p, n) < 0) : !(row_at(r, p, n) <= 0)) return false;
  for (const auto& r : eq)
    if (row_at(r, p, n) != 0) return false;
  return true;
}

static std::string text(const std::array<std::string, 4>& p) { return p[0] + " " + p[1] + " " + p[2] + " " + p[3]; }

static void check_regularised(const std::string& entry, const Scene& scene, const json& x, Number n, bool sbounds)
{
  for (bool earliest : {false, true}) {
    Check_options o;
    o.all_pairs = true;
    o.earliest = earliest;
    o.sbounds = sbounds;
    Check_answer a = run(n, scene, o);
    std::string label = entry + " " + name(n) + (earliest ? " --earliest" : "") + (sbounds ? "" : " --no-sbounds");
    BOOST_TEST(a.collide == x["collide"].get<bool>(), label << ": " << x["why"]);
    if (!x["collide"].get<bool>()) continue;
    BOOST_TEST_REQUIRE(a.pairs.size() == x["pairs"].size(), label);
    for (std::size_t i = 0; i < a.pairs.size(); ++i) {
      const Pair_answer& p = a.pairs[i];
      BOOST_TEST(p.a + "/" + p.b == x["pairs"][i].get<std::string>(), label);
      BOOST_TEST(p.witness_verified, label);
      BOOST_TEST(in_set(x["inside"], true, json::array(), p.witness, n), label << ": witness " << text(p.witness));
      if (!earliest) continue;
      BOOST_TEST(value(p.t_star, n) == value(x["earliest"].get<std::string>(), Number::exact), label << ": t* " << p.t_star);
      BOOST_TEST(p.contact[3] == p.t_star, label);
      BOOST_TEST(in_set(x["inside"], false, json::array(), p.contact, n), label << ": contact " << text(p.contact));
      BOOST_TEST(in_set(x["inside"], true, json::array(), p.contact_cells[0], n), label << ": generic " << text(p.contact_cells[0]));
    }
  }
}

static void check_closed(const std::string& entry, const Scene& scene, const json& c, Number n, bool sbounds)
{
  for (bool earliest : {false, true}) {
    Check_options o;
    o.semantics = Semantics::closed;
    o.all_pairs = true;
    o.earliest = earliest;
    o.sbounds = sbounds;
    Check_answer a = run(n, scene, o);
    std::string label = entry + " " + name(n) + " closed" + (earliest ? " --earliest" : "") + (sbounds ? "" : " --no-sbounds");
    BOOST_TEST(a.collide == c["collide"].get<bool>(), label << ": " << c["why"]);
    if (!c["collide"].get<bool>()) continue;
    const json& touch = c["touch"];
    for (const Pair_answer& p : a.pairs) {
      BOOST_TEST(p.witness_verified, label);
      BOOST_TEST(in_set(touch["le"], false, touch["eq"], p.witness, n), label << ": common point " << text(p.witness));
      if (!earliest) continue;
      BOOST_TEST(value(p.t_star, n) == value(c["first_contact"].get<std::string>(), Number::exact), label << ": " << p.t_star);
      BOOST_TEST(p.contact[3] == p.t_star, label);
      BOOST_TEST(in_set(touch["le"], false, touch["eq"], p.contact, n), label << ": contact " << text(p.contact));
    }
  }
}

BOOST_DATA_TEST_CASE(every_kernel_semantics_and_bound_answers_as_derived, data::make(entries()), entry)
{
  json x = manifest()[entry];
  Scene scene = read_scene_file(folder + entry);
  if (x.contains("far_exponent")) BOOST_TEST(far_exponent(scene) == x["far_exponent"].get<int>());
  for (Number n : {Number::exact, Number::rational, Number::double_})
    for (bool sbounds : {true, false}) {
      check_regularised(entry, scene, x, n, sbounds);
      check_closed(entry, scene, x["closed"], n, sbounds);
    }
}

// One half-space in a scene: no pair is unbounded on both sides, no bound.
BOOST_AUTO_TEST_CASE(one_halfspace_needs_no_far_bound)
{
  BOOST_TEST(far_exponent(read_scene_file(std::string(CLASH4D_FIXTURES) + "/contact/halfspace_floor_slide.json")) == -1);
}

static Scene scene_of(const std::string& text) { return read_scene(read_json_text(text)); }

// x <= -2^230 and y <= 0: B = 2^230 + 1, so R = 2^921, beyond what doubles
// can search (Double_kernel::far_power_of_two: exit 3, named), while the
// filtered kernel hands the pair to rationals and both exact kernels
// answer: the quadrant x < -2^230, y < 0 is common from tL = 0.
BOOST_AUTO_TEST_CASE(a_far_bound_beyond_doubles_is_refused_by_double_only)
{
  std::string big = "1725436586697640946858688965569256363112777243042596638790631055949824";   // 2^230
  Scene s = scene_of(R"({"format":"clash4d-scene/1","time":[0,1],"objects":[
    {"name":"a","shape":{"halfspace":[1,0,0,)" + big + R"(]}},
    {"name":"b","shape":{"halfspace":[0,1,0,0]}}]})");
  BOOST_TEST(far_exponent(s) == 921);
  Check_options o;
  o.earliest = true;
  for (Number n : {Number::exact, Number::rational}) {
    Check_answer a = run(n, s, o);
    BOOST_TEST_REQUIRE(a.collide, name(n));
    BOOST_TEST(a.pairs[0].t_star == "0");
    BOOST_TEST(a.pairs[0].witness_verified);
  }
  try {
    check_double(s, 0, o);
    BOOST_FAIL("the double instantiation searched a box of 2^921");
  } catch (const Input_error& e) {
    BOOST_TEST(e.exit_code() == CLASH4D_EXIT_LIMIT);
    BOOST_TEST(std::string(e.what()).find("2^921") != std::string::npos, e.what());
  }
}

// The skeleton of two crossing half-spaces: its edges are the lines x = 0,
// y = t at t = tL = 2 and t = tH = 5, every z; unbounded, so reported clipped
// to the far box (|z| about R = 2^12), in every kernel.
BOOST_AUTO_TEST_CASE(skeleton_of_crossing_halfspaces_is_two_clipped_lines)
{
  Scene s = read_scene_file(folder + "crossing_halfspaces.json");
  for (bool rational : {false, true}) {
    Skeleton_answer a = rational ? skeleton_rational(s) : skeleton_exact(s);
    BOOST_TEST_REQUIRE(a.pairs.size() == 1u);
    BOOST_TEST_REQUIRE(a.pairs[0].edges.size() == 2u);
    std::set<std::string> times;
    for (const auto& e : a.pairs[0].edges) {
      for (const auto& end : e) {
        BOOST_TEST(end[0] == "0");
        BOOST_TEST(end[1] == end[3]);
        Rational z = value(end[2], Number::exact);
        BOOST_TEST((z >= 4096 || z <= -4096), "edge end z = " << end[2] << " is not on the far box");
      }
      BOOST_TEST(e[0][3] == e[1][3]);
      times.insert(e[0][3]);
    }
    BOOST_TEST((times == std::set<std::string>{"2", "5"}));
  }
  BOOST_CHECK_NO_THROW(skeleton_double(s));
}
