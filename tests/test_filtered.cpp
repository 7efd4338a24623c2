#define BOOST_TEST_MODULE filtered
// The filtered exact kernel (`--number exact`: intervals first, rationals when
// an interval cannot certify a sign, and for colliding pairs) against the pure
// rational kernel (`--number rational`): the same verdicts, colliding pairs,
// witnesses, earliest times and contact points, on every fixture and on
// seeded random scenes (coarse-grid contact scenes and the fuzzer's contact
// families, whose 1e-9 offsets and rotations make intervals fail).
//
// CLASH4D_SEED overrides the seed, CLASH4D_FILTER_CASES the number of cases
// per generator.
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>

#include "compare/Contact_families.h"
#include "search/Divide_and_conquer.h"
#include "exact/Exact_checker.h"
#include "exact/Exact_instantiation.h"
#include "exact/Interval_kernel.h"
#include "exact/Rational_kernel.h"
#include <CGAL/FPU.h>
#include "float/Double_kernel.h"
#include "scene/Grid_scene.h"
#include "scene/Hull_scene.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include "support/Random_scene.h"

#include "search/Null_object_test.h"
#include "search/Witness.h"
#include "run/Work_budget.h"
#include "exact/Certified_sides.h"
#include "exact/Exact_witness_signs.h"
#include "model/Point_classifier.h"
#include "verify/Object_model.h"
#include <algorithm>
#include <type_traits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <sstream>

using namespace clash4d;
namespace data = boost::unit_test::data;

namespace {

std::uint64_t env_number(const char* name, std::uint64_t fallback)
{
  const char* v = std::getenv(name);
  return v && *v ? std::strtoull(v, nullptr, 10) : fallback;
}

std::string describe(const Check_answer& a)
{
  std::ostringstream out;
  out << semantics_name(a.semantics) << ": " << (a.collide ? "collide" : "no collision") << " earliest_pair "
      << a.earliest_pair;
  for (const auto& p : a.pairs) {
    out << "\n  " << p.a << "/" << p.b << " witness";
    for (const auto& x : p.witness) out << " " << x;
    out << (p.witness_verified ? " verified" : " UNVERIFIED");
    if (a.semantics == Semantics::closed)
      for (const auto& cell : p.witness_cells) {
        out << " inside";
        for (const auto& x : cell) out << " " << x;
      }
    if (p.earliest) {
      out << " t* " << p.t_star << (p.at_start ? " (at start)" : "") << " contact";
      for (const auto& x : p.contact) out << " " << x;
      for (const auto& cell : p.contact_cells) {
        out << " inside";
        for (const auto& x : cell) out << " " << x;
      }
    }
  }
  return out.str();
}

// Whether p's witness is one by the certificate format's own rule
// (section 3: tL < t < tH, no velocity change of either object there, both
// formulas strictly true), on the checker's model of the scene
// (verify/Object_model.h), which shares no code with the pipeline's.
bool checker_holds_witness(const Scene& scene, const Pair_answer& p)
{
  verifier::Point4 w;
  for (int i = 0; i < 4; ++i) {
    w[i] = mpq_class(p.witness[i]);
    w[i].canonicalize();
  }
  if (!(mpq_class(scene.t_lo.mpq()) < w[3] && w[3] < mpq_class(scene.t_hi.mpq()))) return false;
  for (const std::string& name : {p.a, p.b}) {
    auto o = std::find_if(scene.objects.begin(), scene.objects.end(), [&](const auto& x) { return x.name == name; });
    if (o == scene.objects.end()) return false;
    verifier::Object_model m(*o);
    if (m.is_change(w[3]) || !m.strict_true(m.segment_at(w[3]), w)) return false;
  }
  return true;
}

// A witness the hand-over's LP made (witnesses_by_terms: a long regularised
// search ended by a point inside a term of the pair's formula) is the
// filtered run's own, since the rational run hands nothing over. So when
// there is one, each regularised collision's witness (closed: a pair whose
// cells repeat its witness) is held to the certificate checker's rule
// instead, and the witnesses are blanked before the answers are compared.
void blank_term_witnesses(const Scene& scene, Check_answer& filtered, Check_answer& rational, const std::string& label)
{
  if (filtered.stats.witnesses_by_terms == 0) return;
  for (Check_answer* a : {&filtered, &rational})
    for (Pair_answer& p : a->pairs) {
      if (p.earliest) continue;   // an earliest search hands no point over
      bool inside_both = a->semantics == Semantics::regularised ||
                         (p.witness_cells[0] == p.witness && p.witness_cells[1] == p.witness);
      if (a == &filtered && inside_both)
        BOOST_TEST((p.witness_verified && checker_holds_witness(scene, p)), label << ": " << p.a << "/" << p.b);
      p.witness = {};
      p.witness_cells = {};
    }
}

// Runs both kernels with the options; on mismatch prints both answers
// (Kernel_checker style). Returns the filtered answer.
Check_answer same_answers(const Scene& scene, const Check_options& o, const std::string& label)
{
  Check_answer filtered = check_exact(scene, o), rational = check_rational(scene, o);
  Check_answer compared = filtered;
  blank_term_witnesses(scene, compared, rational, label);
  std::string f = describe(compared), r = describe(rational);
  BOOST_TEST(f == r, label << (o.earliest ? " --earliest" : "") << (o.all_pairs ? " --all-pairs" : "")
                           << " --semantics " << semantics_name(o.semantics)
                           << "\nfiltered: " << f << "\nrational: " << r);
  BOOST_TEST(filtered.number == "exact");
  BOOST_TEST(rational.number == "rational");
  return filtered;
}

// Whether intervals decided the whole run (nothing redone in rationals).
bool decided_by_intervals(const Check_answer& a)
{
  return a.stats.exact_fallbacks == 0 && a.stats.exact_witness_runs == 0 && a.stats.exact_regions == 0 &&
         a.stats.exact_plane_tests == 0;
}

// Rational work at decisions the intervals could not certify: whole pairs,
// single regions, single plane comparisons.
std::size_t exact_decisions(const Check_answer& a)
{
  return a.stats.exact_fallbacks + a.stats.exact_regions + a.stats.exact_plane_tests;
}

std::vector<std::string> fixture_scenes()
{
  std::vector<std::string> out;
  for (const char* family : {"paper", "contact", "unbounded"})
    for (const auto& f : std::filesystem::directory_iterator(std::string(CLASH4D_FIXTURES) + "/" + family)) {
      std::string name = f.path().filename().string();
      // The skewed §6 scenes take a rational run of 4-17 s each (issue 6's
      // open item); their verdicts are held to expected.json by test_fixtures.
      if (f.path().extension() != ".json" || name == "expected.json" || name.find("skewed") != std::string::npos) continue;
      out.push_back(std::string(family) + "/" + name);
    }
  std::sort(out.begin(), out.end());
  return out;
}

} // namespace

// Every fixture in six modes, with convex pairs decided by their linear
// programs (search/Convex_pair.h) and, held too, by the paper's cascade:
// twelve checks, each in both kernels. CLASH4D_FIXTURE_MODES=k (the
// sanitizer run, where a rational run costs ten times more) takes k of the
// twelve per fixture, the next k for the next fixture, so that every mode
// is still asked on some fixtures.
BOOST_DATA_TEST_CASE(fixture_answers_match_rational, data::make(fixture_scenes()), entry)
{
  static const std::vector<std::string> all = fixture_scenes();
  std::size_t index = std::find(all.begin(), all.end(), entry) - all.begin();
  std::uint64_t take = std::clamp<std::uint64_t>(env_number("CLASH4D_FIXTURE_MODES", 12), 1, 12);
  Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/" + entry);
  for (std::uint64_t k = 0; k < take; ++k) {
    int mode = static_cast<int>((index * take + k) % 12);
    Check_options o;
    o.convex_lp = mode < 6;
    o.semantics = mode % 6 < 3 ? Semantics::regularised : Semantics::closed;
    o.all_pairs = mode % 3 == 1;
    o.earliest = mode % 3 == 2;
    same_answers(scene, o, entry + (o.convex_lp ? "" : " --no-convex-lp"));
  }
}

namespace {

// The counts a prepared scene reuses or makes again per query (its
// sweep's) are a fresh check's; so are those the model and the pairs add
// (sbound_passes, primitives) when every candidate pair is checked whole:
// --all-pairs, or one pair. (Otherwise pairs run in parallel, and one after
// the first collision may or may not start: those counts vary by run.)
void same_counts(const Check_stats& kept, const Check_stats& fresh, bool all_pairs, const std::string& label)
{
  BOOST_TEST(kept.object_pairs == fresh.object_pairs, label);
  BOOST_TEST(kept.candidate_pairs == fresh.candidate_pairs, label);
  BOOST_TEST(kept.exact_sweep_ties == fresh.exact_sweep_ties, label);
  if (!all_pairs && fresh.candidate_pairs > 1) return;
  BOOST_TEST(kept.pairs == fresh.pairs, label);
  BOOST_TEST(kept.sbound_passes == fresh.sbound_passes, label);
  BOOST_TEST(kept.primitives == fresh.primitives, label);
}

} // namespace

// A prepared scene (exact/Exact_checker.h) answers as a fresh check_exact
// does, in every mode, in any order and again: what it keeps (the model,
// S-bounds, sweeps per semantics, guides, rational parts) never changes an
// answer. Each mode is asked twice, after modes of the other semantics, so
// the second semantics' sweep runs on the first's model, and a reused part
// (a later call) counts the same pairs with no time.
BOOST_DATA_TEST_CASE(prepared_checks_are_check_exact, data::make(fixture_scenes()), entry)
{
  Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/" + entry);
  std::vector<Check_options> modes(6);
  modes[0].semantics = Semantics::closed;
  modes[0].earliest = true;
  modes[2].all_pairs = true;
  modes[3].semantics = Semantics::closed;
  modes[3].all_pairs = true;
  modes[4].earliest = true;
  modes[5].sbounds = false;
  for (Check_options& o : modes) o.stage_seconds = true;
  Exact_checker prepared(scene);
  for (int round = 0; round < 2; ++round)
    for (const Check_options& o : modes) {
      Check_answer fresh = check_exact(scene, o), kept = prepared.check(o);
      std::string f = describe(fresh), k = describe(kept);
      BOOST_TEST(k == f, entry << " round " << round << (o.earliest ? " --earliest" : "")
                                << (o.all_pairs ? " --all-pairs" : "") << (o.sbounds ? "" : " --no-sbounds")
                                << " --semantics " << semantics_name(o.semantics) << "\nprepared: " << k
                                << "\nfresh: " << f);
      BOOST_TEST(kept.stats.pairs == fresh.stats.pairs, entry);
      same_counts(kept.stats, fresh.stats, o.all_pairs, entry);
      if (round == 1) BOOST_TEST(kept.stats.seconds_model == 0.0, entry);
    }
}

