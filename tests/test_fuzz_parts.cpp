#define BOOST_TEST_MODULE fuzz_parts
#include <boost/test/unit_test.hpp>

#include "compare/Contact_families.h"
#include "compare/Shrinker.h"
#include "exact/Exact_instantiation.h"
#include "float/Double_instantiation.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include "scene/Scene_writer.h"
#include <map>
#include <set>

using namespace clash4d;

static const std::uint64_t seed = 20250101;

static Scene scene_of(const std::string& json) { return read_scene(read_json_text(json)); }

static bool exact_collide(const Scene& s) { return check_exact(s, Check_options()).collide; }

BOOST_AUTO_TEST_CASE(cases_depend_on_seed_and_index_only)
{
  std::set<std::string> texts;
  for (std::uint64_t i = 0; i < 200; ++i) {
    Fuzz_case a = make_fuzz_case(seed, i), b = make_fuzz_case(seed, i);
    BOOST_TEST(a.family == b.family);
    BOOST_TEST(a.json == b.json);
    texts.insert(a.json);
  }
  BOOST_TEST(texts.size() == 200u);   // different indices differ
  BOOST_TEST(make_fuzz_case(seed, 7).json != make_fuzz_case(seed + 1, 7).json);
}

BOOST_AUTO_TEST_CASE(every_family_appears_and_every_case_is_valid)
{
  BOOST_TEST_MESSAGE("seed " << seed);
  std::set<std::string> names;
  for (const auto& f : fuzz_families()) {
    BOOST_TEST(std::string(f.description).size() > 20u);
    names.insert(f.name);
  }
  BOOST_TEST(names.size() == fuzz_families().size());
  std::set<std::string> seen;
  for (std::uint64_t i = 0; i < 36; ++i) seen.insert(make_fuzz_case(seed, i).family);
  BOOST_TEST(seen == names);
  for (std::uint64_t i = 0; i < 500; ++i) {
    Fuzz_case c = make_fuzz_case(seed, i);
    try {
      Scene s = scene_of(c.json);
      BOOST_TEST(s.objects.size() >= 2u);
    } catch (const std::exception& e) {
      BOOST_ERROR("seed " << seed << " case " << i << " (" << c.family << ") is invalid: " << e.what() << "\n" << c.json);
    }
  }
}

// Both verdicts occur; every stated expectation ("; expect collision" in the
// scene name) holds exactly; and doubles do disagree, which is the point.
BOOST_AUTO_TEST_CASE(families_give_both_verdicts_and_trip_doubles)
{
  const std::uint64_t n = 300;
  std::uint64_t collide = 0, disagree = 0;
  std::map<std::string, std::array<int, 3>> by_family;   // cases, collisions, double disagreements
  for (std::uint64_t i = 0; i < n; ++i) {
    Fuzz_case c = make_fuzz_case(seed, i);
    Scene s = scene_of(c.json);
    bool exact = exact_collide(s);
    bool dbl = exact;
    try {
      dbl = check_double(s, 0, Check_options()).collide;
    } catch (const std::exception& e) {
      BOOST_TEST_MESSAGE("case " << i << ": double failed: " << e.what());
    }
    auto& f = by_family[c.family];
    ++f[0];
    f[1] += exact;
    f[2] += dbl != exact;
    collide += exact;
    disagree += dbl != exact;
    if (s.name.find("; expect collision") != std::string::npos) BOOST_TEST(exact, "case " << i << ": " << s.name);
    if (s.name.find("; expect no collision") != std::string::npos) BOOST_TEST(!exact, "case " << i << ": " << s.name);
  }
  for (const auto& f : by_family)
    BOOST_TEST_MESSAGE(f.first << ": " << f.second[0] << " cases, " << f.second[1] << " collide, double disagrees on "
                               << f.second[2]);
  BOOST_TEST_MESSAGE("seed " << seed << ": " << collide << " of " << n << " collide; double disagrees with exact on "
                             << disagree);
  BOOST_TEST(collide * 100 >= 15 * n);
  BOOST_TEST((n - collide) * 100 >= 15 * n);
  BOOST_TEST(disagree > 0u);
}

