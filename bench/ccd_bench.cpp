// clash4d_ccd_bench: time per CCD query (docs/ccd-queries.md) on a
// generated simulation-like set (ccd/Ccd_families.h,
// make_simulation_query): 95% clear misses, the rest near contact, a tenth
// of those degenerate (a vertex through an edge, coplanar motion, parallel
// or zero-length edges, a touch at t = 1). Exact (filtered), double and
// rational side by side on one core, per kind and in all, with the ratio
// exact/double; the degenerate tenth is reported on its own line. Each
// column is timed --repeat times, the columns taking turns, and its least
// time kept (a shared machine moves one measurement by a third).
//
//   clash4d_ccd_bench [--queries N] [--seed S] [--type vf|ee|both] [--repeat R]
//                     [--rational M] [--earliest] [--dump DIR]
#include "bench/Bench_main.h"
#include "bench/Option_number.h"
#include "ccd/Ccd_families.h"
#include "exact/Ccd_instantiation.h"
#include "float/Ccd_double_instantiation.h"
#include "scene/Random_draw.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace clash4d;

namespace {

struct Options {
  unsigned long queries = 1000000, seed = 1, rational = 20000;
  int repeat = 3;
  bool earliest = false;
  std::string type = "both", dump;
};

Options parse(int argc, char** argv)
{
  Options o;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--queries") o.queries = option_number<unsigned long>(a, value());
    else if (a == "--seed") o.seed = option_number<unsigned long>(a, value());
    else if (a == "--rational") o.rational = option_number<unsigned long>(a, value());
    else if (a == "--repeat") o.repeat = option_number<int>(a, value());
    else if (a == "--earliest") o.earliest = true;
    else if (a == "--dump") o.dump = value();
    else if (a == "--type") {
      o.type = value();
      if (o.type != "vf" && o.type != "ee" && o.type != "both") throw std::invalid_argument("--type " + o.type + ": not vf, ee or both");
    } else {
      throw std::invalid_argument("unknown option " + a +
                                  " (--queries N, --seed S, --type vf|ee|both, --repeat R, --rational M, --earliest, --dump DIR)");
    }
  }
  if (o.repeat < 1) throw std::invalid_argument("--repeat must be at least 1");
  if (o.queries == 0) throw std::invalid_argument("--queries must be at least 1");
  return o;
}

enum Kind { miss, near, degenerate };
const char* const kind_names[] = {"clear miss", "near contact", "degenerate"};

using Decide = Ccd_answer (*)(const Ccd_query&, const Ccd_options&);

// Seconds to decide qs once on this thread, and how many collide.
double seconds_for(const std::vector<const Ccd_query*>& qs, Decide decide, const Ccd_options& o, std::size_t& collide)
{
  auto start = std::chrono::steady_clock::now();
  collide = 0;
  for (const Ccd_query* q : qs) collide += decide(*q, o).collide;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void dump(const std::string& dir, Ccd_type type, const std::vector<Ccd_query>& qs)
{
  std::filesystem::path folder = std::filesystem::path(dir) / ccd_type_name(type);
  std::filesystem::create_directories(folder);
  std::ofstream out(folder / "simulation.csv");
  Ccd_options o;
  for (const Ccd_query& q : qs) {
    bool label = ccd_exact(q, o).collide;
    for (const auto& row : q.rows()) {
      for (const Rational& x : row)
        out << mpq_numref(x.mpq()) << "," << mpq_denref(x.mpq()) << ",";
      out << (label ? 1 : 0) << "\n";
    }
  }
}

void run_type(Ccd_type type, const Options& o)
{
  Random_draw draw(o.seed);
  std::vector<Ccd_query> qs;
  std::vector<Kind> kinds;
  qs.reserve(o.queries);
  for (unsigned long i = 0; i < o.queries; ++i) {
    bool is_near = false, is_degenerate = false;
    qs.push_back(make_simulation_query(type, draw, is_near, is_degenerate));
    kinds.push_back(is_degenerate ? degenerate : is_near ? near : miss);
  }
  std::vector<const Ccd_query*> by_kind[3];
  for (std::size_t i = 0; i < qs.size(); ++i) by_kind[kinds[i]].push_back(&qs[i]);
  if (!o.dump.empty()) dump(o.dump, type, qs);
  Ccd_options opt;
  opt.earliest = o.earliest;
  std::printf("\n%s: %lu queries (seed %lu%s), one core, microseconds per query\n", ccd_type_name(type), o.queries,
              o.seed, o.earliest ? ", --earliest" : "");
  std::printf("%-14s %9s %10s %10s %10s %12s %9s %8s\n", "kind", "queries", "exact", "double", "rational",
              "exact/double", "collide", "double differs");
  std::printf("(rational: the first %lu queries of each kind)\n", o.rational);
  double total[3] = {0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    const auto& set = by_kind[k];
    if (set.empty()) continue;
    double best[3] = {1e300, 1e300, 1e300};
    std::size_t collide[3] = {0, 0, 0};
    std::vector<const Ccd_query*> sample(set.begin(), set.begin() + std::min<std::size_t>(set.size(), o.rational));
    for (int r = 0; r < o.repeat; ++r) {
      best[0] = std::min(best[0], seconds_for(set, ccd_exact, opt, collide[0]) / set.size());
      best[1] = std::min(best[1], seconds_for(set, ccd_double, opt, collide[1]) / set.size());
      if (r == 0) best[2] = seconds_for(sample, ccd_rational, opt, collide[2]) / sample.size();
    }
    std::size_t differs = 0;
    for (const Ccd_query* q : set) differs += ccd_exact(*q, opt).collide != ccd_double(*q, opt).collide;
    for (int c = 0; c < 3; ++c) total[c] += best[c] * set.size();
    std::printf("%-14s %9zu %10.3f %10.3f %10.3f %12.2f %9zu %8zu\n", kind_names[k], set.size(), 1e6 * best[0],
                1e6 * best[1], 1e6 * best[2], best[0] / best[1], collide[0], differs);
  }
  double n = static_cast<double>(qs.size());
  std::printf("%-14s %9lu %10.3f %10.3f %10.3f %12.2f\n", "all", o.queries, 1e6 * total[0] / n, 1e6 * total[1] / n,
              1e6 * total[2] / n, total[0] / total[1]);
}

int run(int argc, char** argv)
{
  Options o = parse(argc, argv);
  if (o.type != "ee") run_type(Ccd_type::vertex_face, o);
  if (o.type != "vf") run_type(Ccd_type::edge_edge, o);
  return 0;
}

} // namespace

int main(int argc, char** argv) { return bench_main("clash4d_ccd_bench", run, argc, argv); }
