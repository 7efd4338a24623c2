#define BOOST_TEST_MODULE many_objects
#include <boost/test/unit_test.hpp>

#include "check/Pair_sweep.h"
#include "exact/Exact_instantiation.h"
#include "exact/Interval_kernel.h"
#include "exact/Rational_kernel.h"
#include "float/Double_instantiation.h"
#include "scene/Grid_scene.h"
#include "scene/Json_reader.h"
#include "scene/Random_draw.h"
#include "scene/Scene_builder.h"
#include "scene/Scene_reader.h"
#include "search/S_bounds.h"
#include "support/Stage_tests.h"
#include <random>
#include <set>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

using namespace clash4d;

static Scene parse(const std::string& text) { return read_scene(read_json_text(text)); }

static std::set<std::pair<std::string, std::string>> pair_set(const Check_answer& a)
{
  std::set<std::pair<std::string, std::string>> s;
  for (const auto& p : a.pairs) s.insert({p.a, p.b});
  return s;
}

BOOST_AUTO_TEST_CASE(grid_scenes_report_exactly_the_pairs_built_to_collide)
{
  for (int n : {10, 100, 1000}) {
    Grid_scene g = make_grid_scene(n, n >= 100 ? 7 : 2, 42);
    Scene scene = parse(g.json);
    Check_options opts;
    opts.all_pairs = true;
    opts.earliest = true;
    Check_answer a = check_exact(scene, opts);
    std::set<std::pair<std::string, std::string>> expected;
    for (const auto& p : g.colliding) expected.insert({"b" + std::to_string(p.first), "b" + std::to_string(p.second)});
    BOOST_TEST(pair_set(a) == expected, "n = " << n);
    // Gap 3 closed at relative speed 3/5: contact at t* = 5.
    for (const auto& p : a.pairs) {
      BOOST_TEST(p.t_star == "5");
      BOOST_TEST(p.witness_verified);
    }
    BOOST_TEST(a.stats.candidate_pairs < a.stats.object_pairs / 10 + 20, "the sweep must prune most pairs, n = " << n);
    BOOST_TEST(pair_set(check_double(scene, 0, opts)) == expected);
  }
}

// A scene of several unit blocks in random motion; returns its JSON.
static std::string random_cluster(std::mt19937_64& rng, int n)
{
  Random_draw draw(rng);
  Scene_builder b("", 0, 4);
  for (int i = 0; i < n; ++i) {
    long x = draw.range(0, 6), y = draw.range(0, 6) / 2;
    Rational vx = Rational(draw.range(-2, 2)) / 2, vy = Rational(draw.range(-2, 2)) / 2;
    Vec3 v = vec(vx, vy, 0);
    b.object("o" + std::to_string(i), block(vec(x, y, 0), vec(x + 1, y + 1, 1)), piecewise({v, vec(0, 0, 0)}, {2}));
  }
  return b.text();
}

BOOST_AUTO_TEST_CASE(many_objects_equal_the_union_of_pairwise_checks)
{
  std::uint64_t seed = 6061990;
  BOOST_TEST_MESSAGE("seed " << seed);
  std::mt19937_64 rng(seed);
  int collisions = 0;
  for (int round = 0; round < 30; ++round) {
    std::string text = random_cluster(rng, 6);
    Scene scene = parse(text);
    Check_options all;
    all.all_pairs = true;
    auto together = pair_set(check_exact(scene, all));
    std::set<std::pair<std::string, std::string>> pairwise;
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
      for (std::size_t j = i + 1; j < scene.objects.size(); ++j) {
        Scene two = scene;
        two.objects = {scene.objects[i], scene.objects[j]};
        if (check_exact(two, Check_options()).collide) pairwise.insert({scene.objects[i].name, scene.objects[j].name});
      }
    BOOST_TEST(together == pairwise, "round " << round << ": " << text);
    collisions += static_cast<int>(pairwise.size());
  }
  BOOST_TEST(collisions > 10);   // the campaign exercises collisions at all
}

