#define BOOST_TEST_MODULE compare_ccd
#include <boost/test/unit_test.hpp>

// compare, fuzz and report on CCD queries (docs/ccd-queries.md, "Compare
// and fuzz"): hand-made queries whose causes are known, the subject
// protocol's CCD requests, a seeded fuzz --ccd campaign whose findings
// replay with `clash4d ccd --labels`, and the report's CCD rows.

#include "support/Cli_run.h"
#include "support/Comparison_rows.h"
#include "support/Stage_tests.h"
#include "ccd/Ccd_families.h"
#include "compare/Ccd_comparer.h"
#include "compare/Ccd_fuzz_campaign.h"
#include "compare/Ccd_query_files.h"
#include "compare/External_subject.h"
#include "compare/Report_writer.h"
#include "exact/Ccd_instantiation.h"

#include <nlohmann/json.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>

using namespace clash4d;
namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

fs::path fresh(const std::string& name)
{
  fs::path p = fs::temp_directory_path() / ("clash4d_test_compare_ccd_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

std::string slurp(const fs::path& p)
{
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// A file of JSON lines, one query each.
std::string write_queries(const fs::path& dir, const std::string& name, const std::vector<std::string>& lines)
{
  std::string path = (dir / name).string();
  std::ofstream f(path);
  for (const auto& l : lines) f << l << "\n";
  return path;
}

// The vertex falls onto the triangle z = 0 and reaches it exactly at t = 1.
const std::string touch_at_end = R"({"type": "vertex-face", "t0": [["1/4","1/4",1], [0,0,0], [1,0,0], [0,1,0]],
  "t1": [["1/4","1/4",0], [0,0,0], [1,0,0], [0,1,0]]})";
// The vertex falls through the triangle's plane 1e-15 outside its edge x = 0.
const std::string miss_by_1e15 = R"({"type": "vertex-face",
  "t0": [["-1/1000000000000000","1/4",1], [0,0,0], [1,0,0], [0,1,0]],
  "t1": [["-1/1000000000000000","1/4",-1], [0,0,0], [1,0,0], [0,1,0]]})";

std::string one_line(std::string s)
{
  for (char& c : s)
    if (c == '\n') c = ' ';
  return s;
}

const json& row(const json& comparison, const std::string& name) { return subject_row(comparison, name); }

json compare_json(std::vector<std::string> args)
{
  args.insert(args.begin(), "compare");
  args.push_back("--json");
  Cli_run r = run_clash4d(args);
  BOOST_TEST_REQUIRE((r.status == 0 || r.status == 1), r.err);
  return json::parse(r.out);
}

// Shell subjects; each request line starts {"id":N, (clash4d writes id first).
const std::string read_id = R"(id=$(printf '%s\n' "$line" | sed 's/^{"id":\([0-9]*\).*/\1/'); )";
const std::string hello = R"(echo '{"subject":"t","semantics":"closed","tolerance":1e-9}'; )";
const std::string garbage = hello + R"(while read -r line; do echo 'collide: maybe'; done)";
const std::string with_witness =
    hello + "while read -r line; do " + read_id + R"(echo "{\"id\":$id,\"collide\":false,\"witness\":[0,0,0,0]}"; done)";
const std::string unsupported =
    hello + "while read -r line; do " + read_id + R"(echo "{\"id\":$id,\"unsupported\":\"scenes only\"}"; done)";

#ifdef CLASH4D_PYTHON
const std::string cubic = std::string(CLASH4D_PYTHON) + " " + CLASH4D_SOURCE "/examples/subjects/ccd_cubic_subject.py";
#endif

} // namespace

BOOST_AUTO_TEST_CASE(touching_exactly_at_t_1_is_agreed_by_the_tolerance_subject)
{
  fs::path dir = fresh("touch");
  std::string file = write_queries(dir, "touch.jsonl", {one_line(touch_at_end)});
  json all = compare_json({file, "--earliest"});
  BOOST_TEST_REQUIRE(all.size() == 1u);
  const json& c = all[0];
  BOOST_TEST(c["file"] == file);
  BOOST_TEST(c["index"] == 0);
  BOOST_TEST(c["line"] == 1);
  BOOST_TEST(c["query"]["type"] == "vertex-face");
  BOOST_TEST(row(c, "exact")["collide"] == true);
  BOOST_TEST(row(c, "exact")["t"] == "1");
  BOOST_TEST(row(c, "exact")["semantics"] == "closed");
  BOOST_TEST(row(c, "double tol=1e-09")["collide"] == true);
  BOOST_TEST(row(c, "double tol=1e-09")["agrees"] == true);
  BOOST_TEST(row(c, "double tol=1e-09")["t"] == "1");
  BOOST_TEST(c["disagreements"].empty());
  fs::remove_all(dir);
}