// Four objects; only o1 (a translated union) and o3 collide.
static Scene four_objects()
{
  return scene_of(R"({"format": "clash4d-scene/1", "time": [0, 10], "objects": [
    {"name": "o0", "shape": {"block": {"min": [0, 0, 0], "max": [1, 1, 1]}}},
    {"name": "o1", "shape": {"translate": [10, 0, 0], "solid": {"union": [
        {"block": {"min": [0, 0, 0], "max": [1, 1, 1]}}, {"block": {"min": [1, 0, 0], "max": [2, 1, 1]}}]}}},
    {"name": "o2", "shape": {"hull": [[20, 0, 0], [21, 0, 0], [20, 1, 0], [20, 0, 1], [21, 1, 1]]},
     "motion": "vel 0 1 0 until 5 rest"},
    {"name": "o3", "shape": {"block": {"min": [11.5, 0.25, 0.25], "max": [12.75, 0.75, 0.75]}},
     "motion": "rest until 2 vel 0 0 0.1 until 4 rest"}],
   "ignore": [["o0", "o2"]]})");
}

BOOST_AUTO_TEST_CASE(shrinker_keeps_the_colliding_pair)
{
  Scene original = four_objects();
  BOOST_REQUIRE(exact_collide(original));
  std::size_t calls = 0;
  Scene small = shrink_scene(original, [&](const Scene& s) {
    ++calls;
    BOOST_CHECK_NO_THROW(scene_of(write_scene(s)));   // only valid candidates
    return exact_collide(s);
  });
  BOOST_TEST_MESSAGE("shrunk with " << calls << " checks to\n" << write_scene(small));
  BOOST_REQUIRE(small.objects.size() == 2u);
  BOOST_TEST(small.objects[0].name == "o1");
  BOOST_TEST(small.objects[1].name == "o3");
  BOOST_TEST(small.ignore.empty());
  BOOST_TEST(exact_collide(small));
  BOOST_TEST(write_scene(small).size() < write_scene(original).size());
}

BOOST_AUTO_TEST_CASE(shrinker_respects_max_checks)
{
  for (std::size_t limit : {0u, 1u, 7u, 40u}) {
    std::size_t calls = 0;
    Scene small = shrink_scene(four_objects(), [&](const Scene&) { return ++calls, true; }, limit);
    BOOST_TEST(calls <= limit);
    BOOST_TEST(small.objects.size() >= 2u);
  }
}

BOOST_AUTO_TEST_CASE(shrinker_returns_the_original_when_nothing_smaller_fails)
{
  Scene original = four_objects();
  std::string text = write_scene(original);
  std::size_t calls = 0;
  Scene same = shrink_scene(original, [&](const Scene& s) { return ++calls, write_scene(s) == text; });
  BOOST_TEST(write_scene(same) == text);
  BOOST_TEST(calls > 0u);
}

// A real finding: the first case on which doubles disagree, shrunk while they still do.
BOOST_AUTO_TEST_CASE(shrinker_on_a_double_disagreement)
{
  auto disagrees = [](const Scene& s) { return check_double(s, 0, Check_options()).collide != exact_collide(s); };
  for (std::uint64_t i = 0; i < 300; ++i) {
    Scene s = scene_of(make_fuzz_case(seed, i).json);
    if (!disagrees(s)) continue;
    std::size_t calls = 0;
    Scene small = shrink_scene(s, [&](const Scene& c) { return ++calls, disagrees(c); }, 300);
    BOOST_TEST(disagrees(small));
    BOOST_TEST(calls <= 300u);
    BOOST_TEST(write_scene(small).size() <= write_scene(s).size());
    BOOST_TEST_MESSAGE("case " << i << " shrunk with " << calls << " checks from " << write_scene(s).size() << " to "
                               << write_scene(small).size() << " characters:\n" << write_scene(small));
    return;
  }
  BOOST_ERROR("no case where doubles disagree");
}