BOOST_AUTO_TEST_CASE(parallel_answers_equal_single_threaded_answers)
{
  std::mt19937_64 rng(77);
  for (int round = 0; round < 10; ++round) {
    Scene scene = parse(random_cluster(rng, 8));
    for (bool all_pairs : {false, true})
      for (bool earliest : {false, true}) {
        Check_options o;
        o.all_pairs = all_pairs;
        o.earliest = earliest;
        Check_answer parallel = check_exact(scene, o);
        Check_answer single;
        {
          tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
          single = check_exact(scene, o);
        }
        BOOST_TEST(parallel.collide == single.collide);
        BOOST_TEST_REQUIRE(parallel.pairs.size() == single.pairs.size());
        for (std::size_t i = 0; i < parallel.pairs.size(); ++i) {
          BOOST_TEST(parallel.pairs[i].a == single.pairs[i].a);
          BOOST_TEST(parallel.pairs[i].b == single.pairs[i].b);
          BOOST_TEST((parallel.pairs[i].witness == single.pairs[i].witness));
          BOOST_TEST(parallel.pairs[i].t_star == single.pairs[i].t_star);
        }
      }
  }
}

// Issue 59 item 5: pairs are checked a chunk at a time, so the memory kept
// per pair is the chunk's; the answer must not depend on the chunk's size.
BOOST_AUTO_TEST_CASE(chunked_answers_equal_one_chunk)
{
  std::uint64_t seed = 5959;
  BOOST_TEST_MESSAGE("seed " << seed);
  std::mt19937_64 rng(seed);
  for (int round = 0; round < 8; ++round) {
    Scene scene = parse(random_cluster(rng, 8));
    for (Semantics semantics : {Semantics::regularised, Semantics::closed})
      for (bool all_pairs : {false, true})
        for (bool earliest : {false, true}) {
          Check_options o;
          o.semantics = semantics;
          o.all_pairs = all_pairs;
          o.earliest = earliest;
          Check_answer whole = check_exact(scene, o);
          for (std::size_t chunk : {1, 2, 3, 5}) {
            o.pair_chunk = chunk;
            Check_answer chunked = check_exact(scene, o);
            BOOST_TEST(chunked.collide == whole.collide);
            BOOST_TEST_REQUIRE(chunked.pairs.size() == whole.pairs.size());
            for (std::size_t i = 0; i < whole.pairs.size(); ++i) {
              BOOST_TEST(chunked.pairs[i].a == whole.pairs[i].a);
              BOOST_TEST(chunked.pairs[i].b == whole.pairs[i].b);
              BOOST_TEST((chunked.pairs[i].witness == whole.pairs[i].witness));
              BOOST_TEST(chunked.pairs[i].t_star == whole.pairs[i].t_star);
            }
            BOOST_TEST(chunked.stats.candidate_pairs == whole.stats.candidate_pairs);
          }
        }
  }
  // 100 identical blocks: n (n - 1) / 2 = 4950 colliding pairs, more than the
  // default chunk of 4096, every one listed once, in order.
  Scene_builder b("", 0, 1);
  for (int i = 0; i < 100; ++i) b.object("b" + std::to_string(i), block(vec(0, 0, 0), vec(1, 1, 1)));
  Check_options all;
  all.all_pairs = true;
  Check_answer a = check_exact(parse(b.text()), all);
  BOOST_TEST(a.pairs.size() == 4950u);
  BOOST_TEST(pair_set(a).size() == 4950u);
  BOOST_TEST(a.pairs.back().a == "b98");
  BOOST_TEST(a.pairs.back().b == "b99");
}

BOOST_AUTO_TEST_CASE(ignored_pairs_get_the_empty_bound)
{
  Grid_scene g = make_grid_scene(20, 2, 5);
  Scene scene = parse(g.json);
  scene.ignore.push_back(g.colliding[0]);
  Check_options opts;
  opts.all_pairs = true;
  Check_answer a = check_exact(scene, opts);
  BOOST_TEST(a.pairs.size() == 1u);
  BOOST_TEST(a.pairs[0].a == "b" + std::to_string(g.colliding[1].first));
}