namespace {

// Seeded motions for a scene's objects, each changed with odds 2 in 3: 0-2
// breakpoints at eighths of the span, velocities eighths in [-2, 2].
std::vector<Motion> random_motions(const Scene& scene, std::mt19937_64& rng)
{
  std::vector<Motion> out;
  auto eighth = [&](int lo, int hi) { return Rational(std::uniform_int_distribution<int>(lo, hi)(rng), 8); };
  for (const Scene_object& o : scene.objects) {
    if (rng() % 3 == 0) {
      out.push_back(o.motion);
      continue;
    }
    Motion m;
    std::vector<int> at{1, 2, 3, 4, 5, 6, 7};
    std::shuffle(at.begin(), at.end(), rng);
    at.resize(rng() % 3);
    std::sort(at.begin(), at.end());
    for (int k : at) m.times.push_back(scene.t_lo + (scene.t_hi - scene.t_lo) * Rational(k, 8));
    for (std::size_t s = 0; s <= m.times.size(); ++s) m.velocities.push_back({eighth(-16, 16), eighth(-16, 16), eighth(-16, 16)});
    out.push_back(m);
  }
  return out;
}

// Every velocity plus w: the same relative motion, so the same answer (the
// shear (x, t) -> (x + w t, t) maps each extrusion onto the moved one,
// interiors and closures included): the verdict and t* are unchanged.
std::vector<Motion> plus_velocity(const Scene& scene, const std::array<Rational, 3>& w)
{
  std::vector<Motion> out;
  for (const Scene_object& o : scene.objects) {
    Motion m = o.motion;
    for (auto& v : m.velocities)
      for (int q = 0; q < 3; ++q) v[q] += w[q];
    out.push_back(m);
  }
  return out;
}

} // namespace

// A prepared scene checked under other motions (Exact_checker::check with
// motions, the shapes' parts kept) answers as check_exact on the scene with
// those motions, in four modes, for seeded motions and for the scene's own
// shifted by a common velocity, whose verdicts and t* must be the scene's;
// the scene's own motions answer as before after them.
BOOST_DATA_TEST_CASE(moved_checks_are_check_exact, data::make(fixture_scenes()), entry)
{
  Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/" + entry);
  std::uint64_t seed = env_number("CLASH4D_SEED", 20261130ull);
  std::uint64_t stream = seed;
  for (char c : entry) stream = stream * 1099511628211ull + static_cast<unsigned char>(c);   // one per fixture
  std::mt19937_64 rng(stream);
  BOOST_TEST_MESSAGE("moved checks, " << entry << ": seed " << seed);
  std::vector<Check_options> modes(4);
  modes[1].semantics = Semantics::closed;
  modes[2].earliest = true;
  modes[3].semantics = Semantics::closed;
  modes[3].earliest = true;
  modes[3].all_pairs = true;
  Exact_checker prepared(scene);
  std::vector<Check_answer> own;
  for (const Check_options& o : modes) own.push_back(prepared.check(o));
  std::vector<std::vector<Motion>> sets{random_motions(scene, rng), plus_velocity(scene, {Rational(1, 3), Rational(-2), Rational(0)}),
                                        random_motions(scene, rng)};
  for (std::size_t m = 0; m < sets.size(); ++m) {
    Scene moved = with_motions(scene, sets[m]);
    for (std::size_t k = 0; k < modes.size(); ++k) {
      const Check_options& o = modes[k];
      Check_answer fresh = check_exact(moved, o), kept = prepared.check(sets[m], o);
      std::string label = entry + " (seed " + std::to_string(seed) + ") motion set " + std::to_string(m) +
                          (o.earliest ? " --earliest" : "") + " --semantics " + semantics_name(o.semantics);
      BOOST_TEST(describe(kept) == describe(fresh), label << "\nprepared: " << describe(kept) << "\nfresh: " << describe(fresh));
      same_counts(kept.stats, fresh.stats, o.all_pairs, label);
      if (m == 1) {
        BOOST_TEST(fresh.collide == own[k].collide, label);
        if (o.earliest && fresh.collide && own[k].collide)
          BOOST_TEST(fresh.pairs.at(0).t_star == own[k].pairs.at(0).t_star, label);
      }
    }
  }
  for (std::size_t k = 0; k < modes.size(); ++k)
    BOOST_TEST(describe(prepared.check(modes[k])) == describe(own[k]), entry << " own motions again, mode " << k);
}

BOOST_AUTO_TEST_CASE(moved_checks_refuse_motions_that_are_not_ones)
{
  Scene scene = read_scene(read_json_text(
      R"({"format":"clash4d-scene/1","time":[0,1],"objects":[)"
      R"({"name":"a","shape":{"block":{"min":[0,0,0],"max":[2,2,2]}}},)"
      R"({"name":"b","shape":{"block":{"min":[3,0,0],"max":[4,2,2]}},"motion":"vel -2 0 0"}]})"));
  Exact_checker prepared(scene);
  std::vector<Motion> motions{scene.objects[0].motion, scene.objects[1].motion};
  BOOST_TEST(prepared.check(motions, Check_options()).collide);
  auto refused = [&](const std::vector<Motion>& m, const std::string& says) {
    try {
      prepared.check(m, Check_options());
    } catch (const std::invalid_argument& e) {
      BOOST_TEST(std::string(e.what()).find(says) != std::string::npos, e.what() << " should say " << says);
      return;
    }
    BOOST_ERROR("accepted motions that should say " << says);
  };
  refused({motions[0]}, "1 motions for a scene of 2 objects");
  std::vector<Motion> bad = motions;
  bad[1].times = {Rational(1, 2)};
  refused(bad, "object \"b\": 1 times need 2 velocities, not 1");
  bad[1].times = {Rational(1, 2), Rational(1, 2)};
  bad[1].velocities.resize(3, bad[1].velocities[0]);
  refused(bad, "object \"b\": times must be strictly increasing (time 2)");
  // Refused motions leave the checker as it was: b at rest misses a.
  motions[1].velocities[0] = {Rational(0), Rational(0), Rational(0)};
  BOOST_TEST(!prepared.check(motions, Check_options()).collide);
  BOOST_TEST(prepared.check(Check_options()).collide);
}

// On this machine (natively, not under valgrind: tests/exact_under_valgrind.sh
// holds that case) the FPU honours the interval kernel's rounding, so exact
// runs intervals first: a penetrating box pair's witness is made in
// intervals, with no fallback to rationals. Were encloses_here() wrong here,
// every exact run would silently be the rational one.
BOOST_AUTO_TEST_CASE(intervals_are_trusted_where_rounding_works)
{
  BOOST_TEST(Interval_kernel::encloses_here());
  Scene scene = read_scene(read_json_text(
      R"({"format":"clash4d-scene/1","time":[0,1],"objects":[)"
      R"({"name":"a","shape":{"block":{"min":[0,0,0],"max":[2,2,2]}}},)"
      R"({"name":"b","shape":{"block":{"min":[1,1,1],"max":[3,3,3]}}}]})"));
  Check_answer a = check_exact(scene, Check_options());
  BOOST_TEST(a.collide);
  BOOST_TEST(a.stats.exact_fallbacks == 0u);
  BOOST_TEST(a.stats.witnesses_by_intervals == 1u);
}

// A prepared scene's check stopped by --max-seconds (Budget_exceeded, in
// the search) leaves nothing half-made behind: the next checks answer as
// a fresh check_exact does.
BOOST_AUTO_TEST_CASE(a_prepared_scene_answers_after_a_stopped_check)
{
  Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/paper/section6_weaving_vehicle_late_stop_1e-9.json");
  Exact_checker prepared(scene);
  for (Semantics s : {Semantics::regularised, Semantics::closed}) {
    Check_options o;
    o.semantics = s;
    Work_budget::start(1e-9);
    BOOST_CHECK_THROW(prepared.check(o), Budget_exceeded);
    Work_budget::start(0);
    BOOST_TEST(describe(prepared.check(o)) == describe(check_exact(scene, o)), semantics_name(s));
  }
}

BOOST_AUTO_TEST_CASE(random_contact_scenes_match_rational)
{
  std::uint64_t seed = env_number("CLASH4D_SEED", 20261122ull), cases = env_number("CLASH4D_FILTER_CASES", 1000);
  BOOST_TEST_MESSAGE("filtered vs rational, coarse-grid scenes: seed " << seed << ", " << cases << " cases");
  std::mt19937_64 rng(seed);
  std::size_t by_intervals = 0, collide = 0, witnessed = 0, searched = 0, earliest_colliding = 0,
              earliest_by_intervals = 0, earliest_made = 0, adopted = 0, rerun = 0, convex = 0, found_lines = 0,
              by_terms = 0;
  for (std::uint64_t i = 0; i < cases; ++i) {
    Random_scene rs = random_scene_with_text(rng);
    Check_options o;
    o.convex_lp = i % 2 == 0;   // odd cases: convex pairs through the paper's cascade too
    std::string label = "seed " + std::to_string(seed) + " case " + std::to_string(i) +
                        (o.convex_lp ? "" : " --no-convex-lp");
    Check_answer a = same_answers(rs.scene, o, label + ": " + rs.json);
    if (a.stats.witnesses_by_terms > 0) {
      // A hand-over ended the search with a witness of its own: the
      // search's own point, and the paths that make it, are held too.
      by_terms += a.stats.witnesses_by_terms;
      Check_options searched = o;
      searched.apart_proofs = false;
      a = same_answers(rs.scene, searched, label + " (not handed over): " + rs.json);
    }
    convex += a.stats.convex_spans;
    by_intervals += decided_by_intervals(a);
    collide += a.collide;
    witnessed += a.stats.witnesses_by_intervals;
    found_lines += a.stats.witness_lines_rerun;
    o.earliest = true;
    Check_answer e = same_answers(rs.scene, o, label + ": " + rs.json);
    adopted += e.stats.replay_stages_adopted;
    searched += e.stats.exact_witness_runs - e.stats.earliest_by_intervals;
    earliest_colliding += e.stats.exact_witness_runs + e.stats.witnesses_by_intervals;
    earliest_by_intervals += e.stats.earliest_by_intervals;
    earliest_made += e.stats.witnesses_by_intervals;
    rerun += e.stats.earliest_lines_rerun;
  }
  BOOST_TEST_MESSAGE(by_intervals << " of " << cases << " decided by intervals alone, " << collide << " collide, "
                                  << witnessed << " witnesses made by the interval run, " << found_lines
                                  << " made in rationals from the line that found the point, " << searched
                                  << " earliest-mode pairs searched again in rationals; of " << earliest_colliding
                                  << " colliding earliest-mode pairs, " << earliest_made
                                  << " had t*, contact and witness made by the interval run, " << earliest_by_intervals
                                  << " were searched by intervals with the rational run replaying the last "
                                     "improvement (" << adopted << " region stages adopted) or (" << rerun
                                  << ") only its line; " << convex
                                  << " sub-spans decided by a convex pair's linear programs, " << by_terms
                                  << " witnesses made from a hand-over's point inside a term (seed " << seed << ")");
  // The comparison must exercise every path: many answers from intervals
  // alone (coarse-grid numbers are exact doubles), witnesses made by the
  // interval run itself, and the rational rerun of the line that found
  // the point.
  // (Since box simplifications are retried on the keys, no regularised
  // earliest pair of this seed is searched again in full: the closed
  // campaign below holds that path.)
  BOOST_TEST(by_intervals > cases / 4);
  BOOST_TEST(collide > cases / 10);
  BOOST_TEST(witnessed > collide / 4);
  BOOST_TEST(found_lines > 0u);
  // An earliest replay adopts a region stage the interval run made in
  // rationals: counted, not a floor (it holds for some seeds only);
  // an_earliest_replay_adopts_a_region_stage holds the path.
  // Earliest mode (issue 16): most colliding pairs' t* comes from the
  // interval search, ties with t* decided in rationals line by line, not
  // from a whole rational search: either the interval run made t*, the
  // contact point and the witness as points (the rational run's numbers),
  // or a rational run replayed its last improvement. Both paths are held.
  BOOST_TEST((earliest_by_intervals + earliest_made) * 4 > earliest_colliding * 3,
             "seed " << seed << ": " << earliest_by_intervals << " + " << earliest_made << " of " << earliest_colliding);
  BOOST_TEST(earliest_made > 0u);
  BOOST_TEST(earliest_by_intervals > 0u);
  BOOST_TEST(convex > 0u);   // the linear programs' path is held to rationals too
  // Long searches ended by a point inside a term (Filtered_runner::witness_at):
  // 11 at this seed's 1,000 cases, 3 at the sanitizer run's 100.
  BOOST_TEST(by_terms > 0u);
}

