#include "compare/Fuzz_campaign.h"
#include "compare/Rotation_families.h"
#include "compare/Contact_families.h"
#include "compare/External_subject.h"
#include "compare/Shrinker.h"
#include "scene/Files.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include "scene/Scene_writer.h"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <tbb/parallel_for.h>

namespace clash4d {
namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

json campaign_json(const Fuzz_options& o)
{
  json c = {{"format", "clash4d-fuzz/1"}, {"seed", o.seed}, {"cases", o.cases}, {"tolerances", o.compare.tolerances}};
  if (o.compare.fcl) c["fcl"] = true;   // only when on, so folders of campaigns without it still match
  if (o.compare.semantics == Semantics::closed) c["semantics"] = "closed";
  if (o.compare.bullet) c["bullet"] = true;
  if (!o.compare.externals.empty()) c["subjects"] = subjects_json(o.compare.externals);
  if (o.rotation) c["families"] = "rotation";   // only when on, as fcl
  return c;
}

// The campaign folder: created, or checked to hold this very campaign.
void prepare(const Campaign_options& o, const json& want)
{
  fs::create_directories(fs::path(o.out) / "findings");
  std::string path = (fs::path(o.out) / "campaign.json").string();
  if (fs::exists(path)) {
    if (read_json_document(path) != want)
      throw std::runtime_error(path + ": this folder holds another campaign (seed, cases, tolerances, --semantics, --fcl, --ccd, --rotation or --subject differ)");
  } else {
    write_file_atomically(path, want.dump(2) + "\n");
  }
}

std::string file_text(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string progress_path(const Campaign_options& o)
{
  return (fs::path(o.out) / ("progress-" + std::to_string(o.shard) + "-of-" + std::to_string(o.shards) + ".json")).string();
}

// One run per shard of a folder at a time: a second one would redo the same
// cases and print counts the folder does not hold. The lock is the kernel's
// (flock), so a killed run leaves none behind.
class Shard_lock {
public:
  explicit Shard_lock(const Campaign_options& o)
  {
    std::string path = (fs::path(o.out) / ("lock-" + std::to_string(o.shard) + "-of-" + std::to_string(o.shards))).string();
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0) throw std::runtime_error(path + ": cannot open the campaign's lock: " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) return;
    int why = errno;
    ::close(fd_);
    if (why == EWOULDBLOCK)
      throw std::runtime_error(path + ": another clash4d fuzz is running shard " + std::to_string(o.shard) + "/" +
                               std::to_string(o.shards) + " in this folder (it holds this lock); wait for it to end, "
                               "or give another --out");
    throw std::runtime_error(path + ": cannot take the campaign's lock: " + std::strerror(why));
  }
  ~Shard_lock() { ::close(fd_); }
  Shard_lock(const Shard_lock&) = delete;
  Shard_lock& operator=(const Shard_lock&) = delete;

private:
  int fd_;
};

// The findings the folder holds (every shard's): what a run reports.
std::uint64_t count_findings(const Campaign_options& o)
{
  std::uint64_t n = 0;
  for (const auto& f : fs::directory_iterator(fs::path(o.out) / "findings"))
    n += f.path().string().find(".min.json") == std::string::npos && f.path().extension() == ".json";
  return n;
}

// Shrinks while the first disagreement (same subject, same cause) persists,
// running only the subjects that decide it.
Scene shrink(const Fuzz_options& o, const Scene& scene, const Disagreement& first)
{
  std::string key = first.subject + ": " + first.cause;
  Compare_options narrow = narrowed_to(o.compare, first.subject);
  narrow.fcl = o.compare.fcl && first.subject == "fcl";
  narrow.bullet = o.compare.bullet && first.subject == "bullet";
  auto still_fails = [&](const Scene& candidate) {
    std::vector<std::string> k = compare_scene(candidate, "", narrow).disagreement_keys();
    return std::find(k.begin(), k.end(), key) != k.end();
  };
  return shrink_scene(scene, still_fails, o.max_shrink_checks);
}

// Compares one case; on disagreement saves it, shrinks it, saves the minimum.
bool run_case(const Fuzz_options& o, std::uint64_t index)
{
  Fuzz_case c = o.rotation ? make_rotation_case(o.seed, index).scene : make_fuzz_case(o.seed, index);
  Scene scene = read_scene(read_json_text(c.json));
  std::string name = "case-" + std::to_string(index);
  Comparison comparison = compare_scene(scene, name, o.compare);
  if (!comparison.has_disagreement()) return false;
  // A finding is a scene file (check, compare and validate take it as it
  // is); where it came from goes under its `meta` key (spec). Timings are
  // left out: they differ from run to run, and findings must not.
  json found = finding_meta(o, c.family, index, comparison);
  found["comparison"] = comparison.reproducible().to_json();
  write_file_atomically(finding_path(o, index, ".json"), write_scene(scene, found));
  const Disagreement& first = comparison.disagreements.front();
  bool fault = is_fault(first.cause);
  Scene small = fault ? scene : shrink(o, scene, first);
  Comparison again = fault ? comparison : compare_scene(small, name + ".min", o.compare);
  json meta = finding_meta(o, c.family, index, again);
  meta["comparison"] = again.reproducible().to_json();
  meta["shrunk_from"] = name + ".json";
  meta["disagreement"] = disagreement_meta(comparison, first);
  if (fault) meta["not_shrunk"] = "a subject's crash, time-out or protocol fault may depend on its state";
  write_file_atomically(finding_path(o, index, ".min.json"), write_scene(small, meta));
  return true;
}

// done/total, the rate, the findings and the time left.
std::string campaign_progress(double seconds, std::uint64_t done, std::uint64_t total, std::uint64_t findings)
{
  double rate = seconds > 0 ? done / seconds : 0;
  double eta = rate > 0 ? (total - done) / rate : 0;
  std::ostringstream text;
  text << done << "/" << total << " cases, " << static_cast<int>(rate * 10) / 10.0 << "/s, " << findings
       << " findings, ETA " << static_cast<long>(eta) << " s";
  return text.str();
}

} // namespace

