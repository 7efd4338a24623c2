// The public API (clash4d/clash4d.h) on the pipeline: scenes are written in
// the scene format and read by scene/Scene_reader.h, check runs the
// instantiation the command line runs (exact/, float/), compare runs
// compare/Comparer.h; answers are converted here, at the edge, from the
// pipeline's text answers (check/Check_answer.h) to exact api::Rational.
// Inside namespace clash4d::api the public names hide the pipeline's
// (Rational, Scene, ...); the pipeline's are written in::Name.
#include "clash4d/clash4d.h"

#include "ccd/Ccd_query.h"
#include "compare/Comparer.h"
#include "exact/Ccd_instantiation.h"
#include "exact/Exact_checker.h"
#include "exact/Exact_instantiation.h"
#include "float/Ccd_double_instantiation.h"
#include "float/Double_instantiation.h"
#include "numbers/Algebraic.h"
#include "numbers/Rational.h"
#include "rotation/Critical_times.h"
#include "rotation/Rotating_check.h"
#include "scene/Input_error.h"
#include "scene/Json_reader.h"
#include "scene/Number_json.h"
#include "scene/Number_text.h"
#include "scene/Pose_motion.h"
#include "scene/Scene_reader.h"
#include "scene/Scene_writer.h"
#include "run/Work_budget.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_scheduler_observer.h>
#include <cmath>
#include <mutex>
#include <sstream>
#include <optional>
#include <new>

namespace clash4d {
namespace api {
namespace in = ::clash4d;

#ifndef CLASH4D_VERSION
#define CLASH4D_VERSION "0.1.0"
#endif

const char* version() { return CLASH4D_VERSION; }

// ---------------------------------------------------------------- numbers

namespace {

in::Rational internal(const Rational& r) { return in::Rational(r.to_string()); }

// Sets num and den from an exact rational in lowest terms.
void split(const in::Rational& q, std::string& num, std::string& den)
{
  std::string text = in::to_string(q);
  auto slash = text.find('/');
  num = text.substr(0, slash);
  den = slash == std::string::npos ? "1" : text.substr(slash + 1);
}

Rational external(const in::Rational& q)
{
  return Rational(in::to_string(q));
}

} // namespace

Rational::Rational() = default;

Rational::Rational(long long n) : num_(std::to_string(n)) {}

Rational::Rational(long long p, long long q)
{
  if (q == 0) throw std::invalid_argument("clash4d::api::Rational: zero denominator");
  in::Rational r(p);
  r /= in::Rational(q);
  split(r, num_, den_);
}

// The scene format's forms, under the reader's limits; beyond them, still
// "p" or "p/q" of any length: the form of every number this library
// returns and of its arithmetic's results (issue 59 item 2).
Rational::Rational(const std::string& text)
{
  in::Number_parse n = in::parse_number_text(text, true);
  if (n.ok) {
    split(n.value, num_, den_);
    return;
  }
  if (n.limit) {
    try {
      split(in::rational_from_string(text), num_, den_);
      return;
    } catch (const std::invalid_argument&) {
    }
  }
  throw std::invalid_argument("not an exact number: \"" + text.substr(0, 40) + (text.size() > 40 ? "...\": " : "\": ") +
                              n.error);
}

std::string Rational::to_string() const { return den_ == "1" ? num_ : num_ + "/" + den_; }

double Rational::to_double() const { return in::round_to_nearest(internal(*this)); }

bool operator==(const Rational& a, const Rational& b)
{
  return a.numerator() == b.numerator() && a.denominator() == b.denominator();   // lowest terms
}

bool operator<(const Rational& a, const Rational& b) { return internal(a) < internal(b); }

Rational operator+(const Rational& a, const Rational& b) { return external(internal(a) + internal(b)); }
Rational operator-(const Rational& a, const Rational& b) { return external(internal(a) - internal(b)); }
Rational operator*(const Rational& a, const Rational& b) { return external(internal(a) * internal(b)); }
Rational operator-(const Rational& a) { return external(-internal(a)); }

Rational operator/(const Rational& a, const Rational& b)
{
  if (b == Rational(0)) throw std::domain_error("clash4d::api::Rational: division by zero");
  return external(internal(a) / internal(b));
}

// The pipeline's algebraic number, never refined in place: the pipeline
// refines a number's isolating interval inside const calls, so each call
// here works on a copy (a shared polynomial and two rational handles), and
// one Algebraic is safe to use from several threads.
struct Algebraic::Impl {
  in::Algebraic value;

