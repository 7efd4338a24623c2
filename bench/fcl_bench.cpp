// Per-query time of exact (the filtered kernel, `--number exact`), double
// (tolerance 0) and FCL's continuous collision (compare/Fcl_subject.h:
// conservative advancement on fcl::Convexd) on the same convex pairs under
// translation: box-box and hull-hull (12-point random hulls), each touching,
// separated and penetrating. Issue 6: FCL measured beside exact for speed.
//   clash4d_fcl_bench [--family translation|rotation|all] [--seed N] [--min-seconds S]
//                     [--repeat R] [--dump-scenes DIR] [--every-minor]
// --family (default all) picks the translation table, the rotation table
// (below) or both, translation first.
// --repeat R (default 3) times every column R times, the columns taking
// turns, and keeps each one's least time (bench/Timing.h, time_in_turns).
// --dump-scenes writes each case's scene to DIR (box-box-touching.json, ...)
// to rerun or profile one with `clash4d check` or `clash4d_bench --scene`.
// --every-minor: the rotation table with the critical times of every mixed
// minor of a convex pair, not only its vertex-face and edge-edge minors
// (Check_options::feature_events off): the cost before that restriction.
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
//
// The rotation section (issue 61; bench/Fcl_rotation_cases.h): box-box and
// hull-hull, one object turning about a fixed point by 90 degrees while the
// other rests, so FCL's screw motion (CCDM_SCREW, conservative advancement)
// sweeps the pose's configurations (regularised-semantics fact 13). Every
// query there asks for t* (--earliest). "exact us" is check_rotating on the
// scene (the shapes' planes, the pose segments, the critical times, the
// slices' static checks, all per query), "moved us" the same pair's time
// slices with the shapes' planes made once and the motions given per query
// (the scene's and the same restated, alternating: the pose segments made
// again each time), as the translation table's moved column; "fcl us" and
// "fcl+build us" as above, the latter through Fcl_subject::check, which maps
// FCL's time back to the pose's (Convex_motion.cpp, the change of time).
// "double us" is the same time slices in doubles (check_rotating with
// --number double, tolerance 0: the float subject), "ex/dbl" exact's time
// over it (the table ends with its geometric mean), and "dbl t*-exact" the
// double t*'s error ("DIFFER" when its verdict is not exact's).
// "verdict" says whether FCL's verdict is exact's, "t* fcl" is FCL's mapped
// time, "fcl-exact" its error, "within tol" whether that error is within
// FCL's time tolerance and how many tolerances it is: FCL's shape
// advancement stops once its step falls to 1e-4 of its time, which is at
// most 1e-4 pi/2 (tH - tL) of the pose's for these turns (q from 1 to
// 1 + v, |v| = 1: ds/du <= pi/2). The step is a distance over FCL's bound
// on the motion, so FCL may stop a few steps' worth before the contact.
#include "compare/Fcl_subject.h"
#include "bench/Bench_main.h"
#include "bench/Fcl_cases.h"
#include "bench/Fcl_rotation_cases.h"
#include "bench/Option_number.h"
#include "bench/Timing.h"
#include "exact/Exact_checker.h"
#include "exact/Exact_instantiation.h"
#include "float/Double_instantiation.h"
#include "rotation/Exact_slices.h"
#include "rotation/Rotating_check.h"
#include "scene/Files.h"

#include <algorithm>
#include <chrono>
#include <cmath>
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

