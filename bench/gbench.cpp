// `check` per-query time under Google Benchmark (Debian's libbenchmark-dev),
// one benchmark per case, number type and mode, so a run's JSON
// (--benchmark_out=FILE --benchmark_out_format=json; scripts/bench-record
// keeps it under bench/results/) can be compared with later ones
// (scripts/bench-compare). What is timed:
//   fcl/<pair>/{exact,prepared,moved,double,fcl}: the six convex pairs of
//     clash4d_fcl_bench (bench/Fcl_cases.h, seed 1990); prepared is exact on
//     the scene prepared once (exact/Exact_checker.h), moved exact on its
//     shapes prepared once, motions per query, fcl FCL's query alone
//     on shapes converted once (built with FCL only);
//   {paper,contact}/<fixture>/{exact,double}/{regularised,closed}[/earliest]:
//     every scene of fixtures/paper and fixtures/contact.
// Each run's counter `collide` (0/1) is its verdict. After the runs, a
// summary: per scene and mode the ratio exact/double (fcl: exact/fcl,
// double/fcl too) and each family's geometric mean (issue 6's targets: 1.5
// general, 3 contact).
//   clash4d_gbench [--benchmark_filter=REGEX] [--benchmark_min_time=S] [...]
// --benchmark_filter picks families, scenes, numbers or modes (it is a
// regular expression on the names): `^contact/`, `/exact/`, `/closed`,
// `fcl/box-box touching`. The minimum time per benchmark is 0.05 s unless
// --benchmark_min_time is given (passed as the flag, not with MinTime(),
// which would put "min_time:..." in every name and break comparisons).
// Times are wall-clock (`real_time` in the JSON); the summary uses them.
#include "bench/Fcl_cases.h"
#include "bench/Fixtures.h"
#include "compare/Fcl_subject.h"
#include "exact/Exact_checker.h"
#include "exact/Exact_instantiation.h"
#include "float/Double_instantiation.h"
#include "scene/Scene_reader.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

using namespace clash4d;

