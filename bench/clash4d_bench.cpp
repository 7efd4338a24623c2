// `check` per-query time on the paper scenes, the contact fixtures and seeded
// random general-position scenes: exact (the filtered kernel), rational (the
// pure rational kernel) and double side by side in one run, with the ratios
// exact/double and rational/double (issue 6's targets: 1.5 general, 3 contact),
// in regularised semantics and, beside them, in closed semantics (issue 14:
// the same targets).
//   clash4d_bench [--seed N] [--random M] [--fuzz K] [--min-seconds S] [--family F] [--dump-random DIR] [--earliest]
//                 [--scene FILE] [--repeat R]
// --repeat R times each scene's five columns R times (default 1), taking
// turns, and keeps each one's least time (bench/Timing.h, time_in_turns):
// for before-and-after comparisons on a shared machine.
// --earliest times `check --earliest` (t* and the contact point) everywhere.
// --every-minor: turning pairs of convex pieces take every mixed minor's
// critical times, not only their vertex-face and edge-edge minors' (the
// cost before that restriction; Check_options::feature_events off).
// --family paper|contact|rotation|grid|random|fuzz|rotation-fuzz runs one
// family only (rotation: fixtures/rotation and the first K cases of `clash4d
// fuzz --rotation`, timed through the time slices); fuzz is the
// first K cases (default 40) of `clash4d fuzz --seed N`'s contact families
// (compare/Contact_families.h: rotations, pockets, nested CSG, decimal
// values), the nearest public stand-in for a set of user contact scenes
// (--dump-random writes them too, as DIR/fuzz-I.json); --dump-random writes the random scenes to DIR/random-I.json (to rerun one
// with `clash4d check --stats`); --scene times one scene file alone (to profile it).
// A row whose double answer is wrong says so: "(double differs)", or
// "(double unverified)" for the same verdict with a witness that fails the
// check against the scene.
#include "bench/Bench_main.h"
#include "bench/Fixtures.h"
#include "bench/Option_number.h"
#include "bench/Timing.h"
#include "compare/Contact_families.h"
#include "compare/Rotation_families.h"
#include "rotation/Rotating_check.h"
#include "exact/Exact_instantiation.h"
#include "float/Double_instantiation.h"
#include "scene/Files.h"
#include "scene/Grid_scene.h"
#include "scene/Hull_scene.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>

using namespace clash4d;

