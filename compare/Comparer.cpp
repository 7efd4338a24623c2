#include "compare/Comparer.h"
#include "compare/Bullet_subject.h"
#include "compare/External_subject.h"
#include "compare/Fcl_subject.h"
#include "compare/Tolerance_judge.h"
#include "compare/Witness_judge.h"
#include "rotation/Rotating_check.h"
#include "scene/Number_json.h"
#include "check/Closed_membership.h"
#include "model/Point_classifier.h"
#include "exact/Exact_checker.h"
#include "exact/Exact_instantiation.h"
#include "exact/Rational_kernel.h"
#include "float/Double_instantiation.h"
#include "scene/Input_error.h"
#include "scene/Json_reader.h"
#include "scene/Number_text.h"
#include "scene/Rotation_refusal.h"
#include "scene/Scene_reader.h"
#include "scene/Scene_writer.h"
#include "run/Work_budget.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <memory>
#include <sstream>

namespace clash4d {
namespace {

struct Run : Subject_run {
  bool exact_numbers = true;      // witness strings are rationals (else doubles)
  bool reads_doubles = false;     // it sees the scene's numbers as doubles (input rounding applies)
  Check_answer answer;
  // A turning scene's exact t* of the reported pair (it may be irrational,
  // written as text in answer): the t errors are measured against it.
  std::optional<Algebraic> t_star;
  // A library whose motions are not the scene's (regularised-semantics fact
  // 13): why; its verdicts then differ by the motion law, not arithmetic.
  std::string motion_law;
};

// What the toolkit's own subjects give (Own_checks below).
struct Own_answer {
  Check_answer answer;
  std::optional<Algebraic> t_star;   // a turning scene's exact t* of the reported pair
};

void take(Run& r, Check_answer a) { r.answer = std::move(a); }
void take(Run& r, Own_answer a)
{
  r.answer = std::move(a.answer);
  r.t_star = std::move(a.t_star);
}

template <class F>
Run timed(const std::string& subject, bool exact_numbers, F f)
{
  Run r;
  r.subject = subject;
  r.exact_numbers = exact_numbers;
  r.reads_doubles = !exact_numbers;
  auto start = std::chrono::steady_clock::now();
  try {
    take(r, f());
  } catch (const std::exception& e) {
    r.ok = false;
    r.error = e.what();
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

// The exact value a subject meant: a rational, or the double its text names.
Rational value_of(const std::string& text, bool exact_numbers)
{
  if (exact_numbers) return parse_number_text(text, true).value;
  return Rational(std::strtod(text.c_str(), nullptr));
}

// |a - b| for display (t_error_text's three digits, never decided on):
// both isolating intervals refined until they are narrow against the gap.
Rational distance(const Algebraic& a, const Algebraic& b)
{
  if (a == b) return Rational(0);
  auto mid = [](const Algebraic& x) { return (x.lower() + x.upper()) / 2; };
  for (int i = 0; i < 200; ++i) {
    Rational gap = mid(a) - mid(b), width = (a.upper() - a.lower()) + (b.upper() - b.lower());
    if (gap < 0) gap = -gap;
    if (width * 1000000 <= gap) break;
    a.refine();
    b.refine();
  }
  Rational gap = mid(a) - mid(b);
  return gap < 0 ? Rational(-gap) : gap;
}

int object_index(const Scene& s, const std::string& name)
{
  for (std::size_t i = 0; i < s.objects.size(); ++i)
    if (s.objects[i].name == name) return static_cast<int>(i);
  return -1;
}

// A witness in the subject's own terms, checked exactly against the true
// scene (compare/Witness_judge.h); none when a coordinate is not a rational
// (an exact closed contact at an irrational time of a turning scene).
std::optional<bool> witness_valid(const Witness_judge& judge, const Scene& scene, const Run& r)
{
  const Pair_answer& p = *r.answer.reported();
  int a = object_index(scene, p.a), b = object_index(scene, p.b);
  if (a < 0 || b < 0) return false;   // an external subject's point inside no pair
  Vector4<Rational> w;
  for (int i = 0; i < 4; ++i) {
    if (r.exact_numbers && !parse_number_text(p.witness[i], true).ok) return std::nullopt;
    w[i] = value_of(p.witness[i], r.exact_numbers);
  }
  return judge.holds(a, b, w, r.semantics == "closed");
}

// An external subject's answer as a run: unsupported is skipped, a fault
// fails with its cause; its numbers are exact (read from its text).
Run external_run(External_pool& pool, const Scene& scene, const Witness_judge& judge, bool earliest)
{
  External_pool::Lease subject = pool.acquire();
  Run r;
  r.subject = pool.spec().name;
  r.reads_doubles = true;   // engines read the scene's numbers as doubles, as a rule
  auto start = std::chrono::steady_clock::now();
  Subject_answer a = subject->ask(scene, earliest);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.semantics = subject->semantics();
  r.tolerance = subject->tolerance();
  r.answer.number = r.subject;
  if (a.kind == Subject_answer::Kind::Unsupported) r.skipped = "unsupported: " + a.why;
  if (a.kind == Subject_answer::Kind::Fault) {
    r.ok = false;
    r.fault = a.fault;
    r.error = a.why;
  }
  if (a.kind != Subject_answer::Kind::Answer || !a.collide) return r;
  r.answer.collide = true;
  Pair_answer p;
  if (a.witness) {
    p.witness = *a.witness;
    Vector4<Rational> w;
    for (int i = 0; i < 4; ++i) w[i] = parse_number_text((*a.witness)[i], true).value;
    std::array<std::string, 2> names = judge.pair_holding(w, r.semantics == "closed");
    p.a = names[0];
    p.b = names[1];
  }
  if (a.t) {
    p.earliest = true;
    p.t_star = *a.t;
  }
  r.answer.pairs.push_back(p);
  return r;
}

void map_numbers(Solid& s, const std::function<Rational(const Rational&)>& f)
{
  for (auto& q : s.numbers) q = f(q);
  for (auto& c : s.children) map_numbers(c, f);
}

// A subject without points (fcl) leaves them empty: none.
std::optional<std::array<std::string, 4>> point_of(const std::array<std::string, 4>& p)
{
  if (p[0].empty()) return std::nullopt;
  return p;
}

// A compiled-in library's answer (fcl, bullet), or the subject skipped
// with the reason it cannot express the scene; conversion and query are
// timed together, as the other subjects' model building is.
template <class Library>
Run library_run(const char* name, const Scene& scene, const Check_options& co)
{
  std::string reason, law;
  Run r = timed(name, false, [&] {
    Library library(scene);
    if (!library.expressible()) {
      reason = library.reason();
      return Check_answer();
    }
    law = library.motion_law();
    return library.check(co);
  });
  r.skipped = reason;
  r.motion_law = law;
  return r;
}

} // namespace

Scene rounded_scene(const Scene& scene)
{
  auto round = [](const Rational& q) {
    double d = round_to_nearest(q);
    if (!std::isfinite(d)) throw std::range_error("the number " + to_string(q) + " has no double");
    return Rational(d);
  };
  Scene r = scene;
  r.t_lo = round(r.t_lo);
  r.t_hi = round(r.t_hi);
  for (auto& o : r.objects) {
    map_numbers(o.shape, round);
    if (o.motion.rotates()) {   // the poses as written, each number rounded
      for (Pose& p : o.motion.poses) {
        p.t = round(p.t);
        for (auto& c : p.translate) c = round(c);
        for (auto& c : p.rotate) c = round(c);
      }
      continue;
    }
    // A rotation-free pose motion is read by the double instantiation as its
    // translation and its shape at c(0) (scene/Pose_motion.h): those are
    // the numbers rounded here, so the rounded scene is that ROBMOD motion
    // and that shape, not the poses.
    o.motion.poses.clear();
    for (auto& t : o.motion.times) t = round(t);
    for (auto& v : o.motion.velocities)
      for (auto& c : v) c = round(c);
  }
  // Rounding may break validity (equal times, a flat block, a hull's facets
  // changing): re-read it, so it is validated and its combinatorics redone.
  return read_scene(read_json_text(write_scene(r)));
}

namespace {

// The exact answers a comparison holds subjects against, one per semantics
// (each subject is judged in its own: issue 14), and on the rounded scene
// when a verdict must be told apart from input rounding.
struct Reference {
  const Scene& scene;
  const Check_options& options;   // earliest as asked; semantics is set per use
  const Run& regularised;
  const Run& closed;
  const Run* rounded;             // the exact-rounded subject, in `rounded_in`
  Semantics rounded_in;
  const Run* plain_double;        // the double subject (no tolerance), in `rounded_in`; none with --no-doubles
  double time_bound;              // Compare_options::time_bound (its exact value is the bound)
  int rounding_differs[2] = {-1, -1};   // per semantics: computed on first need

  const Run& in(const std::string& semantics) const { return semantics == "closed" ? closed : regularised; }

  // Does exact on the scene rounded to doubles give another verdict?
  bool rounding_changes(const std::string& semantics)
  {
    Semantics s = semantics == "closed" ? Semantics::closed : Semantics::regularised;
    int& known = rounding_differs[static_cast<int>(s)];
    if (known < 0) {
      bool differs = true;   // a rounded scene that is invalid or has no double differs
      if (rounded && rounded_in == s) {
        differs = !rounded->ok || rounded->answer.collide != in(semantics).answer.collide;
      } else {
        try {
          Check_options o = options;
          o.semantics = s;
          differs = check_exact(rounded_scene(scene), o).collide != in(semantics).answer.collide;
        } catch (const std::exception&) {
        }
      }
      known = differs ? 1 : 0;
    }
    return known == 1;
  }
  // Touching only: the closed objects meet, their interiors do not.
  bool touching_only() const { return !regularised.answer.collide && closed.answer.collide; }
};

// The answer fields of a row that ran: verdict, witness (checked exactly
// against the true scene, in the subject's semantics), t* and its error
// against the exact t* of that semantics.
void fill_answer(Subject_row& s, const Run& r, const Reference& ref, const Witness_judge& judge)
{
  const Check_answer& a = r.answer;
  if (r.ok) s.collide = a.collide;
  const Pair_answer* main = a.reported();
  if (!main) return;
  if (!main->a.empty() || !main->witness[0].empty()) s.witness = Located{{main->a, main->b}, point_of(main->witness), ""};
  if (s.witness && s.witness->point) s.witness_valid = witness_valid(judge, ref.scene, r);
  if (!main->earliest) return;
  s.earliest = Located{{main->a, main->b}, point_of(main->contact), main->t_star};
  const Run& exact_run = ref.in(r.semantics);
  const Pair_answer* exact = exact_run.answer.reported();
  if (!exact || !exact->earliest) return;
  if (exact_run.t_star) {
    Algebraic t = r.t_star ? *r.t_star : Algebraic(value_of(main->t_star, r.exact_numbers));
    s.t_error = t_error_text(distance(*exact_run.t_star, t));
  } else {
    Rational e = value_of(main->t_star, r.exact_numbers) - value_of(exact->t_star, true);
    s.t_error = t_error_text(e < 0 ? Rational(-e) : e);
  }
}

// With earliest: the subject's t* is farther from exact's (in its
// semantics) than the bound.
bool beyond_time_bound(const Run& r, const Reference& ref)
{
  const Pair_answer* main = r.answer.reported();
  const Run& exact_run = ref.in(r.semantics);
  const Pair_answer* exact = exact_run.answer.reported();
  if (!main || !main->earliest || !exact || !exact->earliest) return false;
  Algebraic t = r.t_star ? *r.t_star : Algebraic(value_of(main->t_star, r.exact_numbers));
  Algebraic e = exact_run.t_star ? *exact_run.t_star : Algebraic(value_of(exact->t_star, true));
  return farther_than(t, e, Rational(ref.time_bound));
}

// The disagreement is the subject's declared tolerance at work
// (compare/Comparer.h, cause `tolerance`).
bool tolerance_explains(const Run& r, const Reference& ref)
{
  if (!r.tolerance || *r.tolerance <= 0) return false;
  if (r.subject == tolerance_subject(*r.tolerance))   // double tol=EPS: the same pipeline without EPS agrees
    return ref.plain_double && ref.plain_double->ok && ref.plain_double->semantics == r.semantics &&
           ref.plain_double->answer.collide == ref.in(r.semantics).answer.collide;
  std::vector<std::string> movable;
  if (const Pair_answer* p = r.answer.reported(); p && !p->a.empty()) movable = {p->a};
  Semantics s = r.semantics == "closed" ? Semantics::closed : Semantics::regularised;
  return verdict_within_tolerance(ref.scene, s, r.answer.collide, Rational(*r.tolerance), movable);
}

// The cause of a subject's disagreement with exact in its own semantics
// (empty: none), with the detail. A verdict is "contact" exactly when the
// scene is one of touching only (regularised no, closed yes) and "input
// rounding" when exact on the rounded scene already gives the subject's
// verdict's opposite of exact's, or is the subject and its witness (exact
// for the rounded scene) is not one of the true scene.
std::string classify(const Run& r, const Subject_row& s, Reference& ref, std::string& detail)
{
  if (s.reference) return "";
  if (!r.fault.empty()) {
    detail = r.subject + ": " + r.fault + ": " + r.error;
    return r.fault;
  }
  if (!r.ok) return "";
  const Run& exact = ref.in(r.semantics);
  if (r.answer.collide != exact.answer.collide) {
    detail = r.subject + " (" + r.semantics + ") says " + (r.answer.collide ? "collision" : "no collision") +
             ", exact " + r.semantics + " says " + (exact.answer.collide ? "collision" : "no collision");
    if (!r.motion_law.empty()) {
      detail += " (" + r.motion_law + ")";
      return "motion law";
    }
    if (&r == ref.rounded || (r.reads_doubles && ref.rounding_changes(r.semantics))) return "input rounding";
    if (ref.touching_only()) return "contact";
    if (!tolerance_explains(r, ref)) return "arithmetic";
    detail += ", but within its tolerance " + shortest_decimal(*r.tolerance);
    return "tolerance";
  }
  if (s.witness_valid == false) {
    detail = r.subject + "'s witness is not " +
             (r.semantics == "closed" ? "in both closed objects" : "strictly inside both objects") + " of the true scene";
    if (&r != ref.rounded) return "invalid witness";
    // Exact on the rounded scene: its witness holds there, and only the
    // rounding of the scene's numbers moved it out.
    detail += " (it holds in the scene rounded to doubles)";
    return "input rounding";
  }
  if (beyond_time_bound(r, ref)) {
    detail = r.subject + "'s t* is " + s.t_error.value_or("?") + " from exact " + r.semantics + "'s, beyond the bound " +
             shortest_decimal(ref.time_bound);
    if (r.motion_law.empty()) return "time";
    detail += " (" + r.motion_law + ")";
    return "motion law";
  }
  return "";
}

Subject_row row_of(const Run& r, Reference& ref, const Witness_judge& judge, std::vector<Disagreement>& list)
{
  Subject_row s = r.row(&r == &ref.regularised || &r == &ref.closed);
  if (s.skipped) return s;
  fill_answer(s, r, ref, judge);
  std::string detail, cause = classify(r, s, ref, detail);
  s.agrees = r.ok && cause.empty();
  if (!cause.empty()) {
    s.cause = cause;
    list.push_back({r.subject, cause, detail, r.semantics});
  }
  return s;
}

// How the toolkit's own subjects answer one scene: the exact references
// and exact-rounded (exact numbers), the double subjects (tolerance 0 or
// EPS). A scene without rotation goes through the 4D pipeline, one where
// something turns through the time slices (rotation/), in the same roles.
struct Own_checks {
  std::function<Own_answer(const Check_options&)> exact;
  std::function<Own_answer(double, const Check_options&)> in_doubles;
  std::function<Own_answer(const Check_options&)> rounded;
};

// A turning scene's answer in the comparison's text: exact numbers as
// "p/q" or, irrational, the algebraic number's text; doubles as their
// shortest decimals.
std::string answer_text(const Algebraic& x, bool exact)
{
  if (!exact) return shortest_decimal(x.to_double());
  return x.is_rational() ? to_string(x.rational()) : x.to_text();
}

Check_answer as_check_answer(const Rotating_check_answer& a)
{
  bool exact = a.number != "double";
  Check_answer out;
  out.number = a.number;
  out.semantics = a.semantics;
  out.collide = a.collide;
  out.earliest_pair = a.earliest_pair;
  for (const Rotating_pair_answer& p : a.pairs) {
    Pair_answer q;
    q.a = p.a;
    q.b = p.b;
    for (int i = 0; i < 4; ++i) q.witness[i] = answer_text(p.answer.witness[i], exact);
    q.witness_verified = p.answer.witness_verified;
    q.earliest = p.answer.earliest;
    if (q.earliest) {
      q.t_star = answer_text(p.answer.t_star, exact);
      for (int i = 0; i < 3; ++i) q.contact[i] = answer_text(p.answer.contact[i], exact);
      q.contact[3] = q.t_star;
      q.at_start = p.answer.at_start;
    }
    out.pairs.push_back(std::move(q));
  }
  return out;
}

Own_answer own_answer(const Rotating_check_answer& a)
{
  Own_answer out{as_check_answer(a), std::nullopt};
  if (a.reported() && a.reported()->answer.earliest) out.t_star = a.reported()->answer.t_star;
  return out;
}

Own_checks own_checks(const Scene& scene, std::shared_ptr<Exact_checker>& exact)
{
  if (!scene_rotates(scene)) {
    // The exact references on the scene the first one prepared (exact/Exact_checker.h).
    exact = std::make_shared<Exact_checker>(scene);
    return {[exact](const Check_options& o) { return Own_answer{exact->check(o), std::nullopt}; },
            [&scene](double tol, const Check_options& o) { return Own_answer{check_double(scene, tol, o), std::nullopt}; },
            [&scene](const Check_options& o) { return Own_answer{check_exact(rounded_scene(scene), o), std::nullopt}; }};
  }
  return {[&scene](const Check_options& o) { return own_answer(check_rotating(scene, o, "exact")); },
          [&scene](double tol, const Check_options& o) { return own_answer(check_rotating(scene, o, "double", tol)); },
          [&scene](const Check_options& o) { return own_answer(check_rotating(rounded_scene(scene), o, "exact")); }};
}

// Every subject is judged against the exact ones: without them there is
// no comparison, only a scene this release does not decide (as check
// reports it, exit 2 naming the reason), and no subject is run for it.
void require_references(const std::vector<Run>& runs)
{
  for (int i : {0, 1})
    if (!runs[i].ok)
      throw Input_error("", "not compared: the " + runs[i].subject + " subject, the reference, did not decide it: " +
                                runs[i].error);
}

// The exact references (regularised, then closed) and the toolkit's own
// subjects in the semantics asked for, then the libraries (closed).
std::vector<Run> builtin_runs(const Scene& scene, const Compare_options& options, const Check_options& co)
{
  std::vector<Run> runs;
  Check_options closed = co, own = co;
  closed.semantics = Semantics::closed;
  own.semantics = options.semantics;
  std::shared_ptr<Exact_checker> kept;
  Own_checks checks = own_checks(scene, kept);
  auto announce = [&](const std::string& subject) {
    if (options.on_subject) options.on_subject(subject);
    return subject;
  };
  runs.push_back(timed(announce("exact"), true, [&] { return checks.exact(co); }));
  runs.push_back(timed(announce("exact closed"), true, [&] { return checks.exact(closed); }));
  runs.back().semantics = "closed";
  require_references(runs);
  std::size_t own_from = runs.size();
  if (options.doubles) {
    runs.push_back(timed(announce("double"), false, [&] { return checks.in_doubles(0, own); }));
    for (double tol : options.tolerances) {
      runs.push_back(timed(announce(tolerance_subject(tol)), false, [&] { return checks.in_doubles(tol, own); }));
      runs.back().tolerance = tol;
    }
  }
  if (options.rounded) runs.push_back(timed(announce("exact-rounded"), true, [&] { return checks.rounded(own); }));
  for (std::size_t i = own_from; i < runs.size(); ++i) runs[i].semantics = semantics_name(options.semantics);
  if (options.fcl) runs.push_back(library_run<Fcl_subject>(announce("fcl").c_str(), scene, closed));
  if (options.bullet) {
    runs.push_back(library_run<Bullet_subject>(announce("bullet").c_str(), scene, closed));
    runs.back().tolerance = Bullet_subject::tolerance;
  }
  for (Run& r : runs)
    if (r.subject == "fcl" || r.subject == "bullet") r.semantics = builtin_semantics(r.subject);
  return runs;
}

} // namespace

Comparison compare_scene(const Scene& scene, const std::string& file, const Compare_options& options)
{
  Work_budget::check();
  Check_options co;
  co.earliest = options.earliest;
  std::vector<Run> runs = builtin_runs(scene, options, co);
  Witness_judge judge(scene);
  for (const auto& pool : options.externals) {
    if (options.on_subject) options.on_subject(pool->spec().name);
    runs.push_back(external_run(*pool, scene, judge, options.earliest));
  }

  auto named = [&](const char* subject) {
    auto it = std::find_if(runs.begin(), runs.end(), [&](const Run& r) { return r.subject == subject; });
    return it != runs.end() ? &*it : nullptr;
  };
  Reference ref{scene, co, runs[0], runs[1], named("exact-rounded"), options.semantics, named("double"), options.time_bound};

  Comparison out;
  out.file = file;
  out.name = scene.name;
  for (const Run& r : runs) out.subjects.push_back(row_of(r, ref, judge, out.disagreements));
  // Where the regularised answer is no, the closed one says whether the
  // objects touch (never null there); where it is yes, they collide.
  if (!ref.regularised.answer.collide) out.closed_touch = ref.closed.answer.collide;
  Work_budget::check();   // a comparison finished past the budget is not shown (--max-seconds)
  return out;
}

std::string t_error_text(const Rational& error)
{
  std::ostringstream out;
  out.precision(3);
  out << std::scientific << CGAL::to_double(error);
  return out.str();
}

const char* builtin_semantics(const std::string& subject)
{
  return subject == "fcl" || subject == "bullet" ? "closed" : "regularised";
}

std::string tolerance_subject(double tol)
{
  std::ostringstream name;
  name << "double tol=" << tol;
  return name.str();
}

} // namespace clash4d