// The exact answer with separation 1e-9 says the primitives come within it:
// a subject with that tolerance that calls it a collision is right in its
// own terms, and the cause says so.
BOOST_AUTO_TEST_CASE(a_near_miss_of_1e_15_is_a_tolerance_disagreement)
{
  fs::path dir = fresh("near");
  std::string file = write_queries(dir, "near.jsonl", {one_line(miss_by_1e15)});
  json c = compare_json({file})[0];
  BOOST_TEST(row(c, "exact")["collide"] == false);
  BOOST_TEST(row(c, "exact-rounded")["collide"] == false);   // -1e-15 is still left of the edge in doubles
  const json& tol = row(c, "double tol=1e-09");
  BOOST_TEST(tol["collide"] == true);
  BOOST_TEST(tol["cause"] == "tolerance");
  BOOST_TEST(tol["tolerance"] == 1e-9);
  Ccd_options within;
  within.separation = Rational(1e-9);
  BOOST_TEST(ccd_exact(ccd_query_from_json(json::parse(miss_by_1e15)), within).collide);
#ifdef CLASH4D_PYTHON
  json with_cubic = compare_json({file, "--subject", "cubic=" + cubic})[0];
  BOOST_TEST(row(with_cubic, "cubic")["collide"] == true);
  BOOST_TEST(row(with_cubic, "cubic")["cause"] == "tolerance");
#endif
  fs::remove_all(dir);
}

// Every cause follows its definition (compare/Ccd_comparer.h) on the first
// cases of every family, with --earliest.
BOOST_AUTO_TEST_CASE(causes_follow_their_definitions_on_the_families)
{
  Ccd_compare_options o;
  o.earliest = true;
  o.tolerances = {1e-9, 1e-6};
  std::map<std::string, int> causes;
  for (std::uint64_t i = 0; i < 3 * ccd_families().size(); ++i) {
    Ccd_case k = make_ccd_case(11, i);
    Ccd_comparison c = compare_query(k.query, k.family, 0, o);
    json j = c.to_json();
    const json &exact = row(j, "exact"), &rounded = row(j, "exact-rounded");
    BOOST_TEST(exact["agrees"] == true);
    BOOST_TEST(exact["collide"].is_boolean());
    BOOST_TEST(exact["t"].is_string() == (exact["collide"] == true), k.family);
    for (const auto& s : j["subjects"]) {
      if (s["cause"].is_null()) continue;
      std::string cause = s["cause"];
      ++causes[cause];
      if (cause == "time") BOOST_TEST(s["collide"] == exact["collide"], k.family);
      else BOOST_TEST(s["collide"] != exact["collide"], k.family);
      if (cause == "input rounding") BOOST_TEST(rounded["collide"] == s["collide"], k.family);
      if (cause == "tolerance") BOOST_TEST(s["tolerance"].is_number(), k.family);
      if (cause == "arithmetic") BOOST_TEST(rounded["collide"] != s["collide"], k.family);
    }
    // The JSON form reads back to the same rows.
    BOOST_TEST(Ccd_comparison::from_json(j).to_json() == j);
  }
  for (const auto& c : causes) BOOST_TEST_MESSAGE("seed 11: " << c.second << " disagreements of cause " << c.first);
}

BOOST_AUTO_TEST_CASE(bad_query_files_name_the_file_and_place)
{
  fs::path dir = fresh("bad");
  std::string csv = (dir / "vertex-face-bad.csv").string();
  std::ofstream(csv) << "1,1,2,1,3,1,0\n1,1,2,x,3,1,0\n";
  Cli_run r = run_clash4d({"compare", csv});
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.err.find(csv + ": line 2, column 7: ") != std::string::npos, r.err);
  std::string untyped = (dir / "queries.csv").string();
  std::ofstream(untyped) << "";
  BOOST_TEST(run_clash4d({"compare", untyped}).status == 2);
  BOOST_TEST(run_clash4d({"compare", untyped, "--type", "vf"}).status == 0);
  fs::remove_all(dir);
}