// A check run from a task whose group is being cancelled (a sibling case of a
// fuzz batch threw Budget_exceeded) must still check every pair: a nested loop
// that inherits the cancellation ends early and silently, and its pairs would
// read as "no collision" nobody decided.  The grid's colliding pairs are known
// by construction.
BOOST_AUTO_TEST_CASE(a_check_under_a_cancelled_caller_still_checks_every_pair)
{
  Grid_scene g = make_grid_scene(100, 7, 42);
  Scene scene = parse(g.json);
  std::set<std::pair<std::string, std::string>> expected;
  for (const auto& p : g.colliding) expected.insert({"b" + std::to_string(p.first), "b" + std::to_string(p.second)});
  Check_options opts;
  opts.all_pairs = true;
  Skeleton_answer calm = skeleton_exact(scene);
  Check_answer a, r;
  Skeleton_answer s;
  tbb::task_group_context caller;
  tbb::parallel_for(0, 1, [&](int) {
    caller.cancel_group_execution();
    a = check_exact(scene, opts);
    r = check_rational(scene, opts);
    s = skeleton_exact(scene);
  }, caller);
  BOOST_TEST(pair_set(a) == expected);
  BOOST_TEST(pair_set(r) == expected);
  BOOST_TEST_REQUIRE(s.pairs.size() == calm.pairs.size());
  for (std::size_t i = 0; i < s.pairs.size(); ++i) BOOST_TEST((s.pairs[i].edges == calm.pairs[i].edges));
  BOOST_TEST(!calm.pairs.empty());
}

// The filtered sweep's ties, decided on rational boxes (Filtered_runner::
// drop_apart_ties). The unit cube rotated by q = (3,0,0,4) (cos = -7/25,
// sin = 24/25 about z) reaches y = 24/25 exactly, at its vertical edge
// x = -7/25; a block slides along x with its face y = lo + e. Intervals
// cannot tell 24/25 from its neighbours, so the pair is a tie; by hand:
//  - e = 0: boxes touch, the edge lies on the face: no regularised
//    collision (pair dropped at the sweep), closed: they meet;
//  - e = +1e-30: a gap: apart in both semantics, dropped at the sweep in
//    regularised semantics;
//  - e = -1e-30: the edge's wedge enters the block: a collision in both,
//    the pair kept.
// Closed semantics keeps every tie unexamined (touching boxes meet), and
// the pair's own check proves the gap: the rational run, which drops it
// at the sweep, gives the same answer.
BOOST_AUTO_TEST_CASE(sweep_ties_are_decided_on_exact_boxes)
{
  struct Case {
    const char* lo;   // the slider's face: 24/25, 24/25 + 1e-30, 24/25 - 1e-30
    bool regularised, closed;
  };
  for (Case c : {Case{"24/25", false, true}, Case{"0.960000000000000000000000000001", false, false},
                 Case{"0.959999999999999999999999999999", true, true}}) {
    std::string lo = c.lo, y = "\"" + lo + "\"";
    Scene scene = parse(R"({"format":"clash4d-scene/1","time":[0,4],"objects":[
      {"name":"tilted","shape":{"rotate":[3,0,0,4],"solid":{"block":{"min":[0,0,0],"max":[1,1,1]}}}},
      {"name":"slider","motion":"vel 1 0 0","shape":{"block":{"min":[-3,)" + y + R"(,0],"max":[-2,2,1]}}}]})");
    for (Semantics s : {Semantics::regularised, Semantics::closed}) {
      bool expected = s == Semantics::closed ? c.closed : c.regularised;
      bool closed = s == Semantics::closed;
      bool kept = expected;   // the rational sweep keeps a pair exactly when the boxes meet (touching: closed only)
      Check_options opts;
      opts.semantics = s;
      Check_answer e = check_exact(scene, opts), r = check_rational(scene, opts);
      BOOST_TEST(e.collide == expected, lo << (closed ? " closed" : ""));
      BOOST_TEST(r.collide == expected, lo << (closed ? " closed (rational)" : " (rational)"));
      BOOST_TEST(e.stats.exact_sweep_ties == (closed ? 0u : 1u), lo);
      BOOST_TEST(e.stats.candidate_pairs == (kept || closed ? 1u : 0u), lo << (closed ? " closed" : ""));
      BOOST_TEST(r.stats.candidate_pairs == (kept ? 1u : 0u), lo << (closed ? " closed (rational)" : " (rational)"));
    }
  }
}

