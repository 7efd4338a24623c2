#define BOOST_TEST_MODULE fuzz_campaign
#include <boost/test/unit_test.hpp>

#include "cli/Commands.h"
#include "compare/Comparer.h"
#include "compare/Fuzz_campaign.h"
#include "scene/Files.h"
#include "scene/Scene_reader.h"
#include <algorithm>
#include "run/Work_budget.h"
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sys/file.h>
#include <unistd.h>
#include <map>
#include <sstream>

using namespace clash4d;
namespace fs = std::filesystem;

static fs::path fresh(const std::string& name)
{
  fs::path p = fs::temp_directory_path() / ("clash4d_test_fuzz_" + name);
  fs::remove_all(p);
  return p;
}

static Fuzz_options campaign(const fs::path& out, std::uint64_t shard = 1, std::uint64_t shards = 1)
{
  Fuzz_options o;
  o.seed = 20261122;
  o.cases = 24;
  o.shard = shard;
  o.shards = shards;
  o.out = out.string();
  o.max_shrink_checks = 8;   // the shrinker has its own tests; here only the files matter
  return o;
}

// Every file of a folder (relative name -> contents).
static std::map<std::string, std::string> contents(const fs::path& dir)
{
  std::map<std::string, std::string> out;
  for (const auto& f : fs::directory_iterator(dir)) {
    std::ifstream in(f.path());
    std::ostringstream s;
    s << in.rdbuf();
    out[f.path().filename().string()] = s.str();
  }
  return out;
}

BOOST_AUTO_TEST_CASE(same_seed_same_findings_and_shards_cover_the_campaign)
{
  std::ostringstream err;
  fs::path whole = fresh("whole"), a = fresh("a"), b = fresh("b"), merged = fresh("merged");
  Fuzz_summary s = run_fuzz(campaign(whole), err);
  BOOST_TEST_MESSAGE("seed 20261122: " << s.findings << " findings in 24 cases");
  BOOST_TEST(s.findings > 0u);   // the families do find float errors
  run_fuzz(campaign(a, 1, 2), err);
  run_fuzz(campaign(b, 2, 2), err);
  merge_fuzz({a.string(), b.string()}, merged.string());
  BOOST_TEST((contents(whole / "findings") == contents(merged / "findings")));
  // A rerun of the finished campaign changes nothing.
  auto before = contents(whole / "findings");
  run_fuzz(campaign(whole), err);
  BOOST_TEST((contents(whole / "findings") == before));
}

BOOST_AUTO_TEST_CASE(an_interrupted_campaign_resumes_and_loses_nothing)
{
  std::ostringstream err;
  fs::path full = fresh("full"), cut = fresh("cut");
  run_fuzz(campaign(full), err);
  // Simulate a kill in the middle of the second batch: progress still says
  // 16, some later findings were written, one rename never happened.
  run_fuzz(campaign(cut), err);
  for (const auto& f : fs::directory_iterator(cut / "findings")) {
    std::string name = f.path().filename().string();
    if (std::stoi(name.substr(5)) >= 20) fs::remove(f.path());
  }
  std::ofstream(cut / "progress-1-of-1.json") << "{\"next\":16}\n";
  std::ofstream(cut / "findings" / "case-17.json.tmp") << "{\"half";
  Fuzz_summary s = run_fuzz(campaign(cut), err);
  BOOST_TEST(s.resumed_from == 16u);
  fs::remove(cut / "findings" / "case-17.json.tmp");
  BOOST_TEST((contents(cut / "findings") == contents(full / "findings")));
}

// --max-seconds (run/Work_budget.h): a budget that runs out in the first
// case stops the campaign with Budget_exceeded before any batch is saved;
// run again without it, the campaign ends with the findings of a run never
// stopped.
BOOST_AUTO_TEST_CASE(a_campaign_stopped_by_its_budget_resumes_and_loses_nothing)
{
  std::ostringstream err;
  fs::path full = fresh("budget_full"), cut = fresh("budget_cut");
  run_fuzz(campaign(full), err);
  Work_budget::start(1e-9);
  BOOST_CHECK_THROW(run_fuzz(campaign(cut), err), Budget_exceeded);
  Work_budget::start(0);
  BOOST_TEST(!fs::exists(cut / "progress-1-of-1.json"));
  Fuzz_summary s = run_fuzz(campaign(cut), err);
  BOOST_TEST(s.done == 24u);
  BOOST_TEST((contents(cut / "findings") == contents(full / "findings")));
}

BOOST_AUTO_TEST_CASE(a_folder_holds_one_campaign)
{
  std::ostringstream err;
  fs::path dir = fresh("other");
  run_fuzz(campaign(dir), err);
  Fuzz_options other = campaign(dir);
  other.seed = 1;
  BOOST_CHECK_THROW(run_fuzz(other, err), std::runtime_error);
}

