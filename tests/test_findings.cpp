#define BOOST_TEST_MODULE findings
#include <boost/test/unit_test.hpp>

// Every file a tool writes as a scene is a scene: fuzz findings and their
// shrunk forms, generated scenes (spec: `meta`; issue 17 item 4). Driven
// through the command line in-process, as a user would replay them.

#include "support/Cli_run.h"
#include "compare/Fuzz_campaign.h"
#include <nlohmann/json.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace clash4d;
namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

using Cli_result = Cli_run;
Cli_result run(std::vector<std::string> args) { return run_clash4d(std::move(args)); }

fs::path fresh(const std::string& name)
{
  fs::path p = fs::temp_directory_path() / ("clash4d_test_findings_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  return p;
}

json read_json(const fs::path& p)
{
  std::ifstream in(p);
  return json::parse(in);
}

} // namespace

BOOST_AUTO_TEST_CASE(every_finding_replays_with_validate_check_and_compare)
{
  fs::path dir = fresh("fuzz");
  Fuzz_options o;
  o.seed = 20261122;
  o.cases = 13;             // one case of each family
  o.out = dir.string();
  o.max_shrink_checks = 6;
  std::ostringstream err;
  Fuzz_summary s = run_fuzz(o, err);
  BOOST_TEST_MESSAGE("seed " << o.seed << ": " << s.findings << " findings in " << o.cases << " cases");
  BOOST_TEST_REQUIRE(s.findings > 0u);
  std::size_t files = 0;
  for (const auto& f : fs::directory_iterator(dir / "findings")) {
    std::string path = f.path().string(), name = f.path().filename().string();
    ++files;
    Cli_result v = run({"validate", path});
    BOOST_TEST(v.status == 0, name << ": " << v.err);
    Cli_result c = run({"check", path, "--json"});
    BOOST_TEST((c.status == 0 || c.status == 1), name << ": " << c.err);
    Cli_result k = run({"compare", path, "--json"});
    BOOST_TEST((k.status == 0 || k.status == 1), name << ": " << k.err);
    // The provenance is there, and check's verdict is the recorded exact one.
    json meta = read_json(f.path())["meta"];
    BOOST_TEST(meta["seed"] == o.seed);
    BOOST_TEST(meta["family"].is_string());
    BOOST_TEST(!meta["disagreements"].empty(), name);
    for (const auto& d : meta["disagreements"]) BOOST_TEST(d["semantics"].is_string());
    bool exact_collide = meta["comparison"]["subjects"][0]["collide"].get<bool>();
    BOOST_TEST(c.status == (exact_collide ? 1 : 0), name);
    if (name.find(".min.json") != std::string::npos) BOOST_TEST(meta["disagreement"]["subject"].is_string());
  }
  BOOST_TEST(files == 2 * s.findings);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_generated_scene_is_a_scene)
{
  fs::path dir = fresh("generate");
  fs::create_directories(dir);
  std::string file = (dir / "grid.json").string();
  BOOST_TEST_REQUIRE(run({"generate", "--n", "12", "--colliding", "2", "--seed", "3", "--out", file}).status == 0);
  BOOST_TEST(run({"validate", file}).status == 0);
  Cli_result c = run({"check", file, "--all-pairs", "--json"});
  BOOST_TEST(c.status == 1);   // two pairs collide by construction
  json meta = read_json(file)["meta"];
  BOOST_TEST(json::parse(c.out)["pairs"].size() == meta["colliding_pairs"].size());
  BOOST_TEST(meta["colliding_pairs"].size() == 2u);
  fs::remove_all(dir);
}