// An earliest replay adopts a region stage the interval run made in
// rationals (S-bounds that meet exactly: Interval_filter::region_stage)
// instead of making it again. The scene is a fuzz family's tiny gap: a
// pyramid's apex and a face close in y at 3/20 each from t = 15/2 to their
// rest at 35/4, where they overlap by 1e-12. By hand: they first touch at
// 35/4 - 1e-12 / (3/10) = 26249999999999/3000000000000, which no double is,
// so t* and the contact point are made by the replay. The answer must be
// the rational run's. The paper's cascade is asked (no linear programs):
// the pair's programs decide it since their double simplex tries coarser
// pivot tolerances (Convex_pair::pivot_eps), and no replay is left to make.
BOOST_AUTO_TEST_CASE(an_earliest_replay_adopts_a_region_stage)
{
  const std::string json =
      R"({"format":"clash4d-scene/1","time":[0,10],"objects":[)"
      R"({"name":"b","shape":{"convex":[[-1,0,0,"774967/10"],[0,0,-1,"87/10"],)"
      R"([0,"1/2",0,"-88638474999999999/20000000000000"],[-1,1,0,"686329025000000001/10000000000000"],)"
      R"([0,"-1/2",0,"88637474999999999/20000000000000"],[2,0,0,"-774973/5"],[0,0,"1/2","-93/20"]]},)"
      R"("motion":"rest until 15/2 vel 0 -3/20 0 until 35/4 rest"},)"
      R"({"name":"a","shape":{"hull":[["387486/5","3545309/400","87/10"],["774971/10","3545309/400","91/10"],)"
      R"(["387484/5","3545309/400","89/10"],[77497,"3545349/400",9]]},)"
      R"("motion":"rest until 15/2 vel 0 3/20 0 until 35/4 rest"}]})";
  Scene scene = read_scene(read_json_text(json));
  for (Semantics s : {Semantics::regularised, Semantics::closed}) {
    Check_options o;
    o.earliest = true;
    o.semantics = s;
    o.convex_lp = false;
    std::string label = std::string("tiny gap, ") + (s == Semantics::closed ? "closed" : "regularised");
    Check_answer e = same_answers(scene, o, label);
    BOOST_REQUIRE(e.collide);
    BOOST_TEST(e.reported()->t_star == "26249999999999/3000000000000", label);
    BOOST_TEST(e.stats.earliest_by_intervals == 1u, label);
    BOOST_TEST(e.stats.replay_stages_adopted > 0u, label << ": " << e.stats.replay_stages_adopted);
  }
}

// Closed semantics on the same coarse-grid scenes: the filtered run decides
// "apart" in intervals, makes a touching point in intervals when it is an
// exact double (a point interval), and otherwise in rationals from the
// line that found it (a touching point is any rational).
BOOST_AUTO_TEST_CASE(random_contact_scenes_match_rational_closed)
{
  std::uint64_t seed = env_number("CLASH4D_SEED", 20261122ull) + 1, cases = env_number("CLASH4D_FILTER_CASES", 1000) / 2;
  BOOST_TEST_MESSAGE("filtered vs rational, closed semantics: seed " << seed << ", " << cases << " cases");
  std::mt19937_64 rng(seed);
  std::size_t by_intervals = 0, collide = 0, witnessed = 0, searched = 0, earliest_made = 0,
              earliest_replayed = 0, found_lines = 0;
  for (std::uint64_t i = 0; i < cases; ++i) {
    Random_scene rs = random_scene_with_text(rng);
    Check_options o;
    o.semantics = Semantics::closed;
    o.all_pairs = i % 3 == 1;
    o.earliest = i % 3 == 2;
    o.convex_lp = i % 2 == 0;   // odd cases: the paper's cascade for convex pairs too
    Check_answer a = same_answers(rs.scene, o, "seed " + std::to_string(seed) + " case " + std::to_string(i) +
                                                   (o.convex_lp ? "" : " --no-convex-lp") + ": " + rs.json);
    by_intervals += decided_by_intervals(a);
    collide += a.collide;
    found_lines += a.stats.witness_lines_rerun + a.stats.earliest_lines_rerun;
    witnessed += a.stats.witnesses_by_intervals;
    if (o.earliest) {
      searched += a.stats.exact_witness_runs - a.stats.earliest_by_intervals;
      earliest_made += a.stats.witnesses_by_intervals;
      earliest_replayed += a.stats.earliest_by_intervals;
    }
  }
  BOOST_TEST_MESSAGE(by_intervals << " of " << cases << " decided by intervals alone, " << collide << " touch or collide, "
                                  << witnessed << " touching points made by the interval run, " << found_lines
                                  << " made in rationals from the line that found them (earliest mode too); "
                                     "earliest mode: " << earliest_made
                                  << " first touches made by the interval run, " << earliest_replayed
                                  << " replayed from its last improvement, " << searched
                                  << " searched again in full");
  BOOST_TEST(by_intervals > cases / 5);
  BOOST_TEST(collide > cases / 5);
  BOOST_TEST(witnessed > collide / 4);
  BOOST_TEST(found_lines > 0u);
  // Closed earliest mode (issue 16) takes the regularised one's path: the
  // interval search with ties decided in rationals, then the first touch
  // made by the interval run or a replay of its last improvement.
  BOOST_TEST(earliest_made > 0u);
  BOOST_TEST(earliest_replayed > 0u);
}

// Two objects change velocity at one decimal time, t = 3/10, and stop
// touching face to face there (hand-derived: a's face x = 1 + t/10 and b's
// x = 1.06 - t/10 meet at 1.03 and stay): no collision, a closed contact.
// The sub-spans are cut on the scene's rationals (intervals could not
// order 3/10 with itself), and the S-bounds that meet exactly are made in
// rationals and adopted: the interval run goes on, nothing is run again
// whole, and the answers are the rational run's. With the convex pair's
// linear programs (the default), the touch is a multiplier sum exactly
// zero, that one sign decided in rationals, again with nothing run whole.
// That is closed semantics, where the sweep's tie (the swept boxes only
// touch at x = 1.03) is kept unexamined: touching boxes meet. In
// regularised semantics the tie is told apart on rational boxes at the
// sweep, and no pair is left to examine.
BOOST_AUTO_TEST_CASE(coinciding_decimal_velocity_changes_stay_in_intervals)
{
  Scene scene = read_scene(read_json_text(R"({"format": "clash4d-scene/1", "time": [0, 1], "objects": [
    {"name": "a", "shape": {"block": {"min": [0, 0, 0], "max": [1, 1, 1]}}, "motion": "vel 0.1 0 0 until 0.3 rest"},
    {"name": "b", "shape": {"block": {"min": [1.06, 0, 0], "max": [2.06, 1, 1]}}, "motion": "vel -0.1 0 0 until 0.3 rest"}]})"));
  for (bool convex_lp : {false, true})
    for (Semantics s : {Semantics::regularised, Semantics::closed}) {
      Check_options o;
      o.semantics = s;
      o.convex_lp = convex_lp;
      Check_answer a = same_answers(scene, o, "coinciding decimal velocity changes");
      BOOST_TEST(a.collide == (s == Semantics::closed));
      BOOST_TEST(a.stats.exact_fallbacks == 0u);
      BOOST_TEST(a.stats.exact_sweep_ties == (s == Semantics::regularised ? 1u : 0u));
      BOOST_TEST(a.stats.candidate_pairs == (s == Semantics::regularised ? 0u : 1u));
      if (s == Semantics::closed && convex_lp)
        BOOST_TEST(a.stats.convex_exact_signs > 0u);
      if (s == Semantics::closed && !convex_lp) BOOST_TEST(a.stats.exact_region_stages > 0u);
    }
}

// §6's weaving vehicle (fixtures/paper/section6_weaving_vehicle.json)
// drives in under the tray line, stops, and only touches: no collision.
// On each sub-span the rational run's S-bounds prune the pair (every span
// pruned, none searched). On the span it drives in, some node bounds meet
// exactly at decimal heights, which the intervals cannot decide; kept
// undecided, the intervals' bounds prune the span all the same, so no stage
// is made in rationals. Closed, the vehicle touches the trays on that span:
// its stage is alive, and an alive stage with undecided boxes is made in
// rationals as before.
BOOST_AUTO_TEST_CASE(undecided_bounds_that_prune_stay_in_intervals)
{
  Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/paper/section6_weaving_vehicle.json");
  Check_options o;
  Check_answer rational = check_rational(scene, o);
  BOOST_TEST_REQUIRE(!rational.collide);
  BOOST_TEST(rational.stats.sub_spans_pruned == rational.stats.sub_spans);
  Check_answer a = same_answers(scene, o, "weaving vehicle");
  BOOST_TEST(a.stats.doubtful_stages_pruned > 0u);
  BOOST_TEST(a.stats.exact_region_stages == 0u);
  BOOST_TEST(a.stats.exact_fallbacks == 0u);
  o.semantics = Semantics::closed;
  Check_answer c = same_answers(scene, o, "weaving vehicle");
  BOOST_TEST(c.collide);
  BOOST_TEST(c.stats.exact_region_stages > 0u);
}

// Earliest mode, a convex pair whose contact vertex ties with a time the
// intervals only enclose (hand-derived: b's face x = 0.1 + 0.1 t reaches
// a's face x = 0.3 at t = 2, where b stops; c's face x = 1.5 - 0.1 t
// reaches a's other face x = 1.3 at t = 2 too). The sub-span starting at
// t* = 2, and the second pair's vertex against the first pair's t*, are
// compared on the vertex in rationals inside the interval run
// (Interval_filter::enters_span, convex_improves): nothing is run again in
// rationals, and the answers are the rational run's.
BOOST_AUTO_TEST_CASE(convex_vertex_ties_with_t_star_stay_in_intervals)
{
  Scene stop = read_scene(read_json_text(R"({"format": "clash4d-scene/1", "time": [0, 10], "objects": [
    {"name": "a", "shape": {"block": {"min": [0.3, 0, 0], "max": [1.3, 1, 1]}}},
    {"name": "b", "shape": {"block": {"min": [-1, 0, 0], "max": [0.1, 1, 1]}}, "motion": "vel 0.1 0 0 until 2 rest"}]})"));
  Scene both = read_scene(read_json_text(R"({"format": "clash4d-scene/1", "time": [0, 2], "objects": [
    {"name": "a", "shape": {"block": {"min": [0.3, 0, 0], "max": [1.3, 1, 1]}}},
    {"name": "b", "shape": {"block": {"min": [-1, 0, 0], "max": [0.1, 1, 1]}}, "motion": "vel 0.1 0 0"},
    {"name": "c", "shape": {"block": {"min": [1.5, 0, 0], "max": [2.5, 1, 1]}}, "motion": "vel -0.1 0 0"}]})"));
  Check_options o;
  o.earliest = true;
  o.semantics = Semantics::closed;
  for (const Scene* scene : {&stop, &both}) {
    Check_answer a = same_answers(*scene, o, "convex vertex tie");
    BOOST_TEST(a.collide);
    BOOST_TEST_REQUIRE(a.reported() != nullptr);
    BOOST_TEST(a.reported()->t_star == "2");
    BOOST_TEST(a.reported()->b == "b");   // the first pair in order wins the tie
    BOOST_TEST(a.stats.exact_fallbacks == 0u);
  }
  Check_answer a = check_exact(stop, o);
  BOOST_TEST(a.stats.exact_ties == 1u);   // the sub-span [2, 10] against t* = 2
  o.semantics = Semantics::regularised;   // touching only: no collision
  BOOST_TEST(!same_answers(stop, o, "convex vertex tie").collide);
  BOOST_TEST(!same_answers(both, o, "convex vertex tie").collide);
}

