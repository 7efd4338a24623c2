// Uses the installed clash4d package: builds a scene in code and reads one
// from the fixtures, checks them, prints the answers and exits 1 when an
// answer is not the hand-derived one.
//   clash4d_example FIXTURES_DIR
#include <clash4d/clash4d.h>

#include <array>
#include <atomic>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

namespace c4 = clash4d::api;

namespace {

int failures = 0;

void expect(bool ok, const std::string& what)
{
  std::cout << (ok ? "  ok: " : "  FAILED: ") << what << "\n";
  if (!ok) ++failures;
}

template <std::size_t N>
std::string text(const std::array<c4::Algebraic, N>& p)
{
  std::string out = "(";
  for (std::size_t i = 0; i < N; ++i) out += (i ? ", " : "") + p[i].text();
  return out + ")";
}

// x is the root of the polynomial (coefficients from the constant term up)
// in the open interval (lo, hi): an irrational answer, derived by hand.
bool is_root(const c4::Algebraic& x, const std::vector<std::string>& poly, const c4::Rational& lo, const c4::Rational& hi)
{
  return !x.is_rational() && x.polynomial() == poly && x > lo && x < hi;
}

// The block [-1, 1]^3 turning a quarter turn about z over [0, 1] (q(t) =
// (1, 0, 0, t)) into the slab x >= 6/5 (fixtures/rotation/square_into_slab.json).
c4::Scene_builder square_into_slab(const c4::Rational& slab_x)
{
  c4::Pose start, end;
  start.t = 0;
  end.t = 1;
  end.rotate = {1, 0, 0, 1};
  c4::Scene_builder b("square into slab", 0, 1);
  b.object("square", c4::Solid::block({-1, -1, -1}, {1, 1, 1}), c4::Motion::poses({start, end}));
  b.object("slab", c4::Solid::block({slab_x, -1, -1}, {3, 1, 1}));
  return b;
}

c4::Pose pose(const c4::Rational& t, const c4::Vec3& translate, const std::array<c4::Rational, 4>& rotate = {1, 0, 0, 0})
{
  c4::Pose p;
  p.t = t;
  p.translate = translate;
  p.rotate = rotate;
  return p;
}

// A first contact at an irrational time, and a door closing on its stop.
void touch_and_door(const std::string& fixtures, c4::Check_options o)
{
  // The corner edge of a turning, sliding block passes through a static edge
  // at the single instant t = sqrt 2 - 1 (root of t^2 + 2t - 1), at x = 1,
  // y = 0: no collision, but a closed contact, its witness at that instant.
  c4::Scene touch = c4::Scene::read_file(fixtures + "/rotation/touch_at_irrational_time.json");
  o.semantics = c4::Semantics::regularised;
  expect(!c4::check(touch, o).collide, "touch at an irrational time: no collision (regularised)");
  o.semantics = c4::Semantics::closed;
  c4::Check_result r = c4::check(touch, o);
  const c4::Colliding_pair* p = r.reported();
  if (p) std::cout << "  closed: witness " << text(p->witness) << "\n";
  expect(r.collide && p->earliest && is_root(p->earliest->t, {"-1", "2", "1"}, {2, 5}, {1, 2}) &&
             p->earliest->point[0] == c4::Rational(1) && p->earliest->point[1] == c4::Rational(0) &&
             !p->witness[3].is_rational() && p->witness[3] == p->earliest->t,
         "closed: first contact at t* = sqrt 2 - 1 at x = 1, y = 0, the witness then");
  // The door [0, 1] x [0, 1/10] turns from a quarter turn to shut over [0, 1]
  // onto the stop's face y = 0 and rests there: contact at t = 1 only.
  c4::Scene door = c4::Scene::read_file(fixtures + "/rotation/door_against_stop.json");
  o.semantics = c4::Semantics::regularised;
  expect(!c4::check(door, o).collide, "door against its stop: no collision (regularised)");
  o.semantics = c4::Semantics::closed;
  c4::Check_result d = c4::check(door, o);
  expect(d.collide && d.reported()->earliest->t == c4::Rational(1) && d.reported()->earliest->point[1] == c4::Rational(0) &&
             d.reported()->earliest->point[0] >= c4::Rational(1, 2),
         "closed: the door touches the stop at t = 1 on y = 0");
}

// Poses without rotation are the translation they describe; what rotation
// cannot be asked is refused.
void poses_and_refusals(const c4::Scene& turning, c4::Check_options o)
{
  // a = [0, 1]^3 moving by 1 per unit of time until t = 2, b = [5/2, 7/2] x
  // [0, 1]^2 at rest: a's face 1 + t reaches 5/2 at t* = 3/2.
  auto moving = [](const c4::Motion& m) {
    c4::Scene_builder b("translation", 0, 4);
    b.object("a", c4::Solid::block({0, 0, 0}, {1, 1, 1}), m);
    b.object("b", c4::Solid::block({c4::Rational(5, 2), 0, 0}, {c4::Rational(7, 2), 1, 1}));
    return b.build();
  };
  o.semantics = c4::Semantics::regularised;
  c4::Check_result robmod = c4::check(moving(c4::Motion::from_text("rest until 0 vel 1 0 0 until 2 rest")), o);
  c4::Check_result posed = c4::check(moving(c4::Motion::poses({pose(0, {0, 0, 0}), pose(2, {2, 0, 0})})), o);
  expect(robmod.collide && posed.collide && posed.reported()->earliest->t == c4::Rational(3, 2) &&
             robmod.reported()->earliest->t == posed.reported()->earliest->t &&
             robmod.reported()->earliest->point == posed.reported()->earliest->point &&
             robmod.reported()->witness == posed.reported()->witness,
         "a pose motion without rotation answers as the same ROBMOD motion: t* = 3/2");
  // Given motions: poses in place of the scene's. a from [1/2, 3/2] at t = 0
  // at speed 1 meets b's face x = 5/2 at t* = 1 (x = 5/2).
  c4::Scene at_rest = moving(c4::Motion::rest());
  c4::Check_result given = c4::check(at_rest, {c4::Motion::poses({pose(0, {c4::Rational(1, 2), 0, 0}), pose(4, {c4::Rational(9, 2), 0, 0})}), c4::Motion::rest()}, o);
  expect(given.collide && given.reported()->earliest->t == c4::Rational(1) && given.reported()->earliest->point[0] == c4::Rational(5, 2),
         "given pose motions: t* = 1 at x = 5/2");
  try {
    c4::check(at_rest, {c4::Motion::poses({pose(1, {0, 0, 0}), pose(1, {1, 0, 0})}), c4::Motion::rest()}, o);
    expect(false, "poses at the same time are refused");
  } catch (const c4::Input_error& e) {
    std::cout << "  refused: " << e.what() << "\n";
    expect(e.place().rfind("motions[0].poses", 0) == 0 && e.exit_code() == c4::exit_invalid, "the error names motions[0].poses");
  }
  o.number = c4::Number::double_;   // the float subject: t* a double near the exact one
  {
    c4::Check_result d = c4::check(turning, o);
    expect(d.collide && d.reported()->earliest && d.reported()->earliest->t.is_rational(), "double: a double t*");
    double t = d.reported()->earliest->t.to_double();
    expect(t > 0.1143947830205 && t < 0.1143947830206, "double: t* near (5 - sqrt 14)/11");
  }
  o.number = c4::Number::exact;
  std::atomic<bool> cancel{true};
  o.cancel = &cancel;
  try {
    c4::check(turning, o);
    expect(false, "a cancelled rotating check stops");
  } catch (const c4::Cancelled&) {
    expect(true, "a cancelled rotating check throws Cancelled");
  }
}

// Scenes whose objects turn (pose motions), against the hand-derived answers
// of fixtures/rotation/expected.json.
void rotation(const std::string& fixtures)
{
  std::cout << "rotation:\n";
  c4::Check_options o;
  o.earliest = true;
  // The square's reach along x is (1 + 2t - t^2) / (1 + t^2) (its corner
  // (1, -1)), past 6/5 first at the root of 11t^2 - 10t + 1 in (0, 1/2),
  // (5 - sqrt 14) / 11 ~ 0.1144, where the corner edge is at x = 6/5, y =
  // -sqrt(14) / 5 (root of 25y^2 - 14): the same in both semantics.
  c4::Scene file = c4::Scene::read_file(fixtures + "/rotation/square_into_slab.json");
  c4::Scene built = square_into_slab(c4::Rational(6, 5)).build();
  for (c4::Semantics sem : {c4::Semantics::regularised, c4::Semantics::closed}) {
    o.semantics = sem;
    for (const c4::Scene* s : {&file, &built}) {
      c4::Check_result r = c4::check(*s, o);
      const c4::Colliding_pair* p = r.reported();
      bool ok = r.collide && p && p->earliest && is_root(p->earliest->t, {"1", "-10", "11"}, {1, 10}, {1, 8}) &&
                p->earliest->point[0] == c4::Rational(6, 5) &&
                is_root(p->earliest->point[1], {"-14", "0", "25"}, {-4, 5}, {-7, 10}) &&
                p->earliest->point[2] >= c4::Rational(-1) && p->earliest->point[2] <= c4::Rational(1) &&
                !p->earliest->inside;
      if (p && p->earliest) std::cout << "  t* = " << p->earliest->t.text() << " at " << text(p->earliest->point) << "\n";
      expect(ok, std::string(c4::name(sem)) + (s == &file ? ", file" : ", Motion::poses") +
                     ": square into slab, t* = root of 11t^2 - 10t + 1 in (1/10, 1/8)");
    }
  }
  // Rationals give the same answer (regularised: a rational witness inside both).
  o.semantics = c4::Semantics::regularised;
  o.number = c4::Number::rational;
  c4::Check_result q = c4::check(built, o);
  expect(q.collide && q.reported()->earliest && q.reported()->earliest->t == c4::check(file, o).reported()->earliest->t &&
             q.reported()->witness[3].is_rational() && q.reported()->witness_verified,
         "Number::rational: the same t*, a rational verified witness");
  // With the slab at 7/5: 6t^2 - 5t + 1 = 0, t* = 1/3 (cos 4/5, sin 3/5), the
  // corner at (7/5, -1/5).
  o.number = c4::Number::exact;
  c4::Check_result c = c4::check(square_into_slab(c4::Rational(7, 5)).build(), o);
  expect(c.collide && c.reported()->earliest->t == c4::Rational(1, 3) && c.reported()->earliest->point[0] == c4::Rational(7, 5) &&
             c.reported()->earliest->point[1] == c4::Rational(-1, 5),
         "slab at 7/5: t* = 1/3 at (7/5, -1/5)");
  touch_and_door(fixtures, o);
  poses_and_refusals(built, o);
}

} // namespace

