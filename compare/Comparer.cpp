#include "compare/Comparer.h"
#include "compare/Bullet_subject.h"
#include "compare/External_subject.h"
#include "compare/Fcl_subject.h"
#include "model/Point_classifier.h"
#include "exact/Exact_instantiation.h"
#include "exact/Rational_kernel.h"
#include "float/Double_instantiation.h"
#include "scene/Input_error.h"
#include "scene/Json_reader.h"
#include "scene/Number_text.h"
#include "scene/Scene_reader.h"
#include "scene/Scene_writer.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <sstream>

namespace clash4d {
namespace {

struct Run {
  std::string subject;
  bool exact_numbers = true;      // witness strings are rationals (else doubles)
  bool reads_doubles = false;     // it sees the scene's numbers as doubles (input rounding applies)
  bool ok = true;
  std::string error;
  std::string fault;              // external subject: crash, timeout or protocol
  std::string skipped;            // why the subject did not run (fcl: scene not expressible)
  std::string semantics = "regularised";
  std::optional<double> tolerance;
  Check_answer answer;
  double seconds = 0;
};

template <class F>
Run timed(const std::string& subject, bool exact_numbers, F f)
{
  Run r;
  r.subject = subject;
  r.exact_numbers = exact_numbers;
  r.reads_doubles = !exact_numbers;
  auto start = std::chrono::steady_clock::now();
  try {
    r.answer = f();
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

int object_index(const Scene& s, const std::string& name)
{
  for (std::size_t i = 0; i < s.objects.size(); ++i)
    if (s.objects[i].name == name) return static_cast<int>(i);
  return -1;
}

bool witness_valid(const Scene_model<Rational_kernel>& model, const Scene& scene, const Run& r)
{
  const Pair_answer& p = *r.answer.reported();
  int a = object_index(scene, p.a), b = object_index(scene, p.b);
  if (a < 0 || b < 0) return false;   // an external subject's point inside no pair
  Vector4<Rational> w;
  for (int i = 0; i < 4; ++i) w[i] = value_of(p.witness[i], r.exact_numbers);
  return is_valid_witness(Rational_kernel(), model, a, b, w);
}

// The pair (names) whose objects both hold the point strictly, or none:
// external subjects give a point, not a pair.
std::array<std::string, 2> pair_holding(const Scene_model<Rational_kernel>& model, const Scene& scene,
                                        const std::array<std::string, 4>& point)
{
  Vector4<Rational> w;
  for (int i = 0; i < 4; ++i) w[i] = parse_number_text(point[i], true).value;
  for (std::size_t a = 0; a < scene.objects.size(); ++a)
    for (std::size_t b = a + 1; b < scene.objects.size(); ++b)
      if (!scene.ignored(int(a), int(b)) && is_valid_witness(Rational_kernel(), model, int(a), int(b), w))
        return {scene.objects[a].name, scene.objects[b].name};
  return {"", ""};
}

// An external subject's answer as a run: unsupported is skipped, a fault
// fails with its cause; its numbers are exact (read from its text).
Run external_run(External_pool& pool, const Scene& scene, const Scene_model<Rational_kernel>& model, bool earliest)
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
    std::array<std::string, 2> names = pair_holding(model, scene, *a.witness);
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

Rational largest_magnitude(const Solid& s)
{
  Rational m(1);
  for (const auto& q : s.numbers) m = std::max(m, q < 0 ? Rational(-q) : q);
  for (const auto& c : s.children) m = std::max(m, largest_magnitude(c));
  return m;
}

// Does the exact verdict flip when object i is moved by eps along an axis or
// a diagonal (every direction of {-1, 0, 1}^3), eps = 2^-20 of the scene's
// scale, or 2^-40 of it? Axes first; the diagonals are needed for edge and
// vertex contacts such as two blocks sharing only an edge, which no move
// along a single axis makes overlap; the smaller move for small objects far
// from the origin, which the larger one carries right past each other.
bool hinges_on_contact(const Scene& scene, const std::vector<int>& objects, bool exact_collide)
{
  Rational scale(1);
  for (const auto& o : scene.objects) scale = std::max(scale, largest_magnitude(o.shape));
  // The 26 directions of {-1, 0, 1}^3, axes first.
  std::vector<std::array<int, 3>> directions;
  for (int nonzero = 1; nonzero <= 3; ++nonzero)
    for (int x : {1, 0, -1})
      for (int y : {1, 0, -1})
        for (int z : {1, 0, -1})
          if (std::abs(x) + std::abs(y) + std::abs(z) == nonzero) directions.push_back({x, y, z});
  for (Rational eps : {scale / Rational(1 << 20), scale / Rational(1 << 20) / Rational(1 << 20)})
    for (int i : objects)
      for (const auto& d : directions) {
        Scene moved = scene;
        Solid wrap;
        wrap.kind = Solid::Kind::Translate;
        wrap.path = moved.objects[i].shape.path;
        wrap.numbers = {eps * Rational(d[0]), eps * Rational(d[1]), eps * Rational(d[2])};
        wrap.children.push_back(moved.objects[i].shape);
        moved.objects[i].shape = wrap;
        if (check_exact(moved, Check_options()).collide != exact_collide) return true;
      }
  return false;
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
  std::string reason;
  Run r = timed(name, false, [&] {
    Library library(scene);
    if (!library.expressible()) {
      reason = library.reason();
      return Check_answer();
    }
    return library.check(co);
  });
  r.skipped = reason;
  return r;
}

std::string decimal(const Rational& q)
{
  std::ostringstream out;
  out.precision(3);
  out << std::scientific << CGAL::to_double(q);
  return out.str();
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
    for (auto& t : o.motion.times) t = round(t);
    for (auto& v : o.motion.velocities)
      for (auto& c : v) c = round(c);
  }
  // Rounding may break validity (equal times, a flat block, a hull's facets
  // changing): re-read it, so it is validated and its combinatorics redone.
  return read_scene(read_json_text(write_scene(r)));
}

namespace {

// The answer fields of a row that ran: verdict, witness (checked exactly
// against the true scene), t* and its error against exact's.
void fill_answer(Subject_row& s, const Run& r, const Run& exact, const Scene& scene,
                 const Scene_model<Rational_kernel>& model)
{
  const Check_answer& a = r.answer;
  if (r.ok) s.collide = a.collide;
  const Pair_answer* main = a.reported();
  if (!main) return;
  if (!main->a.empty() || !main->witness[0].empty()) s.witness = Located{{main->a, main->b}, point_of(main->witness), ""};
  if (s.witness && s.witness->point) s.witness_valid = witness_valid(model, scene, r);
  if (!main->earliest) return;
  s.earliest = Located{{main->a, main->b}, point_of(main->contact), main->t_star};
  const Pair_answer* ref = exact.answer.reported();
  if (ref && ref->earliest) {
    Rational e = value_of(main->t_star, r.exact_numbers) - value_of(ref->t_star, true);
    s.t_error = decimal(e < 0 ? Rational(-e) : e);
  }
}

// What the classification of one comparison needs, computed once.
struct Reference {
  const Scene& scene;
  const Run& exact;
  const Run* rounded;
  bool rounding_differs;
  int contact = -1;   // the exact verdict flips under a tiny move: computed on first need
};

// The objects a verdict hinges on: the pairs named by the subject and by
// exact; every object when neither names one (an external subject's bare "yes").
std::vector<int> objects_at_stake(const Scene& scene, const Pair_answer* main, const Pair_answer* ref)
{
  std::vector<int> pair;
  for (const Pair_answer* p : {main, ref})
    if (p && object_index(scene, p->a) >= 0 && object_index(scene, p->b) >= 0)
      pair = {object_index(scene, p->a), object_index(scene, p->b)};
  if (pair.empty())
    for (std::size_t i = 0; i < scene.objects.size(); ++i) pair.push_back(static_cast<int>(i));
  return pair;
}

// The cause of a subject's disagreement with exact (empty: none), with the detail.
std::string classify(const Run& r, const Subject_row& s, Reference& ref, std::string& detail)
{
  const Run& exact = ref.exact;
  if (&r == &exact) return "";
  if (!r.fault.empty()) {
    detail = r.subject + ": " + r.fault + ": " + r.error;
    return r.fault;
  }
  if (!r.ok) return "";
  if (r.answer.collide != exact.answer.collide) {
    detail = r.subject + " says " + (r.answer.collide ? "collision" : "no collision") + ", exact says " +
             (exact.answer.collide ? "collision" : "no collision");
    if (&r == ref.rounded || (ref.rounding_differs && r.reads_doubles)) return "input rounding";
    // Until the exact pipeline decides the closed question too, a closed
    // subject's touching answers are classified as anyone's: contact.
    if (ref.contact < 0)
      ref.contact = hinges_on_contact(ref.scene, objects_at_stake(ref.scene, r.answer.reported(), exact.answer.reported()),
                                      exact.answer.collide) ? 1 : 0;
    return ref.contact ? "contact" : "arithmetic";
  }
  if (s.witness_valid == false) {
    detail = r.subject + "'s witness is not strictly inside both objects of the true scene";
    return "invalid witness";
  }
  return "";
}

Subject_row row_of(const Run& r, Reference& ref, const Scene_model<Rational_kernel>& model, std::vector<Disagreement>& list)
{
  Subject_row s;
  s.subject = r.subject;
  s.semantics = r.semantics;
  s.tolerance = r.tolerance;
  s.reference = &r == &ref.exact;
  s.ok = r.ok;
  s.error = r.error;
  s.seconds = r.seconds;
  if (!r.skipped.empty()) {   // no answer: nothing to hold against exact
    s.skipped = r.skipped;
    return s;
  }
  fill_answer(s, r, ref.exact, ref.scene, model);
  std::string detail, cause = classify(r, s, ref, detail);
  s.agrees = r.ok && cause.empty();
  if (!cause.empty()) {
    s.cause = cause;
    list.push_back({r.subject, cause, detail});
  }
  return s;
}

std::vector<Run> builtin_runs(const Scene& scene, const Compare_options& options, const Check_options& co)
{
  std::vector<Run> runs;
  runs.push_back(timed("exact", true, [&] { return check_exact(scene, co); }));
  runs.push_back(timed("double", false, [&] { return check_double(scene, 0, co); }));
  for (double tol : options.tolerances) {
    runs.push_back(timed(tolerance_subject(tol), false, [&] { return check_double(scene, tol, co); }));
    runs.back().tolerance = tol;
  }
  if (options.rounded)
    runs.push_back(timed("exact-rounded", true, [&] { return check_exact(rounded_scene(scene), co); }));
  if (options.fcl) runs.push_back(library_run<Fcl_subject>("fcl", scene, co));
  if (options.bullet) {
    runs.push_back(library_run<Bullet_subject>("bullet", scene, co));
    runs.back().tolerance = Bullet_subject::tolerance;
  }
  for (Run& r : runs) r.semantics = builtin_semantics(r.subject);
  return runs;
}

} // namespace

Comparison compare_scene(const Scene& scene, const std::string& file, const Compare_options& options)
{
  Check_options co;
  co.earliest = options.earliest;
  std::vector<Run> runs = builtin_runs(scene, options, co);
  if (!runs[0].ok) throw std::runtime_error("the exact subject failed: " + runs[0].error);
  Scene_model<Rational_kernel> model = Scene_model<Rational_kernel>::build(Rational_kernel(), scene);
  for (const auto& pool : options.externals) runs.push_back(external_run(*pool, scene, model, options.earliest));

  auto rounded = std::find_if(runs.begin(), runs.end(), [](const Run& r) { return r.subject == "exact-rounded"; });
  const Run& exact = runs[0];
  Reference ref{scene, exact, rounded != runs.end() ? &*rounded : nullptr, false};
  ref.rounding_differs = ref.rounded && (!ref.rounded->ok || ref.rounded->answer.collide != exact.answer.collide);

  Comparison out;
  out.file = file;
  out.name = scene.name;
  for (const Run& r : runs) out.subjects.push_back(row_of(r, ref, model, out.disagreements));
  // near_contact: the exact verdict flips under a tiny move (none: not
  // needed); closed_touch: so, and exact says no collision (the closed
  // objects meet or nearly meet while the regularised intersection is empty).
  if (ref.contact >= 0) {
    out.near_contact = ref.contact == 1;
    out.closed_touch = ref.contact == 1 && !exact.answer.collide;
  }
  return out;
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