// A CCD request to a subject: an answer out of protocol (not JSON, or a
// witness, which a query has no place for) is a protocol fault; unsupported
// is skipped.
BOOST_AUTO_TEST_CASE(the_protocol_judges_answers_to_ccd_requests)
{
  fs::path dir = fresh("protocol");
  std::string file = write_queries(dir, "q.jsonl", {one_line(touch_at_end), one_line(miss_by_1e15)});
  for (const std::string& subject : {garbage, with_witness}) {
    json all = compare_json({file, "--subject", "s=" + subject, "--subject-timeout", "5"});
    for (const auto& c : all) {
      BOOST_TEST(row(c, "s")["cause"] == "protocol");
      BOOST_TEST(row(c, "s")["ok"] == false);
    }
  }
  json skipped = compare_json({file, "--subject", "s=" + unsupported})[0];
  BOOST_TEST(row(skipped, "s")["skipped"] == "unsupported: scenes only");
  BOOST_TEST(row(skipped, "s")["agrees"].is_null());
  fs::remove_all(dir);
}

// The campaign machinery is the scenes' (compare/Fuzz_campaign.h): shards
// merge to the whole campaign, a rerun changes nothing, and a folder holds
// one campaign.
BOOST_AUTO_TEST_CASE(ccd_campaigns_shard_merge_and_rerun_like_scene_campaigns)
{
  fs::path whole = fresh("whole"), a = fresh("a"), b = fresh("b"), merged = fresh("merged");
  auto campaign = [](const fs::path& out, std::uint64_t shard, std::uint64_t shards) {
    Ccd_fuzz_options o;   // seed 5, 40 cases, 10 shrinking steps
    static_cast<Campaign_options&>(o) = Campaign_options{5, 40, shard, shards, out.string(), Campaign_options::Progress::none, 10};
    return o;
  };
  std::ostringstream err;
  Fuzz_summary s = run_ccd_fuzz(campaign(whole, 1, 1), err);
  BOOST_TEST_MESSAGE("fuzz --ccd seed 5: " << s.findings << " findings in 40 cases (built-in subjects)");
  run_ccd_fuzz(campaign(a, 1, 2), err);
  run_ccd_fuzz(campaign(b, 2, 2), err);
  merge_fuzz({a.string(), b.string()}, merged.string());
  std::map<std::string, std::string> one, two;
  for (const auto& f : fs::directory_iterator(whole / "findings")) one[f.path().filename().string()] = slurp(f.path());
  for (const auto& f : fs::directory_iterator(merged / "findings")) two[f.path().filename().string()] = slurp(f.path());
  BOOST_TEST((one == two));
  run_ccd_fuzz(campaign(whole, 1, 1), err);
  for (const auto& f : fs::directory_iterator(whole / "findings"))
    BOOST_TEST(one[f.path().filename().string()] == slurp(f.path()));
  Fuzz_options scenes;
  scenes.seed = 5;
  scenes.cases = 40;
  scenes.out = whole.string();
  BOOST_CHECK_THROW(run_fuzz(scenes, err), std::runtime_error);
  for (const fs::path& p : {whole, a, b, merged}) fs::remove_all(p);
}

BOOST_AUTO_TEST_CASE(fuzz_arguments_are_checked)
{
  std::string dir = fresh("args").string();
  BOOST_TEST(run_clash4d({"fuzz", "--ccd", "--cases", "2", "--out", dir, "--fcl"}).status == 2);
  BOOST_TEST(run_clash4d({"fuzz", "--ccd", "--cases", "2", "--out", dir, "--semantics", "closed"}).status == 2);
  BOOST_TEST(run_clash4d({"fuzz", "--cases", "2", "--out", dir, "--earliest"}).status == 2);
  fs::remove_all(dir);
}

#ifdef CLASH4D_PYTHON
namespace {

// The disagreement keys ("subject: cause") of every comparison of a
// compare --json list, by file.
std::map<std::string, std::vector<std::string>> keys_by_file(const json& all)
{
  std::map<std::string, std::vector<std::string>> out;
  for (const auto& c : all)
    for (const auto& d : c["disagreements"])
      out[c["file"]].push_back(d["subject"].get<std::string>() + ": " + d["cause"].get<std::string>());
  return out;
}

bool contains(const std::vector<std::string>& v, const std::string& x)
{
  return std::find(v.begin(), v.end(), x) != v.end();
}

} // namespace