int main(int argc, char** argv)
{
  if (argc != 2) {
    std::cerr << "usage: clash4d_example FIXTURES_DIR\n";
    return 2;
  }
  const std::string fixtures = argv[1];
  std::cout << "clash4d " << c4::version() << "\n";

  // Two unit blocks approaching at unit speed with a gap of 1: a = [t, 1+t] and
  // b = [2-t, 3-t] in x (y, z in [0, 1]) meet at t* = 1/2 at x = 3/2.
  c4::Scene_builder builder("approach", 0, 10);
  builder.object("a", c4::Solid::block({0, 0, 0}, {1, 1, 1}), c4::Motion::steady({1, 0, 0}));
  builder.object("b", c4::Solid::block({2, 0, 0}, {3, 1, 1}), c4::Motion::steady({-1, 0, 0}));
  c4::Scene approach = builder.build();

  // Exact numbers of any length: 10^999 squared has 1999 digits, past the
  // 1000 characters the scene reader takes from a file.
  c4::Rational big("1e999");
  expect((big * big).numerator().size() == 1999u && (big * big) / big == big, "arithmetic beyond the reader's limit");

  c4::Check_options options;
  options.earliest = true;
  c4::Check_result r = c4::check(approach, options);
  std::cout << "built scene: " << (r.collide ? "collision" : "no collision") << "\n";
  expect(r.collide, "the approaching blocks collide");
  if (const c4::Colliding_pair* p = r.reported()) {
    std::cout << "  " << p->a << " and " << p->b << ", witness " << text(p->witness) << "\n";
    const std::array<c4::Algebraic, 4>& w = p->witness;
    const c4::Rational t = w[3].rational();   // a regularised witness is rational
    expect(p->a == "a" && p->b == "b", "the pair is a and b");
    expect(p->witness_verified, "the witness is verified");
    expect(w[1] > c4::Rational(0) && w[1] < c4::Rational(1) && w[2] > c4::Rational(0) && w[2] < c4::Rational(1),
           "the witness has 0 < y, z < 1");
    expect(t > c4::Rational(1, 2) && t < c4::Rational(10), "the witness time is after t* = 1/2");
    // At time t, a is t < x < 1 + t and b is 2 - t < x < 3 - t.
    expect(w[0] > t && w[0] < 1 + t && w[0] > 2 - t && w[0] < 3 - t, "the witness x is strictly inside a and b");
    if (p->earliest) {
      std::cout << "  earliest: t* = " << p->earliest->t.text() << " at " << text(p->earliest->point) << "\n";
      expect(p->earliest->t == c4::Rational(1, 2), "t* = 1/2");
      expect(p->earliest->point[0] == c4::Rational("1.5"), "the contact point has x = 3/2");
      expect(p->earliest->point[1] >= c4::Rational(0) && p->earliest->point[1] <= c4::Rational(1), "its y is in [0, 1]");
    } else {
      expect(false, "an earliest answer was asked for");
    }
  }

  // The same blocks with a gap of 1 but b at rest and a stopping after
  // covering 1: they touch at t = 1 and never overlap.
  c4::Scene_builder touching("touch", 0, 10);
  touching.object("a", c4::Solid::block({0, 0, 0}, {1, 1, 1}), c4::Motion::piecewise({{0, 0, 0}, {1, 0, 0}, {0, 0, 0}}, {0, 1}));
  touching.object("b", c4::Solid::block({2, 0, 0}, {3, 1, 1}));
  c4::Scene touch = touching.build();
  expect(!c4::check(touch).collide, "touching is not a collision (regularised)");
  options.semantics = c4::Semantics::closed;
  c4::Check_result closed = c4::check(touch, options);
  expect(closed.collide && closed.reported() && closed.reported()->earliest &&
             closed.reported()->earliest->t == c4::Rational(1),
         "closed semantics: first contact at t = 1");
  // A scene keeps what its first exact check prepared (model, bounds): asked
  // again, in either semantics, the answers are the same.
  expect(!c4::check(touch).collide, "asked again: touching is still not a collision");
  c4::Check_result again = c4::check(touch, options);
  expect(again.collide && again.reported()->earliest->t == c4::Rational(1), "asked again: first contact at t = 1");

  // The same shapes under motions given per check, as an engine queries
  // shapes it keeps with new transforms. a at rest on [0, 1], b moving at
  // -2 from [2, 3]: b's face x = 2 - 2t reaches x = 1 at t* = 1/2.
  options.semantics = c4::Semantics::regularised;
  c4::Check_result m = c4::check(approach, {c4::Motion::rest(), c4::Motion::steady({-2, 0, 0})}, options);
  expect(m.collide && m.reported()->earliest && m.reported()->earliest->t == c4::Rational(1, 2) &&
             m.reported()->earliest->point[0] == c4::Rational(1),
         "moved: a at rest, b at -2: t* = 1/2 at x = 1");
  // Both at rest with a gap of 1: never.
  expect(!c4::check(approach, {c4::Motion::rest(), c4::Motion::rest()}, options).collide, "moved: both at rest, no collision");
  // b leaves at +1 until t = 1, then comes back at -3: its face 2 + t, then
  // 3 - 3(t - 1) = 6 - 3t, meets a's (at rest, x = 1) at t* = 5/3.
  c4::Check_result back = c4::check(approach,
      {c4::Motion::rest(), c4::Motion::piecewise({{1, 0, 0}, {-3, 0, 0}}, {1})}, options);
  expect(back.collide && back.reported()->earliest->t == c4::Rational(5, 3), "moved: out and back, t* = 5/3");
  // The scene's own motions again: t* = 1/2 at x = 3/2, as first found.
  c4::Check_result own = c4::check(approach, options);
  expect(own.collide && own.reported()->earliest->t == c4::Rational(1, 2) &&
             own.reported()->earliest->point[0] == c4::Rational("1.5"),
         "the scene's own motions again: t* = 1/2 at x = 3/2");
  try {
    c4::check(approach, {c4::Motion::rest(), c4::Motion::from_text("vel 1 0")}, options);
    expect(false, "a motion that is not one is refused");
  } catch (const c4::Input_error& e) {
    std::cout << "  refused: " << e.what() << "\n";
    expect(e.place() == "motions[1]" && e.exit_code() == c4::exit_invalid, "the error names motions[1]");
  }

  // A fixture: two blocks moving towards each other, meeting at t = 2.
  c4::Scene head_on = c4::Scene::read_file(fixtures + "/contact/clear_collision_head_on.json");
  options.semantics = c4::Semantics::regularised;
  c4::Check_result h = c4::check(head_on, options);
  std::cout << head_on.file() << ": " << (h.collide ? "collision" : "no collision") << "\n";
  expect(h.collide && h.reported()->earliest && h.reported()->earliest->t == c4::Rational(2), "the fixture's t* = 2");

  // The double instantiation agrees on it; the comparer finds no disagreement.
  options.number = c4::Number::double_;
  expect(c4::check(head_on, options).collide, "double agrees");
  c4::Comparison c = c4::compare(head_on);
  for (const c4::Subject_row& s : c.subjects)
    std::cout << "  " << s.subject << ": " << (s.skipped ? "skipped" : s.collide.value_or(false) ? "collision" : "no collision")
              << (s.cause ? " <- " + *s.cause : "") << "\n";
  expect(c.agree(), "every subject agrees with exact");

  // CCD queries: four vertices moving linearly over t in [0, 1]. The vertex
  // p = (1/4, 1/4, 1 - 2t) crosses the triangle (0,0,0), (1,0,0), (0,1,0) at
  // rest in z = 0 at t* = 1/2, at (u, v) = (1/4, 1/4).
  const c4::Rational q(1, 4);
  c4::Ccd_result vf = c4::ccd_vertex_face({q, q, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                          {q, q, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  std::cout << "ccd vertex-face: " << (vf.collide ? "collision" : "no collision");
  if (vf.t) std::cout << " at t* = " << vf.t->text() << ", (u, v) = (" << vf.u->text() << ", " << vf.v->text() << ")";
  std::cout << "\n";
  expect(vf.collide && vf.t && *vf.t == c4::Rational(1, 2) && *vf.u == q && *vf.v == q,
         "ccd vertex-face: t* = 1/2 at (u, v) = (1/4, 1/4)");
  // Edges a0 = 0, a1 = (1, t, 0) and b0 = (1/2, -1, -1/4 - t), b1 = (1/2, 1, -1/4 + t)
  // are coplanar when det(a1, b0, b1) = 1/2 - t^2 = 0: t* = 1/sqrt 2, irrational,
  // the root of 2t^2 - 1; there u = 1/2 and v = 1/2 + t*/4.
  const c4::Rational half(1, 2);
  c4::Ccd_result ee = c4::ccd_edge_edge({0, 0, 0}, {1, 0, 0}, {half, -1, -q}, {half, 1, -q},
                                        {0, 0, 0}, {1, 1, 0}, {half, -1, c4::Rational(-5, 4)}, {half, 1, c4::Rational(3, 4)});
  if (ee.t) std::cout << "ccd edge-edge: t* = " << ee.t->text() << ", v = " << ee.v->text() << "\n";
  expect(ee.collide && ee.t && !ee.t->is_rational() &&
             ee.t->polynomial() == std::vector<std::string>{"-1", "0", "2"} && *ee.t > c4::Rational(7071, 10000) &&
             *ee.t < c4::Rational(7072, 10000) && *ee.u == half && *ee.v > half && *ee.v < 1,
         "ccd edge-edge: t* = 1/sqrt 2 (root of 2t^2 - 1), u = 1/2");
  // Many queries of one type in parallel, answered in order: p from (x, x, 1)
  // to (x, x, z1) over the same triangle crosses z = 0 at t = 1 / (1 - z1)
  // when x = 1/4; beside the triangle when x = 2.
  auto falling = [](const c4::Rational& x, const c4::Rational& z1) {
    c4::Ccd_query query;
    query.t0 = {{{x, x, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
    query.t1 = {{{x, x, z1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
    return query;
  };
  std::vector<c4::Ccd_result> batch =
      c4::ccd_batch(c4::Ccd_type::vertex_face, {falling(q, -3), falling(2, -1), falling(q, 0)});
  expect(batch.size() == 3 && batch[0].t && *batch[0].t == q && !batch[1].collide && batch[2].t &&
             *batch[2].t == 1,
         "ccd batch: t* = 1/4, no collision, t* = 1, in order");

  // Invalid input is an Input_error with the file and the place.
  try {
    c4::Scene::read_file(fixtures + "/bad/block_min_two_numbers.json");
    expect(false, "a bad scene is refused");
  } catch (const c4::Input_error& e) {
    std::cout << "  refused: " << e.what() << "\n";
    expect(e.place() == "objects[0].shape.block.min" && e.exit_code() == c4::exit_invalid, "the error names the place");
  }

  // A time limit (as `clash4d check --max-seconds`) and a cancel flag. The
  // skewed section 6 scene takes seconds in rationals, far beyond 1 ms: the
  // check stops with an Input_error at place "max_seconds", exit_limit.
  // Meanwhile an unlimited check of the same scene in another thread keeps
  // no limit (each run has its own) and answers.
  c4::Scene skewed = c4::Scene::read_file(fixtures + "/paper/section6_weaving_vehicle_skewed.json");
  c4::Check_options exact;
  bool unlimited_collides = false;
  std::thread other([&] { unlimited_collides = c4::check(skewed, exact).collide; });
  c4::Check_options limited;
  limited.number = c4::Number::rational;
  limited.max_seconds = 0.001;
  try {
    c4::check(skewed, limited);
    expect(false, "max_seconds 0.001 stops a check of seconds");
  } catch (const c4::Input_error& e) {
    std::cout << "  stopped: " << e.what() << "\n";
    expect(e.is_limit() && e.place() == "max_seconds", "max_seconds 0.001 stops a check of seconds (exit_limit)");
  }
  other.join();
  expect(unlimited_collides == c4::check(skewed, exact).collide, "a concurrent unlimited check answers as alone");
  std::atomic<bool> cancel{true};   // set before: the check stops at its first look
  limited.max_seconds = 0;
  limited.cancel = &cancel;
  try {
    c4::check(skewed, limited);
    expect(false, "a cancelled check stops");
  } catch (const c4::Cancelled&) {
    expect(true, "a cancelled check throws Cancelled");
  }
  limited.cancel = nullptr;
  limited.max_seconds = -1;
  try {
    c4::check(approach, limited);
    expect(false, "a negative max_seconds is refused");
  } catch (const std::invalid_argument&) {
    expect(true, "a negative max_seconds is refused");
  }

  rotation(fixtures);

  std::cout << (failures ? "FAILED\n" : "all answers as expected\n");
  return failures ? 1 : 0;
}