// A pair the interval run stops on, run again in rationals whole: case 470
// of the default campaign (a sliding contact in closed semantics, through
// the paper's cascade), its answer the rational run's.
BOOST_AUTO_TEST_CASE(whole_rational_rerun_matches)
{
  Fuzz_case c = make_fuzz_case(20261122ull, 470);
  Scene scene = read_scene(read_json_text(c.json));
  Check_options o;
  o.semantics = Semantics::closed;
  o.convex_lp = false;
  Check_answer a = same_answers(scene, o, "case 470 (" + c.family + "): " + c.json);
  BOOST_TEST(a.stats.exact_fallbacks > 0u, "case 470 is no longer run again whole: pick another");
}

BOOST_AUTO_TEST_CASE(contact_families_match_rational)
{
  std::uint64_t seed = env_number("CLASH4D_SEED", 20261122ull), cases = env_number("CLASH4D_FILTER_CASES", 1000);
  BOOST_TEST_MESSAGE("filtered vs rational, fuzz contact families: seed " << seed << ", " << cases << " cases");
  std::size_t fell_back = 0, whole = 0, stages = 0, convex_ties = 0, ties_dropped = 0,
              ties_kept = 0, doubted = 0;
  for (std::uint64_t i = 0; i < cases; ++i) {
    Fuzz_case c = make_fuzz_case(seed, i);
    Scene scene = read_scene(read_json_text(c.json));
    Check_options o;
    o.earliest = i % 2 == 1;
    o.semantics = i % 4 >= 2 ? Semantics::closed : Semantics::regularised;
    o.convex_lp = i % 8 < 4;   // half the cases: the paper's cascade for convex pairs too
    Check_answer a = same_answers(scene, o, "seed " + std::to_string(seed) + " case " + std::to_string(i) +
                                                (o.convex_lp ? "" : " --no-convex-lp") + " (" + c.family + "): " + c.json);
    // A convex pair's vertex tying with t* or a ceiling (a motion changing
    // at the contact, two pairs touching at one instant), decided in
    // rationals inside the interval run (Interval_filter::enters_span,
    // convex_improves).
    convex_ties += o.convex_lp && o.earliest && a.stats.convex_spans > 0 && a.stats.exact_ties > 0;
    fell_back += exact_decisions(a) + a.stats.exact_region_stages > 0;
    whole += a.stats.exact_fallbacks > 0;
    stages += a.stats.exact_region_stages > 0;
    doubted += a.stats.doubtful_stages_pruned > 0;
    // Pairs the sweep tied: dropped on rational boxes, or kept by them.
    ties_dropped += a.stats.exact_sweep_ties > 0 && a.stats.candidate_pairs == 0;
    ties_kept += a.stats.exact_sweep_ties > 0 && a.stats.candidate_pairs > 0;
  }
  BOOST_TEST_MESSAGE(fell_back << " of " << cases << " needed rationals somewhere; " << stages
                               << " adopted a region stage made in rationals (S-bounds meeting exactly), " << doubted
                               << " pruned a sub-span with S-bounds keeping boxes the intervals could not decide, "
                               << whole
                               << " were run again in rationals whole; "
                               << convex_ties << " had a vertex tying with t* decided in rationals; "
                               << ties_dropped << " were decided at the sweep on rational boxes, " << ties_kept
                               << " had a sweep tie kept");
  BOOST_TEST(fell_back > 0);
  // Contact makes S-bounds meet exactly: the region stage in rationals is
  // exercised, and is what keeps most such pairs from a whole rational run.
  BOOST_TEST(stages > cases / 10);
  BOOST_TEST(whole < stages);
  // Some of those prune the span with the boxes the intervals cannot decide
  // kept (Region_stage::doubtful), no stage in rationals: about 16 in 1000.
  if (cases >= 1000) BOOST_TEST(doubted > cases / 200);
  // The whole rational rerun is held to rationals too: about 4 in 1000
  // cases now reach it, so only the full campaign asks for one here (the
  // sanitizer run's 100 do not); whole_rational_rerun_matches pins one.
  if (cases >= 1000) BOOST_TEST(whole > 0u);
  // A convex pair's ties with t* are decided exactly where they arise.
  BOOST_TEST(convex_ties > cases / 200);
  // Both ways out of a regularised sweep tie (Filtered_runner::
  // drop_apart_ties) are held to rationals: touching boxes (a contact under
  // a rotation) dropped, and boxes that overlap kept (rarer: about 4 in
  // 1000). Closed semantics keeps its ties unexamined.
  BOOST_TEST(ties_dropped > cases / 50);
  if (cases >= 1000) BOOST_TEST(ties_kept > 0u);
}

// General position: intervals certify every decision, and the interval run
// of a colliding pair makes the witness itself (Witness::snap):
// nothing is run in rationals.
BOOST_AUTO_TEST_CASE(no_fallback_in_general_position)
{
  Scene miss = read_scene_file(std::string(CLASH4D_FIXTURES) + "/paper/section4_3_comoving_cubes.json");
  Check_answer a = check_exact(miss, Check_options());
  BOOST_TEST(!a.collide);
  BOOST_TEST(a.stats.pairs == 1u);                 // the pair was examined, by intervals
  BOOST_TEST(a.stats.exact_fallbacks == 0u);
  BOOST_TEST(a.stats.exact_witness_runs == 0u);

  Scene hit = read_scene_file(std::string(CLASH4D_FIXTURES) + "/paper/section3_block_path_obstacle.json");
  Check_answer b = check_exact(hit, Check_options());
  BOOST_TEST(b.collide);
  BOOST_TEST(b.stats.exact_fallbacks == 0u);
  BOOST_TEST(b.stats.exact_witness_runs == 0u);
  BOOST_TEST(b.stats.witnesses_by_intervals == 1u);
  // Earliest mode searches on after the first point. Here t* = 3 (the
  // block's corner, 1 + t on each axis, reaches the obstacle's 4), so
  // t*, the contact point and the witness are points of the interval run:
  // nothing is run in rationals (issue 16).
  Check_options earliest;
  earliest.earliest = true;
  Check_answer e = check_exact(hit, earliest);
  BOOST_TEST(e.stats.witnesses_by_intervals == 1u);
  BOOST_TEST(e.stats.exact_witness_runs == 0u);
  BOOST_TEST(e.stats.exact_fallbacks == 0u);
  BOOST_TEST(e.stats.earliest_by_intervals == 0u);
}

// Convex pairs decided by their linear programs (search/Convex_pair.h), in
// the interval run: a clear collision needs no rational at all (its point
// inside and witness are the intervals'); a touch after a rotation by
// (3/5, 4/5) needs the few signs the intervals cannot certify (the
// multipliers' sum, exactly zero) from the rational stage, nothing run
// whole; and t* at the pyramid's apex, 999999999/1000000000 (expected.json),
// is the rational stage's vertex, the rest the intervals'. No line of the
// cascade is searched, and every answer is the rational run's.
BOOST_AUTO_TEST_CASE(convex_pairs_ask_rationals_only_the_signs_intervals_leave)
{
  auto fixture = [](const std::string& name) {
    return read_scene_file(std::string(CLASH4D_FIXTURES) + "/contact/" + name + ".json");
  };
  Check_answer clear = same_answers(fixture("clear_collision_head_on"), Check_options(), "clear_collision_head_on");
  BOOST_TEST(clear.collide);
  BOOST_TEST(clear.stats.convex_spans >= 1u);
  BOOST_TEST(clear.stats.convex_exact_signs == 0u);
  BOOST_TEST(clear.stats.witnesses_by_intervals == 1u);

  Check_answer touch = same_answers(fixture("rotated_skew_face_touch"), Check_options(), "rotated_skew_face_touch");
  BOOST_TEST(!touch.collide);
  BOOST_TEST(touch.stats.convex_exact_signs > 0u);
  BOOST_TEST(touch.stats.exact_fallbacks == 0u);

  Check_options earliest;
  earliest.earliest = true;
  for (Semantics sem : {Semantics::regularised, Semantics::closed}) {
    earliest.semantics = sem;
    Check_answer apex = same_answers(fixture("vertex_face_touch_instant_overlap_1e-9"), earliest, "apex");
    BOOST_REQUIRE(apex.collide);
    BOOST_TEST(apex.reported()->t_star == "999999999/1000000000");
    BOOST_TEST(apex.stats.lines == 0u);
    BOOST_TEST(apex.stats.exact_fallbacks == 0u);
  }
}

namespace {

// A contact fixture in earliest mode, held to the rational run's answer.
// The paper's cascade (these are convex pairs, which the linear programs
// decide otherwise: search/Convex_pair.h), whose filter these tests hold.
Check_answer earliest_fixture(const std::string& name, Semantics semantics = Semantics::regularised)
{
  Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/contact/" + name + ".json");
  Check_options earliest;
  earliest.earliest = true;
  earliest.semantics = semantics;
  earliest.convex_lp = false;
  return same_answers(scene, earliest, name);
}

} // namespace

// A sub-span that ends off the grid (b stops at t = 2.000000001): the
// region's time face there is a number intervals only enclose, so until
// now an earliest-mode line decided in rationals had no exact region and
// the whole pair was searched again in rationals. The rational run's region
// follows from the root's faces and the bisections (exact/Region_faces.h):
// the interval run goes on, and the answer is the rational run's.
BOOST_AUTO_TEST_CASE(earliest_mode_keeps_regions_exact_at_off_grid_ends)
{
  Check_answer e = earliest_fixture("rotated_skew_approach_stop_overlap_1e-9");
  BOOST_REQUIRE(e.collide);
  // A rotated copy of approach_stop_at_contact_overlap_1e-9: b's face
  // reaches a's at t = 2 and stops 1e-9 beyond (expected.json).
  BOOST_TEST(e.reported()->t_star == "2");
  BOOST_TEST(e.stats.exact_fallbacks == 0u);
  BOOST_TEST(e.stats.exact_lines > 0u);
  // The span starts at -1e-9, where b already overlaps a by 1e-9, so
  // t* = tL (expected.json): regions whose lower time is that end tie with
  // t*, which intervals cannot tell; the comparison is made exactly
  // (Interval_filter::can_enter) instead of searching again in rationals.
  Check_answer t = earliest_fixture("touch_only_at_tL_overlap_1e-9");
  BOOST_REQUIRE(t.collide);
  BOOST_TEST(t.reported()->t_star == "-1/1000000000");
  BOOST_TEST(t.reported()->at_start);
  BOOST_TEST(t.stats.exact_fallbacks == 0u);
}

