#define BOOST_TEST_MODULE subjects
#include <boost/test/unit_test.hpp>

// External subjects (spec: "External subjects"; docs/subject-protocol.md):
// the toolkit's own exact check run as a subject agrees everywhere; a subject
// that always says no is flagged on every colliding scene; subjects that
// crash, hang or print garbage are findings about the subject, and the run
// completes with no child process left behind.

#include "support/Cli_run.h"
#include "support/Comparison_rows.h"
#include "compare/Comparer.h"
#include "compare/External_subject.h"
#include "compare/Subject_processes.h"
#include "compare/Fuzz_campaign.h"
#include "scene/Scene_builder.h"
#include "scene/Scene_reader.h"

#include <nlohmann/json.hpp>
#include <dirent.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <unistd.h>

using namespace clash4d;
namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

// Shell subjects; each request line starts {"id":N, (clash4d writes id first).
const std::string read_id = R"(id=$(printf '%s\n' "$line" | sed 's/^{"id":\([0-9]*\).*/\1/'); )";
const std::string hello = R"(echo '{"subject":"t","semantics":"regularised"}'; )";
const std::string always_no = hello + "while read -r line; do " + read_id + R"(echo "{\"id\":$id,\"collide\":false}"; done)";
// Answers "no" to its first request, then dies by a signal.
const std::string crash_on_second = hello + "n=0; while read -r line; do " + read_id +
    R"(n=$((n+1)); if [ $n -ge 2 ]; then kill -SEGV $$; fi; echo "{\"id\":$id,\"collide\":false}"; done)";
// Never answers; its sleep (a grandchild of clash4d) must die with it.
const std::string hangs = hello + "while read -r line; do sleep 937; done";
const std::string garbage = hello + R"(while read -r line; do echo 'collide: maybe'; done)";

using Cli_result = Cli_run;
Cli_result run(std::vector<std::string> args) { return run_clash4d(std::move(args)); }

std::string fixture(const std::string& entry) { return std::string(CLASH4D_FIXTURES) + "/" + entry; }

// Scenes of both verdicts, quick to decide.
std::vector<std::string> some_fixtures()
{
  std::vector<std::string> files;
  for (const char* f : {"contact/face_touch_static.json", "contact/clear_collision_head_on.json",
                        "contact/hull_face_touch.json", "contact/touch_only_at_tH_overlap_1e-9.json",
                        "contact/sliding_contact_decimal.json", "contact/approach_stop_decimal_overlap_1e-9.json"})
    files.push_back(fixture(f));
  return files;
}

const json& row(const json& comparison, const std::string& name) { return subject_row(comparison, name); }

json compare_json(const std::vector<std::string>& files, const std::string& subject, double timeout = 5)
{
  std::vector<std::string> args{"compare"};
  args.insert(args.end(), files.begin(), files.end());
  for (std::string a : std::vector<std::string>{"--earliest", "--json", "--subject", "s=" + subject, "--subject-timeout",
                                                std::to_string(timeout)})
    args.push_back(a);
  Cli_result r = run(args);
  BOOST_TEST_REQUIRE((r.status == 0 || r.status == 1), r.err);
  return json::parse(r.out);
}

// Processes still running our marker command (the hanging subject's sleep),
// and our children that were not reaped.
std::size_t leftovers_now()
{
  std::size_t n = 0;
  std::string me = std::to_string(::getpid());
  for (const auto& e : fs::directory_iterator("/proc")) {
    std::string pid = e.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream cmd(e.path() / "cmdline"), stat(e.path() / "stat");
    std::string c((std::istreambuf_iterator<char>(cmd)), std::istreambuf_iterator<char>()), s;
    std::getline(stat, s);
    if (s.find(')') == std::string::npos) continue;   // gone meanwhile
    std::istringstream fields(s.substr(s.rfind(')') + 2));
    std::string state, ppid;
    fields >> state >> ppid;
    if (c.find(std::string("sleep") + '\0' + "937") != std::string::npos || ppid == me) ++n;
  }
  return n;
}

