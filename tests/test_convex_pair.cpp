// Convex pairs decided by linear programs (search/Convex_pair.h): the double
// simplex that guesses, and the stage's verdicts on hand-derived scenes, in
// the rational and the double kernel; end to end through `check` in every
// kernel, against the paper's cascade.
#define BOOST_TEST_MODULE convex_pair
#include <boost/test/unit_test.hpp>

#include "exact/Exact_instantiation.h"
#include "exact/Interval_kernel.h"
#include "exact/Rational_kernel.h"
#include "float/Double_instantiation.h"
#include "float/Double_kernel.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include "search/Convex_pair.h"
#include "search/Witness.h"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <random>

using namespace clash4d;

namespace {

Scene scene_of(const std::string& objects, const std::string& time = "[0, 5]")
{
  return read_scene(read_json_text(R"({"format": "clash4d-scene/1", "time": )" + time + R"(, "objects": [)" +
                                   objects + "]}"));
}

// a = [0,1]^3 at rest; b a unit block starting at x = start, moving by
// `motion`.
Scene two_blocks(const std::string& b_min, const std::string& b_max, const std::string& motion,
                 const std::string& time = "[0, 5]")
{
  return scene_of(R"({"name": "a", "shape": {"block": {"min": [0, 0, 0], "max": [1, 1, 1]}}},
                     {"name": "b", "shape": {"block": {"min": )" + b_min + R"(, "max": )" + b_max + R"(}},
                      "motion": ")" + motion + R"("})",
                  time);
}

// The stage on the pair's first sub-span, in kernel K.
template <class K>
struct Staged {
  typename Convex_pair<K>::Verdict verdict;
  Search_goal<typename K::FT> goal;
};

template <class K>
Staged<K> decide(const Scene& scene, bool earliest, Semantics semantics, std::size_t index = 0, K k = K())
{
  Scene_model<K> model = Scene_model<K>::build(k, scene);
  BOOST_TEST_REQUIRE(Convex_pair<K>::applies(model, 0, 1));
  Convex_pair<K> stage(k, model, 0, 1);
  auto span = model.sub_spans({0, 1}).at(index);
  auto A = moving_on(model, 0, span, {}), B = moving_on(model, 1, span, {});
  Staged<K> s;
  s.goal.earliest = earliest;
  s.goal.semantics = semantics;
  s.verdict = stage.decide(index, A, B, span, s.goal);
  return s;
}

using Verdict = Convex_pair<Rational_kernel>::Verdict;
using Q = Rational;

bool strictly_between(const Q& lo, const Q& x, const Q& hi) { return lo < x && x < hi; }

} // namespace

// maximise 3 y0 + y1  s.t.  y0 + y1 + y2 = 2, y0 - y2 = -1, y >= 0:
// y2 = y0 + 1 and y1 = 1 - 2 y0, so the objective is 1 + y0 on
// 0 <= y0 <= 1/2: y = (1/2, 0, 3/2), value 3/2. The multipliers are tight on
// y0's and y2's columns: pi1 + pi2 = 3, pi1 - pi2 = 0, so pi = (3/2, 3/2)
// (and pi1 >= 1 on y1's), with pi . b = 3 - 3/2 = 3/2. The second row's
// negative right-hand side is turned for phase 1 and back for pi.
BOOST_AUTO_TEST_CASE(double_simplex_optimum_and_multipliers)
{
  Double_simplex lp(2, 3, {2, -1, 0, 0, 0});
  double a0[2] = {1, 1}, a1[2] = {1, 0}, a2[2] = {1, -1};
  lp.column(0, a0, 3);
  lp.column(1, a1, 1);
  lp.column(2, a2, 0);
  std::optional<Double_simplex::Optimum> o = lp.solve();
  BOOST_TEST_REQUIRE(o.has_value());
  BOOST_TEST(std::abs(o->value - 1.5) < 1e-12);
  BOOST_TEST(std::abs(o->pi[0] - 1.5) < 1e-12);
  BOOST_TEST(std::abs(o->pi[1] - 1.5) < 1e-12);
  std::vector<int> basis(o->basis.begin(), o->basis.end());
  std::sort(basis.begin(), basis.end());
  BOOST_TEST((basis == std::vector<int>{0, 2}));
  // y0 + y1 = -1 has no solution with y >= 0.
  Double_simplex none(1, 2, {-1, 0, 0, 0, 0});
  double one[1] = {1};
  none.column(0, one, 1);
  none.column(1, one, 0);
  BOOST_TEST(!none.solve().has_value());
}