// Earliest mode at a contact vertex the intervals only enclose (issue 16):
// b's apex reaches a's top face at t* = 0.999999999 (expected.json: apex
// height 1.999999999 - t, above the face's centre); in closed semantics the
// first contact is that same instant, when the apex touches the face. Every
// edge of another conquer that ends at that vertex ties with t*, and
// several planes pass through it, parallel to lines there. The ties are
// decided by the vertex's exact time (exact_ties), the cut orders and
// zeros on the rational planes (exact_cut_orders, exact_zeros), each a
// small exact computation, no longer by the line in rationals: before,
// 186 lines went to rationals (regularised) and 746 (closed); now 17 and
// 67. Ceilings with room; the answers are the rational run's.
BOOST_AUTO_TEST_CASE(earliest_ties_are_decided_at_their_vertex)
{
  struct Case {
    Semantics semantics;
    std::size_t most;
  };
  for (const Case& c : {Case{Semantics::regularised, 60}, Case{Semantics::closed, 200}}) {
    Check_answer e = earliest_fixture("vertex_face_touch_instant_overlap_1e-9", c.semantics);
    BOOST_REQUIRE(e.collide);
    BOOST_TEST(e.reported()->t_star == "999999999/1000000000");
    BOOST_TEST(e.stats.exact_fallbacks == 0u);
    BOOST_TEST(e.stats.exact_ties > 0u);
    BOOST_TEST(e.stats.exact_zeros > 0u);
    BOOST_TEST(e.stats.exact_lines <= c.most, e.stats.exact_lines << " lines in rationals");
    if (c.semantics == Semantics::closed) BOOST_TEST(e.stats.exact_cut_orders > 0u);
  }
}

// Earliest mode on a thin overlap (issue 16): b starts at x = 0.999999999
// inside a, static, so t* = tL = 0 (expected.json) and the contact point
// lies on that face, which intervals only enclose; the generic point near
// it needs to know which planes pass through it, which intervals cannot
// say. The line that found it is run again in rationals on its own planes
// and the witness made from it, without a replay of the search, and the
// answer is the rational run's, witness and generic point included.
BOOST_AUTO_TEST_CASE(earliest_contact_off_the_grid_is_made_from_its_line)
{
  Check_answer e = earliest_fixture("face_touch_static_overlap_1e-9");
  BOOST_REQUIRE(e.collide);
  BOOST_TEST(e.reported()->t_star == "0");
  BOOST_TEST(e.reported()->at_start);
  // A vertex of the overlap's closure at t*: x* is one of its faces.
  const std::string& x = e.reported()->contact[0];
  BOOST_TEST((x == "999999999/1000000000" || x == "1"), x);
  BOOST_TEST(e.stats.earliest_lines_rerun == 1u);
  BOOST_TEST(e.stats.exact_fallbacks == 0u);
}

// An --earliest answer the intervals made of points is printed from them,
// with its t* in rationals for the comparisons between pairs
// (exact/Filtered_result.h); the answer is the rational run's. By hand: b's
// face x = 2 - t meets a's x = 1 at t = 1, so t* = 1 in both semantics, not
// at the start; a third block c, already inside a, makes t* the start. A
// start of 1/3 is no double, so at_start cannot be asked of the points
// (Filtered_runner::kept_in_points takes the rationals' copy instead).
BOOST_AUTO_TEST_CASE(earliest_answers_in_points_are_the_rationals)
{
  auto scene = [](const std::string& start, bool inside) {
    return read_scene(read_json_text(
        R"({"format":"clash4d-scene/1","time":[)" + start + R"(,4],"objects":[)"
        R"({"name":"a","shape":{"block":{"min":[0,0,0],"max":[1,1,1]}}},)"
        R"({"name":"b","shape":{"block":{"min":[2,0,0],"max":[3,1,1]}},"motion":"vel -1 0 0"})" +
        std::string(inside ? R"(,{"name":"c","shape":{"block":{"min":["1/4",0,0],"max":[1,1,1]}}})" : "") + "]}"));
  };
  for (const char* start : {"0", "\"1/3\""})
    for (bool inside : {false, true})
      for (Semantics s : {Semantics::regularised, Semantics::closed})
        for (bool all : {false, true}) {
          Check_options o;
          o.earliest = true;
          o.semantics = s;
          o.all_pairs = all;
          std::string label = std::string("start ") + start + (inside ? " with c" : "");
          Check_answer e = same_answers(scene(start, inside), o, label);
          BOOST_REQUIRE(e.collide);
          const Pair_answer& first = *e.reported();
          std::string t_lo = start[0] == '0' ? "0" : "1/3";
          BOOST_TEST(first.t_star == (inside ? t_lo : "1"), label);
          BOOST_TEST(first.at_start == inside, label);
          BOOST_TEST(e.stats.witnesses_by_intervals >= 1u, label);
        }
}

// Closed semantics, any witness (issue 16): in §6 the trays only touch
// the weaving vehicle (fixtures/paper/expected.json), at faces on the
// scene's decimals (y = -0.1), so the touching point is no double and the
// generic points beside it need the planes through it, which intervals
// cannot say. The line that found it is run again in rationals and the
// witness made from it, without searching the pair again; the answer is
// the rational run's, touching point and generic points included.
BOOST_AUTO_TEST_CASE(closed_touch_off_the_grid_is_made_from_its_line)
{
  Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/paper/section6_weaving_vehicle.json");
  Check_options o;
  o.semantics = Semantics::closed;
  Check_answer a = same_answers(scene, o, "section6_weaving_vehicle");
  BOOST_REQUIRE(a.collide);
  BOOST_TEST(a.reported()->witness_verified);
  BOOST_TEST(a.stats.witness_lines_rerun == 1u);
  BOOST_TEST(a.stats.exact_fallbacks == 0u);
}

// Corners (model/Motion_groups.h): a square pyramid's apex lies on four
// facets, so the fourth is exactly zero on the path of the other three, and
// its apex here is at non-dyadic coordinates, where intervals only enclose
// that zero. Written as zeros, the path and the cells around it are decided
// by intervals alone, witness included, and the answer is the rational one.
BOOST_AUTO_TEST_CASE(corners_are_decided_by_intervals)
{
  Scene scene = read_scene(read_json_text(R"({"format":"clash4d-scene/1","time":[0,10],"objects":[
    {"name":"pyramid","shape":{"hull":[[0,0,0],[2,0,0],[2,2,0],[0,2,0],["1/3","5/6","5/7"]]},"motion":"vel 0 0 3/7"},
    {"name":"slab","shape":{"block":{"min":["-1/3","-1/5",2],"max":["7/3","11/5","13/5"]}}}]})"));
  Check_answer a = same_answers(scene, Check_options(), "pyramid apex through a slab");
  BOOST_TEST(a.collide);
  BOOST_TEST(a.stats.exact_lines == 0u);
  BOOST_TEST(a.stats.exact_fallbacks == 0u);
  BOOST_TEST(a.stats.witnesses_by_intervals == 1u);
}

// A face touch after a rotation by (3/5, 4/5): the touching planes' values
// are exactly zero but their intervals straddle zero, so the filter must
// fall back at those decisions (here: the regions holding the touch, and the
// parallel faces), and the answer is still "no collision".
BOOST_AUTO_TEST_CASE(fallback_on_contact)
{
  Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/contact/rotated_skew_face_touch.json");
  Check_options cascade;
  cascade.convex_lp = false;   // a convex pair: the paper's cascade, whose filter this holds
  Check_answer a = check_exact(scene, cascade);
  BOOST_TEST(!a.collide);
  BOOST_TEST(exact_decisions(a) > 0u);
  BOOST_TEST(a.stats.exact_regions > 0u);
  BOOST_TEST(a.stats.exact_plane_tests > 0u);
}

// General position in earnest (scene/Hull_scene.h, the benchmark's random
// family): hull vertices are where three or more planes meet and S-bounds
// are vertex coordinates, so the search meets exact zeros of its own making
// (region faces through vertex lines, lines along an object's motion); the
// filter must answer as rationals do without rerunning whole pairs.
BOOST_AUTO_TEST_CASE(random_hull_scenes_match_rational)
{
  // At least 8 scenes, so that the shortened sanitizer run still meets a
  // collision (seed 1990's first colliding hull scene is its 7th).
  std::uint64_t seed = env_number("CLASH4D_SEED", 1990ull),
                cases = std::max<std::uint64_t>(8, env_number("CLASH4D_FILTER_CASES", 1000) / 50 + 2);
  BOOST_TEST_MESSAGE("filtered vs rational, random hull scenes: seed " << seed << ", " << cases << " cases");
  std::mt19937_64 rng(seed);
  std::size_t whole = 0, regions = 0, collide = 0;
  for (std::uint64_t i = 0; i < cases; ++i) {
    std::string text = make_hull_scene(rng);
    Check_answer a = same_answers(read_scene(read_json_text(text)), Check_options(),
                                  "seed " + std::to_string(seed) + " case " + std::to_string(i) + ": " + text);
    whole += a.stats.exact_fallbacks;
    regions += a.stats.exact_regions;
    collide += a.collide;
  }
  BOOST_TEST_MESSAGE(whole << " whole-pair fallbacks, " << regions << " regions conquered in rationals, " << collide
                           << " of " << cases << " collide");
  BOOST_TEST(whole <= cases / 10);
  BOOST_TEST(collide > 0u);
}

// Motion groups (model/Motion_groups.h): three planes (n, -n.r) of one object
// moving with r meet in a line along (r, 1), and the generalised cross
// product is its last coordinate times (r, 1) exactly; generate-and-test
// writes it so. Checked in rationals on random planes, with r zero on some
// axes as in the object's own frame, where intervals of the plain product
// only enclose the zero.
BOOST_AUTO_TEST_CASE(group_lines_run_along_the_motion)
{
  std::uint64_t seed = env_number("CLASH4D_SEED", 20261124ull);
  BOOST_TEST_MESSAGE("group lines: seed " << seed);
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> d(-9, 9);
  auto q = [&] { return Rational(d(rng), 7); };
  for (int c = 0; c < 200; ++c) {
    Vector3<Rational> r{q(), Rational(0), c % 2 ? Rational(0) : q()};
    std::array<Vector4<Rational>, 3> n;
    for (auto& p : n) {
      Vector3<Rational> m{q(), q(), q()};
      p = {m[0], m[1], m[2], -dot(m, r)};
    }
    Vector4<Rational> l = generalised_cross(n[0], n[1], n[2]);
    for (int a = 0; a < 3; ++a) BOOST_TEST(l[a] == l[3] * r[a]);
    for (const auto& p : n) BOOST_TEST(dot(p, l) == Rational(0));
  }
}