// The rotation section's row (see the top): the exact answer is held to
// the case's construction (verdict, and t* exactly when rational), the moved
// query's to the whole check's.
// Returns exact's time over double's.
double rotation_row(const Turning_case& rc, double min_seconds, int repeat, bool every_minor)
{
  const Case& c = rc.c;
  Check_options opts;
  opts.earliest = true;
  opts.feature_events = !every_minor;
  Fcl_subject fcl(c.scene);
  if (!fcl.expressible()) {
    std::printf("%-26s %s\n", c.name.c_str(), fcl.reason().c_str());
    return 0;
  }
  if (std::string law = fcl.motion_law(); !law.empty())
    throw std::logic_error(c.name + ": FCL's motion is not the pose's: " + law);
  Rotating_object a = Rotating_object::make(c.scene.objects[0]), b = Rotating_object::make(c.scene.objects[1]);
  std::array<std::vector<Motion>, 2> motions = restated_turning_motions(c.scene);
  Exact_slices slices(&check_exact);
  int turn = 0;
  Rotating_answer moved_answer;
  auto moved = [&] {
    turn ^= 1;
    a.segments = pose_segments(motions[turn][0]);
    b.segments = pose_segments(motions[turn][1]);
    moved_answer = decide_rotating_pair(a, b, c.scene.t_lo, c.scene.t_hi, opts, slices);
    return moved_answer.collide;
  };
  Rotating_check_answer exact_answer, double_answer;
  Check_answer fcl_answer;
  auto [e, m, d, f, fb] = time_in_turns(
      repeat, min_seconds,
      [&] {
        exact_answer = check_rotating(c.scene, opts, "exact");
        return exact_answer.collide;
      },
      moved,
      [&] {
        double_answer = check_rotating(c.scene, opts, "double");
        return double_answer.collide;
      }, [&] { return fcl.time_of_contact(0, 1).has_value(); },
      [&] {
        fcl_answer = Fcl_subject(c.scene).check(opts);
        return fcl_answer.collide;
      });
  // The answers against the construction and each other.
  if (exact_answer.collide != rc.collide)
    throw std::logic_error(c.name + ": exact says " + verdict(exact_answer.collide) + ", the construction " + verdict(rc.collide));
  if (moved_answer.collide != exact_answer.collide)
    throw std::logic_error(c.name + ": the moved check's verdict differs from check's");
  std::string t_exact = "-", t_fcl = "-", diff = "-", within = "-", double_diff = "-";
  double fcl_tolerance = 1e-4 * (std::acos(-1.0) / 2) * round_to_nearest(c.scene.t_hi - c.scene.t_lo);
  if (exact_answer.collide) {
    const Algebraic& t = exact_answer.reported()->answer.t_star;
    if (moved_answer.t_star != t) throw std::logic_error(c.name + ": the moved check's t* differs from check's");
    if (rc.t0 ? !(t.is_rational() && t.rational() == *rc.t0) : (t.is_rational() || std::fabs(t.to_double() - rc.t_approx) > 1e-9))
      throw std::logic_error(c.name + ": exact t* " + t.to_text() + " is not the construction's");
    char buf[64];
    if (t.is_rational()) t_exact = to_string(t.rational());
    else {
      std::snprintf(buf, sizeof buf, "%.9f (irr.)", t.to_double());
      t_exact = buf;
    }
    if (double_answer.collide) {
      std::snprintf(buf, sizeof buf, "%+.1e", double_answer.reported()->answer.t_star.to_double() - t.to_double());
      double_diff = buf;
    }
    if (fcl_answer.collide) {
      const Pair_answer* p = fcl_answer.reported();
      double tf = std::stod(p->t_star);
      std::snprintf(buf, sizeof buf, "%.9f", tf);
      t_fcl = buf;
      std::snprintf(buf, sizeof buf, "%+.1e", tf - t.to_double());
      diff = buf;
      double tols = std::fabs(tf - t.to_double()) / fcl_tolerance;
      std::snprintf(buf, sizeof buf, "%s (%.1f)", tols <= 1 ? "yes" : "no", tols);
      within = buf;
    }
  }
  if (d.collide != e.collide) double_diff = "DIFFER";
  double fq = f.seconds_per_query, ratio = e.seconds_per_query / d.seconds_per_query;
  std::printf("%-26s %10.1f %10.1f %10.1f %6.2f %8.2f %12.1f %10.0f %10.0f   %-7s %-7s %-7s %-22s %-12s %-9s %-10s %s\n",
              c.name.c_str(), e.seconds_per_query * 1e6, m.seconds_per_query * 1e6, d.seconds_per_query * 1e6, ratio,
              fq * 1e6, fb.seconds_per_query * 1e6, e.seconds_per_query / fq, m.seconds_per_query / fq,
              verdict(e.collide), verdict(f.collide), e.collide == f.collide ? "same" : "DIFFER", t_exact.c_str(),
              t_fcl.c_str(), diff.c_str(), within.c_str(), double_diff.c_str());
  return ratio;
}

const char* usage = "usage: clash4d_fcl_bench [--family translation|rotation|all] [--seed N] [--min-seconds S] [--repeat R]\n"
                    "                         [--dump-scenes DIR] [--every-minor]\n";