Fuzz_summary run_fuzz(const Fuzz_options& o, std::ostream& err)
{
  return run_campaign(o, campaign_json(o), [&](std::uint64_t index) { return run_case(o, index); }, err);
}

Fuzz_summary run_campaign(const Campaign_options& o, const json& description,
                          const std::function<bool(std::uint64_t)>& run_case, std::ostream& err)
{
  if (o.shards == 0 || o.shard == 0 || o.shard > o.shards) throw std::runtime_error("--shard K/S needs 1 <= K <= S");
  prepare(o, description);
  Shard_lock lock(o);
  // The cases of this shard: indices i with i mod S = K - 1, in order.
  std::vector<std::uint64_t> mine;
  for (std::uint64_t i = o.shard - 1; i < o.cases; i += o.shards) mine.push_back(i);
  Fuzz_summary s;
  std::string progress = progress_path(o);
  if (fs::exists(progress)) s.resumed_from = read_json_document(progress).value("next", 0u);
  std::size_t start = 0;
  while (start < mine.size() && mine[start] < s.resumed_from) ++start;
  std::atomic<std::uint64_t> findings{count_findings(o)};
  Progress_line shown(o.progress, err, "clash4d fuzz");
  const std::size_t batch = 16;
  for (std::size_t b = start; b < mine.size(); b += batch) {
    std::size_t end = std::min(mine.size(), b + batch);
    tbb::parallel_for(b, end, [&](std::size_t k) {
      bool known = fs::exists(finding_path(o, mine[k], ".json"));   // redone after an interruption
      if (run_case(mine[k]) && !known) ++findings;
    });
    // Only after the whole batch is saved does the progress move past it.
    std::uint64_t next = end < mine.size() ? mine[end] : o.cases;
    write_file_atomically(progress, json{{"next", next}}.dump() + "\n");
    s.done = end;
    shown.show(campaign_progress(shown.seconds(), end, mine.size(), findings), end == mine.size());
  }
  s.done = mine.size();
  s.findings = count_findings(o);   // the folder's, whoever else wrote to it
  return s;
}