// Normal keys (search/No_filter.h normal_keys, exact/Exact_span.h): a cube
// rotated by R = (1/3)[[1,2,2],[2,1,-2],[-2,2,-1]] has face normals
// u = (1,2,-2)/3, v = (2,1,2)/3, w = (2,-2,-1)/3 (R's columns), thirds that
// intervals only enclose. Opposite faces are parallel: a line of two of
// them and a third plane has direction zero, and every face parallel to a
// line's plane is cut nowhere on it (along = 0), zeros intervals cannot
// certify. Keyed by the integer multiples 3u, 3v, 3w (and the faces'
// own unit normals), those zeros are certified on point intervals and
// written: the interval run decides every line itself, and its verdict is
// the rational run's. Without keys it meets an uncertain sign.
template <class K, class FT = typename K::FT>
std::vector<Hyperplane4<FT>> rotated_cube(const K& kernel, const std::array<Rational, 3>& shift)
{
  auto FT_ = [&](const Rational& x) { return kernel.from_rational(x); };
  const Rational n[3][3] = {{Rational(1, 3), Rational(2, 3), Rational(-2, 3)},
                            {Rational(2, 3), Rational(1, 3), Rational(2, 3)},
                            {Rational(2, 3), Rational(-2, 3), Rational(-1, 3)}};
  std::vector<Hyperplane4<FT>> planes;
  for (int k = 0; k < 3; ++k) {
    // shift along the rotated axes: k.(x - s) in [0, 1], s = sum shift_q n_q
    Rational at = shift[k];   // n_k . s, the normals being orthonormal
    Vector4<FT> e{FT_(n[k][0]), FT_(n[k][1]), FT_(n[k][2]), FT(0)};
    Vector4<FT> minus{FT_(-n[k][0]), FT_(-n[k][1]), FT_(-n[k][2]), FT(0)};
    planes.push_back({minus, FT_(at)});            // -n.x + at <= 0
    planes.push_back({e, FT_(-at - 1)});           //  n.x - at - 1 <= 0
  }
  return planes;
}

// Two table planes are compared on the rational table (as Exact_span does
// for the interval run), so the runs differ in the keys alone; a line with
// an uncertain sign is counted and skipped.
struct Exact_planes : No_filter {
  std::vector<Hyperplane4<Rational>> exact;
  std::size_t uncertain = 0;
  template <class G, class FT>
  void test_line(G& g, const Pair_formula& f, std::size_t i, std::size_t j, std::size_t m, Search_goal<FT>& goal)
  {
    try {
      g.test_line(f, i, j, m, goal);
    } catch (const CGAL::Uncertain_conversion_exception&) {
      ++uncertain;
    }
  }
  template <class K, class FT>
  int same_plane(const K& k, const Hyperplane4<FT>& h, const Hyperplane4<FT>& g, long eh, int, long eg, int,
                 const Box<FT, 4>&)
  {
    if (eh >= 0 && eg >= 0) return proportional(Rational_kernel(), exact.at(eh), exact.at(eg));
    return proportional(k, h, g);
  }
};

struct Keyed_filter : Exact_planes {
  std::vector<Vector4<Interval>> keys;
  std::vector<Hyperplane4<Interval>> whole;
  template <class FT>
  const std::vector<Vector4<Interval>>* normal_keys() const
  {
    static_assert(std::is_same_v<FT, Interval>);
    return keys.empty() ? nullptr : &keys;
  }
  template <class FT>
  const std::vector<Hyperplane4<Interval>>* plane_keys() const
  {
    return whole.empty() ? nullptr : &whole;
  }
};

// Whether the cube at the origin and the one shifted meet (a And b), run by
// generate-and-test on K over [-13/4, 11/2]^3 x [0, 1], whose faces meet no
// point of three planes of the cubes (no tie the keys do not write).
template <class K, class Policy>
bool cubes_meet(const std::array<Rational, 3>& shift, Policy* policy)
{
  K k;
  using FT = typename K::FT;
  std::vector<Hyperplane4<FT>> table = rotated_cube(k, {Rational(0), Rational(0), Rational(0)});
  for (const auto& h : rotated_cube(k, shift)) table.push_back(h);
  Formula::Builder fa, fb;
  std::size_t ma = fa.open(), mb = fb.open();
  for (std::uint32_t h = 0; h < 6; ++h) fa.leaf(h), fb.leaf(h + 6);
  fa.close(Formula::Op::And, ma);
  fb.close(Formula::Op::And, mb);
  Pair_formula f(fa.finish(), fb.finish());
  Box<FT, 4> region;
  for (int q = 0; q < 3; ++q) region.set(q, k.from_rational(Rational(-13, 4)), k.from_rational(Rational(11, 2)));
  region.set(3, FT(0), FT(1));
  Check_stats stats;
  Null_object_test<K, Policy> g(k, table, stats, nullptr, policy);
  Search_goal<FT> goal;
  g.run(f, region, goal);
  return goal.found;
}

BOOST_AUTO_TEST_CASE(parallel_planes_are_keyed_zeros)
{
  Keyed_filter keyed;
  Exact_planes unkeyed;
  const int key[3][3] = {{1, 2, -2}, {2, 1, 2}, {2, -2, -1}};
  for (int cube = 0; cube < 2; ++cube)
    for (int k = 0; k < 3; ++k)
      for (int side : {-1, 1})
        keyed.keys.push_back({Interval(side * key[k][0]), Interval(side * key[k][1]), Interval(side * key[k][2]),
                              Interval(0)});
  Rational half(1, 2), quarter(1, 4);
  const std::array<Rational, 3> apart{Rational(2), half, quarter}, overlapping{half, quarter, half};
  for (const auto& shift : {apart, overlapping}) {
    bool exact = cubes_meet<Rational_kernel, No_filter>(shift, nullptr);
    std::vector<Hyperplane4<Rational>> table = rotated_cube(Rational_kernel(), {Rational(0), Rational(0), Rational(0)});
    for (const auto& h : rotated_cube(Rational_kernel(), shift)) table.push_back(h);
    keyed.exact = unkeyed.exact = table;
    keyed.whole.clear();   // 3 times each plane: integer normals, dyadic offsets
    for (const auto& h : table)
      keyed.whole.push_back({{Interval(CGAL::to_double(3 * h.n[0])), Interval(CGAL::to_double(3 * h.n[1])),
                              Interval(CGAL::to_double(3 * h.n[2])), Interval(0)},
                             Interval(CGAL::to_double(3 * h.c))});
    Interval_kernel::Protector protect;
    unkeyed.uncertain = keyed.uncertain = 0;
    cubes_meet<Interval_kernel, Exact_planes>(shift, &unkeyed);
    bool by_intervals = cubes_meet<Interval_kernel, Keyed_filter>(shift, &keyed);
    BOOST_TEST_MESSAGE("rotated cubes: " << unkeyed.uncertain << " uncertain lines without keys, " << keyed.uncertain
                                         << " with");
    BOOST_TEST(unkeyed.uncertain > 100u);
    BOOST_TEST(keyed.uncertain * 10 < unkeyed.uncertain);
    if (exact) BOOST_TEST(by_intervals);   // a found point is the rational run's (no sign was guessed)
  }
  bool meet_apart = cubes_meet<Rational_kernel, No_filter>(apart, nullptr),
       meet_overlapping = cubes_meet<Rational_kernel, No_filter>(overlapping, nullptr);
  BOOST_TEST(!meet_apart);
  BOOST_TEST(meet_overlapping);
}

// The rotated scenes of issue 16: with normal keys, the lines the interval
// run hands to rationals are the few whose zeros the keys do not certify.
// Before keys these scenes handed 300,565, 89,133, 1,052, 108 and 836 lines
// to rationals; with normal keys alone 4,131, 123, 891, 11 and 25 (ties of
// cuts, where five planes meet, and neighbourhoods of dependent normals);
// with ties and neighbourhoods decided on the keys too, 3, 26, 1, 1 and 1.
// Ceilings with room.
BOOST_AUTO_TEST_CASE(rotated_scenes_keep_few_rational_lines)
{
  struct Case {
    const char* file;
    std::size_t most;
  };
  for (const Case& c : {Case{"paper/section6_weaving_vehicle_skewed.json", 30},
                        Case{"paper/section6_weaving_vehicle_skewed_late_stop_1e-9.json", 100},
                        Case{"contact/rotated_skew_approach_stop.json", 10},
                        Case{"contact/rotated_block_edge_touch.json", 10},
                        Case{"contact/rotated_skew_face_touch.json", 10}}) {
    Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/" + c.file);
    Check_options o;
    o.apart_proofs = false;   // the whole interval search, not handed over
    Check_answer a = check_exact(scene, o);
    BOOST_TEST_MESSAGE(c.file << ": " << a.stats.exact_lines << " lines in rationals, " << a.stats.exact_regions
                              << " regions");
    BOOST_TEST(a.stats.exact_lines <= c.most, c.file << ": " << a.stats.exact_lines << " lines in rationals");
  }
}

// A long any-witness search is handed over to conflicts that close off
// every term of the pair's formula (exact/Interval_filter.h decides_here,
// search/Apart_pieces.h): each of these fixtures' "no collision" took
// generate-and-test thousands of lines, and is now proven apart after a few
// hundred. Where a term stays open (closed semantics: the objects touch),
// the search goes on and finds the touch. The verdicts are
// fixtures/*/expected.json's hand-derived ones; the rational run (which
// never hands over) and the interval search without the hand-over agree.
BOOST_AUTO_TEST_CASE(long_searches_are_handed_over_to_apart_proofs)
{
  struct Case {
    const char* file;
    Semantics semantics;
    bool collide, proven;
  };
  const Semantics reg = Semantics::regularised, closed = Semantics::closed;
  for (const Case& c : {Case{"contact/convex_edge_edge_segment.json", reg, false, true},
                        Case{"contact/hull_face_touch.json", reg, false, true},
                        Case{"contact/pocket_peg_insert_exact.json", reg, false, true},
                        Case{"contact/rotated_skew_approach_stop.json", reg, false, true},
                        Case{"paper/section4_1_sphere_cube.json", closed, false, true},
                        Case{"contact/vertex_face_touch_instant.json", closed, true, false},
                        Case{"contact/approach_stop_decimal.json", closed, true, false}}) {
    Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/" + c.file);
    Check_options o;
    o.semantics = c.semantics;
    o.convex_lp = false;   // convex pairs: the paper's search, which is what is handed over
    Check_answer a = same_answers(scene, o, c.file);
    BOOST_TEST(a.collide == c.collide, c.file);
    if (c.proven) BOOST_TEST(a.stats.apart_proofs >= 1u, c.file);
    else BOOST_TEST((a.stats.apart_proofs == 0u && a.stats.apart_attempts >= 1u), c.file);
    o.apart_proofs = false;   // the rational run is the same without it: it never hands over
    Check_answer searched = check_exact(scene, o);
    BOOST_TEST(describe(searched) == describe(a), c.file << " (not handed over)");
    BOOST_TEST(searched.stats.apart_proofs + searched.stats.apart_attempts == 0u, c.file);
    // Proven: the search stopped early; not: it went on to the same end.
    if (c.proven) BOOST_TEST(searched.stats.lines > a.stats.lines, c.file);
    else BOOST_TEST(searched.stats.lines == a.stats.lines, c.file);
  }
}

// The hand-over counts the search's work, not its lines alone: each cell
// tested around a point whose neighbourhood is classified counts as a line
// (Interval_filter::search_work). The dangling faces of a difference
// touched in closed semantics are such points: the search without the
// hand-over examines more than 512 lines, and it is handed over after
// fewer than 256 (its first 128 lines' work); the answer is the same (no
// touch: the faces are not the regularised solid's).
BOOST_AUTO_TEST_CASE(searches_are_handed_over_by_their_work)
{
  const char* file = "contact/difference_dangling_face_touch.json";
  Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/" + file);
  Check_options o;
  o.semantics = Semantics::closed;
  Check_answer a = same_answers(scene, o, file);
  BOOST_TEST(!a.collide);
  BOOST_TEST(a.stats.apart_proofs == 1u);
  BOOST_TEST(a.stats.lines < 256u);
  BOOST_TEST(a.stats.cells_tested > a.stats.lines);
  o.apart_proofs = false;   // the rational run is the same without it: it never hands over
  Check_answer searched = check_exact(scene, o);
  BOOST_TEST(describe(searched) == describe(a), file << " (not handed over)");
  BOOST_TEST(!searched.collide);
  BOOST_TEST(searched.stats.lines > 512u);
}