void dump(const std::string& dir, const Case& c)
{
  if (dir.empty()) return;
  std::string file = c.name;
  std::replace(file.begin(), file.end(), ' ', '-');
  std::replace(file.begin(), file.end(), '/', '_');   // "hit 1/4"
  write_file_atomically(dir + "/" + file + ".json", c.json + "\n");
}

int run_bench(int argc, char** argv)
{
  unsigned long seed = 1990;
  double min_seconds = 0.05;
  int repeat = 3;
  std::string dump_dir, family = "all";
  bool every_minor = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::printf("%s  times check per query, exact (filtered) and double, beside FCL's continuous collision,\n"
                  "  on box-box and hull-hull pairs (touching, separated, penetrating); each column timed\n"
                  "  --repeat times (default 3), the columns taking turns, its least time kept;\n"
                  "  --family rotation: box-box and hull-hull, one turning about a fixed point, the other\n"
                  "  at rest, with t* (FCL's screw motion, its time mapped back to the pose's)\n", usage);
      return 0;
    }
    auto value = [&](auto number) { return option_number<decltype(number)>(a, argv[++i]); };
    if (a == "--seed" && i + 1 < argc) seed = value(0ul);
    else if (a == "--min-seconds" && i + 1 < argc) min_seconds = value(0.0);
    else if (a == "--repeat" && i + 1 < argc) repeat = value(0);
    else if (a == "--dump-scenes" && i + 1 < argc) dump_dir = argv[++i];
    else if (a == "--family" && i + 1 < argc) family = argv[++i];
    else if (a == "--every-minor") every_minor = true;
    else {
      std::fprintf(stderr, "clash4d_fcl_bench: unknown option or missing value: %s\n%s", a.c_str(), usage);
      return 2;
    }
  }
  if (!(min_seconds > 0)) throw std::invalid_argument("--min-seconds must be positive");
  if (repeat < 1) throw std::invalid_argument("--repeat must be at least 1");
  if (family != "translation" && family != "rotation" && family != "all")
    throw std::invalid_argument("--family " + family + ": not translation, rotation or all");
  if (!dump_dir.empty() && !std::filesystem::is_directory(dump_dir))
    throw std::invalid_argument("--dump-scenes " + dump_dir + ": not a directory");
  std::printf("clash4d_fcl_bench: seed %lu (hulls), at least %g s per measurement, the least of %d\n", seed,
              min_seconds, repeat);
  if (family != "rotation") {
    std::printf("%-22s %9s %8s %8s %9s %9s %12s %9s %8s %9s %10s   %-7s %-7s %-7s\n", "case", "exact us", "prep us",
                "moved us", "double us", "fcl us", "fcl+build us", "exact/fcl", "prep/fcl", "moved/fcl", "double/fcl",
                "exact", "double", "fcl");
    for (const Case& c : all_cases(seed)) {
      dump(dump_dir, c);
      row(c, min_seconds, repeat);
    }
  }
  if (family != "translation") {
    if (family == "all") std::printf("\n");
    std::printf("rotation: one object turns 90 degrees about a fixed point, the other rests; --earliest%s\n",
                every_minor ? "; every mixed minor (--every-minor)" : "");
    std::printf("%-26s %10s %10s %10s %6s %8s %12s %10s %10s   %-7s %-7s %-7s %-22s %-12s %-9s %-10s %s\n", "case",
                "exact us", "moved us", "double us", "ex/dbl", "fcl us", "fcl+build us", "exact/fcl", "moved/fcl",
                "exact", "fcl", "verdict", "t* exact", "t* fcl", "fcl-exact", "within tol", "dbl t*-exact");
    double log_ratio = 0;
    int rows = 0;
    for (const Turning_case& rc : all_rotation_cases(seed)) {
      dump(dump_dir, rc.c);
      if (double r = rotation_row(rc, min_seconds, repeat, every_minor); r > 0) {
        log_ratio += std::log(r);
        ++rows;
      }
    }
    if (rows > 0) std::printf("geometric mean of exact/double over %d rotation cases: %.2f\n", rows, std::exp(log_ratio / rows));
  }
  return 0;
}

} // namespace

// Bad options end with a message naming them and exit 2.
int main(int argc, char** argv) { return bench_main("clash4d_fcl_bench", run_bench, argc, argv); }
