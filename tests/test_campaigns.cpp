#define BOOST_TEST_MODULE campaigns
#include <boost/test/unit_test.hpp>

// Campaigns across processes and machines (docs/campaigns.md): the shard a
// process runs, from --shard or from the scheduler's variables; four shards
// at once under GNU parallel, merged, equal a single run byte for byte.

#include "cli/Campaign_commands.h"
#include "support/Cli_run.h"
#include <boost/test/data/test_case.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>

using namespace clash4d;
namespace fs = std::filesystem;
namespace data = boost::unit_test::data;

namespace {

struct Shard_case {
  std::string shard;                          // --shard ("" absent)
  std::uint64_t count;                        // --shard-count (0 absent)
  std::map<std::string, std::string> env;
  std::uint64_t k, s;                         // expected; s = 0: refused
};

std::ostream& operator<<(std::ostream& out, const Shard_case& c)
{
  out << "--shard '" << c.shard << "' --shard-count " << c.count;
  for (const auto& e : c.env) out << " " << e.first << "=" << e.second;
  return out;
}

const std::vector<Shard_case> shard_cases = {
    {"", 0, {}, 1, 1},                                                      // nothing: the whole campaign
    {"2/4", 0, {}, 2, 4},
    {"2/4", 0, {{"SLURM_ARRAY_TASK_ID", "0"}}, 2, 4},                      // the option wins
    {"2/4", 3, {}, 0, 0},                                                   // contradicts itself
    {"5/4", 0, {}, 0, 0},
    {"0/4", 0, {}, 0, 0},
    {"x", 0, {}, 0, 0},
    {"", 0, {{"JOB_COMPLETION_INDEX", "0"}}, 0, 0},                        // Kubernetes: the count is needed
    {"", 4, {{"JOB_COMPLETION_INDEX", "0"}}, 1, 4},                        // indices are 0-based
    {"", 4, {{"JOB_COMPLETION_INDEX", "3"}}, 4, 4},
    {"", 4, {{"JOB_COMPLETION_INDEX", "4"}}, 0, 0},
    {"", 4, {{"JOB_COMPLETION_INDEX", "-1"}}, 0, 0},
    {"", 0, {{"SLURM_ARRAY_TASK_ID", "7"}, {"SLURM_ARRAY_TASK_MIN", "5"}, {"SLURM_ARRAY_TASK_COUNT", "4"}}, 3, 4},
    {"", 0, {{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_MIN", "0"}, {"SLURM_ARRAY_TASK_COUNT", "2"}}, 1, 2},
    {"", 3, {{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_COUNT", "4"}}, 0, 0},
    {"", 4, {{"SLURM_ARRAY_TASK_ID", "2"}}, 3, 4},                          // no MIN: 0-based
    {"", 0, {{"SLURM_ARRAY_TASK_ID", "2"}}, 0, 0},                          // no count anywhere
    {"", 4, {}, 0, 0},                                                      // a count and no scheduler
};

} // namespace

BOOST_DATA_TEST_CASE(the_shard_comes_from_the_option_or_the_scheduler, data::make(shard_cases), c)
{
  Fuzz_options o;
  std::ostringstream err;
  auto env = [&](const char* name) -> const char* {
    auto it = c.env.find(name);
    return it == c.env.end() ? nullptr : it->second.c_str();
  };
  bool ok = resolve_shard(c.shard, c.count, env, o, err);
  BOOST_TEST(ok == (c.s != 0), err.str());
  if (ok) {
    BOOST_TEST(o.shard == c.k);
    BOOST_TEST(o.shards == c.s);
  } else {
    BOOST_TEST(!err.str().empty());
  }
}

#ifdef CLASH4D_PARALLEL
namespace {

std::map<std::string, std::string> contents(const fs::path& dir)
{
  std::map<std::string, std::string> out;
  for (const auto& f : fs::directory_iterator(dir)) {
    std::ifstream in(f.path(), std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    out[f.path().filename().string()] = s.str();
  }
  return out;
}

int merge(const fs::path& root, const std::string& prefix, const std::vector<std::string>& parts, const fs::path& out)
{
  std::vector<std::string> args{"fuzz", "--merge"};
  for (const auto& p : parts) args.push_back((root / (prefix + p)).string());
  args.push_back("--out");
  args.push_back(out.string());
  return run_clash4d(args).status;
}

} // namespace

// docs/campaigns.md's recipes, on one machine: GNU parallel with --shard {}/4,
// then as four Slurm array tasks and four Kubernetes indices (their variables
// set by parallel). Each merge equals the single run, file for file.
BOOST_AUTO_TEST_CASE(four_shards_under_gnu_parallel_merge_to_the_single_run)
{
  fs::path root = fs::temp_directory_path() / ("clash4d_test_campaigns_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  // Each run sees only the scheduler variables it is meant to (this test may
  // itself run under a scheduler).
  std::string clean = "env -u SLURM_ARRAY_TASK_ID -u JOB_COMPLETION_INDEX ";
  std::string tool = CLASH4D_BINARY, campaign = " fuzz --seed 20261122 --cases 24", parallel = CLASH4D_PARALLEL;
  std::string r = root.string() + "/";
  std::vector<std::string> commands = {
      clean + tool + campaign + " --out " + r + "single",
      parallel + " -j4 " + clean + tool + campaign + " --shard {}/4 --out " + r + "gnu{} ::: 1 2 3 4",
      parallel + " -j4 '" + clean + "SLURM_ARRAY_TASK_ID={} SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_COUNT=4 " + tool +
          campaign + " --out " + r + "slurm{}' ::: 0 1 2 3",
      parallel + " -j4 '" + clean + "JOB_COMPLETION_INDEX={} " + tool + campaign + " --shard-count 4 --out " + r +
          "k8s{}' ::: 0 1 2 3"};
  for (const auto& command : commands) {
    BOOST_TEST_MESSAGE(command);
    std::system((command + " > /dev/null 2>&1").c_str());   // fuzz exits 1 when it finds something
  }
  auto single = contents(root / "single" / "findings");
  BOOST_TEST_REQUIRE(!single.empty());
  for (const auto& [prefix, parts] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"gnu", {"1", "2", "3", "4"}}, {"slurm", {"0", "1", "2", "3"}}, {"k8s", {"0", "1", "2", "3"}}}) {
    for (const auto& p : parts) BOOST_TEST(fs::exists(root / (prefix + p) / ("progress-" + std::to_string(std::stoi(p) + (prefix == "gnu" ? 0 : 1)) + "-of-4.json")), prefix + p);
    BOOST_TEST(merge(root, prefix, parts, root / (prefix + "-merged")) == 0, prefix);
    BOOST_TEST((contents(root / (prefix + "-merged") / "findings") == single), prefix);
  }
  fs::remove_all(root);
}
#endif