// A hand-over whose proof stops at a term with a point (the collision, in
// a later sub-span) still proves the sub-spans before it apart: their
// search stops there. The skewed late stop collides first at t* = 25/4
// (fixtures/paper/expected.json, hand-derived), after its first sub-span
// [0, 6 + 1e-9], whose long search of sliding contacts is cut short. In
// earliest mode the search goes on in the later sub-spans (an earliest
// search wants t*, not a point), and the answer is the hand-derived t* and
// the search's without the hand-over. (The scene's rational run is the next
// case's: one run of the rational search took 46 s under the sanitizers.)
BOOST_AUTO_TEST_CASE(sub_spans_before_a_collision_are_proven_apart)
{
  Scene scene =
      read_scene_file(std::string(CLASH4D_FIXTURES) + "/paper/section6_weaving_vehicle_skewed_late_stop_1e-9.json");
  Check_options o;
  o.earliest = true;
  Check_answer a = check_exact(scene, o);
  BOOST_TEST(a.collide);
  BOOST_TEST(a.pairs.at(0).t_star == "25/4");
  BOOST_TEST((a.stats.apart_proofs == 0u && a.stats.apart_attempts == 1u && a.stats.apart_spans == 1u));
  BOOST_TEST(a.stats.witnesses_by_terms == 0u);
  o.apart_proofs = false;
  Check_answer searched = check_exact(scene, o);
  BOOST_TEST(describe(searched) == describe(a));
  BOOST_TEST(searched.stats.apart_spans == 0u);
  BOOST_TEST(searched.stats.lines > a.stats.lines);
}

// A regularised search for any point inside hands over the same way, and
// the term left open (the collision's) ends it: the double simplex's point
// inside that term, moved off every plane, snapped and checked in
// rationals, is the witness (Filtered_runner::witness_at). It is the
// filtered run's own (same_answers holds it to the certificate checker's
// rule); the verdict is the rational run's and the search's without the
// hand-over, which examines many more lines to find its point. Closed
// semantics asks the regularised search first, so it ends there too.
BOOST_AUTO_TEST_CASE(a_term_left_open_gives_the_witness)
{
  Scene scene =
      read_scene_file(std::string(CLASH4D_FIXTURES) + "/paper/section6_weaving_vehicle_skewed_late_stop_1e-9.json");
  Check_options o;
  Check_answer a = same_answers(scene, o, "skewed late stop");
  BOOST_TEST(a.collide);
  BOOST_TEST((a.stats.apart_attempts == 1u && a.stats.witnesses_by_terms == 1u && a.stats.apart_spans == 0u));
  BOOST_TEST(checker_holds_witness(scene, a.pairs.at(0)));
  o.semantics = Semantics::closed;
  Check_answer closed = check_exact(scene, o);
  BOOST_TEST(closed.collide);
  BOOST_TEST(closed.stats.witnesses_by_terms == 1u);
  BOOST_TEST(closed.pairs.at(0).witness == a.pairs.at(0).witness);
  o.semantics = Semantics::regularised;
  o.apart_proofs = false;
  Check_answer searched = check_exact(scene, o);
  BOOST_TEST(searched.collide);
  BOOST_TEST(searched.stats.witnesses_by_terms == 0u);
  BOOST_TEST(searched.stats.lines > 100 * a.stats.lines);
}

// Earliest mode in general position (issue 16): each improvement of t* in
// intervals leaves the other lines of the conquer through the same point
// tying with t*, which intervals cannot certify. Where those lines end at
// the four planes (or three and a region face) of the recorded contact,
// the tie is written (Search_goal::vertex). The seventh hull scene of
// clash4d_bench's seed 1990 (its `random #6`) handed 155 lines to
// rationals before, 40 now; a ceiling with room, and the rational answer.
BOOST_AUTO_TEST_CASE(earliest_ties_at_the_contact_are_written)
{
  std::mt19937_64 rng(1990);
  std::string text;
  for (int i = 0; i < 7; ++i) text = make_hull_scene(rng);
  Scene scene = read_scene(read_json_text(text));
  Check_options o;
  o.earliest = true;
  Check_answer a = same_answers(scene, o, "bench random #6 (seed 1990): " + text);
  BOOST_TEST(a.collide);
  BOOST_TEST_MESSAGE("bench random #6 --earliest: " << a.stats.exact_lines << " lines in rationals, "
                                                    << a.stats.exact_regions << " regions");
  BOOST_TEST(a.stats.exact_lines <= 80u, a.stats.exact_lines << " lines in rationals");
}

// Region faces on the grid (Span_region::on_grid) round with
// floor_to_grid, which every kernel must compute alike: the largest multiple
// of 2^-bits at or below x.
BOOST_AUTO_TEST_CASE(floor_to_grid_agrees_across_kernels)
{
  Rational_kernel rk;
  BOOST_TEST(rk.floor_to_grid(Rational(7, 3), 2) == Rational(9, 4));      // 7/3 = 2.33.. -> 2.25
  BOOST_TEST(rk.floor_to_grid(Rational(-1, 3), 2) == Rational(-1, 2));    // -0.33.. -> -0.5
  BOOST_TEST(rk.floor_to_grid(Rational(5, 4), 2) == Rational(5, 4));      // on the grid: itself
  BOOST_TEST(Double_kernel().floor_to_grid(7.0 / 3.0, 2) == 2.25);
  CGAL::Protect_FPU_rounding<true> protect;
  Interval_kernel ik;
  Interval third = ik.from_rational(Rational(1, 3));
  Interval f = ik.floor_to_grid(third, 20);
  BOOST_TEST(f.is_point());
  BOOST_TEST(Rational(f.inf()) == rk.floor_to_grid(Rational(1, 3), 20));
  // An enclosure straddling a grid point cannot be rounded: the filter fails.
  BOOST_CHECK_THROW(ik.floor_to_grid(Interval(std::nextafter(0.25, 0.0), std::nextafter(0.25, 1.0)), 20),
                    CGAL::Uncertain_conversion_exception);
}

// The witness's grid (Witness::snap): the least k with 2^-k <= x,
// and rounding to the nearest multiple of 2^-k, alike in every kernel; an
// interval between two powers of two cannot say which.
BOOST_AUTO_TEST_CASE(snap_grid_agrees_across_kernels)
{
  Rational_kernel rk;
  Double_kernel dk;
  for (auto [x, k] : std::vector<std::pair<Rational, int>>{
           {Rational(1), 0}, {Rational(3, 4), 1}, {Rational(1, 2), 1}, {Rational(1, 3), 2}, {Rational(5), -2},
           {Rational(1, 1024), 10}, {Rational(1023, 1024), 1}, {Rational(1, 1000000000), 30}}) {
    BOOST_TEST(rk.grid_exponent(x) == k, x);
    BOOST_TEST(dk.grid_exponent(dk.from_rational(x)) == k, x);
  }
  BOOST_TEST(rk.round_to_grid(Rational(7, 3), 2) == Rational(9, 4));    // 2.33.. -> 2.25
  BOOST_TEST(rk.round_to_grid(Rational(5, 8), 2) == Rational(3, 4));    // a tie rounds up
  BOOST_TEST(rk.round_to_grid(Rational(-7, 3), 2) == Rational(-9, 4));
  CGAL::Protect_FPU_rounding<true> protect;
  Interval_kernel ik;
  BOOST_TEST(ik.grid_exponent(ik.from_rational(Rational(1, 3))) == 2);
  Interval r = ik.round_to_grid(ik.from_rational(Rational(7, 3)), 2);
  BOOST_TEST((r.is_point() && Rational(r.inf()) == Rational(9, 4)));
  BOOST_CHECK_THROW(ik.grid_exponent(Interval(std::nextafter(0.5, 0.0), std::nextafter(0.5, 1.0))),
                    CGAL::Uncertain_conversion_exception);
  BOOST_CHECK_THROW(ik.grid_exponent(Interval(-1e-300, 1e-300)), CGAL::Uncertain_conversion_exception);
}

// Witness (search/Witness.h) in intervals: where its enclosure of the
// point found cannot tell whether a plane is through it, it gives no point
// (the rational run makes it), without a throw; where it can, its point is
// the rational one. The unit cube at rest, a second cube at rest on
// [1/2, 3/2] x [0, 1]^2, time [0, 1]: p = (1 - 2^-53, 1/2, 1/2, 1/2) is
// strictly inside both, 2^-53 from the first cube's face x = 1, which x
// enclosed as [1 - 2^-53, 1] straddles; rationals make the witness there.
// The same p with x = 3/4 (a point interval, far from every plane) is made
// in both kernels alike.
namespace {
// Two objects of a scene on its first sub-span, in kernel K, and the
// witness Witness<K> makes from a point p found (world frame).
template <class K>
struct Witness_pair {
  using FT = typename K::FT;
  K k;
  Scene_model<K> model;
  Time_span<FT> span;
  Moving_object<FT> A, B;
  Witness_pair(const Scene& scene)
    : model(Scene_model<K>::build(k, scene)), span(model.sub_spans({0, 1}).at(0)), A(moving_on(model, 0, span, {})),
      B(moving_on(model, 1, span, {}))
  {}
  std::optional<Vector4<FT>> make(const Vector4<FT>& p) const
  {
    return Witness<K>(k).make(p, {FT(0), FT(0), FT(0)}, A, B, span.lo, span.hi);
  }
};
} // namespace

BOOST_AUTO_TEST_CASE(witness_the_intervals_cannot_make_is_none)
{
  Scene scene = read_scene(read_json_text(R"({"format":"clash4d-scene/1","time":[0,1],"objects":[
      {"name":"a","shape":{"block":{"min":[0,0,0],"max":[1,1,1]}}},
      {"name":"b","shape":{"block":{"min":["1/2",0,0],"max":["3/2",1,1]}}}]})"));
  Witness_pair<Rational_kernel> r(scene);
  const Rational half(1, 2), near_face = Rational(1) - Rational(1) / Rational(std::ldexp(1.0, 53));
  std::optional<Vector4<Rational>> thin = r.make({near_face, half, half, half});
  BOOST_TEST_REQUIRE(thin.has_value());
  BOOST_TEST(is_valid_witness(r.k, r.model, 0, 1, *thin));

  CGAL::Protect_FPU_rounding<true> protect;
  Witness_pair<Interval_kernel> i(scene);
  std::optional<Vector4<Interval>> unsure;
  BOOST_CHECK_NO_THROW(unsure = i.make({Interval(std::nextafter(1.0, 0.0), 1.0), Interval(0.5), Interval(0.5), Interval(0.5)}));
  BOOST_TEST(!unsure.has_value());
  std::optional<Vector4<Interval>> sure = i.make({Interval(0.75), Interval(0.5), Interval(0.5), Interval(0.5)});
  std::optional<Vector4<Rational>> exact = r.make({Rational(3, 4), half, half, half});
  BOOST_TEST_REQUIRE((sure.has_value() && exact.has_value()));
  for (int q = 0; q < 4; ++q) BOOST_TEST(((*sure)[q].is_point() && Rational((*sure)[q].inf()) == (*exact)[q]), q);
}