// The simplex's pivot (built for AVX2 too, and chosen when loaded) rounds
// as the plain loop does, bit for bit, so that a guess, and every answer
// made from it, is the same on every machine: seeded random tableaux of
// every width up to 61 (odd ones leave a remainder past the vector width),
// entries over many exponents, zeros in the pivot column (rows skipped).
BOOST_AUTO_TEST_CASE(pivot_tableau_rounds_as_the_plain_loop)
{
  std::uint64_t seed = 20261130;
  bool avx2 = __builtin_cpu_supports("avx2") != 0;
  BOOST_TEST_MESSAGE("pivot_tableau: seed " << seed << (avx2 ? ", the AVX2 build" : ", the base build"));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-60, 60);
  int compared = 0;
  for (int width = 1; width <= 61; ++width)
    for (int rows = 1; rows <= 6; ++rows) {
      std::vector<double> t(static_cast<std::size_t>(rows * width));
      for (double& x : t) x = rng() % 5 == 0 ? 0.0 : std::ldexp(mantissa(rng), exponent(rng));
      int leave = static_cast<int>(rng() % static_cast<std::uint64_t>(rows));
      int enter = static_cast<int>(rng() % static_cast<std::uint64_t>(width));
      if (t[static_cast<std::size_t>(leave * width + enter)] == 0.0) t[static_cast<std::size_t>(leave * width + enter)] = 0.75;
      std::vector<double> want = t;
      auto at = [&](int r, int c) -> double& { return want[static_cast<std::size_t>(r * width + c)]; };
      double p = at(leave, enter);
      for (int c = 0; c < width; ++c) at(leave, c) = at(leave, c) / p;
      for (int r = 0; r < rows; ++r) {
        double f = at(r, enter);
        if (r == leave || f == 0.0) continue;
        for (int c = 0; c < width; ++c) at(r, c) = at(r, c) - f * at(leave, c);
      }
      pivot_tableau(t.data(), rows, width, leave, enter);
      BOOST_TEST(std::memcmp(t.data(), want.data(), t.size() * sizeof(double)) == 0,
                 "width " << width << ", rows " << rows);
      ++compared;
    }
  BOOST_TEST(compared == 61 * 6);
}

// The spec's example: ram [3, 4] x [0, 1]^2 moving -x at speed 1 passes box
// [0, 1]^3 for 2 < t < 4 (3 - t < 1 and 4 - t > 0). Regularised, the point
// inside is strictly inside both; t* = 2, where ram's face x = 3 - t reaches
// box's face x = 1: a contact point on that square, y and z in [0, 1].
template <class K>
void passing_blocks()
{
  Scene s = two_blocks("[3, 0, 0]", "[4, 1, 1]", "vel -1 0 0");
  Staged<K> any = decide<K>(s, false, Semantics::regularised);
  BOOST_TEST((any.verdict == Convex_pair<K>::Verdict::collide));
  Vector4<Q> p;
  for (int q = 0; q < 4; ++q) p[q] = K().to_rational(any.goal.inside[q]);
  for (int q = 0; q < 3; ++q) BOOST_TEST(strictly_between(Q(0), p[q], Q(1)));
  BOOST_TEST(strictly_between(Q(3) - p[3], p[0], Q(4) - p[3]));
  BOOST_TEST(strictly_between(Q(0), p[3], Q(5)));

  Staged<K> first = decide<K>(s, true, Semantics::regularised);
  BOOST_TEST((first.verdict == Convex_pair<K>::Verdict::collide));
  BOOST_TEST(K().to_rational(first.goal.t_star) == Q(2));
  BOOST_TEST(K().to_rational(first.goal.contact[0]) == Q(1));
  for (int q = 1; q < 3; ++q) {
    Q c = K().to_rational(first.goal.contact[q]);
    BOOST_TEST((Q(0) <= c && c <= Q(1)));
  }
  // Closed, the first contact is the same instant.
  Staged<K> closed = decide<K>(s, true, Semantics::closed);
  BOOST_TEST((closed.verdict == Convex_pair<K>::Verdict::collide));
  BOOST_TEST(K().to_rational(closed.goal.t_star) == Q(2));
}

