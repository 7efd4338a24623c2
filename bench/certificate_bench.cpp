// The cost of certificates (issue 15), per family: `check` alone, `check`
// plus making and serialising its certificate, the certificate's size, and
// the independent checker's time on it (verify/), all in process and exact
// (the filtered kernel), in regularised and closed semantics, plain and
// --earliest. Targets: writing at most 3x check; verifying faster than
// deciding; on turning scenes (rotation: fixtures/rotation; rotation-fuzz:
// the first M cases of `clash4d fuzz --rotation`'s families, issue 56)
// writing at most 5x check. "pieces" counts a turning certificate's APART
// pieces (section 8.3), over its pairs.
//   clash4d_certificate_bench [--seed N] [--random M] [--min-seconds S]
//                             [--family paper|contact|random|rotation|rotation-fuzz] [--every-minor]
//                             [--scene FILE]
// --scene: the four modes on one scene file alone.
// --every-minor: turning pairs of convex pieces are decided, and their
// certificates cut, at every mixed minor's critical times, not only at
// their vertex-face and edge-edge minors' (Check_options::feature_events
// off: the cost before that restriction).
#include "bench/Bench_main.h"
#include "bench/Fixtures.h"
#include "bench/Option_number.h"
#include "bench/Timing.h"
#include "certify/Certificate_writer.h"
#include "certify/Turning_certificate.h"
#include "compare/Rotation_families.h"
#include "exact/Exact_instantiation.h"
#include "scene/Hull_scene.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include "verify/Certificate_checker.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

using namespace clash4d;