namespace {

// Where a benchmark stands in the summary; its name is
// family/scene/number[/mode].
struct Entry {
  std::string family, scene, number, mode;
  std::string name() const { return family + "/" + scene + "/" + number + (mode.empty() ? "" : "/" + mode); }
};

std::vector<Entry> entries;   // in registration (and run) order

// One query, returning its verdict.
using Query = std::function<bool()>;

void add(Entry e, Query query)
{
  benchmark::RegisterBenchmark(e.name().c_str(), [query](benchmark::State& state) {
    bool collide = false;
    for (auto _ : state) {
      try {
        collide = query();
      } catch (const std::exception& ex) {   // a failed check is reported, not fatal to the run
        state.SkipWithError(ex.what());
        break;
      }
      benchmark::DoNotOptimize(collide);
    }
    state.counters["collide"] = collide;
  })->Unit(benchmark::kMicrosecond);
  entries.push_back(std::move(e));
}

// Every scene of fixtures/<family>, exact and double, in both semantics,
// plain and --earliest.
void add_fixtures(const char* family)
{
  for (const auto& file : fixture_files(family)) {
    auto scene = std::make_shared<const Scene>(read_scene_file(file.string()));
    for (Semantics semantics : {Semantics::regularised, Semantics::closed})
      for (bool earliest : {false, true}) {
        Check_options opts;
        opts.semantics = semantics;
        opts.earliest = earliest;
        std::string mode = std::string(semantics_name(semantics)) + (earliest ? "/earliest" : "");
        add({family, file.stem().string(), "exact", mode}, [scene, opts] { return check_exact(*scene, opts).collide; });
        add({family, file.stem().string(), "double", mode},
            [scene, opts] { return check_double(*scene, 0, opts).collide; });
      }
  }
}

// The six convex pairs: exact and double run `check` on the scene, prepared
// exact's check on the scene prepared once (the same answer), moved on its
// shapes prepared once with the motions given per query (restated_motions);
// fcl is FCL's query alone on shapes converted once (how FCL is used).
void add_fcl_pairs()
{
  for (fcl_cases::Case& c : fcl_cases::all_cases(1990)) {
    auto scene = std::make_shared<const Scene>(std::move(c.scene));
    add({"fcl", c.name, "exact", ""}, [scene] { return check_exact(*scene, Check_options()).collide; });
    auto prepared = std::make_shared<Exact_checker>(*scene);   // holds a reference to *scene
    add({"fcl", c.name, "prepared", ""}, [scene, prepared] { return prepared->check(Check_options()).collide; });
    auto moving = std::make_shared<Exact_checker>(*scene);
    auto motions = std::make_shared<std::array<std::vector<Motion>, 2>>(fcl_cases::restated_motions(*scene));
    add({"fcl", c.name, "moved", ""}, [scene, moving, motions, turn = 0]() mutable {
      return moving->check((*motions)[turn ^= 1], Check_options()).collide;
    });
    add({"fcl", c.name, "double", ""}, [scene] { return check_double(*scene, 0, Check_options()).collide; });
    auto fcl = std::make_shared<const Fcl_subject>(*scene);
    if (fcl->expressible()) add({"fcl", c.name, "fcl", ""}, [fcl] { return fcl->time_of_contact(0, 1).has_value(); });
    else std::fprintf(stderr, "clash4d_gbench: %s: %s\n", c.name.c_str(), fcl->reason().c_str());
  }
}

struct Measure {
  double seconds = 0;   // wall-clock per query, averaged over repetitions
  int runs = 0;
  bool collide = false;
};

// A column of the summary: the time ratio num/den in one mode.
struct Column {
  std::string label, mode, num, den;
};

std::vector<Column> columns_of(const std::string& family)
{
  if (family == "fcl") return {{"exact/double", "", "exact", "double"}, {"exact/fcl", "", "exact", "fcl"},
                               {"prepared/fcl", "", "prepared", "fcl"}, {"moved/fcl", "", "moved", "fcl"},
                               {"double/fcl", "", "double", "fcl"}};
  std::vector<Column> out;
  for (const char* mode : {"regularised", "closed", "regularised/earliest", "closed/earliest"})
    out.push_back({mode, mode, "exact", "double"});
  return out;
}

// s padded with spaces to width w, on the left (right-aligned) or right.
std::string pad(const std::string& s, std::size_t w, bool left = true)
{
  std::string fill(w > s.size() ? w - s.size() : 0, ' ');
  return left ? fill + s : s + fill;
}

std::string ratio_text(double ratio)
{
  char buf[32];
  std::snprintf(buf, sizeof buf, ratio >= 0.1 ? "%.2f" : "%.2g", ratio);   // small ratios keep two digits
  return buf;
}

// One family's table: a row per scene measured, its geometric mean per
// column last; '*' marks a ratio whose two verdicts differ.
void print_family(std::ostream& out, const std::string& family, const std::map<std::string, Measure>& measured)
{
  std::vector<Column> columns = columns_of(family);
  std::vector<std::string> scenes;
  for (const Entry& e : entries)
    if (e.family == family && measured.count(e.name()) && (scenes.empty() || scenes.back() != e.scene))
      scenes.push_back(e.scene);
  if (scenes.empty()) return;
  out << "\n" << family << ": time ratio per scene (* where the two verdicts differ)\n" << pad("", 50);
  for (const Column& c : columns) out << pad(c.label, 21) << " ";
  std::vector<double> log_sum(columns.size(), 0);
  std::vector<int> count(columns.size(), 0);
  for (const std::string& scene : scenes) {
    out << "\n" << pad(scene, 50, false);
    for (std::size_t i = 0; i < columns.size(); ++i) {
      auto n = measured.find(Entry{family, scene, columns[i].num, columns[i].mode}.name());
      auto d = measured.find(Entry{family, scene, columns[i].den, columns[i].mode}.name());
      if (n == measured.end() || d == measured.end()) {
        out << pad("-", 21) << " ";
        continue;
      }
      double ratio = n->second.seconds / d->second.seconds;
      log_sum[i] += std::log(ratio);
      ++count[i];
      out << pad(ratio_text(ratio), 21) << (n->second.collide == d->second.collide ? " " : "*");
    }
  }
  out << "\n" << pad("geometric mean over " + family, 50, false);
  for (std::size_t i = 0; i < columns.size(); ++i)
    out << pad(count[i] ? ratio_text(std::exp(log_sum[i] / count[i])) : "-", 21) << " ";
  out << "\n";
}

// The display reporter (--benchmark_format) forwarded to, remembering each
// run's time and verdict for the summary printed at the end: on the
// display's output when it is the console, else on its error stream (so
// --benchmark_format=json on stdout stays JSON).
class Summary_reporter : public benchmark::BenchmarkReporter {
public:
  explicit Summary_reporter(benchmark::BenchmarkReporter* display) : display_(display) {}