BOOST_AUTO_TEST_CASE(passing_blocks_collide_from_t_2)
{
  passing_blocks<Rational_kernel>();
  passing_blocks<Double_kernel>();
}

// b = [1, 2] x [0, 1]^2 at rest against a's face x = 1: touching, so no
// regularised collision (Motzkin's multipliers on the two faces x <= 1 and
// -x + 1 <= 0 sum to 0) and a closed one, at a point with x = 1. b 1/2
// further is apart in both (Farkas: the sum is 1/2 > 0).
template <class K>
void touching_and_apart_blocks()
{
  Scene touch = two_blocks("[1, 0, 0]", "[2, 1, 1]", "rest", "[0, 1]");
  BOOST_TEST((decide<K>(touch, false, Semantics::regularised).verdict == Convex_pair<K>::Verdict::apart));
  BOOST_TEST((decide<K>(touch, true, Semantics::regularised).verdict == Convex_pair<K>::Verdict::apart));
  Staged<K> closed = decide<K>(touch, false, Semantics::closed);
  BOOST_TEST((closed.verdict == Convex_pair<K>::Verdict::collide));
  BOOST_TEST(K().to_rational(closed.goal.inside[0]) == Q(1));
  Staged<K> first = decide<K>(touch, true, Semantics::closed);
  BOOST_TEST((first.verdict == Convex_pair<K>::Verdict::collide));
  BOOST_TEST(K().to_rational(first.goal.t_star) == Q(0));   // touching from the start

  Scene apart = two_blocks(R"(["3/2", 0, 0])", R"(["5/2", 1, 1])", "rest", "[0, 1]");
  for (Semantics sem : {Semantics::regularised, Semantics::closed})
    for (bool earliest : {false, true})
      BOOST_TEST((decide<K>(apart, earliest, sem).verdict == Convex_pair<K>::Verdict::apart));
}

BOOST_AUTO_TEST_CASE(touching_blocks_are_a_closed_contact_only)
{
  touching_and_apart_blocks<Rational_kernel>();
  touching_and_apart_blocks<Double_kernel>();
}

// A square pyramid, apex (1/2, 1/2, 2), falling at speed 1 onto [0,1]^3:
// the apex reaches the top face z = 1 at t = 1 and goes on in, so t* = 1 in
// both semantics, at the apex: five rows meet there (four facets and the
// top face), a vertex the multipliers y >= 0 prove least.
BOOST_AUTO_TEST_CASE(pyramid_apex_meets_the_face_at_t_1)
{
  Scene s = scene_of(R"({"name": "a", "shape": {"block": {"min": [0, 0, 0], "max": [1, 1, 1]}}},
    {"name": "p", "shape": {"hull": [[0, 0, 3], [1, 0, 3], [1, 1, 3], [0, 1, 3], ["1/2", "1/2", 2]]},
     "motion": "vel 0 0 -1"})",
                     "[0, 3]");
  for (Semantics sem : {Semantics::regularised, Semantics::closed}) {
    Staged<Rational_kernel> e = decide<Rational_kernel>(s, true, sem);
    BOOST_TEST((e.verdict == Verdict::collide));
    BOOST_TEST(e.goal.t_star == Q(1));
    BOOST_TEST((e.goal.contact == Vector4<Q>{Q(1, 2), Q(1, 2), Q(1), Q(1)}));
  }
}