// The leftovers once the kills have landed. kill(2) returns before its target
// exits, and the hanging subject's sleep is a grandchild we cannot wait for:
// on a loaded machine it can still be listed for a moment after its group was
// killed. A process that is really left running is still there after 10 s.
std::size_t leftovers()
{
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  std::size_t n = leftovers_now();
  while (n != 0 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    n = leftovers_now();
  }
  return n;
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

fs::path scratch(const std::string& name)
{
  fs::path dir = fs::temp_directory_path() / ("clash4d_test_subjects_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A subject that starts a grandchild which leaves its process group
// (setsid) and sleeps, and writes "LEADER GRANDCHILD" to `pids` before its
// hello; then it answers no (or, `hang`, never answers).
std::string escaping(const fs::path& pids, bool hang)
{
  return "setsid sleep 947 & echo $$ $! >> '" + pids.string() + "'; " + hello + "while read -r line; do " +
         (hang ? std::string("sleep 948; done") : read_id + R"(echo "{\"id\":$id,\"collide\":false}"; done)");
}

// The pids written to `file`: leaders at even places, grandchildren at odd.
std::vector<pid_t> pids_in(const fs::path& file)
{
  std::ifstream in(file);
  std::vector<pid_t> pids;
  for (long p; in >> p;) pids.push_back(static_cast<pid_t>(p));
  return pids;
}

// The processes not yet gone (kill(pid, 0) is not ESRCH) once the kills
// have had 10 s to land. A dead one may come back to this process as a
// zombie (the test is a subreaper once it has run a subject): reaped here.
std::vector<pid_t> still_there(const std::vector<pid_t>& pids)
{
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  std::vector<pid_t> left;
  do {
    while (::waitpid(-1, nullptr, WNOHANG) > 0) {}
    left.clear();
    for (pid_t p : pids)
      if (::kill(p, 0) == 0 || errno != ESRCH) left.push_back(p);
    if (!left.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  } while (!left.empty() && std::chrono::steady_clock::now() < deadline);
  return left;
}

// Ends what a check left (a failure, or the group members kill -9 leaves
// behind) with their groups, and reaps those that came back to this
// process, so nothing leaks into the next test.
void kill_left(const std::vector<pid_t>& pids)
{
  for (pid_t p : pids) {
    ::kill(-p, SIGKILL);
    ::kill(p, SIGKILL);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  while (::waitpid(-1, nullptr, WNOHANG) > 0) {}
}

// `clash4d ARGS...` as a process of its own, SIGTERM and SIGINT at their
// default actions (a test runner may have them ignored).
pid_t spawn_clash4d(const std::vector<std::string>& args)
{
  std::vector<char*> argv{const_cast<char*>(CLASH4D_BINARY)};
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGTERM);
  sigaddset(&defaults, SIGINT);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF);
  pid_t pid = -1;
  int failed = posix_spawn(&pid, CLASH4D_BINARY, nullptr, &attr, argv.data(), environ);
  posix_spawnattr_destroy(&attr);
  BOOST_TEST_REQUIRE(failed == 0);
  return pid;
}

} // namespace

BOOST_AUTO_TEST_CASE(the_exact_check_as_a_subject_agrees_everywhere)
{
  std::vector<std::string> files = some_fixtures();
  for (const char* f : {"paper/section5_vehicle_trays.json", "contact/difference_dangling_face_touch.json"})
    files.push_back(fixture(f));
  json all = compare_json(files, CLASH4D_EXACT_SUBJECT);
  BOOST_TEST(all.size() == files.size());
  for (const auto& c : all) {
    const json &mine = row(c, "s"), &exact = row(c, "exact");
    BOOST_TEST(mine["agrees"] == true, c["file"]);
    BOOST_TEST(mine["collide"] == exact["collide"], c["file"]);
    if (exact["collide"] == true) {
      BOOST_TEST(mine["witness_valid"] == true, c["file"]);
      BOOST_TEST(mine["earliest"]["t"] == exact["earliest"]["t"], c["file"]);
    }
  }
}

BOOST_AUTO_TEST_CASE(a_subject_that_always_says_no_is_flagged_on_every_colliding_scene)
{
  json all = compare_json(some_fixtures(), always_no);
  std::size_t colliding = 0;
  for (const auto& c : all) {
    const json &no = row(c, "s"), &exact = row(c, "exact");
    BOOST_TEST(no["collide"] == false);
    BOOST_TEST(no["agrees"] == (exact["collide"] == false), c["file"]);
    if (exact["collide"] == true) {
      ++colliding;
      BOOST_TEST(no["cause"].is_string(), c["file"]);
    }
  }
  BOOST_TEST(colliding >= 2u);
}

// Each misbehaving subject: every scene still gets a row, the faults carry
// their cause, the subject is restarted after each, and nothing is left running.
BOOST_AUTO_TEST_CASE(crashes_hangs_and_garbage_are_findings_about_the_subject)
{
  std::vector<std::string> files = some_fixtures();
  struct Expect { std::string command, cause; };
  for (const Expect& e : {Expect{crash_on_second, "crash"}, Expect{hangs, "timeout"}, Expect{garbage, "protocol"}}) {
    json all = compare_json(files, e.command, 0.5);
    BOOST_TEST(all.size() == files.size());
    std::size_t faults = 0;
    for (const auto& c : all) {
      const json& s = row(c, "s");
      if (s["cause"] != e.cause) continue;
      ++faults;
      BOOST_TEST(s["ok"] == false);
      BOOST_TEST(!s["error"].get<std::string>().empty());
    }
    // crash on the 2nd request of each process: a fresh one answers the next.
    if (e.cause == "crash") BOOST_TEST(faults == files.size() / 2, e.cause);
    else BOOST_TEST(faults == files.size(), e.cause);
    BOOST_TEST(leftovers() == 0u, e.cause);
  }
}

BOOST_AUTO_TEST_CASE(a_fuzz_campaign_saves_subject_faults_as_replayable_scenes)
{
  fs::path dir = fs::temp_directory_path() / ("clash4d_test_subjects_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  Fuzz_options o;
  o.seed = 3;
  o.cases = 8;
  o.out = dir.string();
  o.max_shrink_checks = 4;
  o.compare.externals.push_back(std::make_shared<External_pool>(Subject_spec{"crashy", crash_on_second, 2}));
  std::ostringstream err;
  Fuzz_summary s = run_fuzz(o, err);
  o.compare.externals.clear();
  BOOST_TEST(s.done == 8u);
  std::size_t crashes = 0;
  for (const auto& f : fs::directory_iterator(dir / "findings")) {
    Scene scene = read_scene_file(f.path().string());   // a scene as it is
    std::ifstream in(f.path());
    json meta = json::parse(in)["meta"];
    for (const auto& d : meta["disagreements"]) crashes += d["subject"] == "crashy" && d["cause"] == "crash";
    BOOST_TEST(run({"check", f.path().string()}).status <= 1);
  }
  BOOST_TEST(crashes >= 2u);   // several workers' processes each crash on their second case
  BOOST_TEST(leftovers() == 0u);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(subject_arguments_are_checked)
{
  BOOST_TEST(run({"compare", fixture("contact/face_touch_static.json"), "--subject", "nocommand"}).status == 2);
  BOOST_TEST(run({"compare", fixture("contact/face_touch_static.json"), "--subject", "exact=true"}).status == 2);
  BOOST_TEST(run({"compare", fixture("contact/face_touch_static.json"), "--subject", "a=x", "--subject", "a=y"}).status == 2);
  BOOST_TEST(run({"compare", fixture("contact/face_touch_static.json"), "--subject", "a=x", "--subject-timeout", "0"}).status == 2);
}

#ifdef CLASH4D_PYTHON
// The naive sampling engine of examples/subjects: a block passing through a
// thin wall between two of its 21 instants tunnels (exact: collision, it:
// none, far from contact: arithmetic); faces touching at rest are a
// collision to it (closed, with tolerance), which is right in its own terms.
BOOST_AUTO_TEST_CASE(the_python_sampling_subject_tunnels_and_counts_touching)
{
  fs::path dir = fs::temp_directory_path() / ("clash4d_test_python_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string tunnel = (dir / "tunnel.json").string(), touch = (dir / "touch.json").string();
  std::ofstream(tunnel) << Scene_builder("bullet through a wall", 0, 1)
                               .object("wall", block(vec(0, 0, 0), vec(Rational(1, 10), 1, 1)))
                               .object("bullet", block(vec(Rational(-523, 100), 0, 0), vec(Rational(-513, 100), 1, 1)),
                                       steady(vec(10, 0, 0)))
                               .text();
  std::ofstream(touch) << Scene_builder("faces touching", 0, 1)
                              .object("a", block(vec(0, 0, 0), vec(1, 1, 1)))
                              .object("b", block(vec(1, 0, 0), vec(2, 1, 1)))
                              .text();
  // Apart by 2^-34 (about 5.8e-11, exact in doubles): within its tolerance
  // 1e-9, so a collision to it; exact closed says no, and exact with one
  // block moved 1e-9 along x says yes: cause tolerance (compare/Tolerance_judge.h).
  std::string near = (dir / "near.json").string();
  std::ofstream(near) << Scene_builder("faces 2^-34 apart", 0, 1)
                             .object("a", block(vec(0, 0, 0), vec(1, 1, 1)))
                             .object("b", block(vec(rational_from_string("17179869185/17179869184"), 0, 0), vec(2, 1, 1)))
                             .text();
  json all = compare_json({tunnel, touch, near}, std::string(CLASH4D_PYTHON) + " " + CLASH4D_SOURCE "/examples/subjects/sampling_subject.py");
  const json& n = row(all[2], "s");
  BOOST_TEST(row(all[2], "exact closed")["collide"] == false);
  BOOST_TEST(n["collide"] == true);
  BOOST_TEST(n["cause"] == "tolerance");
  const json &t = row(all[0], "s"), &c = row(all[1], "s");
  BOOST_TEST(row(all[0], "exact")["collide"] == true);
  BOOST_TEST(t["collide"] == false);
  BOOST_TEST(t["cause"] == "arithmetic");
  BOOST_TEST(t["semantics"] == "closed");
  BOOST_TEST(row(all[1], "exact")["collide"] == false);
  BOOST_TEST(row(all[1], "exact closed")["collide"] == true);
  BOOST_TEST(c["collide"] == true);
  BOOST_TEST(c["agrees"] == true);
  fs::remove_all(dir);
}
#endif

// Issue 59 item 7: a subject's grandchild that left its group (setsid) is
// gone at the end of the run, as is the subject.
BOOST_AUTO_TEST_CASE(nothing_a_subject_started_outlives_a_normal_end)
{
  // This test program owns its children, as the clash4d command does.
  subject_processes::keep_descendants();
  fs::path dir = scratch("escape");
  fs::path pids = dir / "pids";
  compare_json({fixture("contact/face_touch_static.json"), fixture("contact/clear_collision_head_on.json")},
               escaping(pids, false));
  std::vector<pid_t> started = pids_in(pids);
  BOOST_TEST(started.size() == 2u);
  std::vector<pid_t> left = still_there(started);
  BOOST_TEST(left.empty(), left.size() << " of the subject's processes left running");
  kill_left(left);
  BOOST_TEST(leftovers() == 0u);
  fs::remove_all(dir);
}

// Issue 59 item 7: SIGTERM or SIGINT to `clash4d fuzz` with hung subjects
// kills them and what they started, then ends clash4d by that signal;
// kill -9 still takes the subjects (their parent-death signal).
BOOST_AUTO_TEST_CASE(nothing_a_subject_started_outlives_a_signal_to_fuzz)
{
  for (int sig : {SIGTERM, SIGINT, SIGKILL}) {
    fs::path dir = scratch("signal");
    fs::path pids = dir / "pids";
    pid_t fuzz = spawn_clash4d({"fuzz", "--cases", "4", "--out", (dir / "fz").string(), "--subject",
                                "e=" + escaping(pids, true), "--subject-timeout", "300"});
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (pids_in(pids).empty() && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    std::this_thread::sleep_for(std::chrono::milliseconds(200));   // its request sent: it hangs
    ::kill(fuzz, sig);
    int status = 0;
    while (::waitpid(fuzz, &status, 0) < 0 && errno == EINTR) {}
    BOOST_TEST((WIFSIGNALED(status) && WTERMSIG(status) == sig), "signal " << sig << ", status " << status);
    std::vector<pid_t> started = pids_in(pids), watched;
    BOOST_TEST_REQUIRE(!started.empty());
    for (std::size_t i = 0; i < started.size(); ++i)
      if (sig != SIGKILL || i % 2 == 0) watched.push_back(started[i]);   // kill -9: the leaders only (spec)
    std::vector<pid_t> left = still_there(watched);
    BOOST_TEST(left.empty(), "signal " << sig << ": " << left.size() << " processes left running");
    kill_left(started);
    fs::remove_all(dir);
  }
}

// Issue 59 item 6: --max-seconds bounds the wait for a hung subject in
// compare, report and fuzz: exit 3 naming the budget, no answer, no report,
// nothing left running (each run would take the 60 s time limit otherwise).
BOOST_AUTO_TEST_CASE(max_seconds_bounds_the_wait_for_a_hung_subject)
{
  fs::path dir = scratch("budget");
  std::string scene = fixture("contact/face_touch_static.json");
  std::vector<std::string> subject{"--subject", "s=" + hangs, "--subject-timeout", "60", "--max-seconds", "1"};
  std::vector<std::vector<std::string>> runs{{"compare", scene},
                                             {"report", scene, "--out", (dir / "report").string()},
                                             {"fuzz", "--cases", "4", "--out", (dir / "fz").string()}};
  auto start = std::chrono::steady_clock::now();
  for (auto args : runs) {
    args.insert(args.end(), subject.begin(), subject.end());
    Cli_result r = run(args);
    BOOST_TEST(r.status == 3, args[0] << ": " << r.err);
    BOOST_TEST(r.out.empty(), args[0]);
    BOOST_TEST(r.err.find("the work budget of --max-seconds 1 ran out") != std::string::npos, r.err);
  }
  BOOST_TEST(!fs::exists(dir / "report"));
  BOOST_TEST(seconds_since(start) < 50);
  BOOST_TEST(leftovers() == 0u);
  fs::remove_all(dir);
}

// Issue 59 item 9: a subject that dies while a child of its holds its output
// open is a crash at once, not after the time limit.
BOOST_AUTO_TEST_CASE(a_subject_that_exits_is_reported_at_once)
{
  const std::string dies_on_second = hello + "n=0; while read -r line; do " + read_id +
      R"(n=$((n+1)); if [ $n -ge 2 ]; then sleep 937 & exit 3; fi; echo "{\"id\":$id,\"collide\":false}"; done)";
  auto start = std::chrono::steady_clock::now();
  json all = compare_json(some_fixtures(), dies_on_second, 60);
  std::size_t crashes = 0;
  for (const auto& c : all) {
    const json& s = row(c, "s");
    if (s["cause"] != "crash") continue;
    ++crashes;
    BOOST_TEST(s["error"] == "exited with status 3");
  }
  BOOST_TEST(crashes == some_fixtures().size() / 2);
  BOOST_TEST(seconds_since(start) < 50);   // 3 crashes: 180 s when each waited out its time limit
  BOOST_TEST(leftovers() == 0u);
}

// Issue 59 item 17: a subject that never says hello is reported with the
// cause, at once where there is one.
BOOST_AUTO_TEST_CASE(no_hello_is_reported_with_its_cause)
{
  struct Expect { std::string command; double timeout; std::string error; };
  auto start = std::chrono::steady_clock::now();
  for (const Expect& e : {Expect{"exec >&-; sleep 937", 60, "it closed its output before its hello line"},
                          Expect{"sleep 937 & exit 4", 60, "exited with status 4 before its hello line"},
                          Expect{"sleep 937", 0.5, "did not say hello within 0.5 s (--subject-timeout)"}}) {
    json all = compare_json({fixture("contact/face_touch_static.json")}, e.command, e.timeout);
    const json& s = row(all[0], "s");
    BOOST_TEST(s["cause"] == (e.timeout < 1 ? "timeout" : "crash"), e.command);
    BOOST_TEST(s["error"] == e.error, e.command);
  }
  BOOST_TEST(seconds_since(start) < 50);
  BOOST_TEST(leftovers() == 0u);
}

// Issue 59 item 17: the findings fuzz prints are the folder's, even when
// another run wrote one meanwhile (here the subject plays that run).
BOOST_AUTO_TEST_CASE(fuzz_prints_the_findings_its_folder_holds)
{
  fs::path dir = scratch("count");
  fs::path other = dir / "fz" / "findings" / "case-999.json";
  std::string writes_a_finding = "echo '{}' > '" + other.string() + "'; " + always_no;
  Cli_result r = run({"fuzz", "--cases", "2", "--out", (dir / "fz").string(), "--subject", "s=" + writes_a_finding});
  std::size_t held = 0;
  for (const auto& f : fs::directory_iterator(dir / "fz" / "findings"))
    held += f.path().extension() == ".json" && f.path().string().find(".min.json") == std::string::npos;
  BOOST_TEST(fs::exists(other));
  BOOST_TEST(r.out.find(", " + std::to_string(held) + " findings in") != std::string::npos, r.out << r.err);
  fs::remove_all(dir);
}