  static Algebraic make(const in::Algebraic& x) { return Algebraic(std::make_shared<const Impl>(Impl{x})); }
};

namespace {

// "8x^2 - 1", "32x^2 - 32x + 7": coefficients constant first, the last one
// positive (a minimal polynomial).
std::string polynomial_text(const std::vector<mpz_class>& p)
{
  std::string out;
  for (std::size_t i = p.size(); i-- > 0;) {
    if (p[i] == 0) continue;
    mpz_class c = abs(p[i]);
    out += out.empty() ? (p[i] < 0 ? "-" : "") : (p[i] < 0 ? " - " : " + ");
    if (c != 1 || i == 0) out += c.get_str();
    if (i > 0) out += "x";
    if (i > 1) out += "^" + std::to_string(i);
  }
  return out;
}

} // namespace

Algebraic::Algebraic()
{
  static const std::shared_ptr<const Impl> zero = std::make_shared<const Impl>(Impl{in::Algebraic()});
  impl_ = zero;
}

Algebraic::Algebraic(const Rational& q) : impl_(std::make_shared<const Impl>(Impl{in::Algebraic(internal(q))})) {}

bool Algebraic::is_rational() const { return impl_->value.is_rational(); }

Rational Algebraic::rational() const
{
  if (!is_rational()) throw std::logic_error("clash4d::api::Algebraic::rational: " + text() + " is not rational");
  return external(impl_->value.rational());
}

std::vector<std::string> Algebraic::polynomial() const
{
  const in::Algebraic& x = impl_->value;
  if (x.is_rational()) {
    const in::Rational& q = x.rational();
    return {mpz_class(-mpz_class(mpq_numref(q.mpq()))).get_str(), mpz_class(mpq_denref(q.mpq())).get_str()};
  }
  std::vector<std::string> out;
  for (const mpz_class& c : x.polynomial()) out.push_back(c.get_str());
  return out;
}

std::array<Rational, 2> Algebraic::between() const
{
  in::Algebraic x = impl_->value;
  if (x.is_rational()) return {external(x.rational()), external(x.rational())};
  auto [lo, hi] = x.short_interval();
  return {external(lo), external(hi)};
}

double Algebraic::to_double() const { return in::Algebraic(impl_->value).to_double(); }

std::string Algebraic::approx() const { return in::Algebraic(impl_->value).approx(); }

std::string Algebraic::text() const
{
  in::Algebraic x = impl_->value;
  if (x.is_rational()) return in::to_string(x.rational());
  std::array<Rational, 2> b = between();
  return "root of " + polynomial_text(x.polynomial()) + " in (" + b[0].to_string() + ", " + b[1].to_string() +
         ") ~ " + x.approx();
}

int compare(const Algebraic& a, const Algebraic& b)
{
  return in::compare(in::Algebraic(a.impl().value), in::Algebraic(b.impl().value));
}

int compare(const Algebraic& a, const Rational& b) { return in::compare(in::Algebraic(a.impl().value), internal(b)); }

// ---------------------------------------------------------------- errors

Input_error::Input_error(std::string file, std::string place, std::string message, int exit_code)
  : std::runtime_error(file + ": " + (place.empty() ? "" : place + ": ") + message),
    file_(std::move(file)), place_(std::move(place)), message_(std::move(message)), exit_code_(exit_code) {}

namespace {

// Runs f, turning the pipeline's input failures into api::Input_error as the
// command line turns them into messages and exit statuses (cli/Commands.cpp).
template <class F>
auto guarded(const std::string& file, F f) -> decltype(f())
{
  try {
    return f();
  } catch (const in::Input_error& e) {
    throw Input_error(file, e.place(), e.what(), e.exit_code());
  } catch (const std::range_error& e) {
    throw Input_error(file, "", std::string(e.what()) + " (the double instantiation cannot read this scene)",
                      exit_invalid);
  } catch (const std::bad_alloc&) {
    throw Input_error(file, "", "out of memory", exit_limit);
  }
}

// The worker threads of one budgeted run's arena take its budget on entry
// and drop it on exit (run/Work_budget.h: held weakly, so a thread that
// leaves unnoticed holds nothing once the run is over).
class Budget_observer : public tbb::task_scheduler_observer {
public:
  Budget_observer(tbb::task_arena& arena, const std::shared_ptr<const in::Run_budget>& run)
    : tbb::task_scheduler_observer(arena), run_(run)
  {
    observe(true);
  }
  ~Budget_observer() override { observe(false); }
  void on_scheduler_entry(bool worker) override
  {
    if (worker) in::Work_budget::this_thread_run() = run_;
  }
  void on_scheduler_exit(bool worker) override
  {
    if (worker) in::Work_budget::this_thread_run().reset();
  }

private:
  std::weak_ptr<const in::Run_budget> run_;
};

// This thread's run for a scope, the one before restored after.
struct Run_scope {
  std::weak_ptr<const in::Run_budget> saved = in::Work_budget::this_thread_run();
  explicit Run_scope(const std::shared_ptr<const in::Run_budget>& run) { in::Work_budget::this_thread_run() = run; }
  ~Run_scope() { in::Work_budget::this_thread_run() = saved; }
};

// f() within max_seconds (0: unlimited) and the cancel flag, in a task arena
// of its own, so that concurrent runs keep their own limits. Past the
// deadline, Input_error (exit_limit) as `clash4d check --max-seconds`
// reports it; when cancelled, Cancelled.
template <class F>
auto budgeted(const std::string& file, double max_seconds, const std::atomic<bool>* cancel, F f) -> decltype(f())
{
  if (!(max_seconds >= 0)) throw std::invalid_argument("clash4d::api: max_seconds must be >= 0 (0: unlimited)");
  if (max_seconds == 0 && !cancel) return f();
  auto run = std::make_shared<in::Run_budget>();
  run->seconds = max_seconds;
  run->deadline = in::Work_budget::deadline_after(max_seconds);
  run->cancel = cancel;
  try {
    tbb::task_arena arena;
    Budget_observer observer(arena, run);
    Run_scope scope(run);
    return arena.execute([&] { return f(); });
  } catch (const in::Budget_exceeded& e) {
    std::ostringstream m;
    m << "the work budget of max_seconds " << e.seconds << " ran out before an answer";
    throw Input_error(file, "max_seconds", m.str(), exit_limit);
  } catch (const in::Run_cancelled&) {
    throw Cancelled();
  }
}

} // namespace

Cancelled::Cancelled() : std::runtime_error("clash4d: the run was cancelled") {}

std::size_t max_json_depth() { return in::CLASH4D_MAX_JSON_DEPTH; }
std::size_t max_number_chars() { return in::CLASH4D_MAX_NUMBER_CHARS; }

// ---------------------------------------------------------------- scenes

namespace {

std::string quoted(const std::string& s) { return nlohmann::json(s).dump(); }
std::string number(const Rational& r) { return quoted(r.to_string()); }

template <class Seq>
std::string numbers(const Seq& xs)
{
  std::string out = "[";
  for (const auto& x : xs) out += (out.size() > 1 ? ", " : "") + number(x);
  return out + "]";
}

template <class Seq, class Each>
std::string list(const Seq& xs, Each each)
{
  std::string out = "[";
  bool first = true;
  for (const auto& x : xs) {
    out += (first ? "" : ", ") + each(x);
    first = false;
  }
  return out + "]";
}

std::string solids(const std::vector<Solid>& xs)
{
  return list(xs, [](const Solid& s) { return s.json(); });
}

} // namespace

Solid Solid::halfspace(const Plane& h) { return Solid("{\"halfspace\": " + numbers(h) + "}"); }

Solid Solid::block(const Vec3& min, const Vec3& max)
{
  return Solid("{\"block\": {\"min\": " + numbers(min) + ", \"max\": " + numbers(max) + "}}");
}

Solid Solid::convex(const std::vector<Plane>& halfspaces)
{
  return Solid("{\"convex\": " + list(halfspaces, [](const Plane& h) { return numbers(h); }) + "}");
}

Solid Solid::prism(const std::vector<std::array<Rational, 2>>& base, const Rational& z0, const Rational& z1)
{
  return Solid("{\"prism\": {\"base\": " + list(base, [](const std::array<Rational, 2>& p) { return numbers(p); }) +
               ", \"z\": " + numbers(std::array<Rational, 2>{z0, z1}) + "}}");
}

Solid Solid::hull(const std::vector<Vec3>& points)
{
  return Solid("{\"hull\": " + list(points, [](const Vec3& p) { return numbers(p); }) + "}");
}

Solid Solid::unite(const std::vector<Solid>& xs) { return Solid("{\"union\": " + solids(xs) + "}"); }

Solid Solid::intersection(const std::vector<Solid>& xs) { return Solid("{\"intersection\": " + solids(xs) + "}"); }

Solid Solid::difference(const Solid& from, const std::vector<Solid>& removed)
{
  std::vector<Solid> all{from};
  all.insert(all.end(), removed.begin(), removed.end());
  return Solid("{\"difference\": " + solids(all) + "}");
}

Solid Solid::translate(const Vec3& d, const Solid& solid)
{
  return Solid("{\"translate\": " + numbers(d) + ", \"solid\": " + solid.json() + "}");
}

Solid Solid::rotate(const std::array<Rational, 4>& q, const Solid& solid)
{
  return Solid("{\"rotate\": " + numbers(q) + ", \"solid\": " + solid.json() + "}");
}

Solid Solid::from_json(const std::string& json) { return Solid(json); }

Motion Motion::rest() { return Motion("rest"); }

Motion Motion::steady(const Vec3& v)
{
  return Motion("vel " + v[0].to_string() + " " + v[1].to_string() + " " + v[2].to_string());
}

Motion Motion::piecewise(const std::vector<Vec3>& velocities, const std::vector<Rational>& times)
{
  if (velocities.size() != times.size() + 1)
    throw std::invalid_argument("clash4d::api::Motion::piecewise: needs one velocity more than times");
  std::string text;
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    if (i > 0) text += " until " + times[i - 1].to_string() + " ";
    text += steady(velocities[i]).text();
  }
  return Motion(text);
}

Motion Motion::from_text(const std::string& robmod) { return Motion(robmod); }

Motion Motion::poses(const std::vector<Pose>& poses)
{
  Motion m("");
  m.poses_ = poses;
  m.has_poses_ = true;
  return m;
}

std::string Motion::json() const
{
  if (!has_poses_) return quoted(text_);
  return "{\"poses\": " + list(poses_, [](const Pose& p) {
           return "{\"t\": " + number(p.t) + ", \"translate\": " + numbers(p.translate) +
                  ", \"rotate\": " + numbers(p.rotate) + "}";
         }) + "}";
}

// The scene, and the exact kernel's preparation of it (in::Exact_checker:
// model, S-bounds, sweeps, guides), made by the first exact check and kept
// for the next ones on any copy of this scene: the same answers, without
// building it all again. One check at a time uses it; another thread's
// check meanwhile runs on its own (a fresh in::check_exact).
struct Scene::Impl {
  std::string file;
  in::Scene scene;
  mutable std::mutex exact_mutex;
  mutable std::unique_ptr<in::Exact_checker> exact;