// An overlap of 10^-30 is beyond the guide's doubles (1 - 10^-30 rounds to
// 1, a touch): its multipliers prove nothing exactly (their sum is
// -10^-30), and the programs' optimum made exactly from the guess's five
// rows, where the two faces' margins are equal (10^-30 / 2), is inside:
// a collision, with a witness strictly inside both. A scene number beyond
// the doubles (10^400) leaves no guess at all: the sub-span goes to the
// cascade, which finds the collision; every kernel's `check` agrees.
BOOST_AUTO_TEST_CASE(thin_overlaps_and_numbers_beyond_the_guess)
{
  Scene thin = two_blocks(R"(["0.999999999999999999999999999999", 0, 0])", "[2, 1, 1]", "rest", "[0, 1]");
  Staged<Rational_kernel> t = decide<Rational_kernel>(thin, false, Semantics::regularised);
  BOOST_TEST((t.verdict == Verdict::collide));
  Q micro(1, 1000000);
  BOOST_TEST(t.goal.inside[0] == Q(1) - micro * micro * micro * micro * micro / Q(2));   // the faces' mid-plane
  Scene huge = scene_of(R"({"name": "a", "shape": {"block": {"min": [0, 0, 0], "max": ["1e400", 1, 1]}}},
    {"name": "b", "shape": {"block": {"min": [2, 0, 0], "max": [3, 1, 1]}}})",
                        "[0, 1]");
  BOOST_TEST((decide<Rational_kernel>(huge, false, Semantics::regularised).verdict == Verdict::undecided));
  for (const Scene* s : {&thin, &huge})
    for (const Check_answer& a : {check_rational(*s, Check_options()), check_exact(*s, Check_options())}) {
      BOOST_TEST(a.collide);
      BOOST_TEST(a.reported()->witness_verified);
      BOOST_TEST(a.stats.convex_undecided == (s == &huge ? 1u : 0u));
    }
}

namespace {

// A query's options with the linear programs, and the same for the paper's
// cascade alone.
std::pair<Check_options, Check_options> lp_and_cascade(Semantics semantics, bool earliest)
{
  Check_options lp;
  lp.semantics = semantics;
  lp.earliest = earliest;
  Check_options cascade = lp;
  cascade.convex_lp = false;
  return {lp, cascade};
}

} // namespace

// End to end over the contact fixtures' convex pairs: the linear programs
// and the paper's cascade give the same verdicts and t* (the witnesses
// differ: any point inside will do), in the rational and double kernels.
BOOST_AUTO_TEST_CASE(linear_programs_agree_with_the_cascade)
{
  std::size_t decided = 0;
  for (const char* name : {"clear_collision_head_on", "face_touch_static", "vertex_face_touch_instant",
                           "vertex_face_touch_instant_overlap_1e-9", "hull_vertex_on_face", "prism_edge_on_face",
                           "rotated_3_4_vertex_touch", "approach_stop_at_contact_overlap_1e-9", "touch_only_at_tL_overlap_1e-9"}) {
    Scene s = read_scene_file(std::string(CLASH4D_FIXTURES) + "/contact/" + name + ".json");
    for (Semantics sem : {Semantics::regularised, Semantics::closed})
      for (bool earliest : {false, true}) {
        auto [lp, cascade] = lp_and_cascade(sem, earliest);
        Check_answer a = check_rational(s, lp), b = check_rational(s, cascade);
        BOOST_TEST(a.collide == b.collide, name);
        if (a.collide && earliest) BOOST_TEST(a.reported()->t_star == b.reported()->t_star, name);
        if (a.collide) BOOST_TEST(a.reported()->witness_verified, name);
        decided += a.stats.convex_spans;
        BOOST_TEST(b.stats.convex_spans == 0u);
      }
  }
  BOOST_TEST(decided > 0u);
}

// Two convex pieces of real meshes (fixtures/meshes/ur5_piece_pair.json:
// piece 1 of the UR5 base and piece 3 of its wrist, as the mesh cache made
// them, the wrist passing in x): their facets' normals span 1e-12 to 1e-4,
// and the double simplex of the least time did not settle at the finest
// pivot tolerance, which sent --earliest to the cascade. With the coarser
// tolerances tried next, the programs decide every query, with the
// cascade's verdict and t*, in the exact and rational kernels.
BOOST_AUTO_TEST_CASE(mesh_pieces_are_decided_by_their_programs)
{
  Scene s = read_scene_file(std::string(CLASH4D_FIXTURES) + "/meshes/ur5_piece_pair.json");
  for (Semantics sem : {Semantics::regularised, Semantics::closed})
    for (bool earliest : {false, true}) {
      auto [lp, cascade] = lp_and_cascade(sem, earliest);
      std::string what = std::string(sem == Semantics::closed ? "closed" : "regularised") + (earliest ? " earliest" : "");
      Check_answer c = check_exact(s, cascade);
      BOOST_TEST_REQUIRE(c.collide, what);
      for (const Check_answer& a : {check_exact(s, lp), check_rational(s, lp)}) {
        BOOST_TEST(a.collide, what);
        BOOST_TEST(a.stats.convex_spans == 1u, what);
        BOOST_TEST(a.stats.convex_undecided == 0u, what);
        BOOST_TEST(a.reported()->witness_verified, what);
        if (earliest) BOOST_TEST(a.reported()->t_star == c.reported()->t_star, what);
      }
    }
}

