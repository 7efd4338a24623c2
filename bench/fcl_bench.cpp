// Per-query time of exact (the filtered kernel, `--number exact`), double
// (tolerance 0) and FCL's continuous collision (compare/Fcl_subject.h:
// conservative advancement on fcl::Convexd) on the same convex pairs under
// translation: box-box and hull-hull (12-point random hulls), each touching,
// separated and penetrating. Issue 6: FCL measured beside exact for speed.
//   clash4d_fcl_bench [--seed N] [--min-seconds S] [--dump-scenes DIR]
// --dump-scenes writes each case's scene to DIR (box-box-touching.json, ...)
// to rerun or profile one with `clash4d check` or `clash4d_bench --scene`.
//
// What each column times: exact and double run `check` on the scene (their
// model is built from the scene's numbers on every query, as `check` does);
// "fcl us" is FCL's query alone on shapes converted once (how FCL is used),
// "fcl+build us" adds the conversion (exact hull, rounding, fcl::Convexd),
// which is what the comparer's fcl subject pays.
#include "compare/Fcl_subject.h"
#include "bench/Timing.h"
#include "exact/Exact_instantiation.h"
#include "float/Double_instantiation.h"
#include "scene/Files.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

using namespace clash4d;

namespace {


// A point with integer coordinates on a 1/997 grid: (x, y, z) / 997.
using Grid_point = std::array<long, 3>;

std::string coordinate(long k) { return "\"" + std::to_string(k) + "/997\""; }

std::string hull_json(const std::vector<Grid_point>& points)
{
  std::string s = "{\"hull\":[";
  for (std::size_t i = 0; i < points.size(); ++i)
    s += std::string(i ? "," : "") + "[" + coordinate(points[i][0]) + "," + coordinate(points[i][1]) + "," +
         coordinate(points[i][2]) + "]";
  return s + "]}";
}

// The solid moved by (x, y, z) / d, exactly.
std::string translated(const std::string& solid, const Grid_point& by, long d)
{
  auto q = [&](long k) { return "\"" + std::to_string(k) + "/" + std::to_string(d) + "\""; };
  return "{\"translate\":[" + q(by[0]) + "," + q(by[1]) + "," + q(by[2]) + "],\"solid\":" + solid + "}";
}

// 12 points in [-1, 1]^3 with pairwise different x, so the largest and the
// smallest x are each taken by one point, which is then a vertex of the hull.
std::vector<Grid_point> random_points(std::mt19937_64& rng)
{
  std::uniform_int_distribution<long> d(-997, 997);
  std::vector<Grid_point> out;
  std::set<long> xs;
  while (out.size() < 12) {
    Grid_point p{d(rng), d(rng), d(rng)};
    if (xs.insert(p[0]).second) out.push_back(p);
  }
  return out;
}

std::string scene_json(const std::string& name, const std::string& a, const std::string& b, const std::string& b_motion)
{
  return "{\"format\":\"clash4d-scene/1\",\"name\":\"" + name + "\",\"time\":[0,10],\"objects\":[" +
         "{\"name\":\"a\",\"shape\":" + a + "}," + "{\"name\":\"b\",\"shape\":" + b + ",\"motion\":\"" + b_motion +
         "\"}]}";
}

struct Case {
  std::string name;
  std::string json;
  Scene scene;
};

Case make_case(const std::string& name, const std::string& json)
{
  return {name, json, read_scene(read_json_text(json))};
}

// a = [0,1]^3 at rest; b a unit block sliding along y past a's face x = 1:
// flush (touching, no collision), 1/2 away, or 1/2 into a (collision at t = 2).
std::vector<Case> box_cases()
{
  std::vector<Case> out;
  const std::string a = "{\"block\":{\"min\":[0,0,0],\"max\":[1,1,1]}}";
  for (auto [what, x] : {std::pair<const char*, const char*>{"touching", "1"}, {"separated", "3/2"}, {"penetrating", "1/2"}}) {
    std::string b = "{\"translate\":[\"" + std::string(x) + "\",-3,0],\"solid\":{\"block\":{\"min\":[0,0,0],\"max\":[1,1,1]}}}";
    std::string name = std::string("box-box ") + what;
    out.push_back(make_case(name, scene_json(name, a, b, "vel 0 1 0")));
  }
  return out;
}

// a and b random hulls; b passes a along y. Touching: b's smallest-x vertex
// q is placed on the plane x = p_x of a's largest-x vertex p, at p's z, and
// reaches p at t = 5 (a single vertex-vertex contact, the hulls on either
// side of that plane: no collision). Separated: b 1/2 further in x.
// Penetrating: at t = 5 the mean of b's points is exactly that of a's, a
// point inside both hulls (collision).
std::vector<Case> hull_cases(std::mt19937_64& rng)
{
  std::vector<Grid_point> pa = random_points(rng), pb = random_points(rng);
  auto by_x = [](const Grid_point& u, const Grid_point& v) { return u[0] < v[0]; };
  Grid_point p = *std::max_element(pa.begin(), pa.end(), by_x), q = *std::min_element(pb.begin(), pb.end(), by_x);
  Grid_point touch{p[0] - q[0], p[1] - q[1] - 5 * 997, p[2] - q[2]}, mean{0, -5 * 997 * 12, 0};
  for (int i = 0; i < 3; ++i)
    for (std::size_t k = 0; k < pa.size(); ++k) mean[i] += pa[k][i] - pb[k][i];
  std::string a = hull_json(pa), b = hull_json(pb);
  std::vector<Case> out;
  auto add = [&](const char* what, const std::string& moved) {
    std::string name = std::string("hull-hull ") + what;
    out.push_back(make_case(name, scene_json(name, a, moved, "vel 0 1 0")));
  };
  add("touching", translated(b, touch, 997));
  add("separated", translated(b, {2 * touch[0] + 997, 2 * touch[1], 2 * touch[2]}, 2 * 997));
  add("penetrating", translated(b, mean, 12 * 997));
  return out;
}

const char* verdict(bool c) { return c ? "collide" : "no"; }

void row(const Case& c, double min_seconds)
{
  Check_options opts;
  Timing e = time_it([&] { return check_exact(c.scene, opts).collide; }, min_seconds);
  Timing d = time_it([&] { return check_double(c.scene, 0, opts).collide; }, min_seconds);
  Fcl_subject fcl(c.scene);
  if (!fcl.expressible()) {
    std::printf("%-22s %s\n", c.name.c_str(), fcl.reason().c_str());
    return;
  }
  Timing f = time_it([&] { return fcl.time_of_contact(0, 1).has_value(); }, min_seconds);
  Timing fb = time_it([&] { return Fcl_subject(c.scene).check(opts).collide; }, min_seconds);
  std::printf("%-22s %9.1f %9.1f %9.1f %12.1f %9.1f %10.1f   %-7s %-7s %-7s\n", c.name.c_str(),
              e.seconds_per_query * 1e6, d.seconds_per_query * 1e6, f.seconds_per_query * 1e6,
              fb.seconds_per_query * 1e6, e.seconds_per_query / f.seconds_per_query,
              d.seconds_per_query / f.seconds_per_query, verdict(e.collide), verdict(d.collide), verdict(f.collide));
}

const char* usage = "usage: clash4d_fcl_bench [--seed N] [--min-seconds S] [--dump-scenes DIR]\n";

int run_bench(int argc, char** argv)
{
  unsigned long seed = 1990;
  double min_seconds = 0.05;
  std::string dump_dir;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::printf("%s  times check per query, exact (filtered) and double, beside FCL's continuous collision,\n"
                  "  on box-box and hull-hull pairs (touching, separated, penetrating)\n", usage);
      return 0;
    }
    // A number option's whole value, or an error naming the option.
    auto value = [&](auto parse) {
      std::string text = argv[++i];
      std::size_t used = 0;
      try {
        auto v = parse(text, &used);
        if (used == text.size()) return v;
      } catch (const std::logic_error&) {   // std::invalid_argument, std::out_of_range
      }
      throw std::invalid_argument(a + " " + text + ": not a number in range");
    };
    if (a == "--seed" && i + 1 < argc) seed = value([](const std::string& t, std::size_t* n) { return std::stoul(t, n); });
    else if (a == "--min-seconds" && i + 1 < argc)
      min_seconds = value([](const std::string& t, std::size_t* n) { return std::stod(t, n); });
    else if (a == "--dump-scenes" && i + 1 < argc) dump_dir = argv[++i];
    else {
      std::fprintf(stderr, "clash4d_fcl_bench: unknown option or missing value: %s\n%s", a.c_str(), usage);
      return 2;
    }
  }
  if (!(min_seconds > 0)) throw std::invalid_argument("--min-seconds must be positive");
  if (!dump_dir.empty() && !std::filesystem::is_directory(dump_dir))
    throw std::invalid_argument("--dump-scenes " + dump_dir + ": not a directory");
  std::printf("clash4d_fcl_bench: seed %lu (hulls), at least %g s per measurement\n", seed, min_seconds);
  std::printf("%-22s %9s %9s %9s %12s %9s %10s   %-7s %-7s %-7s\n", "case", "exact us", "double us", "fcl us",
              "fcl+build us", "exact/fcl", "double/fcl", "exact", "double", "fcl");
  std::mt19937_64 rng(seed);
  std::vector<Case> cases = box_cases();
  for (Case& c : hull_cases(rng)) cases.push_back(std::move(c));
  for (const Case& c : cases) {
    if (!dump_dir.empty()) {
      std::string file = c.name;
      std::replace(file.begin(), file.end(), ' ', '-');
      write_file_atomically(dump_dir + "/" + file + ".json", c.json + "\n");
    }
    row(c, min_seconds);
  }
  return 0;
}

} // namespace

// Bad options end with a message and exit 2.
int main(int argc, char** argv)
{
  try {
    return run_bench(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clash4d_fcl_bench: %s\n", e.what());
    return 2;
  }
}