// A campaign of turning parts (--rotation): its folder is its own (a
// contact campaign with the same seed is another campaign), its findings
// are scenes that turn, and each shrunk finding still shows the
// disagreement it was shrunk for.
BOOST_AUTO_TEST_CASE(a_rotation_campaign_finds_and_shrinks_turning_scenes)
{
  std::ostringstream err;
  fs::path dir = fresh("rotation");
  Fuzz_options o = campaign(dir);
  o.rotation = true;
  o.cases = 12;
  Fuzz_summary s = run_fuzz(o, err);
  BOOST_TEST(s.done == 12u);
  Fuzz_options contact = campaign(dir);
  contact.cases = 12;
  BOOST_CHECK_THROW(run_fuzz(contact, err), std::runtime_error);
  int shrunk = 0;
  for (const auto& f : fs::directory_iterator(dir / "findings")) {
    std::string name = f.path().filename().string();
    if (name.find(".min.json") == std::string::npos) continue;
    Scene small = read_scene_file(f.path().string());
    nlohmann::ordered_json meta = read_json_document(f.path().string())["meta"];
    std::string key = meta["disagreement"]["subject"].get<std::string>() + ": " + meta["disagreement"]["cause"].get<std::string>();
    std::vector<std::string> keys = compare_scene(small, name, o.compare).disagreement_keys();
    BOOST_TEST((std::find(keys.begin(), keys.end(), key) != keys.end()), name << " no longer shows " << key);
    BOOST_TEST(meta["family"].get<std::string>().rfind("rotation_", 0) == 0);
    ++shrunk;
  }
  BOOST_TEST_MESSAGE(shrunk << " shrunk findings in 12 rotation cases");
  BOOST_TEST(shrunk == static_cast<int>(s.findings));
}

// Issue 59 item 17: a second run of the same shard in the same folder,
// while the first holds its lock, is refused with exit 2 naming the lock
// (the lock is held here by this test); another shard, or the same shard
// once the lock is free, runs.
BOOST_AUTO_TEST_CASE(one_run_per_shard_and_folder_at_a_time)
{
  fs::path dir = fresh("lock");
  fs::create_directories(dir);
  std::string lock = (dir / "lock-1-of-2").string();
  int held = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  BOOST_TEST_REQUIRE(::flock(held, LOCK_EX | LOCK_NB) == 0);
  std::vector<std::string> args{"clash4d", "fuzz", "--cases", "4", "--shard", "1/2", "--out", dir.string()};
  auto run = [&] {
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    std::ostringstream out, err;
    int status = run_cli(static_cast<int>(argv.size()), argv.data(), out, err);
    return std::make_pair(status, err.str());
  };
  auto [refused, why] = run();
  BOOST_TEST(refused == 2);
  BOOST_TEST(why.find(lock + ": another clash4d fuzz is running shard 1/2 in this folder") != std::string::npos, why);
  BOOST_TEST(!fs::exists(dir / "progress-1-of-2.json"));
  args[5] = "2/2";
  BOOST_TEST(run().first <= 1);
  ::close(held);
  args[5] = "1/2";
  BOOST_TEST(run().first <= 1);
  BOOST_TEST(fs::exists(dir / "progress-1-of-2.json"));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(command_line_checks_its_arguments)
{
  auto run = [](std::vector<std::string> args) {
    args.insert(args.begin(), "clash4d");
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    std::ostringstream out, err;
    return run_cli(static_cast<int>(argv.size()), argv.data(), out, err);
  };
  std::string dir = fresh("cli").string();
  BOOST_TEST(run({"fuzz", "--seed", "1", "--cases", "2", "--shard", "3/2", "--out", dir}) == 2);
  BOOST_TEST(run({"fuzz", "--seed", "1", "--cases", "2", "--shard", "x", "--out", dir}) == 2);
  BOOST_TEST(run({"fuzz", "--merge", "/nonexistent", "--out", dir}) == 2);
  BOOST_TEST(run({"report", "/nonexistent.json", "--out", dir}) == 2);
}

// Progress in a log (not a terminal: a Slurm job's file): whole lines, the
// last one at the end of the campaign; none unless asked; on a terminal the
// line is rewritten in place.
BOOST_AUTO_TEST_CASE(progress_in_a_log_is_whole_lines)
{
  fs::path out = fresh("progress_log");
  Fuzz_options o = campaign(out);
  o.progress = Campaign_options::Progress::log;
  std::ostringstream err;
  run_fuzz(o, err);
  BOOST_TEST(err.str().find("clash4d fuzz: 24/24 cases") != std::string::npos, err.str());
  BOOST_TEST(err.str().find('\r') == std::string::npos);
  BOOST_TEST(err.str().back() == '\n');
  std::ostringstream quiet;
  run_fuzz(campaign(fresh("progress_none")), quiet);
  BOOST_TEST(quiet.str().empty(), quiet.str());
  std::ostringstream terminal;
  Fuzz_options t = campaign(fresh("progress_terminal"));
  t.progress = Campaign_options::Progress::terminal;
  run_fuzz(t, terminal);
  BOOST_TEST(terminal.str().find("\r24/24 cases") != std::string::npos, terminal.str());
}