// A one-primitive solid's planes made as asked (model/Primitive_planes.h)
// are the model's planes (Model_builder), plane by plane, for every such
// object of the contact and paper fixtures (translated, rotated, hulls,
// prisms, half-spaces): the same transforms, applied one plane at a time.
BOOST_AUTO_TEST_CASE(planes_made_as_asked_are_the_models)
{
  Rational_kernel k;
  std::size_t objects = 0;
  for (const char* family : {"contact", "paper"})
    for (const auto& f : std::filesystem::directory_iterator(std::string(CLASH4D_FIXTURES) + "/" + family)) {
      if (f.path().filename() == "expected.json") continue;
      Scene s = read_scene_file(f.path().string());
      Scene_model<Rational_kernel> m = Scene_model<Rational_kernel>::build(k, s);
      for (std::size_t i = 0; i < s.objects.size(); ++i) {
        const Csg_model<Q>& csg = m.objects[i].csg;
        if (csg.nodes.size() != 1) continue;
        Primitive_planes<Rational_kernel> lazy(k, s.objects[i].shape);
        BOOST_TEST_REQUIRE(lazy.size() == csg.primitives[0].planes.size());
        for (std::size_t p = lazy.size(); p-- > 0;)   // out of order: each made alone
          BOOST_TEST((lazy[p] == csg.primitives[0].planes[p]), f.path().filename() << " " << s.objects[i].name);
        ++objects;
      }
    }
  BOOST_TEST(objects > 100u);
}

namespace {

// Whether each row of a convex pair's stage on every sub-span of every pair
// of one-primitive objects in `scene` is Witness::world_planes' plane in
// the same place (the witness is made on the rows instead,
// Collision_checker::check_span): the same numbers, bound for bound in
// intervals. Counts the rows compared.
template <class K, class Same>
std::size_t rows_against_world_planes(const K& k, const Scene& scene, const std::string& file, Same same)
{
  Scene_model<K> model = Scene_model<K>::build(k, scene);
  std::size_t rows = 0;
  for (int a = 0; a < static_cast<int>(scene.objects.size()); ++a)
    for (int b = a + 1; b < static_cast<int>(scene.objects.size()); ++b) {
      if (!Convex_pair<K>::applies(model, a, b)) continue;
      Convex_pair<K> stage(k, model, a, b);
      auto spans = model.sub_spans({a, b});
      for (std::size_t i = 0; i < spans.size(); ++i) {
        auto A = moving_on(model, a, spans[i], {}), B = moving_on(model, b, spans[i], {});
        Search_goal<typename K::FT> goal;
        stage.start_span(i, A, B, spans[i]);
        try {
          if (i % 2 == 0) stage.decide(i, A, B, spans[i], goal);   // some rows made by decide, the rest as asked
        } catch (const CGAL::Uncertain_conversion_exception&) {   // intervals: a construction they cannot make
        }
        auto world = Witness<K>::world_planes(A, B, spans[i].lo, spans[i].hi);
        auto made = stage.world_rows();
        BOOST_TEST_REQUIRE(made.size() == world.size(), file);
        for (std::size_t j = 0; j < made.size(); ++j, ++rows)
          for (int q = 0; q < 5; ++q) {
            const auto& x = q < 4 ? made[j].n[q] : made[j].c;
            const auto& y = q < 4 ? world[j].n[q] : world[j].c;
            BOOST_TEST(same(x, y), file << " objects " << a << ", " << b << " span " << i << " row " << j);
          }
      }
    }
  return rows;
}

} // namespace

// The regularised witness of a convex pair is made on the stage's rows
// (Witness::make_on), so they must be the world planes Witness::make would
// make, in its order (A's planes, B's, t >= lo, t <= hi): otherwise the
// snap would keep the point off the wrong planes. Every contact and paper
// fixture, in rationals and in intervals.
BOOST_AUTO_TEST_CASE(rows_are_the_witness_world_planes)
{
  std::size_t rational = 0, interval = 0;
  for (const char* family : {"contact", "paper"})
    for (const auto& f : std::filesystem::directory_iterator(std::string(CLASH4D_FIXTURES) + "/" + family)) {
      if (f.path().filename() == "expected.json") continue;
      Scene s = read_scene_file(f.path().string());
      std::string file = f.path().filename().string();
      rational += rows_against_world_planes(Rational_kernel(), s, file, [](const Q& x, const Q& y) { return x == y; });
      Interval_kernel::Protector protect;
      interval += rows_against_world_planes(Interval_kernel(), s, file, [](const Interval_kernel::FT& x,
                                                                           const Interval_kernel::FT& y) {
        return x.inf() == y.inf() && x.sup() == y.sup();
      });
    }
  BOOST_TEST(rational > 1000u);
  BOOST_TEST(interval == rational);
}

