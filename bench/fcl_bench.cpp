// Per-query time of exact (the filtered kernel, `--number exact`), double
// (tolerance 0) and FCL's continuous collision (compare/Fcl_subject.h:
// conservative advancement on fcl::Convexd) on the same convex pairs under
// translation: box-box and hull-hull (12-point random hulls), each touching,
// separated and penetrating. Issue 6: FCL measured beside exact for speed.
//   clash4d_fcl_bench [--seed N] [--min-seconds S] [--repeat R] [--dump-scenes DIR]
// --repeat R (default 3) times every column R times, the columns taking
// turns, and keeps each one's least time (bench/Timing.h, time_in_turns).
// --dump-scenes writes each case's scene to DIR (box-box-touching.json, ...)
// to rerun or profile one with `clash4d check` or `clash4d_bench --scene`.
//
// What each column times: exact and double run `check` on the scene (their
// model is built from the scene's numbers on every query, as `check` does);
// "prep us" is exact's check on the scene prepared once (exact/
// Exact_checker.h: model, S-bounds, sweep and guides kept; the same answer,
// witness included), "fcl us" FCL's query alone on shapes converted once
// (how FCL is used), "fcl+build us" adds the conversion (exact hull,
// rounding, fcl::Convexd), which is what the comparer's fcl subject pays.
// "moved us" is exact's check on the shapes prepared once with the motions
// given per query (Exact_checker::check(motions, options)), as FCL takes
// new transforms per query: the queries alternate the scene's motions and
// the same restated (bench/Fcl_cases.h, restated_motions), so each query
// makes the motions, the sweep and the guides' motions again.
// "prep/fcl" and "moved/fcl" hold those queries beside FCL's; "exact/fcl"
// the whole check against FCL's prepared query.
#include "compare/Fcl_subject.h"
#include "bench/Bench_main.h"
#include "bench/Fcl_cases.h"
#include "bench/Option_number.h"
#include "bench/Timing.h"
#include "exact/Exact_checker.h"
#include "exact/Exact_instantiation.h"
#include "float/Double_instantiation.h"
#include "scene/Files.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

using namespace clash4d;
using namespace clash4d::fcl_cases;

namespace {

const char* verdict(bool c) { return c ? "collide" : "no"; }

void row(const Case& c, double min_seconds, int repeat)
{
  Check_options opts;
  Exact_checker prepared(c.scene);
  Fcl_subject fcl(c.scene);
  if (!fcl.expressible()) {
    std::printf("%-22s %s\n", c.name.c_str(), fcl.reason().c_str());
    return;
  }
  Exact_checker moving(c.scene);
  std::array<std::vector<Motion>, 2> motions = restated_motions(c.scene);
  int turn = 0;
  auto [e, p, m, d, f, fb] = time_in_turns(
      repeat, min_seconds, [&] { return check_exact(c.scene, opts).collide; },
      [&] { return prepared.check(opts).collide; },
      [&] { return moving.check(motions[turn ^= 1], opts).collide; },
      [&] { return check_double(c.scene, 0, opts).collide; }, [&] { return fcl.time_of_contact(0, 1).has_value(); },
      [&] { return Fcl_subject(c.scene).check(opts).collide; });
  double fq = f.seconds_per_query;
  std::printf("%-22s %9.2f %8.2f %8.2f %9.2f %9.2f %12.1f %9.2f %8.2f %9.2f %10.2f   %-7s %-7s %-7s\n", c.name.c_str(),
              e.seconds_per_query * 1e6, p.seconds_per_query * 1e6, m.seconds_per_query * 1e6,
              d.seconds_per_query * 1e6, fq * 1e6, fb.seconds_per_query * 1e6, e.seconds_per_query / fq,
              p.seconds_per_query / fq, m.seconds_per_query / fq, d.seconds_per_query / fq, verdict(e.collide),
              verdict(d.collide), verdict(f.collide));
  if (p.collide != e.collide) throw std::logic_error(c.name + ": the prepared check's verdict differs from check's");
  if (m.collide != e.collide) throw std::logic_error(c.name + ": the moved check's verdict differs from check's");
}

const char* usage = "usage: clash4d_fcl_bench [--seed N] [--min-seconds S] [--repeat R] [--dump-scenes DIR]\n";

int run_bench(int argc, char** argv)
{
  unsigned long seed = 1990;
  double min_seconds = 0.05;
  int repeat = 3;
  std::string dump_dir;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::printf("%s  times check per query, exact (filtered) and double, beside FCL's continuous collision,\n"
                  "  on box-box and hull-hull pairs (touching, separated, penetrating); each column timed\n"
                  "  --repeat times (default 3), the columns taking turns, its least time kept\n", usage);
      return 0;
    }
    auto value = [&](auto number) { return option_number<decltype(number)>(a, argv[++i]); };
    if (a == "--seed" && i + 1 < argc) seed = value(0ul);
    else if (a == "--min-seconds" && i + 1 < argc) min_seconds = value(0.0);
    else if (a == "--repeat" && i + 1 < argc) repeat = value(0);
    else if (a == "--dump-scenes" && i + 1 < argc) dump_dir = argv[++i];
    else {
      std::fprintf(stderr, "clash4d_fcl_bench: unknown option or missing value: %s\n%s", a.c_str(), usage);
      return 2;
    }
  }
  if (!(min_seconds > 0)) throw std::invalid_argument("--min-seconds must be positive");
  if (repeat < 1) throw std::invalid_argument("--repeat must be at least 1");
  if (!dump_dir.empty() && !std::filesystem::is_directory(dump_dir))
    throw std::invalid_argument("--dump-scenes " + dump_dir + ": not a directory");
  std::printf("clash4d_fcl_bench: seed %lu (hulls), at least %g s per measurement, the least of %d\n", seed,
              min_seconds, repeat);
  std::printf("%-22s %9s %8s %8s %9s %9s %12s %9s %8s %9s %10s   %-7s %-7s %-7s\n", "case", "exact us", "prep us",
              "moved us", "double us", "fcl us", "fcl+build us", "exact/fcl", "prep/fcl", "moved/fcl", "double/fcl",
              "exact", "double", "fcl");
  for (const Case& c : all_cases(seed)) {
    if (!dump_dir.empty()) {
      std::string file = c.name;
      std::replace(file.begin(), file.end(), ' ', '-');
      write_file_atomically(dump_dir + "/" + file + ".json", c.json + "\n");
    }
    row(c, min_seconds, repeat);
  }
  return 0;
}

} // namespace

// Bad options end with a message naming them and exit 2.
int main(int argc, char** argv) { return bench_main("clash4d_fcl_bench", run_bench, argc, argv); }