namespace {

bool earliest_mode = false;   // --earliest: every query asks for t* (§5)
bool every_minor = false;     // --every-minor: Check_options::feature_events off
int repeat_count = 1;         // --repeat

// Geometric means of the ratios over one family of scenes: regularised
// exact/double and rational/double, then closed exact/double.
struct Means {
  double log_exact = 0, log_rational = 0, log_closed = 0;
  int count = 0;
  void print(const char* family) const
  {
    std::printf("geometric mean over %s: exact/double %.2f, rational/double %.2f; closed exact/double %.2f\n\n", family,
                std::exp(log_exact / count), std::exp(log_rational / count), std::exp(log_closed / count));
  }
};

// How double's answer compares with exact's: a verdict that differs, or
// the same "collide" with a witness that fails the check against the scene
// (the ratio then compares exact with a wrong answer either way).
// The verdict and whether every witness verified, in a number: the 4D
// pipeline, or the time slices on a scene where something turns.
std::pair<bool, bool> answer(const Scene& scene, const std::string& number, const Check_options& opts)
{
  bool verified = true;
  if (scene_rotates(scene)) {
    Rotating_check_answer a = check_rotating(scene, opts, number);
    for (const auto& p : a.pairs) verified = verified && p.answer.witness_verified;
    return {a.collide, verified};
  }
  Check_answer a = number == "exact" ? check_exact(scene, opts) : number == "rational" ? check_rational(scene, opts)
                                                                                       : check_double(scene, 0, opts);
  for (const Pair_answer& p : a.pairs) verified = verified && p.witness_verified;
  return {a.collide, verified};
}

const char* double_note(const Scene& scene, const Check_options& opts, bool exact_collides)
{
  auto [collide, verified] = answer(scene, "double", opts);
  if (collide != exact_collides) return " (double differs)";
  return verified ? "" : " (double unverified)";
}

void timed_row(const std::string& name, const Scene& scene, double min_seconds, Means& means, Check_options opts);

// One scene's row; a scene some number refuses (a double witness that is
// not finite, a degenerate contact: Rotation_unsupported) is named with the
// reason and left out of the means, and the run goes on.
void row(const std::string& name, const Scene& scene, double min_seconds, Means& means,
         Check_options opts = Check_options())
{
  try {
    timed_row(name, scene, min_seconds, means, opts);
  } catch (const Rotation_unsupported& e) {
    std::printf("%-58s not timed, refused: %s\n", name.c_str(), e.what());
  }
}

void timed_row(const std::string& name, const Scene& scene, double min_seconds, Means& means, Check_options opts)
{
  opts.earliest = opts.earliest || earliest_mode;
  opts.feature_events = !every_minor;
  Check_options closed = opts;
  closed.semantics = Semantics::closed;
  auto [e, r, d, ce, cd] = time_in_turns(
      repeat_count, min_seconds, [&] { return answer(scene, "exact", opts).first; },
      [&] { return answer(scene, "rational", opts).first; }, [&] { return answer(scene, "double", opts).first; },
      [&] { return answer(scene, "exact", closed).first; }, [&] { return answer(scene, "double", closed).first; });
  double ratio = e.seconds_per_query / d.seconds_per_query, rational_ratio = r.seconds_per_query / d.seconds_per_query;
  double closed_ratio = ce.seconds_per_query / cd.seconds_per_query;
  means.log_exact += std::log(ratio);
  means.log_rational += std::log(rational_ratio);
  means.log_closed += std::log(closed_ratio);
  ++means.count;
  std::printf("%-58s %11.1f %11.1f %11.1f %8.2f %8.2f %11.1f %11.1f %8.2f  %s%s%s | %s%s\n", name.c_str(),
              e.seconds_per_query * 1e6, r.seconds_per_query * 1e6, d.seconds_per_query * 1e6, ratio, rational_ratio,
              ce.seconds_per_query * 1e6, cd.seconds_per_query * 1e6, closed_ratio, e.collide ? "collide" : "no",
              double_note(scene, opts, e.collide), e.collide == r.collide ? "" : " (RATIONAL DIFFERS)",
              ce.collide ? "meet" : "apart", double_note(scene, closed, ce.collide));
}

} // namespace