// A random solid with every coordinate on the 1/997 grid (none a double,
// so boxes meeting there tie in the intervals): a block, a hull of 8
// points, a triangular prism, or a union of two blocks (two primitives:
// S-bounds in rationals); its exact x range in xr.
static Solid grid_solid(std::mt19937_64& rng, std::array<Rational, 2>& xr)
{
  using stage_tests::pick;
  auto g = [&] { return Rational(pick(rng, -997, 997)) / 997; };
  auto box_of = [&](Rational& lo, Rational& hi) {
    Vec3 a = vec(g(), g(), g()), b = vec(g(), g(), g());
    Vec3 l = vec(std::min(a[0], b[0]), std::min(a[1], b[1]), std::min(a[2], b[2]));
    Vec3 h = vec(std::max(a[0], b[0]), std::max(a[1], b[1]), std::max(a[2], b[2]));
    for (int q = 0; q < 3; ++q) h[q] += Rational(1) / 997;   // never flat
    lo = l[0], hi = h[0];
    return block(l, h);
  };
  switch (pick(rng, 0, 3)) {
    case 0: return box_of(xr[0], xr[1]);
    case 1: {
      std::vector<Vec3> pts;
      for (int i = 0; i < 8; ++i) pts.push_back(vec(g(), g(), g()));
      xr = {pts[0][0], pts[0][0]};
      for (const Vec3& p : pts) xr = {std::min(xr[0], p[0]), std::max(xr[1], p[0])};
      return hull(pts);
    }
    case 2: {
      std::vector<Point2> base;
      while (base.size() < 3) {
        base = {Point2{g(), g()}, Point2{g(), g()}, Point2{g(), g()}};
        Rational area = (base[1][0] - base[0][0]) * (base[2][1] - base[0][1]) -
                        (base[2][0] - base[0][0]) * (base[1][1] - base[0][1]);
        if (area == 0) base.clear();
      }
      xr = {std::min({base[0][0], base[1][0], base[2][0]}), std::max({base[0][0], base[1][0], base[2][0]})};
      Rational z = g();
      return prism(base, z, z + Rational(1, 2));
    }
    default: {
      std::array<Rational, 2> r0, r1;
      Solid a = box_of(r0[0], r0[1]), b = box_of(r1[0], r1[1]);
      xr = {std::min(r0[0], r1[0]), std::max(r0[1], r1[1])};
      return csg(Solid::Kind::Union, {a, b});
    }
  }
}

// Sweep ties decided on exact sides (exact/Sweep_tie.h) as the rational
// run's whole sweep decides them: b is placed so that its box meets a's on
// x exactly, or misses or crosses it by 997^-10, and moves across y (with
// a velocity change half the time: two sub-spans). The exact run keeps
// the pair exactly when the rational run's sweep does (candidate_pairs),
// and answers as that run does; most cases must tie, and both outcomes
// must occur.
BOOST_AUTO_TEST_CASE(sweep_ties_match_the_rational_sweep)
{
  using stage_tests::pick;
  std::uint64_t seed = stage_tests::env_number("CLASH4D_SEED", 28111990);
  BOOST_TEST_MESSAGE("seed " << seed);
  const int cases = 160;
  int ties = 0, dropped = 0, kept = 0;
  for (int c = 0; c < cases; ++c) {
    std::mt19937_64 rng(stage_tests::case_seed(seed, static_cast<std::uint64_t>(c)));
    std::array<Rational, 2> ax, bx;
    Solid a = grid_solid(rng, ax), b = grid_solid(rng, bx);
    Rational tiny(1);   // 997^-10, about 1e-30: far below an interval's width at these coordinates
    for (int k = 0; k < 10; ++k) tiny /= 997;
    Rational e = Rational(pick(rng, -1, 1)) * tiny;   // past touching: a gap (> 0) or an overlap
    bool right = pick(rng, 0, 1) == 1;
    Rational dx = right ? ax[1] - bx[0] + e : ax[0] - bx[1] - e;
    Motion m = pick(rng, 0, 1) ? steady(vec(0, Rational(1, 3), 0))
                               : piecewise({vec(0, Rational(1, 3), 0), vec(0, Rational(-1, 7), 0)}, {Rational(5, 3)});
    Scene_builder sb("tie", 0, 4);
    sb.object("a", a).object("b", translate(vec(dx, 0, 0), b), m);
    Check_options opts;
    Check_answer x = check_exact(sb.scene(), opts), r = check_rational(sb.scene(), opts);
    std::string where = "case " + std::to_string(c) + " of seed " + std::to_string(seed);
    BOOST_TEST(x.collide == r.collide, where);
    BOOST_TEST(x.stats.candidate_pairs == r.stats.candidate_pairs, where);
    if (x.stats.exact_sweep_ties == 0) continue;
    ++ties;
    (x.stats.candidate_pairs == 0 ? dropped : kept)++;
  }
  BOOST_TEST_MESSAGE("ties " << ties << ", dropped " << dropped << ", kept " << kept);
  BOOST_TEST(ties >= cases / 2);
  BOOST_TEST(dropped >= cases / 10);
  BOOST_TEST(kept >= cases / 10);
}