namespace {

// The rows of the stage on `scene`'s first sub-span, found by their signs:
// the one zero at `on` and positive at `out` (the row's outside).
template <class K>
std::size_t row_between(Convex_pair<K>& stage, std::size_t rows, const Vector4<double>& on, const Vector4<double>& out)
{
  for (std::size_t j = 0; j < rows; ++j)
    if (stage.row_sign(j, on) == CGAL::ZERO && stage.row_sign(j, out) == CGAL::POSITIVE) return j;
  BOOST_FAIL("no such row");
  return 0;
}

// a = [0,1]^3 at rest, b = [2,3] x [0,1]^2 moving at -1 along x from t = 0:
// b's face x = 2 - t reaches a's face x = 1 at t = 1. The three rows
// x - 1 <= 0 (a), 2 - t - x <= 0 (b) and t - hi <= 0 (the span's end) have
// normals (1,0,0,0), (-1,0,0,-1), (0,0,0,1): lambda = (1, 1, 1) is their
// one dependency, with sum lambda c = -1 + 2 - hi. For hi = 1 that is 0: the
// open system is empty (the faces touch at t = 1), the closed one is not;
// for hi = 1/2 it is 1/2 > 0: both empty. With the span's start t >= 0
// (normal (0,0,0,-1)) instead of its end the dependency needs lambda < 0:
// nothing proved. Every order of the rows is asked, so pivots of either sign
// come first (the back substitution's scaling by |p|).
template <class K>
void multipliers_on_a_moving_touch()
{
  for (const char* hi : {"1", "1/2"}) {
    Scene s = two_blocks("[2, 0, 0]", "[3, 1, 1]", "vel -1 0 0", std::string("[0, \"") + hi + "\"]");
    K k;
    Scene_model<K> model = Scene_model<K>::build(k, s);
    Convex_pair<K> stage(k, model, 0, 1);
    auto span = model.sub_spans({0, 1}).at(0);
    auto A = moving_on(model, 0, span, {}), B = moving_on(model, 1, span, {});
    stage.start_span(0, A, B, span);
    double end = std::string(hi) == "1" ? 1 : 0.5;
    std::size_t a = row_between(stage, 6, {1, 0.5, 0.5, 0}, {2, 0.5, 0.5, 0});
    std::size_t b = row_between(stage, 14, {2 - end, 0.5, 0.5, end}, {0, 0.5, 0.5, end});
    std::size_t last = row_between(stage, 14, {0.5, 0.5, 0.5, end}, {0.5, 0.5, 0.5, end + 1});
    std::size_t first = row_between(stage, 14, {0.5, 0.5, 0.5, 0}, {0.5, 0.5, 0.5, -1});
    BOOST_TEST_REQUIRE((a < 6 && b >= 6 && b < 12 && last >= 12 && first >= 12));
    std::vector<std::size_t> rows{a, b, last};
    std::sort(rows.begin(), rows.end());
    do {
      BOOST_TEST(stage.proves_empty(rows, false), K::name() << " hi " << hi);
      BOOST_TEST(stage.proves_empty(rows, true) == (end < 1), K::name() << " hi " << hi);
      BOOST_TEST(!stage.proves_empty({rows[0], rows[1]}, false), "independent normals");
    } while (std::next_permutation(rows.begin(), rows.end()));
    std::vector<std::size_t> wrong{a, b, first};
    BOOST_TEST(!stage.proves_empty(wrong, false), K::name() << " a negative multiplier");
  }
}

} // namespace

BOOST_AUTO_TEST_CASE(multipliers_prove_a_moving_touch_empty_only_when_open)
{
  multipliers_on_a_moving_touch<Rational_kernel>();
  multipliers_on_a_moving_touch<Double_kernel>();
}