  bool ReportContext(const Context& context) override { return display_->ReportContext(context); }

  void ReportRuns(const std::vector<Run>& runs) override
  {
    for (const Run& r : runs) {
      if (r.error_occurred || r.run_type != Run::RT_Iteration || r.iterations == 0) continue;
      Measure& m = measured_[r.run_name.function_name];
      double seconds = r.real_accumulated_time / static_cast<double>(r.iterations);
      m.seconds = (m.seconds * m.runs + seconds) / (m.runs + 1);
      ++m.runs;
      auto c = r.counters.find("collide");
      m.collide = c != r.counters.end() && c->second.value != 0;
    }
    display_->ReportRuns(runs);
  }

  void Finalize() override
  {
    display_->Finalize();
    bool console = dynamic_cast<benchmark::ConsoleReporter*>(display_) != nullptr;
    std::ostream& out = console ? display_->GetOutputStream() : display_->GetErrorStream();
    for (const char* family : {"fcl", "paper", "contact"}) print_family(out, family, measured_);
    out.flush();
  }

private:
  benchmark::BenchmarkReporter* display_;   // the library's, not owned
  std::map<std::string, Measure> measured_;
};

void print_help()
{
  std::printf("usage: clash4d_gbench [--benchmark_filter=REGEX] [--benchmark_min_time=S (default 0.05)] ...\n"
              "  times check per query: fcl/<pair>/{exact,prepared,moved,double,fcl}, {paper,contact}/<fixture>/\n"
              "  {exact,double}/{regularised,closed}[/earliest]; then time ratios per scene and geometric means\n"
              "  per family\n\n");
  benchmark::PrintDefaultHelp();
}

// argv with --benchmark_min_time=0.05 first unless the caller gave one.
std::vector<char*> with_default_min_time(int argc, char** argv)
{
  static char default_min_time[] = "--benchmark_min_time=0.05";
  std::vector<char*> args(argv, argv + argc);
  bool given = false;
  for (int i = 1; i < argc; ++i) given = given || std::strncmp(argv[i], "--benchmark_min_time", 20) == 0;
  if (!given) args.insert(args.begin() + 1, default_min_time);
  args.push_back(nullptr);
  return args;
}

} // namespace

// Unknown options and unreadable fixtures end with a message and exit 2;
// a filter matching nothing with exit 1.
int main(int argc, char** argv)
{
  std::vector<char*> args = with_default_min_time(argc, argv);
  int count = static_cast<int>(args.size()) - 1;
  benchmark::Initialize(&count, args.data(), print_help);
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 2;
  try {
    if (Fcl_subject::built_in()) add_fcl_pairs();
    for (const char* family : {"paper", "contact"}) add_fixtures(family);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clash4d_gbench: %s\n", e.what());
    return 2;
  }
  Summary_reporter reporter(benchmark::CreateDefaultDisplayReporter());
  std::size_t ran = benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return ran > 0 ? 0 : 1;
}
