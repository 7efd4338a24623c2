#include "compare/Comparer.h"
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

using json = nlohmann::ordered_json;

struct Run {
  std::string subject;
  bool exact_numbers = true;      // witness strings are rationals (else doubles)
  bool ok = true;
  std::string error;
  std::string skipped;            // why the subject did not run (fcl: scene not expressible)
  Check_answer answer;
  double seconds = 0;
};

template <class F>
Run timed(const std::string& subject, bool exact_numbers, F f)
{
  Run r;
  r.subject = subject;
  r.exact_numbers = exact_numbers;
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
  Vector4<Rational> w;
  for (int i = 0; i < 4; ++i) w[i] = value_of(p.witness[i], r.exact_numbers);
  return is_valid_witness(Rational_kernel(), model, object_index(scene, p.a), object_index(scene, p.b), w);
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

// A subject without points (fcl) leaves them empty: null.
json point_json(const std::array<std::string, 4>& p)
{
  if (p[0].empty()) return json();
  return json::array({p[0], p[1], p[2], p[3]});
}

// FCL's answer, or the subject skipped with the reason FCL cannot express
// the scene; conversion and query are timed together, as the other subjects'
// model building is.
Run fcl_run(const Scene& scene, const Check_options& co)
{
  std::string reason;
  Run r = timed("fcl", false, [&] {
    Fcl_subject fcl(scene);
    if (!fcl.expressible()) {
      reason = fcl.reason();
      return Check_answer();
    }
    return fcl.check(co);
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

json compare_scene(const Scene& scene, const std::string& file, const Compare_options& options)
{
  Check_options co;
  co.earliest = options.earliest;
  std::vector<Run> runs;
  runs.push_back(timed("exact", true, [&] { return check_exact(scene, co); }));
  runs.push_back(timed("double", false, [&] { return check_double(scene, 0, co); }));
  for (double tol : options.tolerances)
    runs.push_back(timed(tolerance_subject(tol), false, [&] { return check_double(scene, tol, co); }));
  if (options.rounded)
    runs.push_back(timed("exact-rounded", true, [&] { return check_exact(rounded_scene(scene), co); }));
  if (options.fcl) runs.push_back(fcl_run(scene, co));

  auto rounded_run = std::find_if(runs.begin(), runs.end(), [](const Run& r) { return r.subject == "exact-rounded"; });
  const Run* rounded = rounded_run != runs.end() ? &*rounded_run : nullptr;
  const Run& exact = runs[0];
  if (!exact.ok) throw std::runtime_error("the exact subject failed: " + exact.error);
  Scene_model<Rational_kernel> model = Scene_model<Rational_kernel>::build(Rational_kernel(), scene);
  bool rounding_differs = rounded && (!rounded->ok || rounded->answer.collide != exact.answer.collide);
  int contact = -1;   // computed on first need

  json subjects = json::array(), disagreements = json::array();
  for (const Run& r : runs) {
    json s = {{"subject", r.subject}, {"reference", &r == &exact}, {"ok", r.ok}, {"error", r.error},
              {"skipped", r.skipped.empty() ? json() : json(r.skipped)}};
    if (!r.skipped.empty()) {   // no answer: nothing to hold against exact
      for (const char* key : {"collide", "witness", "witness_valid", "earliest", "t_error"}) s[key] = json();
      s["seconds"] = r.seconds;
      s["agrees"] = json();
      s["cause"] = json();
      subjects.push_back(s);
      continue;
    }
    const Check_answer& a = r.answer;
    s["collide"] = r.ok ? json(a.collide) : json();
    const Pair_answer* main = a.reported();
    bool has_point = main && !main->witness[0].empty();
    s["witness"] = main ? json{{"objects", {main->a, main->b}}, {"point", point_json(main->witness)}} : json();
    s["witness_valid"] = has_point ? json(witness_valid(model, scene, r)) : json();
    s["earliest"] = main && main->earliest ? json{{"objects", {main->a, main->b}}, {"t", main->t_star}, {"point", point_json(main->contact)}} : json();
    s["t_error"] = json();
    const Pair_answer* ref = exact.answer.reported();
    if (main && ref && main->earliest && ref->earliest) {
      Rational e = value_of(main->t_star, r.exact_numbers) - value_of(ref->t_star, true);
      s["t_error"] = decimal(e < 0 ? Rational(-e) : e);
    }
    s["seconds"] = r.seconds;
    std::string cause, detail;
    if (&r != &exact && r.ok && a.collide != exact.answer.collide) {
      std::vector<int> pair;
      for (const Pair_answer* p : {main, ref})
        if (p) pair = {object_index(scene, p->a), object_index(scene, p->b)};
      if (&r == rounded || (rounding_differs && !r.exact_numbers)) cause = "input rounding";
      else {
        if (contact < 0) contact = hinges_on_contact(scene, pair, exact.answer.collide) ? 1 : 0;
        cause = contact ? "contact" : "arithmetic";
      }
      detail = r.subject + " says " + (a.collide ? "collision" : "no collision") + ", exact says " +
               (exact.answer.collide ? "collision" : "no collision");
    } else if (&r != &exact && r.ok && has_point && !s["witness_valid"].get<bool>()) {
      cause = "invalid witness";
      detail = r.subject + "'s witness is not strictly inside both objects of the true scene";
    } else if (!r.ok) {
      detail = r.subject + " failed: " + r.error;
    }
    s["agrees"] = r.ok && cause.empty();
    s["cause"] = cause.empty() ? json() : json(cause);
    if (!cause.empty()) disagreements.push_back({{"subject", r.subject}, {"cause", cause}, {"detail", detail}});
    subjects.push_back(s);
  }
  json out = {{"file", file}, {"name", scene.name}};
  // near_contact: the exact verdict flips under a tiny move (null: not needed);
  // closed_touch: so, and exact says no collision (the closed objects meet or
  // nearly meet while the regularised intersection is empty).
  out["near_contact"] = contact < 0 ? json() : json(contact == 1);
  out["closed_touch"] = contact < 0 ? json() : json(contact == 1 && !exact.answer.collide);
  out["subjects"] = subjects;
  out["disagreements"] = disagreements;
  return out;
}

std::string tolerance_subject(double tol)
{
  std::ostringstream name;
  name << "double tol=" << tol;
  return name.str();
}

std::vector<std::string> disagreement_keys(const json& comparison)
{
  std::vector<std::string> keys;
  for (const auto& d : comparison["disagreements"])
    keys.push_back(d["subject"].get<std::string>() + ": " + d["cause"].get<std::string>());
  return keys;
}

} // namespace clash4d
