#define BOOST_TEST_MODULE rotation
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>

#include "exact/Exact_instantiation.h"
#include "rotation/Rotating_check.h"
#include "rotation/Simplest_rational.h"
#include "scene/Scene_reader.h"
#include "support/Random_scene.h"
#include <nlohmann/json.hpp>
#include <cstdlib>
#include <fstream>

using namespace clash4d;
namespace data = boost::unit_test::data;
using json = nlohmann::json;

// fixtures/rotation/expected.json: per scene and semantics, the verdict,
// t* and the contact point, derived by hand (the "why" of each entry).
static json manifest()
{
  std::ifstream in(std::string(CLASH4D_FIXTURES) + "/rotation/expected.json");
  return in ? json::parse(in) : json::object();
}

static std::vector<std::string> fixture_names()
{
  std::vector<std::string> out;
  json m = manifest();
  for (const auto& item : m.items()) out.push_back(item.key());
  return out;
}

static Rational q(const std::string& s) { return rational_from_string(s); }

// An expected number: "p/q", or {"poly", "between"}: the one root there.
static Algebraic expected_number(const json& e)
{
  if (e.is_string()) return Algebraic(q(e.get<std::string>()));
  std::vector<Rational> poly;
  for (const auto& c : e["poly"]) poly.push_back(q(c.get<std::string>()));
  auto roots = Algebraic::real_roots(poly, q(e["between"][0].get<std::string>()), q(e["between"][1].get<std::string>()));
  BOOST_REQUIRE_EQUAL(roots.size(), 1u);
  return roots[0];
}

// A coordinate: an exact number, or {"range": [lo, hi]} where the contact
// set leaves it free.
static void check_coordinate(const Algebraic& x, const json& e, const std::string& what)
{
  BOOST_TEST_CONTEXT(what << " = " << x.to_text() << ", expected " << e.dump())
  {
    if (e.is_object() && e.contains("range")) {
      BOOST_TEST(compare(x, q(e["range"][0].get<std::string>())) >= 0);
      BOOST_TEST(compare(x, q(e["range"][1].get<std::string>())) <= 0);
    } else {
      BOOST_TEST(compare(x, expected_number(e)) == 0);
    }
  }
}