// The issue's acceptance: the fuzzer finds errors in the example float
// subject's edge cases; each finding replays with `clash4d ccd --labels`
// (exit 0), as CSV and as JSON, and its shrunk files still show the
// disagreement; report writes the findings' rows.
BOOST_AUTO_TEST_CASE(the_fuzzer_finds_the_cubic_subjects_errors_and_they_replay)
{
  // CLASH4D_CCD_FUZZ_CASES: the sanitizer run takes fewer (each finding is
  // replayed by four runs of the program).
  const std::uint64_t seed = 1, cases = stage_tests::env_number("CLASH4D_CCD_FUZZ_CASES", 300);
  fs::path dir = fresh("cubic");
  Ccd_fuzz_options o;
  o.seed = seed;
  o.cases = cases;
  o.out = (dir / "fz").string();
  o.max_shrink_checks = 40;
  o.compare.externals.push_back(std::make_shared<External_pool>(Subject_spec{"cubic", cubic, 10}));
  std::ostringstream err;
  Fuzz_summary s = run_ccd_fuzz(o, err);
  BOOST_TEST(s.done == cases);

  std::map<std::string, int> by_cause;
  std::vector<std::string> min_files, min_keys;
  std::size_t cubic_findings = 0;
  for (const auto& f : fs::directory_iterator(dir / "fz" / "findings")) {
    std::string name = f.path().filename().string();
    if (f.path().extension() != ".json" || name.find(".min.") != std::string::npos) continue;
    json finding = json::parse(slurp(f.path()));
    bool cubic_disagrees = false;
    for (const auto& d : finding["meta"]["disagreements"]) {
      ++by_cause[d["subject"].get<std::string>() + ": " + d["cause"].get<std::string>()];
      cubic_disagrees = cubic_disagrees || d["subject"] == "cubic";
    }
    cubic_findings += cubic_disagrees;
    std::string stem = name.substr(0, name.size() - 5);   // case-I
    std::string type = finding["type"];
    fs::path min_json = f.path().parent_path() / (stem + ".min.json");
    fs::path csv = f.path().parent_path() / (type + "-" + stem + ".csv");
    fs::path min_csv = f.path().parent_path() / (type + "-" + stem + ".min.csv");
    // Replays: the exact answer is the recorded label.
    for (const fs::path& p : {f.path(), min_json, csv, min_csv}) {
      Cli_run r = run_clash4d({"ccd", p.string(), "--labels"});
      BOOST_TEST(r.status == 0, p.string() << ": " << r.out << r.err);
    }
    BOOST_TEST(read_ccd_queries(csv.string(), std::nullopt).front().rows() ==
               read_ccd_queries(f.path().string(), std::nullopt).front().rows());
    json min = json::parse(slurp(min_json));
    min_files.push_back(min_json.string());
    min_keys.push_back(min["meta"]["disagreement"]["subject"].get<std::string>() + ": " +
                       min["meta"]["disagreement"]["cause"].get<std::string>());
  }
  for (const auto& c : by_cause)
    BOOST_TEST_MESSAGE("fuzz --ccd seed " << seed << ", " << cases << " cases: " << c.second << " x " << c.first);
  BOOST_TEST(cubic_findings >= 10u);   // the naive subject errs on the edge cases
  BOOST_TEST(by_cause["cubic: arithmetic"] > 0);
  BOOST_TEST(by_cause["cubic: tolerance"] > 0);

  // The shrunk queries still show their disagreement, compared afresh.
  std::vector<std::string> args = min_files;
  args.insert(args.end(), {"--subject", "cubic=" + cubic});
  std::map<std::string, std::vector<std::string>> again = keys_by_file(compare_json(args));
  for (std::size_t i = 0; i < min_files.size(); ++i)
    BOOST_TEST(contains(again[min_files[i]], min_keys[i]), min_files[i] << ": " << min_keys[i]);

  // The report shows them: a CCD row per finding file, next to a scene.
  Cli_run r = run_clash4d({"report", o.out, std::string(CLASH4D_FIXTURES) + "/contact/face_touch_static.json", "--out",
                           (dir / "report").string()});
  BOOST_TEST(r.status == 1, r.err);
  json report = json::parse(slurp(dir / "report" / "report.json"));
  // Each finding once: its minimised query, the original linked (issue 60).
  BOOST_TEST(report["summary"]["queries"] == min_files.size());
  BOOST_TEST(report["summary"]["scenes"] == 1);
  std::size_t with_query = 0;
  for (const auto& c : report["cases"]) with_query += c.contains("query");
  BOOST_TEST(with_query == min_files.size());
  BOOST_TEST(report["summary"]["by_subject"]["cubic"]["disagreements"].get<int>() > 0);
  std::string junit = slurp(dir / "report" / "junit.xml"), html = slurp(dir / "report" / "index.html");
  BOOST_TEST(junit.find(".json: query 0 (line 1)\" name=\"cubic\"") != std::string::npos);
  BOOST_TEST(html.find("<th>vertex</th><th>at t = 0</th><th>at t = 1</th>") != std::string::npos);
  BOOST_TEST(html.find("face_touch_static.json") != std::string::npos);
  o.compare.externals.clear();
  fs::remove_all(dir);
}
#endif
