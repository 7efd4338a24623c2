#include "cli/Campaign_commands.h"
#include "compare/Ccd_query_files.h"
#include "compare/External_subject.h"
#include "compare/Report_cache.h"
#include "compare/Report_writer.h"
#include "scene/Input_error.h"
#include "scene/Files.h"
#include "scene/Scene_reader.h"
#include "run/Work_budget.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <climits>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>

namespace clash4d {
namespace fs = std::filesystem;

void add_subject_options(CLI::App& command, Subject_args& args)
{
  command.add_option("--subject", args.subjects,
                     "NAME=COMMAND: an external collision engine run by /bin/sh -c COMMAND, speaking the protocol of "
                     "docs/subject-protocol.md; repeatable. '--subject fcl' and '--subject bullet' select the built-in FCL "
                     "(same as --fcl) and Bullet subjects")
      ->allow_extra_args(false);   // one value per occurrence: the files after it stay files
  command.add_option("--subject-timeout", args.timeout_seconds,
                     "seconds an external subject may take per request before it is killed and restarted (default 10)")
      ->check(CLI::PositiveNumber);
}

bool apply_subject_args(const Subject_args& args, Compare_options& o, const char* command, std::ostream& err)
{
  std::vector<std::string> names;
  for (const auto& text : args.subjects) {
    if (text == "fcl") { o.fcl = true; continue; }
    if (text == "bullet") { o.bullet = true; continue; }
    try {
      Subject_spec spec = parse_subject_spec(text, args.timeout_seconds);
      if (std::find(names.begin(), names.end(), spec.name) != names.end())
        throw std::invalid_argument("--subject: two subjects are named '" + spec.name + "'");
      names.push_back(spec.name);
      o.externals.push_back(std::make_shared<External_pool>(spec));
    } catch (const std::invalid_argument& e) {
      err << "clash4d " << command << ": " << e.what() << "\n";
      return false;
    }
  }
  return true;
}

void add_builtin_subject_options(CLI::App& command, Builtin_subject_args& args)
{
  command
      .add_option("--tolerance", args.tolerances,
                  "a subject 'double tol=EPS': the double pipeline with |value| <= EPS taken as zero, where value is a "
                  "half-space's a x + b y + c z + d as written (not a distance: a plane written with coefficients of "
                  "size N moves by about EPS/N); repeatable (default 1e-9)")
      ->check(CLI::PositiveNumber)
      ->allow_extra_args(false);   // one value per occurrence: the files after it stay files
  command.add_flag("--fcl", args.fcl,
                   "also run FCL's continuous collision (the fcl subject) where FCL can express the scene; skipped "
                   "with the reason elsewhere (scenes only)");
  command.add_flag("--no-rounded", args.no_rounded,
                   "do not run the exact-rounded subject (exact on the scene rounded to doubles; often the slowest); "
                   "input rounding is then still told apart, by exact on the rounded scene where a verdict differs "
                   "(scenes; CCD queries always run it: it is cheap there)");
  command.add_flag("--no-doubles", args.no_doubles, "do not run the double subjects (double, double tol=EPS)");
}

void apply_builtin_subject_args(const Builtin_subject_args& args, Compare_options& o)
{
  if (!args.tolerances.empty()) o.tolerances = args.tolerances;
  o.fcl = o.fcl || args.fcl;
  o.rounded = !args.no_rounded;
  o.doubles = !args.no_doubles;
}

void add_ccd_options(CLI::App& command, Ccd_compare_args& args)
{
  command.add_option("--type", args.type,
                     "CCD query files: vf (vertex-face) or ee (edge-edge), for CSV files whose path names no type "
                     "(docs/ccd-queries.md)")
      ->check(CLI::IsMember({"vf", "ee", "vertex-face", "edge-edge"}));
  command.add_option("--time-bound", args.time_bound,
                     "with earliest times: the largest |t* - exact t*| that is no disagreement (default 1e-9; beyond "
                     "it the cause is time), for scenes and CCD queries")
      ->check(CLI::NonNegativeNumber);
}

Ccd_compare_options ccd_options_of(const Compare_options& o, const Ccd_compare_args& args)
{
  Ccd_compare_options c;
  c.tolerances = o.tolerances;
  c.earliest = o.earliest;
  c.time_bound = args.time_bound;
  c.externals = o.externals;
  return c;
}

std::optional<Ccd_type> ccd_type_of(const Ccd_compare_args& args)
{
  return args.type.empty() ? std::nullopt : ccd_type_from_name(args.type);
}

namespace {

// A whole non-negative decimal number, or none.
std::optional<std::uint64_t> whole_number(const char* text)
{
  if (!text || !*text) return std::nullopt;
  std::uint64_t n = 0;
  for (const char* c = text; *c; ++c) {
    if (*c < '0' || *c > '9' || n > (UINT64_MAX - 9) / 10) return std::nullopt;
    n = 10 * n + static_cast<std::uint64_t>(*c - '0');
  }
  return n;
}

// K and S from the scheduler's variables; a message in `problem` when they are wrong.
bool shard_from_scheduler(std::uint64_t count, const std::function<const char*(const char*)>& env, Campaign_options& o,
                          std::string& problem)
{
  if (const char* k8s = env("JOB_COMPLETION_INDEX")) {
    std::optional<std::uint64_t> i = whole_number(k8s);
    if (!i) return problem = std::string("JOB_COMPLETION_INDEX is not a number: '") + k8s + "'", false;
    if (count == 0) return problem = "a Kubernetes Indexed Job needs --shard-count S (its completions)", false;
    o.shard = *i + 1;
    o.shards = count;
    return true;
  }
  if (const char* slurm = env("SLURM_ARRAY_TASK_ID")) {
    std::optional<std::uint64_t> id = whole_number(slurm), min = whole_number(env("SLURM_ARRAY_TASK_MIN")),
                                 n = whole_number(env("SLURM_ARRAY_TASK_COUNT"));
    if (!id) return problem = std::string("SLURM_ARRAY_TASK_ID is not a number: '") + slurm + "'", false;
    if (count != 0 && n && *n != count)
      return problem = "--shard-count " + std::to_string(count) + " but SLURM_ARRAY_TASK_COUNT is " + std::to_string(*n), false;
    if (count == 0 && !n) return problem = "SLURM_ARRAY_TASK_COUNT is not set: give --shard-count S", false;
    std::uint64_t base = min.value_or(0);
    if (*id < base) return problem = "SLURM_ARRAY_TASK_ID is below SLURM_ARRAY_TASK_MIN", false;
    o.shard = *id - base + 1;
    o.shards = count ? count : *n;
    return true;
  }
  if (count != 0) return problem = "--shard-count needs SLURM_ARRAY_TASK_ID or JOB_COMPLETION_INDEX (or use --shard K/S)", false;
  o.shard = o.shards = 1;
  return true;
}

} // namespace

bool resolve_shard(const std::string& shard, std::uint64_t shard_count, const std::function<const char*(const char*)>& env,
                   Campaign_options& o, std::ostream& err)
{
  std::string problem;
  if (!shard.empty()) {
    auto slash = shard.find('/');
    std::optional<std::uint64_t> k = whole_number(shard.substr(0, slash).c_str()),
                                 s = slash == std::string::npos ? std::nullopt : whole_number(shard.substr(slash + 1).c_str());
    o.shard = k.value_or(0);
    o.shards = s.value_or(0);
    if (shard_count != 0 && shard_count != o.shards) problem = "--shard-count differs from the S of --shard K/S";
  } else if (!shard_from_scheduler(shard_count, env, o, problem)) {
    err << "clash4d fuzz: " << problem << "\n";
    return false;
  }
  if (problem.empty() && (o.shards == 0 || o.shard == 0 || o.shard > o.shards))
    problem = "--shard expects K/S with 1 <= K <= S, found '" +
              (shard.empty() ? std::to_string(o.shard) + "/" + std::to_string(o.shards) + "' (from the scheduler)" : shard + "'");
  if (!problem.empty()) {
    err << "clash4d fuzz: " << problem << "\n";
    return false;
  }
  return true;
}

namespace {

int campaign_command(const Campaign_options& options, const std::function<Fuzz_summary()>& run, std::ostream& out,
                     std::ostream& err)
{
  try {
    Fuzz_summary s = run();
    Work_budget::check();   // past --max-seconds no summary is printed (exit 3)
    out << options.out << ": shard " << options.shard << "/" << options.shards << ", " << s.done << " cases"
        << (s.resumed_from ? " (resumed at case " + std::to_string(s.resumed_from) + ")" : "") << ", " << s.findings
        << " findings in " << (fs::path(options.out) / "findings").string() << "\n";
    return s.findings ? 1 : 0;
  } catch (const std::exception& e) {
    err << "clash4d fuzz: " << e.what() << "\n";
    return CLASH4D_EXIT_INVALID;
  }
}

} // namespace

int fuzz_command(const Fuzz_options& options, std::ostream& out, std::ostream& err)
{
  return campaign_command(options, [&] { return run_fuzz(options, err); }, out, err);
}

int fuzz_command(const Ccd_fuzz_options& options, std::ostream& out, std::ostream& err)
{
  return campaign_command(options, [&] { return run_ccd_fuzz(options, err); }, out, err);
}

int merge_command(const std::vector<std::string>& dirs, const std::string& out_dir, std::ostream& out, std::ostream& err)
{
  try {
    Fuzz_summary s = merge_fuzz(dirs, out_dir);
    out << out_dir << ": " << s.findings << " findings merged from " << dirs.size() << " folders\n";
    return 0;
  } catch (const std::exception& e) {
    err << "clash4d fuzz --merge: " << e.what() << "\n";
    return CLASH4D_EXIT_INVALID;
  }
}

namespace {

// One input of a report: a saved fuzz finding (read back: no need to
// rerun it), a scene file (compared, or taken from DIR/cases), or a file of
// CCD queries (a case per query).
struct Report_item {
  enum class Kind { finding, scene, queries } kind;
  fs::path file;
  fs::path original;   // a minimised finding's unminimised scene
};

// A fuzz folder's findings, each once (issue 60): the minimised scene with
// its original linked, or the original alone where no minimum was saved
// (a campaign interrupted between the two).
void add_fuzz_folder(const fs::path& dir, std::vector<Report_item>& items)
{
  std::vector<fs::path> files;
  for (const auto& f : fs::directory_iterator(dir / "findings"))
    if (f.path().extension() == ".json" && f.path().string().find(".min.json") == std::string::npos)
      files.push_back(f.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    fs::path min = f;
    min.replace_extension(".min.json");
    if (fs::exists(min)) items.push_back({Report_item::Kind::finding, min, f});
    else items.push_back({Report_item::Kind::finding, f, {}});
  }
}

// A folder's scene and query files, by name.
std::vector<fs::path> folder_files(const fs::path& dir)
{
  std::vector<fs::path> files;
  for (const auto& f : fs::directory_iterator(dir)) {
    std::string e = f.path().extension().string();
    bool queries = e == ".csv" || e == ".jsonl" || e == ".ndjson";
    if (queries || (e == ".json" && f.path().filename() != "expected.json")) files.push_back(f.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

void add_file(const fs::path& file, std::vector<Report_item>& items)
{
  items.push_back({is_ccd_query_file(file.string()) ? Report_item::Kind::queries : Report_item::Kind::scene, file, {}});
}

std::vector<Report_item> report_items(const Report_inputs& inputs)
{
  std::vector<Report_item> items;
  for (const auto& input : inputs.paths) {
    fs::path p(input);
    if (fs::is_directory(p / "findings")) add_fuzz_folder(p, items);
    else if (!fs::is_directory(p)) add_file(p, items);
    else
      for (const auto& f : folder_files(p)) add_file(f, items);
  }
  return items;
}

Scene read_report_scene(const fs::path& file, const std::vector<std::string>& mesh_folders)
{
  try {
    return read_scene_file(file.string(), mesh_folders);
  } catch (const Input_error& e) {
    throw std::runtime_error(e.format(file.string()));
  }
}

void add_finding(const Report_item& item, std::vector<Report_case>& cases)
{
  std::string f = item.file.string();
  nlohmann::ordered_json document = read_json_document(f);
  std::string family = document.value("meta", nlohmann::ordered_json::object()).value("family", "");
  if (is_ccd_finding(document)) {
    cases.push_back(ccd_report_case(f, finding_ccd_comparison(document, f), family));
  } else {
    cases.push_back({f, read_report_scene(item.file, {}), finding_comparison(document, f), family});
  }
  cases.back().original = item.original.string();
}

// A scene's comparison: the one DIR/cases keeps for the same key, else
// compared now and kept.
void add_scene(const Report_item& item, const Report_inputs& inputs, const Report_cache& cache,
               std::vector<Report_case>& cases)
{
  std::string f = item.file.string();
  Scene scene = read_report_scene(item.file, inputs.mesh_folders);
  std::string key = Report_cache::key(f, scene, inputs.scenes);
  std::optional<Comparison> kept = inputs.fresh ? std::nullopt : cache.find(key);
  if (!kept) {
    kept = compare_scene(scene, f, inputs.scenes);
    cache.store(key, *kept);
  }
  cases.push_back({f, std::move(scene), std::move(*kept), ""});
}

// A case per query of the file.
void add_queries(const Report_item& item, const Report_inputs& inputs, std::vector<Report_case>& cases)
{
  std::vector<Ccd_query> queries;
  try {
    queries = read_ccd_queries(item.file.string(), inputs.type);
  } catch (const Input_error& e) {
    throw std::runtime_error(e.format(item.file.string()));
  }
  for (std::size_t i = 0; i < queries.size(); ++i)
    cases.push_back(ccd_report_case(item.file.string(), compare_query(queries[i], item.file.string(), i, inputs.queries), ""));
}

} // namespace

int report_command(const Report_inputs& inputs, const std::string& out_dir, std::ostream& out, std::ostream& err)
{
  Report_cache cache(out_dir);
  try {
    std::vector<Report_item> items = report_items(inputs);
    Progress_line shown(inputs.progress, err, "clash4d report");
    Report_inputs run = inputs;
    std::string at;   // "k/n FILE" of the item under way
    run.scenes.on_subject = [&](const std::string& subject) { shown.show(at + ": " + subject); };
    std::vector<Report_case> cases;
    for (std::size_t k = 0; k < items.size(); ++k) {
      at = std::to_string(k + 1) + "/" + std::to_string(items.size()) + " " + items[k].file.string();
      shown.show(at);
      switch (items[k].kind) {
        case Report_item::Kind::finding: add_finding(items[k], cases); break;
        case Report_item::Kind::scene: add_scene(items[k], run, cache, cases); break;
        case Report_item::Kind::queries: add_queries(items[k], run, cases); break;
      }
    }
    shown.show(std::to_string(items.size()) + "/" + std::to_string(items.size()) + " inputs compared", true);
    Work_budget::check();   // past --max-seconds no report is written (exit 3)
    write_report(cases, out_dir);
    std::size_t disagreeing = 0;
    for (const auto& c : cases) disagreeing += c.comparison.has_disagreement();
    out << out_dir << ": " << cases.size() << " cases, " << disagreeing << " with disagreements (index.html, report.json, junit.xml)\n";
    return disagreeing ? 1 : 0;
  } catch (const Budget_exceeded&) {
    err << "clash4d report: stopped; " << cache.size() << " comparisons are kept in "
        << (fs::path(out_dir) / "cases").string() << ": the same command resumes from them\n";
    throw;
  } catch (const std::exception& e) {
    err << "clash4d report: " << e.what() << "\n";
    return CLASH4D_EXIT_INVALID;
  }
}

} // namespace clash4d