std::string finding_path(const Campaign_options& o, std::uint64_t index, const std::string& suffix)
{
  return (fs::path(o.out) / "findings" / ("case-" + std::to_string(index) + suffix)).string();
}

json disagreement_meta(const Comparison& c, const Disagreement& d)
{
  const Subject_row* row = c.find(d.subject);
  json m = {{"subject", d.subject}, {"semantics", d.semantics}, {"cause", d.cause}, {"detail", d.detail}};
  if (row && row->tolerance) m["tolerance"] = *row->tolerance;
  return m;
}

json finding_meta(const Campaign_options& o, const std::string& family, std::uint64_t index, const Comparison& comparison)
{
  json disagreements = json::array();
  for (const auto& d : comparison.disagreements) disagreements.push_back(disagreement_meta(comparison, d));
  return {{"tool", "clash4d fuzz"}, {"family", family}, {"seed", o.seed}, {"index", index}, {"disagreements", disagreements}};
}

json subjects_json(const std::vector<std::shared_ptr<External_pool>>& externals)
{
  json list = json::array();
  for (const auto& pool : externals) list.push_back({{"name", pool->spec().name}, {"command", pool->spec().command}});
  return list;
}

bool is_fault(const std::string& cause) { return cause == "crash" || cause == "timeout" || cause == "protocol"; }

namespace {

// meta.comparison of a finding read as `read` reads it, errors naming the file.
template <class Read>
auto saved_comparison(const json& finding, const std::string& path, Read read)
{
  if (!finding.is_object() || !finding.contains("meta") || !finding["meta"].is_object() ||
      !finding["meta"].contains("comparison"))
    throw std::runtime_error(path + ": not a clash4d fuzz finding (no meta.comparison)");
  try {
    return read(finding["meta"]["comparison"]);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": meta." + e.what());
  }
}

} // namespace

Comparison finding_comparison(const json& finding, const std::string& path)
{
  if (is_ccd_finding(finding)) return finding_ccd_comparison(finding, path).comparison;
  return saved_comparison(finding, path, Comparison::from_json);
}

Ccd_comparison finding_ccd_comparison(const json& finding, const std::string& path)
{
  return saved_comparison(finding, path, Ccd_comparison::from_json);
}

bool is_ccd_finding(const json& finding) { return finding.is_object() && finding.contains("t0"); }

Fuzz_summary merge_fuzz(const std::vector<std::string>& dirs, const std::string& out)
{
  fs::create_directories(fs::path(out) / "findings");
  Fuzz_summary s;
  std::map<std::string, std::size_t> by_family, by_subject_cause;
  for (const auto& d : dirs) {
    fs::path findings = fs::path(d) / "findings";
    if (!fs::is_directory(findings)) throw std::runtime_error(d + ": not a fuzz output folder (no findings/)");
    for (const auto& f : fs::directory_iterator(findings)) {
      std::string extension = f.path().extension().string(), name = f.path().filename().string();
      if (extension != ".json" && extension != ".csv") continue;
      // Copied as they are: a CCD finding's JSON line must stay one line.
      std::string text = file_text(f.path());
      fs::path target = fs::path(out) / "findings" / name;
      if (fs::exists(target) && file_text(target) != text)
        throw std::runtime_error(target.string() + ": two campaigns disagree on this finding (different seeds?)");
      if (extension == ".csv") {
        write_file_atomically(target.string(), text);
        continue;
      }
      json finding = read_json_document(f.path().string());
      Comparison comparison = finding_comparison(finding, f.path().string());
      write_file_atomically(target.string(), text);
      if (name.find(".min.json") != std::string::npos) continue;
      ++s.findings;
      ++by_family[finding["meta"].value("family", "")];
      for (const auto& k : comparison.disagreement_keys()) ++by_subject_cause[k];
    }
  }
  json summary = {{"findings", s.findings}, {"by_family", by_family}, {"by_subject_and_cause", by_subject_cause}};
  write_file_atomically((fs::path(out) / "summary.json").string(), summary.dump(2) + "\n");
  return s;
}

} // namespace clash4d