  Impl(std::string f, in::Scene s) : file(std::move(f)), scene(std::move(s)) {}

  in::Check_answer check_exact(const in::Check_options& o) const
  {
    std::unique_lock<std::mutex> lock(exact_mutex, std::try_to_lock);
    if (!lock) return in::check_exact(scene, o);
    if (!exact) exact = std::make_unique<in::Exact_checker>(scene);
    return kept([&] { return exact->check(o); });
  }
  // The same under other motions (Exact_checker::check(motions, options)).
  in::Check_answer check_exact(const std::vector<in::Motion>& motions, const in::Check_options& o) const
  {
    std::unique_lock<std::mutex> lock(exact_mutex, std::try_to_lock);
    // A pose motion's shape is placed for its poses (scene/Pose_motion.h):
    // the kept preparation cannot take other motions, nor pose motions in
    // place of the scene's; a fresh check can.
    bool poses = std::any_of(scene.objects.begin(), scene.objects.end(),
                             [](const in::Scene_object& x) { return !x.motion.poses.empty(); }) ||
                 std::any_of(motions.begin(), motions.end(), [](const in::Motion& m) { return !m.poses.empty(); });
    if (!lock || poses) return in::check_exact(in::with_motions(scene, motions), o);
    if (!exact) exact = std::make_unique<in::Exact_checker>(scene);
    return kept([&] { return exact->check(motions, o); });
  }
  // f() on the kept preparation, dropped when f stops midway (a time limit,
  // a cancel): the next check makes it afresh rather than trust a half.
  template <class F>
  in::Check_answer kept(F f) const
  {
    try {
      return f();
    } catch (...) {
      exact.reset();
      throw;
    }
  }
};

// Read within the cancel flag (budgeted): a mesh's decomposition looks at
// it (scene/Child_process.h).
Scene Scene::read_file(const std::string& path, const std::vector<std::string>& allowed_mesh_folders,
                       const std::atomic<bool>* cancel)
{
  return guarded(path, [&] {
    return budgeted(path, 0, cancel, [&] {
      return Scene(std::make_shared<const Impl>(path, in::read_scene_file(path, allowed_mesh_folders)));
    });
  });
}

Scene Scene::parse(const std::string& json, const std::string& file,
                   const std::vector<std::string>& allowed_mesh_folders, const std::atomic<bool>* cancel)
{
  return guarded(file, [&] {
    return budgeted(file, 0, cancel, [&] {
      return Scene(
          std::make_shared<const Impl>(file, in::read_scene(in::read_json_text(json), "", allowed_mesh_folders)));
    });
  });
}

const std::string& Scene::file() const { return impl_->file; }
const std::string& Scene::name() const { return impl_->scene.name; }
Rational Scene::t_lo() const { return external(impl_->scene.t_lo); }
Rational Scene::t_hi() const { return external(impl_->scene.t_hi); }

std::vector<std::string> Scene::object_names() const
{
  std::vector<std::string> names;
  for (const auto& o : impl_->scene.objects) names.push_back(o.name);
  return names;
}

std::string Scene::to_json() const { return in::write_scene(impl_->scene); }

Scene_builder::Scene_builder(std::string name, const Rational& t_lo, const Rational& t_hi)
  : name_(std::move(name)), t_lo_(t_lo), t_hi_(t_hi) {}

Scene_builder& Scene_builder::object(const std::string& name, const Solid& shape, const Motion& motion)
{
  objects_.push_back("{\"name\": " + quoted(name) + ", \"shape\": " + shape.json() + ", \"motion\": " +
                     motion.json() + "}");
  return *this;
}

Scene_builder& Scene_builder::ignore(const std::string& a, const std::string& b)
{
  ignore_.push_back("[" + quoted(a) + ", " + quoted(b) + "]");
  return *this;
}

std::string Scene_builder::json() const
{
  auto lines = [](const std::vector<std::string>& xs) {
    std::string out = "[";
    for (std::size_t i = 0; i < xs.size(); ++i) out += (i ? ",\n    " : "\n    ") + xs[i];
    return out + (xs.empty() ? "]" : "\n  ]");
  };
  std::string text = "{\n  \"format\": \"clash4d-scene/1\",\n  \"name\": " + quoted(name_) + ",\n  \"time\": " +
                     numbers(std::array<Rational, 2>{t_lo_, t_hi_}) + ",\n  \"objects\": " + lines(objects_);
  if (!ignore_.empty()) text += ",\n  \"ignore\": " + lines(ignore_);
  return text + "\n}\n";
}

Scene Scene_builder::build() const { return Scene::parse(json(), "<built scene>"); }

void validate(const std::string& path) { Scene::read_file(path); }

// ---------------------------------------------------------------- check

const char* name(Number n)
{
  switch (n) {
  case Number::exact: return "exact";
  case Number::rational: return "rational";
  case Number::double_: return "double";
  }
  return "?";
}

const char* name(Semantics s) { return s == Semantics::closed ? "closed" : "regularised"; }

Number number_from_name(const std::string& name)
{
  if (name == "exact") return Number::exact;
  if (name == "rational") return Number::rational;
  if (name == "double") return Number::double_;
  throw std::invalid_argument("unknown number \"" + name + "\": exact, rational or double");
}

Semantics semantics_from_name(const std::string& name)
{
  if (name == "regularised") return Semantics::regularised;
  if (name == "closed") return Semantics::closed;
  throw std::invalid_argument("unknown semantics \"" + name + "\": regularised or closed");
}

const Colliding_pair* Check_result::reported() const
{
  if (reported_index < 0 || reported_index >= static_cast<int>(pairs.size())) return nullptr;
  return &pairs[reported_index];
}

namespace {

in::Semantics internal(Semantics s) { return s == Semantics::closed ? in::Semantics::closed : in::Semantics::regularised; }

// A number of an answer: exact text, or a double's shortest decimal.
Rational answer_number(const std::string& text)
{
  in::Number_parse n = in::parse_number_text(text, true);
  if (!n.ok) throw std::runtime_error("clash4d: the answer holds \"" + text + "\", not a finite number");
  return external(n.value);
}

template <std::size_t N>
std::array<Rational, N> answer_point(const std::array<std::string, 4>& p)
{
  std::array<Rational, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = answer_number(p[i]);
  return out;
}

std::array<Point4, 2> answer_cells(const std::array<std::array<std::string, 4>, 2>& c)
{
  return {answer_point<4>(c[0]), answer_point<4>(c[1])};
}

// An answer's number as an Algebraic: exact text (always rational on the
// translation path), or a double's shortest decimal.
template <std::size_t N>
std::array<Algebraic, N> answer_numbers(const std::array<std::string, 4>& p)
{
  std::array<Algebraic, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = Algebraic(answer_number(p[i]));
  return out;
}

Colliding_pair answer_pair(const in::Pair_answer& p, Semantics semantics)
{
  Colliding_pair out;
  out.a = p.a;
  out.b = p.b;
  out.witness = answer_numbers<4>(p.witness);
  out.witness_verified = p.witness_verified;
  if (semantics == Semantics::closed) out.witness_inside = answer_cells(p.witness_cells);
  if (p.earliest) {
    Earliest e;
    e.t = Algebraic(answer_number(p.t_star));
    e.point = answer_numbers<3>(p.contact);
    e.at_start = p.at_start;
    e.inside = answer_cells(p.contact_cells);
    out.earliest = e;
  }
  return out;
}

// A pair of a scene with rotation: its numbers may be irrational, and time
// slices give no generic inside points (Earliest::inside stays empty).
Colliding_pair rotating_pair(const in::Rotating_pair_answer& p)
{
  const in::Rotating_answer& a = p.answer;
  Colliding_pair out;
  out.a = p.a;
  out.b = p.b;
  for (std::size_t i = 0; i < 4; ++i) out.witness[i] = Algebraic::Impl::make(a.witness[i]);
  out.witness_verified = a.witness_verified;
  if (a.earliest) {
    Earliest e;
    e.t = Algebraic::Impl::make(a.t_star);
    for (std::size_t k = 0; k < 3; ++k) e.point[k] = Algebraic::Impl::make(a.contact[k]);
    e.at_start = a.at_start;
    out.earliest = e;
  }
  return out;
}

} // namespace

namespace {

// A tolerance applies to Number::double_ only, and is >= 0.
void check_tolerance(const char* function, Number number, double tolerance)
{
  if (tolerance != 0 && number != Number::double_)
    throw std::invalid_argument(std::string("clash4d::api::") + function + ": a tolerance applies to Number::double_ only");
  if (!(tolerance >= 0)) throw std::invalid_argument(std::string("clash4d::api::") + function + ": the tolerance must be >= 0");
}

in::Check_options internal(const Check_options& options)
{
  check_tolerance("check", options.number, options.tolerance);
  in::Check_options o;
  o.all_pairs = options.all_pairs;
  o.earliest = options.earliest;
  o.semantics = internal(options.semantics);
  return o;
}

// The pipeline's answer in the API's form.
Check_result result_of(const in::Check_answer& a, const Check_options& options)
{
  Check_result r;
  r.number = options.number;
  r.semantics = options.semantics;
  r.collide = a.collide;
  for (const auto& p : a.pairs) r.pairs.push_back(answer_pair(p, options.semantics));
  if (const in::Pair_answer* main = a.reported()) r.reported_index = static_cast<int>(main - a.pairs.data());
  return r;
}

Check_result result_of(const in::Rotating_check_answer& a, const Check_options& options)
{
  Check_result r;
  r.number = options.number;
  r.semantics = options.semantics;
  r.collide = a.collide;
  for (const auto& p : a.pairs) r.pairs.push_back(rotating_pair(p));
  if (const in::Rotating_pair_answer* main = a.reported()) r.reported_index = static_cast<int>(main - a.pairs.data());
  return r;
}

// A scene where some object turns, by time slices, as `clash4d check`
// decides it (cli/Rotating_check_command.cpp): what it cannot decide is
// invalid input at the first turning object ("objects[i].motion", or
// "motions[i]" for given motions), never an answer.
Check_result check_turning(const in::Scene& s, bool given_motions, const Check_options& options)
{
  std::size_t i = 0;
  while (i + 1 < s.objects.size() && !s.objects[i].motion.rotates()) ++i;
  std::string place = given_motions ? "motions[" + std::to_string(i) + "]" : "objects[" + std::to_string(i) + "].motion";
  std::string who = "object \"" + s.objects[i].name + "\": ";
  try {
    return result_of(in::check_rotating(s, internal(options), name(options.number), options.tolerance), options);
  } catch (const in::Rotation_unsupported& e) {
    throw in::Input_error(place, who + "not decided: " + e.what());
  } catch (const in::Minor_limit& e) {
    throw in::Input_error("objects", e.what(), in::CLASH4D_EXIT_LIMIT);
  }
}

// A check in the number options.number asks for; exact on the scene's kept
// preparation (Scene::Impl::check_exact), given motions or the scene's; a
// scene with rotation (scene_rotates) by time slices.
Check_result run_check(const Scene& scene, const std::vector<in::Motion>* motions, const Check_options& options)
{
  in::Check_options o = internal(options);
  const Scene::Impl& impl = scene.impl();
  bool turning = motions ? std::any_of(motions->begin(), motions->end(), [](const in::Motion& m) { return m.rotates(); })
                         : in::scene_rotates(impl.scene);
  return budgeted(scene.file(), options.max_seconds, options.cancel, [&] {
    return guarded(scene.file(), [&] {
      if (options.number == Number::exact && !turning)
        return result_of(motions ? impl.check_exact(*motions, o) : impl.check_exact(o), options);
      std::optional<in::Scene> moved;
      if (motions) moved = in::with_motions(impl.scene, *motions);
      const in::Scene& s = moved ? *moved : impl.scene;
      if (turning) return check_turning(s, motions != nullptr, options);
      if (options.number == Number::rational) return result_of(in::check_rational(s, o), options);
      return result_of(in::check_double(s, options.tolerance, o), options);
    });
  });
}

// A pose motion as the pipeline's, its poses checked as the scene reader
// checks them (Input_error at place + ".poses[j]...").
in::Motion pose_motion(const Motion& m, const std::string& place)
{
  in::Motion out;
  for (const Pose& p : m.pose_list()) {
    in::Pose q;
    q.t = internal(p.t);
    for (std::size_t k = 0; k < 3; ++k) q.translate[k] = internal(p.translate[k]);
    for (std::size_t k = 0; k < 4; ++k) q.rotate[k] = internal(p.rotate[k]);
    out.poses.push_back(std::move(q));
  }
  in::check_poses(out.poses, place);
  return out;
}

} // namespace

Check_result check(const Scene& scene, const Check_options& options)
{
  return run_check(scene, nullptr, options);
}

namespace {

// Given motions (check's and compare's), read and checked: Input_error at
// "motions[i]", std::invalid_argument naming `function` for a wrong count.
std::vector<in::Motion> parsed_motions(const Scene& scene, const std::vector<Motion>& motions, const char* function)
{
  const in::Scene& s = scene.impl().scene;
  if (motions.size() != s.objects.size())
    throw std::invalid_argument(std::string("clash4d::api::") + function + ": " + std::to_string(motions.size()) +
                                " motions for a scene of " + std::to_string(s.objects.size()) + " objects");
  std::vector<in::Motion> parsed;
  guarded(scene.file(), [&] {
    for (std::size_t i = 0; i < motions.size(); ++i) {
      std::string place = "motions[" + std::to_string(i) + "]";
      parsed.push_back(motions[i].has_poses() ? pose_motion(motions[i], place)
                                              : in::parse_motion(motions[i].text(), place));
    }
    return 0;
  });
  return parsed;
}

} // namespace

Check_result check(const Scene& scene, const std::vector<Motion>& motions, const Check_options& options)
{
  std::vector<in::Motion> parsed = parsed_motions(scene, motions, "check");
  return run_check(scene, &parsed, options);
}

// ---------------------------------------------------------------- CCD

namespace {

in::Ccd_type internal(Ccd_type t) { return t == Ccd_type::edge_edge ? in::Ccd_type::edge_edge : in::Ccd_type::vertex_face; }

} // namespace

const char* name(Ccd_type type) { return in::ccd_type_name(internal(type)); }

Ccd_type ccd_type_from_name(const std::string& name)
{
  std::optional<in::Ccd_type> t = in::ccd_type_from_name(name);
  if (!t) throw std::invalid_argument("unknown CCD type \"" + name + "\": vertex-face (vf) or edge-edge (ee)");
  return *t == in::Ccd_type::edge_edge ? Ccd_type::edge_edge : Ccd_type::vertex_face;
}

namespace {

const char* const ccd_file = "<query>";

in::Ccd_options internal(const Ccd_options& options)
{
  check_tolerance("ccd", options.number, options.tolerance);
  in::Ccd_options o;
  o.earliest = options.earliest;
  o.tolerance = options.tolerance;
  o.separation = internal(options.separation);
  if (o.separation < 0) throw std::invalid_argument("clash4d::api::ccd: the separation must be >= 0");
  if (options.number == Number::double_ && !std::isfinite(in::round_to_nearest(o.separation)))
    throw Input_error(ccd_file, "separation",
                      "the number " + options.separation.to_string() +
                          " is beyond the range of double (the double instantiation cannot read this query)",
                      exit_invalid);
  return o;
}

// The pipeline's query; with Number::double_, every number within the
// double range, else Input_error at place + "t0[i][k]" (as `clash4d ccd`).
in::Ccd_query internal(Ccd_type type, const Ccd_query& q, Number number, const std::string& place)
{
  in::Ccd_query::Rows rows;
  for (std::size_t i = 0; i < 8; ++i)
    for (std::size_t k = 0; k < 3; ++k) rows[i][k] = internal((i < 4 ? q.t0[i] : q.t1[i - 4])[k]);
  in::Ccd_query out(internal(type), rows);
  if (number == Number::double_)
    for (std::size_t i = 0; i < 8; ++i)
      for (std::size_t k = 0; k < 3; ++k)
        if (!std::isfinite(out.nearest()[i][k]))
          throw Input_error(ccd_file,
                            place + (i < 4 ? "t0[" : "t1[") + std::to_string(i % 4) + "][" + std::to_string(k) + "]",
                            "the number " + in::to_string(rows[i][k]) +
                                " is beyond the range of double (the double instantiation cannot read this query)",
                            exit_invalid);
  return out;
}

using Ccd_decide = in::Ccd_answer (*)(const in::Ccd_query&, const in::Ccd_options&);

Ccd_decide ccd_decider(Number number)
{
  if (number == Number::rational) return in::ccd_rational;
  if (number == Number::double_) return in::ccd_double;
  return in::ccd_exact;
}

// An answer's number: exact, or a double's shortest decimal (as check's).
Algebraic ccd_number(const in::Ccd_number& x)
{
  if (const in::Algebraic* a = std::get_if<in::Algebraic>(&x)) return Algebraic::Impl::make(*a);
  return Algebraic(answer_number(in::shortest_decimal(std::get<double>(x))));
}

Ccd_result ccd_result(const in::Ccd_answer& a)
{
  Ccd_result r;
  r.collide = a.collide;
  if (a.earliest) {
    r.t = ccd_number(a.earliest->t);
    r.u = ccd_number(a.earliest->u);
    r.v = ccd_number(a.earliest->v);
  }
  return r;
}

} // namespace

Ccd_result ccd(Ccd_type type, const Ccd_query& query, const Ccd_options& options)
{
  in::Ccd_options o = internal(options);
  in::Ccd_query q = internal(type, query, options.number, "");
  return ccd_result(budgeted(ccd_file, options.max_seconds, options.cancel, [&] {
    return guarded(ccd_file, [&] {
      in::Work_budget::check();
      return ccd_decider(options.number)(q, o);
    });
  }));
}

Ccd_result ccd_vertex_face(const Vec3& p_t0, const Vec3& a_t0, const Vec3& b_t0, const Vec3& c_t0, const Vec3& p_t1,
                           const Vec3& a_t1, const Vec3& b_t1, const Vec3& c_t1, const Ccd_options& options)
{
  return ccd(Ccd_type::vertex_face, {{p_t0, a_t0, b_t0, c_t0}, {p_t1, a_t1, b_t1, c_t1}}, options);
}

Ccd_result ccd_edge_edge(const Vec3& a0_t0, const Vec3& a1_t0, const Vec3& b0_t0, const Vec3& b1_t0, const Vec3& a0_t1,
                         const Vec3& a1_t1, const Vec3& b0_t1, const Vec3& b1_t1, const Ccd_options& options)
{
  return ccd(Ccd_type::edge_edge, {{a0_t0, a1_t0, b0_t0, b1_t0}, {a0_t1, a1_t1, b0_t1, b1_t1}}, options);
}

std::vector<Ccd_result> ccd_batch(Ccd_type type, const std::vector<Ccd_query>& queries, const Ccd_options& options)
{
  in::Ccd_options o = internal(options);
  std::vector<in::Ccd_query> qs;
  qs.reserve(queries.size());
  for (std::size_t j = 0; j < queries.size(); ++j)
    qs.push_back(internal(type, queries[j], options.number, "queries[" + std::to_string(j) + "]."));
  Ccd_decide decide = ccd_decider(options.number);
  std::vector<in::Ccd_answer> answers(qs.size());
  budgeted(ccd_file, options.max_seconds, options.cancel, [&] {
    return guarded(ccd_file, [&] {
      tbb::parallel_for(std::size_t(0), qs.size(), [&](std::size_t j) {
        in::Work_budget::check();   // once per query, as `clash4d ccd --max-seconds`
        answers[j] = decide(qs[j], o);
      });
      return 0;
    });
  });
  std::vector<Ccd_result> out;
  out.reserve(answers.size());
  for (const in::Ccd_answer& a : answers) out.push_back(ccd_result(a));
  return out;
}

// ---------------------------------------------------------------- compare

namespace {

std::optional<Rational> maybe_number(const std::string& text)
{
  if (text.empty()) return std::nullopt;
  in::Number_parse n = in::parse_number_text(text, true);
  if (!n.ok) return std::nullopt;
  return external(n.value);
}

std::optional<Located> located(const std::optional<in::Located>& l)
{
  if (!l) return std::nullopt;
  Located out;
  out.objects = l->objects;
  out.t_text = l->t;
  if (l->point) out.point_text = *l->point;
  if (l->point) {
    Point4 p;
    bool ok = true;
    for (int i = 0; i < 4 && ok; ++i) {
      std::optional<Rational> x = maybe_number((*l->point)[i]);
      if (x) p[i] = *x; else ok = false;
    }
    if (ok) out.point = p;
  }
  out.t = maybe_number(l->t);
  return out;
}

} // namespace

namespace {

Comparison run_compare(const Scene& scene, const in::Scene& moved, const Compare_options& options)
{
  in::Compare_options o;
  o.semantics = internal(options.semantics);
  o.tolerances = options.tolerances;
  o.earliest = options.earliest;
  o.rounded = options.rounded;
  o.fcl = options.fcl;
  o.bullet = options.bullet;
  in::Comparison c = budgeted(scene.file(), options.max_seconds, options.cancel, [&] {
    return guarded(scene.file(), [&] { return in::compare_scene(moved, scene.file(), o); });
  });
  Comparison out;
  out.file = c.file;
  out.name = c.name;
  out.closed_touch = c.closed_touch;
  for (const in::Subject_row& s : c.subjects) {
    Subject_row row;
    row.subject = s.subject;
    row.semantics = s.semantics;
    row.tolerance = s.tolerance;
    row.reference = s.reference;
    row.ok = s.ok;
    row.error = s.error;
    row.skipped = s.skipped;
    row.collide = s.collide;
    row.witness = located(s.witness);
    row.witness_valid = s.witness_valid;
    row.earliest = located(s.earliest);
    row.t_error = s.t_error;
    row.agrees = s.agrees;
    row.cause = s.cause;
    out.subjects.push_back(row);
  }
  for (const in::Disagreement& d : c.disagreements)
    out.disagreements.push_back({d.subject, d.cause, d.detail, d.semantics});
  out.json = c.to_json().dump(2);
  return out;
}

} // namespace

Comparison compare(const Scene& scene, const Compare_options& options)
{
  return run_compare(scene, scene.impl().scene, options);
}

Comparison compare(const Scene& scene, const std::vector<Motion>& motions, const Compare_options& options)
{
  std::vector<in::Motion> parsed = parsed_motions(scene, motions, "compare");
  return run_compare(scene, in::with_motions(scene.impl().scene, parsed), options);
}

} // namespace api
} // namespace clash4d