namespace {

struct Means {
  double log_write = 0, log_verify = 0, bytes = 0;
  int count = 0, rejected = 0;
  void print(const std::string& family) const
  {
    std::printf("geometric mean over %s: (check + certificate)/check %.2f, verify/check %.2f; mean size %.0f bytes%s\n\n",
                family.c_str(), std::exp(log_write / count), std::exp(log_verify / count), bytes / count,
                rejected ? "; SOME CERTIFICATES REJECTED" : "");
  }
};

// check's verdict, and its certificate: the 4D pipeline's, or the time
// slices' on a scene where something turns (certify/Turning_certificate.h).
bool decide(const Scene& scene, const Check_options& opts)
{
  return scene_rotates(scene) ? check_rotating(scene, opts, "exact").collide : check_exact(scene, opts).collide;
}

std::pair<bool, nlohmann::ordered_json> certified(const Scene& scene, const Check_options& opts)
{
  if (scene_rotates(scene)) {
    Rotating_check_answer a = check_rotating(scene, opts, "exact");
    return {a.collide, make_turning_certificate(scene, a, opts)};
  }
  Check_answer a = check_exact(scene, opts);
  return {a.collide, make_certificate(scene, a, opts)};
}

// The APART pieces of a turning certificate (docs/certificate-format.md,
// 8.3), over its pairs; 0 for a certificate of a scene where nothing turns.
std::size_t apart_pieces(const nlohmann::ordered_json& c)
{
  std::size_t n = 0;
  if (c.value("format", "") != "clash4d-certificate/turning-1") return n;
  for (const auto& p : c["pairs"])
    if (p.contains("apart")) n += p["apart"]["pieces"].size();
  return n;
}

void row(const std::string& name, const Scene& scene, const Check_options& opts, double min_seconds, Means& means)
{
  Timing check = time_it([&] { return decide(scene, opts); }, min_seconds);
  std::size_t bytes = 0;
  Timing write = time_it([&] {
    auto [collide, c] = certified(scene, opts);
    bytes = c.dump(1).size();
    return collide;
  }, min_seconds);
  auto [collide, made] = certified(scene, opts);
  nlohmann::json cert = nlohmann::json::parse(made.dump());
  bool ok = false;
  Timing verify = time_it([&] { return ok = verifier::verify_certificate(scene, cert).ok; }, min_seconds);
  double w = write.seconds_per_query / check.seconds_per_query, v = verify.seconds_per_query / check.seconds_per_query;
  means.log_write += std::log(w);
  means.log_verify += std::log(v);
  means.bytes += static_cast<double>(bytes);
  means.rejected += !ok;
  ++means.count;
  std::printf("%-66s %10.1f %10.1f %10.1f %7.2f %7.2f %9zu %6zu  %s%s\n", name.c_str(), check.seconds_per_query * 1e6,
              write.seconds_per_query * 1e6, verify.seconds_per_query * 1e6, w, v, bytes, apart_pieces(made),
              collide ? "collide" : "apart", ok ? "" : " REJECTED");
}

bool every_minor = false;   // --every-minor: Check_options::feature_events off

std::vector<std::pair<std::string, Check_options>> modes()
{
  std::vector<std::pair<std::string, Check_options>> out;
  for (Semantics s : {Semantics::regularised, Semantics::closed})
    for (bool earliest : {false, true}) {
      Check_options o;
      o.semantics = s;
      o.earliest = earliest;
      o.feature_events = !every_minor;
      out.push_back({std::string(semantics_name(s)) + (earliest ? " --earliest" : ""), o});
    }
  return out;
}

const char* usage = "usage: clash4d_certificate_bench [--seed N] [--random M] [--min-seconds S]\n"
                    "                                 [--family paper|contact|random|rotation|rotation-fuzz] [--every-minor]\n"
                    "                                 [--scene FILE]\n";

int run_bench(int argc, char** argv)
{
  unsigned long seed = 1990;
  int random_count = 20;
  double min_seconds = 0.05;
  std::string only, scene_file;
  for (int i = 1; i < argc; i += 2) {
    std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::printf("%s  times check, check with its certificate, and the certificate's verification, per family,\n"
                  "  in both semantics, plain and --earliest\n", usage);
      return 0;
    }
    if (a == "--every-minor") {
      every_minor = true;
      --i;
      continue;
    }
    if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
    if (a == "--seed") seed = option_number<unsigned long>(a, argv[i + 1]);
    else if (a == "--random") random_count = option_number<int>(a, argv[i + 1]);
    else if (a == "--min-seconds") min_seconds = option_number<double>(a, argv[i + 1]);
    else if (a == "--family") only = argv[i + 1];
    else if (a == "--scene") scene_file = argv[i + 1];
    else throw std::invalid_argument("unknown option " + a + "\n" + usage);
  }
  if (!(min_seconds > 0)) throw std::invalid_argument("--min-seconds must be positive");
  if (random_count < 0) throw std::invalid_argument("--random must not be negative");
  if (!only.empty() && only != "paper" && only != "contact" && only != "random" && only != "rotation" &&
      only != "rotation-fuzz")
    throw std::invalid_argument("--family " + only + ": not paper, contact, random, rotation or rotation-fuzz");
  std::printf("%-66s %10s %10s %10s %7s %7s %9s %6s  %s\n", "scene (mode)", "check us", "+cert us", "verify us", "write",
              "verify", "bytes", "pieces", "verdict");
  if (!scene_file.empty()) {
    Scene scene = read_bench_scene(scene_file);
    Means means;
    for (const auto& [mode, opts] : modes()) row(scene_file + " (" + mode + ")", scene, opts, min_seconds, means);
    means.print(scene_file);
    return 0;
  }
  for (const auto& [mode, opts] : modes()) {
    for (const char* family : {"paper", "contact", "rotation"}) {
      if (!only.empty() && only != family) continue;
      Means means;
      for (const auto& f : fixture_files(family))
        row(std::string(family) + "/" + f.filename().string() + " (" + mode + ")", read_bench_scene(f.string()), opts,
            min_seconds, means);
      means.print(std::string(family) + ", " + mode);
    }
    if (only.empty() || only == "rotation-fuzz") {
      Means turning;
      for (int i = 0; i < random_count; ++i) {
        Rotation_case c = make_rotation_case(seed, static_cast<std::uint64_t>(i));
        row("rotation #" + std::to_string(i) + " " + c.scene.family + " (" + mode + ")",
            read_scene(read_json_text(c.scene.json)), opts, min_seconds, turning);
      }
      if (turning.count) turning.print("rotation families (seed " + std::to_string(seed) + "), " + mode);
    }
    if (!only.empty() && only != "random") continue;
    std::mt19937_64 rng(seed);
    Means means;
    for (int i = 0; i < random_count; ++i)
      row("random #" + std::to_string(i) + " (" + mode + ")", read_scene(read_json_text(make_hull_scene(rng))), opts,
          min_seconds, means);
    if (means.count) means.print("random (seed " + std::to_string(seed) + "), " + mode);
  }
  return 0;
}

} // namespace

// Bad options end with a message naming them and exit 2.
int main(int argc, char** argv) { return bench_main("clash4d_certificate_bench", run_bench, argc, argv); }