namespace {

void print_header()
{
  std::printf("%-58s %11s %11s %11s %8s %8s %11s %11s %8s  %s\n", "scene", "exact us", "rational us", "double us",
              "ex/dbl", "rat/dbl", "closed ex", "closed dbl", "cl ratio", "exact verdict | closed");
}

int run_bench(int argc, char** argv)
{
  unsigned long seed = 1990;
  int random_count = 20, fuzz_count = 40;
  double min_seconds = 0.05;
  std::string dump_dir, only, scene_file;
  for (int i = 1; i < argc; i += 2) {
    std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::printf("usage: clash4d_bench [--seed N] [--random M] [--fuzz K] [--min-seconds S] [--family F] [--earliest]\n"
                  "                     [--every-minor] [--scene FILE] [--dump-random DIR] [--repeat R]\n"
                  "  times check per query, exact (filtered), rational and double, in both semantics;\n"
                  "  families: paper, contact, rotation (fixtures/rotation), grid, fuzz (clash4d fuzz's contact\n"
                  "  families), rotation-fuzz (clash4d fuzz --rotation's families), random;\n"
                  "  --repeat R times each scene's columns R times in turn, keeping each one's least time\n");
      return 0;
    }
    if (a == "--earliest") {
      earliest_mode = true;
      --i;
      continue;
    }
    if (a == "--every-minor") {
      every_minor = true;
      --i;
      continue;
    }
    if (i + 1 >= argc) {
      std::fprintf(stderr, "clash4d_bench: %s needs a value\n", a.c_str());
      return 2;
    }
    if (a == "--seed") seed = option_number<unsigned long>(a, argv[i + 1]);
    else if (a == "--random") random_count = option_number<int>(a, argv[i + 1]);
    else if (a == "--fuzz") fuzz_count = option_number<int>(a, argv[i + 1]);
    else if (a == "--min-seconds") min_seconds = option_number<double>(a, argv[i + 1]);
    else if (a == "--dump-random") dump_dir = argv[i + 1];
    else if (a == "--family") only = argv[i + 1];
    else if (a == "--scene") scene_file = argv[i + 1];
    else if (a == "--repeat") repeat_count = option_number<int>(a, argv[i + 1]);
    else {
      std::fprintf(stderr, "clash4d_bench: unknown option %s\n", a.c_str());
      return 2;
    }
  }
  if (!(min_seconds > 0)) throw std::runtime_error("--min-seconds must be positive");
  if (random_count < 0 || fuzz_count < 0) throw std::runtime_error("--random and --fuzz must not be negative");
  if (repeat_count < 1) throw std::runtime_error("--repeat must be at least 1");
  if (!only.empty() && only != "paper" && only != "contact" && only != "rotation" && only != "grid" && only != "fuzz" &&
      only != "rotation-fuzz" && only != "random")
    throw std::runtime_error("--family " + only + ": not paper, contact, rotation, grid, fuzz, rotation-fuzz or random");
  if (!dump_dir.empty() && !std::filesystem::is_directory(dump_dir))
    throw std::runtime_error("--dump-random " + dump_dir + ": not a directory");
  if (!scene_file.empty()) {
    Scene scene = read_bench_scene(scene_file);   // a bad file stops before any output
    Means means;
    print_header();
    row(scene_file, scene, min_seconds, means);
    return 0;
  }
  print_header();
  auto wanted = [&](const std::string& family) { return only.empty() || only == family; };
  for (const char* family : {"paper", "contact", "rotation"}) {
    if (!wanted(family)) continue;
    Means means;
    for (const auto& f : fixture_files(family)) row(std::string(family) + "/" + f.filename().string(), read_bench_scene(f.string()), min_seconds, means);
    means.print(family);
  }
  // §6 scaling: check --all-pairs on n blocks, 5 colliding pairs (reading
  // the scene excluded: it is the same for both number types).
  if (wanted("grid")) {
    Means means;
    Check_options all;
    all.all_pairs = true;
    for (int n : {100, 1000, 10000}) {
      Scene grid = read_scene(read_json_text(make_grid_scene(n, 5, seed).json));
      row("grid n=" + std::to_string(n) + " --all-pairs", grid, min_seconds, means, all);
    }
    means.print("grid");
  }
  if (wanted("fuzz")) {
    Means means;
    std::printf("contact families (clash4d fuzz), seed %lu\n", seed);
    for (int i = 0; i < fuzz_count; ++i) {
      Fuzz_case c = make_fuzz_case(seed, static_cast<std::uint64_t>(i));
      if (!dump_dir.empty()) write_file_atomically(dump_dir + "/fuzz-" + std::to_string(i) + ".json", c.json + "\n");
      row("fuzz #" + std::to_string(i) + " " + c.family, read_scene(read_json_text(c.json)), min_seconds, means);
    }
    if (means.count > 0) means.print("fuzz");
  }
  if (wanted("rotation-fuzz")) {
    Means means;
    std::printf("rotation families (clash4d fuzz --rotation), seed %lu\n", seed);
    for (int i = 0; i < fuzz_count; ++i) {
      Rotation_case c = make_rotation_case(seed, static_cast<std::uint64_t>(i));
      if (!dump_dir.empty()) write_file_atomically(dump_dir + "/rotation-" + std::to_string(i) + ".json", c.scene.json + "\n");
      row("rotation #" + std::to_string(i) + " " + c.scene.family, read_scene(read_json_text(c.scene.json)), min_seconds, means);
    }
    if (means.count > 0) means.print("rotation-fuzz");
  }
  if (!wanted("random")) return 0;
  std::mt19937_64 rng(seed);
  std::printf("random general-position scenes, seed %lu\n", seed);
  Means means;
  for (int i = 0; i < random_count; ++i) {
    std::string text = make_hull_scene(rng);
    if (!dump_dir.empty()) write_file_atomically(dump_dir + "/random-" + std::to_string(i) + ".json", text + "\n");
    row("random #" + std::to_string(i), read_scene(read_json_text(text)), min_seconds, means);
  }
  if (means.count > 0) means.print("random");
  return 0;
}

} // namespace

// Bad options and unreadable scene files end with a message and exit 2.
int main(int argc, char** argv) { return bench_main("clash4d_bench", run_bench, argc, argv); }
