// `check` per-query time on the paper scenes, the contact fixtures and seeded
// random general-position scenes, exact beside double, with their ratio.
//   clash4d_bench [--seed N] [--random M] [--min-seconds S]
#include "exact/Exact_instantiation.h"
#include "float/Double_instantiation.h"
#include "scene/Grid_scene.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

using namespace clash4d;

namespace {

struct Timing {
  double seconds_per_query;
  bool collide;
};

template <class Run>
Timing time_it(Run run, double min_seconds)
{
  auto start = std::chrono::steady_clock::now();
  int reps = 0;
  bool collide = false;
  double elapsed = 0;
  do {
    collide = run().collide;
    ++reps;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } while (elapsed < min_seconds && reps < 100000);
  return {elapsed / reps, collide};
}

// A random convex hull of 8 points in a cube of side 4 near `centre`, with
// coordinates on a 1/997 grid (general position with probability ~1).
std::string random_hull(std::mt19937_64& rng, int cx, int cy, int cz)
{
  std::uniform_int_distribution<int> d(-1994, 1994);
  std::string s = "{\"hull\":[";
  for (int i = 0; i < 8; ++i)
    s += std::string(i ? "," : "") + "[\"" + std::to_string(cx * 997 + d(rng)) + "/997\",\"" +
         std::to_string(cy * 997 + d(rng)) + "/997\",\"" + std::to_string(cz * 997 + d(rng)) + "/997\"]";
  return s + "]}";
}

std::string random_motion(std::mt19937_64& rng)
{
  std::uniform_int_distribution<int> v(-300, 300);
  auto vel = [&] { return "vel " + std::to_string(v(rng)) + "/101 " + std::to_string(v(rng)) + "/101 " + std::to_string(v(rng)) + "/101"; };
  return vel() + " until 3 " + vel() + " until 7 " + vel();
}

Scene random_scene(std::mt19937_64& rng)
{
  std::string text = "{\"format\":\"clash4d-scene/1\",\"time\":[0,10],\"objects\":[";
  text += "{\"name\":\"a\",\"shape\":{\"union\":[" + random_hull(rng, 0, 0, 0) + "," + random_hull(rng, 2, 0, 0) +
          "]},\"motion\":\"" + random_motion(rng) + "\"},";
  text += "{\"name\":\"b\",\"shape\":{\"difference\":[" + random_hull(rng, 6, 1, 0) + "," + random_hull(rng, 6, 1, 2) +
          "]},\"motion\":\"" + random_motion(rng) + "\"}]}";
  return read_scene(read_json_text(text));
}

void row(const std::string& name, const Scene& scene, double min_seconds, double& log_sum, int& count,
         Check_options opts = Check_options())
{
  Timing e = time_it([&] { return check_exact(scene, opts); }, min_seconds);
  Timing d = time_it([&] { return check_double(scene, 0, opts); }, min_seconds);
  double ratio = e.seconds_per_query / d.seconds_per_query;
  log_sum += std::log(ratio);
  ++count;
  std::printf("%-58s %12.1f %12.1f %8.2f  %s%s\n", name.c_str(), e.seconds_per_query * 1e6, d.seconds_per_query * 1e6, ratio,
              e.collide ? "collide" : "no", e.collide == d.collide ? "" : " (double differs)");
}

} // namespace

int main(int argc, char** argv)
{
  unsigned long seed = 1990;
  int random_count = 20;
  double min_seconds = 0.05;
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string a = argv[i];
    if (a == "--seed") seed = std::stoul(argv[i + 1]);
    else if (a == "--random") random_count = std::stoi(argv[i + 1]);
    else if (a == "--min-seconds") min_seconds = std::stod(argv[i + 1]);
  }
  std::printf("%-58s %12s %12s %8s  %s\n", "scene", "exact us", "double us", "ratio", "exact verdict");
  for (const char* family : {"paper", "contact"}) {
    double log_sum = 0;
    int count = 0;
    std::vector<std::filesystem::path> files;
    for (const auto& f : std::filesystem::directory_iterator(std::string(CLASH4D_FIXTURES) + "/" + family))
      if (f.path().extension() == ".json" && f.path().filename() != "expected.json") files.push_back(f.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) row(std::string(family) + "/" + f.filename().string(), read_scene_file(f.string()), min_seconds, log_sum, count);
    std::printf("geometric mean exact/double ratio over %s: %.2f\n\n", family, std::exp(log_sum / count));
  }
  // §6 scaling: check --all-pairs on n blocks, 5 colliding pairs (reading
  // the scene excluded: it is the same for both number types).
  {
    double log_sum = 0;
    int count = 0;
    Check_options all;
    all.all_pairs = true;
    for (int n : {100, 1000, 10000}) {
      Scene grid = read_scene(read_json_text(make_grid_scene(n, 5, seed).json));
      row("grid n=" + std::to_string(n) + " --all-pairs", grid, min_seconds, log_sum, count, all);
    }
    std::printf("geometric mean exact/double ratio over grid: %.2f\n\n", std::exp(log_sum / count));
  }
  std::mt19937_64 rng(seed);
  std::printf("random general-position scenes, seed %lu\n", seed);
  double log_sum = 0;
  int count = 0;
  for (int i = 0; i < random_count; ++i) row("random #" + std::to_string(i), random_scene(rng), min_seconds, log_sum, count);
  if (count > 0) std::printf("geometric mean exact/double ratio over random: %.2f\n", std::exp(log_sum / count));
}