// ---- An independent evaluator of the fixtures' solids (blocks, unions,
// differences) under pose motions, written from the spec: the pose at t by
// linear interpolation of q and c, then p = R(q)^T (x - c).
namespace {

using Point = std::array<Rational, 3>;

struct Pose_at {
  std::array<Rational, 4> q;
  Point c;
};

Pose_at pose_at(const json& motion, const Rational& t)
{
  std::vector<std::pair<Rational, Pose_at>> poses;
  for (const auto& p : motion["poses"]) {
    Pose_at a{{Rational(1), Rational(0), Rational(0), Rational(0)}, {Rational(0), Rational(0), Rational(0)}};
    if (p.contains("rotate"))
      for (int i = 0; i < 4; ++i) a.q[i] = q(p["rotate"][i].is_string() ? p["rotate"][i].get<std::string>() : p["rotate"][i].dump());
    if (p.contains("translate"))
      for (int i = 0; i < 3; ++i)
        a.c[i] = q(p["translate"][i].is_string() ? p["translate"][i].get<std::string>() : p["translate"][i].dump());
    poses.emplace_back(q(p["t"].dump()), a);
  }
  if (!(poses.front().first < t)) return poses.front().second;
  for (std::size_t i = 0; i + 1 < poses.size(); ++i)
    if (t <= poses[i + 1].first) {
      Rational s = (t - poses[i].first) / (poses[i + 1].first - poses[i].first);
      Pose_at out;
      for (int k = 0; k < 4; ++k) out.q[k] = (1 - s) * poses[i].second.q[k] + s * poses[i + 1].second.q[k];
      for (int k = 0; k < 3; ++k) out.c[k] = (1 - s) * poses[i].second.c[k] + s * poses[i + 1].second.c[k];
      return out;
    }
  return poses.back().second;
}

Point to_shape(const Pose_at& p, const Point& x)
{
  const auto& [w, a, b, c] = p.q;
  Rational n = w * w + a * a + b * b + c * c;
  Rational R[3][3] = {{w * w + a * a - b * b - c * c, 2 * (a * b - w * c), 2 * (a * c + w * b)},
                      {2 * (a * b + w * c), w * w - a * a + b * b - c * c, 2 * (b * c - w * a)},
                      {2 * (a * c - w * b), 2 * (b * c + w * a), w * w - a * a - b * b + c * c}};
  Point d = {x[0] - p.c[0], x[1] - p.c[1], x[2] - p.c[2]}, out;
  for (int i = 0; i < 3; ++i) out[i] = (R[0][i] * d[0] + R[1][i] * d[1] + R[2][i] * d[2]) / n;   // R^T d
  return out;
}

Rational number(const json& v) { return q(v.is_string() ? v.get<std::string>() : v.dump()); }

// Strictly inside (interior) or in the closed solid.
bool inside(const json& s, const Point& p, bool strict)
{
  if (s.contains("block")) {
    for (int i = 0; i < 3; ++i) {
      Rational lo = number(s["block"]["min"][i]), hi = number(s["block"]["max"][i]);
      if (strict ? !(lo < p[i] && p[i] < hi) : (p[i] < lo || hi < p[i])) return false;
    }
    return true;
  }
  if (s.contains("union")) {
    for (const auto& c : s["union"])
      if (inside(c, p, strict)) return true;
    return false;
  }
  const json& d = s["difference"];
  if (!inside(d[0], p, strict)) return false;
  for (std::size_t i = 1; i < d.size(); ++i)
    if (inside(d[i], p, !strict)) return false;
  return true;
}

bool object_holds(const json& o, const Point& x, const Rational& t, bool strict)
{
  Point p = o.contains("motion") ? to_shape(pose_at(o["motion"], t), x) : x;
  return inside(o["shape"], p, strict);
}

json scene_json(const std::string& name)
{
  std::ifstream in(std::string(CLASH4D_FIXTURES) + "/rotation/" + name);
  return json::parse(in);
}

const json& object_named(const json& scene, const std::string& name)
{
  for (const auto& o : scene["objects"])
    if (o["name"] == name) return o;
  throw std::logic_error("no object " + name);
}

} // namespace

BOOST_DATA_TEST_CASE(fixtures_hand_derived, data::make(fixture_names()), name)
{
  json e = manifest()[name];
  json sj = scene_json(name);
  Scene scene = read_scene_file(std::string(CLASH4D_FIXTURES) + "/rotation/" + name);
  for (const char* number : {"exact", "rational"})
    for (Semantics sem : {Semantics::regularised, Semantics::closed}) {
      json want = e[semantics_name(sem)];
      Check_options o;
      o.semantics = sem;
      o.earliest = true;
      BOOST_TEST_CONTEXT(name << ", " << number << ", " << semantics_name(sem))
      {
        Rotating_check_answer a = check_rotating(scene, o, number);
        BOOST_TEST(a.collide == want["collide"].get<bool>());
        if (!a.collide || !want["collide"].get<bool>()) continue;
        const Rotating_pair_answer& p = *a.reported();
        if (want.contains("pair")) {
          BOOST_TEST(p.a == want["pair"][0].get<std::string>());
          BOOST_TEST(p.b == want["pair"][1].get<std::string>());
        }
        BOOST_TEST(compare(p.answer.t_star, expected_number(want["t"])) == 0, "t* = " << p.answer.t_star.to_text());
        for (int i = 0; i < 3; ++i) check_coordinate(p.answer.contact[i], want["point"][i], "contact[" + std::to_string(i) + "]");
        // The witness, by the evaluator above: strictly inside both
        // (regularised, where it is always rational) or in both closed.
        const auto& w = p.answer.witness;
        bool rational = w[0].is_rational() && w[1].is_rational() && w[2].is_rational() && w[3].is_rational();
        BOOST_TEST((rational || sem == Semantics::closed));
        if (!rational) continue;
        Point x = {w[0].rational(), w[1].rational(), w[2].rational()};
        bool strict = sem == Semantics::regularised;
        BOOST_TEST(object_holds(object_named(sj, p.a), x, w[3].rational(), strict));
        BOOST_TEST(object_holds(object_named(sj, p.b), x, w[3].rational(), strict));
        BOOST_TEST(scene.t_lo <= w[3].rational());
        BOOST_TEST(w[3].rational() <= scene.t_hi);
      }
    }
}