// The all-pairs test a few boxes get (Pair_sweep's few_boxes) reports the
// pairs CGAL's sweep reports, each with the same certainty, in rationals
// and in intervals, regularised and closed: forced each way on clusters of
// 3 to 12 objects (6 to 24 boxes), whose integer blocks often touch.
template <class K>
static void sweeps_agree(const K& k, const Scene& scene, const std::string& where)
{
  Scene_model<K> model = Scene_model<K>::build(k, scene);
  Check_stats stats;
  std::vector<Box<typename K::FT, 3>> roots;
  for (const auto& b : settled_bounds_all(k, model, stats, true)) roots.push_back(b[0]);
  for (bool closed : {false, true}) {
    std::vector<char> swept_sure, tested_sure;
    auto swept = Pair_sweep<K>(k, closed, 0).candidates(model, roots, scene, &swept_sure);
    auto tested = Pair_sweep<K>(k, closed, 1000).candidates(model, roots, scene, &tested_sure);
    BOOST_TEST((swept == tested), where << (closed ? " closed" : ""));
    BOOST_TEST((swept_sure == tested_sure), where << (closed ? " closed" : ""));
    // Into storage another sweep left filled (a prepared scene's, swept
    // again per query): the same pairs and certainties, nothing kept.
    std::vector<std::pair<int, int>> into{{7, 9}, {0, 1}, {2, 5}, {0, 2}};
    std::vector<char> into_sure(5, 1);
    Pair_sweep<K>(k, closed, 0)
        .candidates_into(model, [&](std::size_t i) -> const auto& { return roots[i]; }, scene, into, &into_sure);
    BOOST_TEST((into == swept), where << (closed ? " closed" : "") << " into used storage");
    BOOST_TEST((into_sure == swept_sure), where << (closed ? " closed" : "") << " into used storage");
  }
}

BOOST_AUTO_TEST_CASE(all_pairs_test_of_few_boxes_equals_the_sweep)
{
  std::uint64_t seed = 1271990;
  BOOST_TEST_MESSAGE("seed " << seed);
  std::mt19937_64 rng(seed);
  std::size_t pairs = 0;
  for (int round = 0; round < 40; ++round) {
    int n = 3 + round % 10;
    Scene scene = parse(random_cluster(rng, n));
    std::string where = "round " + std::to_string(round) + ", " + std::to_string(n) + " objects";
    sweeps_agree(Rational_kernel(), scene, where + " (rational)");
    {
      Interval_kernel::Protector protect;
      sweeps_agree(Interval_kernel(), scene, where + " (intervals)");
    }
    Check_stats stats;
    Rational_kernel k;
    Scene_model<Rational_kernel> model = Scene_model<Rational_kernel>::build(k, scene);
    std::vector<Box<Rational, 3>> roots;
    for (const auto& b : settled_bounds_all(k, model, stats, true)) roots.push_back(b[0]);
    pairs += Pair_sweep<Rational_kernel>(k).candidates(model, roots, scene).size();
  }
  BOOST_TEST(pairs > 40u);   // the clusters' boxes do meet
}