// The witness checks of rational runs take their plane sides from intervals
// where those certify them (exact/Certified_sides.h): the same sides as
// the rationals', plane for plane, at every fixture object's vertices
// (points on three or more planes: zeros the intervals cannot certify), at
// points off a vertex by 2^-70 (nonzero, within the intervals' width) and
// at seeded random points of its box. Both ways of deciding are taken.
BOOST_AUTO_TEST_CASE(certified_sides_are_the_rationals)
{
  std::uint64_t seed = env_number("CLASH4D_SEED", 20261129);
  BOOST_TEST_MESSAGE("certified_sides_are_the_rationals: seed " << seed);
  std::mt19937_64 rng(seed);
  Interval_kernel ak;
  Rational_kernel ek;
  const Rational tiny = power_of_two(-70);
  std::size_t points = 0, planes = 0, exactly = 0;
  for (const std::string& entry : fixture_scenes()) {
    Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/" + entry);
    Scene_model<Interval_kernel> am = [&] {
      Interval_kernel::Protector protect;
      return Scene_model<Interval_kernel>::build(ak, scene);
    }();
    Scene_model<Rational_kernel> em = Scene_model<Rational_kernel>::build(ek, scene);
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
      const Csg_model<Rational>& exact = em.objects[i].csg;
      std::vector<Vector3<Rational>> ys;
      for (const auto& prim : exact.primitives) {
        for (const auto& v : prim.vertices) {
          ys.push_back(v);
          ys.push_back({v[0] + tiny, v[1] - tiny, v[2] + tiny});
        }
        const Box<Rational, 3>& b = prim.box;
        if (b.empty || !b.has_lo[0] || !b.has_hi[0] || !b.has_lo[1] || !b.has_hi[1] || !b.has_lo[2] || !b.has_hi[2])
          continue;
        std::uniform_int_distribution<int> k(0, 64);
        for (int n = 0; n < 4; ++n) {
          Vector3<Rational> y;
          for (int q = 0; q < 3; ++q) y[q] = b.lo[q] + (b.hi[q] - b.lo[q]) * Rational(k(rng), 64);
          ys.push_back(y);
        }
      }
      for (const auto& y : ys) {
        std::size_t before = exactly;
        Plane_sides<Rational> got = certified_sides(ak, am.objects[i].csg, ek, exact, y, &exactly);
        Plane_sides<Rational> want(ek, exact, y);
        BOOST_TEST((got.sides == want.sides), entry << " object " << scene.objects[i].name << " at " << to_string(y[0])
                                                    << " " << to_string(y[1]) << " " << to_string(y[2]));
        BOOST_TEST((got.first == want.first));
        BOOST_TEST(exactly - before <= want.sides.size());
        planes += want.sides.size();
        ++points;
      }
    }
  }
  BOOST_TEST_MESSAGE("certified_sides_are_the_rationals: " << points << " points, " << planes << " sides, "
                                                           << exactly << " decided in rationals");
  BOOST_TEST(points > 1000u);
  BOOST_TEST(exactly > 0u);            // the zeros at vertices, at least
  BOOST_TEST(exactly * 4 < planes);    // most sides in intervals: the point of the filter
}

// Closed semantics: the generic points beside a touch on planes that are no
// doubles made in intervals (search/Witness.h, near_in_space), the signs
// they cannot tell asked of the rational planes (exact/Exact_witness_signs.h):
// the rationals' own points. The touch is on b's face x = 1/10 and on a's
// inner seam x/3 + y = 8/15; the step into a, (-1, 1/3, 0), runs along the
// seam (a zero the intervals cannot see), which is still zero after it.
// Without the exact signs the intervals make none.
BOOST_AUTO_TEST_CASE(closed_cells_made_in_intervals_are_the_rationals)
{
  Scene scene = read_scene(read_json_text(R"({"format":"clash4d-scene/1","time":[0,1],"objects":[
      {"name":"a","shape":{"union":[
        {"convex":[[1,0,0,"-1/10"],[-1,0,0,0],[0,0,-1,0],[0,0,1,-1],[0,-1,0,0],["1/3",1,0,"-8/15"]]},
        {"convex":[[1,0,0,"-1/10"],[-1,0,0,0],[0,0,-1,0],[0,0,1,-1],[0,1,0,-1],["-1/3",-1,0,"8/15"]]}]}},
      {"name":"b","shape":{"block":{"min":["1/10",0,0],"max":[1,1,1]}}}]})"));
  Witness_pair<Rational_kernel> r(scene);
  const Vector3<Rational> still{Rational(0), Rational(0), Rational(0)};
  const Vector4<Rational> p{Rational(1, 10), Rational(1, 2), Rational(1, 2), Rational(1, 3)};
  const Vector4<Rational> toward[2] = {{Rational(-1), Rational(1, 3), Rational(0), Rational(0)},
                                       {Rational(1), Rational(-1, 7), Rational(0), Rational(0)}};
  CGAL::Protect_FPU_rounding<true> protect;
  Witness_pair<Interval_kernel> i(scene);
  auto enclose = [&](const Vector4<Rational>& x) {
    return Vector4<Interval>{i.k.from_rational(x[0]), i.k.from_rational(x[1]), i.k.from_rational(x[2]),
                             i.k.from_rational(x[3])};
  };
  const Vector3<Interval> none{Interval(0), Interval(0), Interval(0)};
  for (int o = 0; o < 2; ++o) {
    const Moving_object<Rational>& exact_m = o == 0 ? r.A : r.B;
    const Moving_object<Interval>& interval_m = o == 0 ? i.A : i.B;
    std::optional<Vector4<Rational>> want;
    {
      CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
      want = Witness<Rational_kernel>(r.k).near_in_space(p, toward[o], still, exact_m);
    }
    BOOST_TEST_REQUIRE(want.has_value());
    std::optional<Vector4<Interval>> alone;
    BOOST_CHECK_NO_THROW(alone = Witness<Interval_kernel>(i.k).near_in_space(enclose(p), enclose(toward[o]), none,
                                                                              interval_m));
    BOOST_TEST(!alone.has_value(), o);
    Exact_witness_signs<Rational_kernel> signs(r.k, exact_m, p, toward[o], still);
    std::optional<Vector4<Interval>> got =
        Witness<Interval_kernel>(i.k).near_in_space(enclose(p), enclose(toward[o]), none, interval_m, &signs);
    BOOST_TEST_REQUIRE(got.has_value(), o);
    for (int q = 0; q < 3; ++q)
      BOOST_TEST(((*got)[q].is_point() && Rational((*got)[q].inf()) == (*want)[q]), "object " << o << " axis " << q);
    BOOST_TEST((Rational((*got)[3].inf()) <= p[3] && p[3] <= Rational((*got)[3].sup())));   // the time stays
  }
  BOOST_TEST(is_valid_touch(r.k, r.model, 0, 1, p,
                            *Witness<Rational_kernel>(r.k).near_in_space(p, toward[0], still, r.A),
                            *Witness<Rational_kernel>(r.k).near_in_space(p, toward[1], still, r.B)));
}

// The whole run: the weaving vehicle's closed touch at (35/4, -1/10, 1,
// 59/10) has its generic points made so, and the answer is the rational
// run's, cells included.
BOOST_AUTO_TEST_CASE(closed_touch_cells_by_intervals_in_a_run)
{
  Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/paper/section6_weaving_vehicle.json");
  Check_options o;
  o.semantics = Semantics::closed;
  Check_answer f = check_exact(scene, o), r = check_rational(scene, o);
  BOOST_TEST_REQUIRE((f.collide && r.collide));
  BOOST_TEST(f.stats.closed_cells_by_intervals == 1u);
  BOOST_TEST_REQUIRE(f.pairs.size() == r.pairs.size());
  BOOST_TEST(f.pairs[0].witness == r.pairs[0].witness);
  BOOST_TEST(f.pairs[0].witness_cells == r.pairs[0].witness_cells);
  BOOST_TEST(f.pairs[0].witness_verified);
}

BOOST_DATA_TEST_CASE(skeleton_matches_rational,
                     data::make(std::vector<std::string>{"contact/face_touch_static_overlap_1e-9.json",
                                                         "contact/union_seam_straddle.json",
                                                         "paper/section3_block_path_obstacle.json",
                                                         "contact/crossing_paths_collide.json",
                                                         "unbounded/crossing_halfspaces.json",
                                                         "unbounded/slab_block_up.json"}),
                     entry)
{
  Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/" + entry);
  Skeleton_answer f = skeleton_exact(scene), r = skeleton_rational(scene);
  BOOST_TEST_REQUIRE(f.pairs.size() == r.pairs.size());
  BOOST_TEST(!f.pairs.empty());
  for (std::size_t i = 0; i < f.pairs.size(); ++i) {
    BOOST_TEST(f.pairs[i].a == r.pairs[i].a);
    BOOST_TEST(f.pairs[i].edges == r.pairs[i].edges, entry);
  }
}

// Box simplification under intervals (Kernel_base::is_nonnegative): the plane
// x <= 1/3 over a box starting at x = 1/3 has minimum exactly 0, which the
// rational kernel folds to "empty here" (non-strict, regularised-semantics
// item 4). The intervals of 1/3 straddle that 0, so the interval kernel keeps
// the leaf (Unknown) instead of failing the filter, and marks its trail
// approximate (exact/Interval_filter.h) so a colliding pair is not replayed
// from it. With the plane's key (a positive multiple in small integers)
// the same simplification is certain on a grid region.
namespace {
// The search policy hears of every simplification left undecided, and may
// hand keys when one is.
struct Counting : No_filter {
  int uncertain = 0, asked = 0;
  std::vector<Hyperplane4<Interval>> keys;
  void uncertain_simplification() { ++uncertain; }
  template <class FT>
  const std::vector<Hyperplane4<FT>>* plane_keys_on_doubt()
  {
    ++asked;
    if constexpr (std::is_same_v<FT, Interval>) return keys.empty() ? nullptr : &keys;
    return nullptr;
  }
};
} // namespace

BOOST_AUTO_TEST_CASE(uncertain_simplification_keeps_the_leaf)
{
  const Rational third(1, 3);
  // x / 3 - 1 / 3 <= 0 over the box 1 <= x <= 2: empty up to the face x = 1,
  // where the plane is zero; its key is x - 1 <= 0.
  auto status_in = [&](const auto& k, Counting& policy) {
    using K = std::decay_t<decltype(k)>;
    using FT = typename K::FT;
    FT z(0), one(1), t = k.from_rational(third);
    std::vector<Hyperplane4<FT>> table{{{t, z, z, z}, -t}};
    Box<FT, 4> box;
    box.set(0, one, FT(2));
    for (int a = 1; a < 4; ++a) box.set(a, z, one);
    Check_stats stats;
    return Divide_and_conquer<K, Counting>(k, table, stats, nullptr, &policy).leaf_status(0, box, false);
  };
  Counting exact_policy;
  BOOST_TEST((status_in(Rational_kernel(), exact_policy) == Truth::False));
  BOOST_TEST(exact_policy.uncertain == 0);
  BOOST_TEST(exact_policy.asked == 0);

  CGAL::Protect_FPU_rounding<true> protect;
  Counting policy;
  BOOST_TEST((status_in(Interval_kernel(), policy) == Truth::Unknown));
  BOOST_TEST(policy.uncertain == 1);
  BOOST_TEST(policy.asked == 1);

  Counting keyed;
  Interval z(0), one(1);
  keyed.keys = {{{one, z, z, z}, Interval(-1)}};
  BOOST_TEST((status_in(Interval_kernel(), keyed) == Truth::False));
  BOOST_TEST(keyed.uncertain == 0);
}