// The time slices on scenes without rotation, against the translation
// pipeline (a different method: S-bounds, divide-and-conquer and
// generate-and-test in 4D): the same verdicts and the same t* in both
// semantics, on contact-heavy random scenes (tests/support/Random_scene.h).
BOOST_AUTO_TEST_CASE(time_slices_agree_with_the_translation_pipeline)
{
  std::uint64_t seed = 61;
  if (const char* s = std::getenv("CLASH4D_ROTATION_SEED")) seed = std::strtoull(s, nullptr, 10);
  int cases = 150;
  if (const char* s = std::getenv("CLASH4D_ROTATION_CASES")) cases = std::atoi(s);
  BOOST_TEST_MESSAGE("seed " << seed << " (CLASH4D_ROTATION_SEED), " << cases << " scenes (CLASH4D_ROTATION_CASES)");
  std::mt19937_64 rng(seed);
  int collisions = 0, contacts = 0;
  for (int i = 0; i < cases; ++i) {
    Random_scene rs = random_scene_with_text(rng);
    for (Semantics sem : {Semantics::regularised, Semantics::closed}) {
      Check_options o;
      o.semantics = sem;
      o.earliest = true;
      Check_answer want = check_exact(rs.scene, o);
      Rotating_check_answer got;
      try {
        got = check_rotating(rs.scene, o, "exact");
      } catch (const Rotation_unsupported& e) {
        BOOST_TEST_MESSAGE("case " << i << " " << semantics_name(sem) << ": unsupported: " << e.what());
        continue;
      }
      BOOST_TEST_CONTEXT("case " << i << ", " << semantics_name(sem) << ":\n" << rs.json)
      {
        BOOST_TEST(got.collide == want.collide);
        if (!got.collide || !want.collide) continue;
        (sem == Semantics::closed ? contacts : collisions) += 1;
        Algebraic t = got.reported()->answer.t_star;
        BOOST_TEST(t.is_rational());
        if (t.is_rational())
          BOOST_TEST(t.rational() == rational_from_string(want.reported()->t_star), "t* " << t.to_text() << " against "
                                                                                        << want.reported()->t_star);
      }
    }
  }
  BOOST_TEST_MESSAGE(collisions << " collisions and " << contacts << " closed contacts compared");
  BOOST_TEST(collisions >= cases / 10);   // the scenes are not all apart
}

BOOST_AUTO_TEST_CASE(simplest_rational_between)
{
  BOOST_TEST(simplest_between(q("1/3"), q("1/2")) == q("2/5"));
  BOOST_TEST(simplest_between(q("-1/2"), q("1/3")) == q("0"));
  BOOST_TEST(simplest_between(q("3"), q("4")) == q("7/2"));
  BOOST_TEST(simplest_between(q("-4"), q("-3")) == q("-7/2"));
  BOOST_TEST(simplest_between(q("1/10"), q("1/8")) == q("1/9"));
  // Around an irrational: (5 - sqrt 14)/11 ~ 0.1144 and 1/8.
  Algebraic r = Algebraic::real_roots(std::vector<Rational>{q("1"), q("-10"), q("11")}, q("1/10"), q("1/8"))[0];
  Rational s = simplest_between(r, Algebraic(q("1/8")));
  BOOST_TEST(compare(r, s) < 0);
  BOOST_TEST(s < q("1/8"));
}
