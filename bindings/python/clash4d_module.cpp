// The compiled module clash4d._core (pybind11) on the public C++ API
// (api/clash4d/clash4d.h), under the package clash4d (clash4d/__init__.py
// types its answers). A scene is a dict in the scene format or a path;
// exact numbers come back as fractions.Fraction. Documented in the module's
// docstring below and in the README ("Use it from Python").
#include <clash4d/clash4d.h>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

namespace py = pybind11;
namespace c4 = clash4d::api;

namespace {

const char* const module_doc = R"(clash4d._core: the compiled part of the package clash4d (exact collision
detection for moving polyhedral CSG solids). Use `import clash4d`: its
check returns a typed clash4d.Answer; the check here returns the dict form
below, which clash4d.Answer wraps.

    clash4d._core.check(scene, earliest=True)["earliest"]["t"]   # a Fraction; scene as in help(clash4d)

Scenes, numbers and motions are as the clash4d package's docstring says
(help(clash4d)).

A dict is refused with clash4d.InputError at the place of the fault (e.g.
"objects[0].shape") when it holds itself (a cycle: a list that contains
itself), nests deeper than the scene reader's limit of 256 levels
(exit_code EXIT_LIMIT, as the reader), holds an integer of more digits than
a number's limit of 1000 characters (EXIT_LIMIT), a nan or an inf, a key
that is not a str, a str with a lone surrogate, or a value that is not JSON
(bytes, a set, any other object). True and False are JSON's booleans, never
numbers: where the format wants a number they are refused as the reader
refuses a boolean there.

Answers are dicts in the form of `clash4d check --json` and
`clash4d compare --json`, with every exact number a fractions.Fraction, or,
where it is irrational (with rotation: t*, a contact point, a closed
witness), a clash4d.Algebraic (below).

CCD queries (`clash4d ccd`, docs/ccd-queries.md): a vertex and a triangle,
or two edges, whose four vertices move linearly over t in [0, 1]:

    clash4d.ccd_vertex_face(t0, t1)   # t0 = [p, a, b, c] at t = 0, t1 at t = 1
    clash4d.ccd_edge_edge(t0, t1)     # t0 = [a0, a1, b0, b1], t1 likewise
    clash4d.ccd_batch([(t0, t1), ...], type="edge-edge")   # in parallel, in order

answer {"collide", "t", "uv"} with t* and (u, v) exact: a Fraction, or a
clash4d.Algebraic (an irrational root, with poly, between and approx,
float() and exact comparisons with Fraction).
Invalid input raises clash4d.InputError (a ValueError) with the attributes
file, place, message and exit_code (EXIT_INVALID = 2, EXIT_LIMIT = 3).
"Verify" (certificates) is not in the toolkit yet.)";

PyObject* input_error_type = nullptr;   // clash4d.InputError (kept for the process)

py::object fraction(const c4::Rational& r)
{
  static py::object* type = new py::object(py::module_::import("fractions").attr("Fraction"));   // never freed
  return (*type)(r.to_string());
}

// A rational as a Fraction, an irrational number as a clash4d.Algebraic.
py::object algebraic(const c4::Algebraic& x)
{
  return x.is_rational() ? fraction(x.rational()) : py::cast(x);
}

template <std::size_t N>
py::list point(const std::array<c4::Algebraic, N>& p)
{
  py::list out;
  for (const auto& x : p) out.append(algebraic(x));
  return out;
}

py::list point(const c4::Point4& p)
{
  py::list out;
  for (const auto& x : p) out.append(fraction(x));
  return out;
}

[[noreturn]] void bad_input(const std::string& file, const std::string& place, const std::string& message)
{
  throw c4::Input_error(file, place, message, c4::exit_invalid);
}

[[noreturn]] void over_limit(const std::string& file, const std::string& place, const std::string& message)
{
  throw c4::Input_error(file, place, message, c4::exit_limit);
}

// repr(v), cut to a readable length; the type's name when repr fails or
// would be long to make (a large bytes).
std::string short_repr(py::handle v)
{
  std::string type = py::str(py::type::handle_of(v).attr("__name__"));
  if (py::isinstance<py::bytes>(v) && py::len(v) > 64) return "a bytes object of " + std::to_string(py::len(v)) + " bytes";
  try {
    std::string r = py::repr(v);
    return r.size() <= 80 ? r : r.substr(0, 60) + "... (a " + type + ")";
  } catch (py::error_already_set&) {
    return "an object of type " + type;
  }
}

// The decimal text of a Python int. One longer than the scene reader's limit
// on a number's characters is refused here (as the reader would), before
// Python writes its digits (or refuses to, past sys.get_int_max_str_digits()).
std::string int_text(py::handle v, const std::string& file, const std::string& place)
{
  py::int_ i = py::reinterpret_borrow<py::object>(v);
  std::size_t bits = i.attr("bit_length")().cast<std::size_t>();
  std::size_t limit = c4::max_number_chars();
  if (bits > 1 && (bits - 1) * 30103 / 100000 >= limit)   // at least 1 + (bits - 1) log10(2) digits
    over_limit(file, place, "an integer of " + std::to_string(bits) + " bits: more digits than the limit of " +
                                std::to_string(limit) + " characters of a number");
  try {
    return py::str(i);
  } catch (py::error_already_set& e) {   // a lower sys.set_int_max_str_digits
    over_limit(file, place, "Python cannot write this integer in decimal: " + std::string(py::str(e.value())));
  }
}

// The exact text of a Python number ("3", "p/q", "1E+5"): an int, any
// numbers.Rational (Fraction), a float by its exact value (a double is a
// binary fraction: 0.1 is 3602879701896397/36028797018963968) and a
// decimal.Decimal by its own text, which is its exact value; inf and nan
// are bad input at `place`. None for anything else (bool included: it is
// not a number here).
std::optional<std::string> number_text(py::handle v, const std::string& file, const std::string& place)
{
  static py::object* rational = new py::object(py::module_::import("numbers").attr("Rational"));
  static py::object* decimal = new py::object(py::module_::import("decimal").attr("Decimal"));
  auto exact = [&](py::handle p, py::handle q) { return int_text(p, file, place) + "/" + int_text(q, file, place); };
  if (py::isinstance<py::bool_>(v)) return std::nullopt;
  if (py::isinstance<py::int_>(v)) return int_text(v, file, place);
  if (py::isinstance(v, *rational)) return exact(v.attr("numerator"), v.attr("denominator"));
  if (py::isinstance<py::float_>(v)) {
    double x = v.cast<double>();
    if (!std::isfinite(x)) bad_input(file, place, "not a finite number: " + short_repr(v));
    py::tuple pq = py::float_(x).attr("as_integer_ratio")();
    return exact(pq[0], pq[1]);
  }
  if (py::isinstance(v, *decimal)) {
    if (!v.attr("is_finite")().cast<bool>()) bad_input(file, place, "not a finite number: " + short_repr(v));
    return std::string(py::str(v));   // JSON's number grammar: "-1.5E+7"
  }
  return std::nullopt;
}

// The JSON text of a JSON-like Python value (dict, list, tuple, str, int,
// float, Fraction, Decimal, bool, None), numbers kept exact. Refused with
// InputError at its place: a container that holds itself (a cycle), nesting
// deeper than the scene reader's limit (exit 3, as the reader), a key that
// is not a str, a str that is not Unicode text, and any other value.
class Json_writer {
public:
  explicit Json_writer(std::string file) : file_(std::move(file)) {}

  std::string write(py::handle v)
  {
    std::string out;
    value(v, "", 1, out);
    return out;
  }

private:
  std::string file_;
  std::unordered_map<const PyObject*, std::string> open_;   // the containers on the path, at their place

  void value(py::handle v, const std::string& place, std::size_t depth, std::string& out);
  void container(py::handle v, const std::string& place, std::size_t depth, std::string& out);
  void text(py::handle v, const std::string& place, std::string& out);
};

void Json_writer::value(py::handle v, const std::string& place, std::size_t depth, std::string& out)
{
  if (v.is_none()) {
    out += "null";
  } else if (py::isinstance<py::bool_>(v)) {
    out += v.ptr() == Py_True ? "true" : "false";
  } else if (std::optional<std::string> number = number_text(v, file_, place)) {
    out += py::isinstance<py::int_>(v) ? *number : "\"" + *number + "\"";
  } else if (py::isinstance<py::str>(v)) {
    text(v, place, out);
  } else if (py::isinstance<py::dict>(v) || py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    container(v, place, depth, out);
  } else {
    bad_input(file_, place, "not a JSON value: " + short_repr(v));
  }
}

// A dict, list or tuple, its items at depth + 1; refused before recursing
// when it is on its own path or too deep, so no input can overflow the stack.
void Json_writer::container(py::handle v, const std::string& place, std::size_t depth, std::string& out)
{
  if (auto seen = open_.find(v.ptr()); seen != open_.end())
    bad_input(file_, place, "a cycle: this " + std::string(py::str(py::type::handle_of(v).attr("__name__"))) +
                                " contains itself (it is also at " + (seen->second.empty() ? "the scene" : seen->second) + ")");
  if (depth > c4::max_json_depth())
    over_limit(file_, place, "nesting deeper than the limit of " + std::to_string(c4::max_json_depth()) + " levels");
  open_.emplace(v.ptr(), place);
  if (py::isinstance<py::dict>(v)) {
    out += "{";
    // Its items held (a list of (key, value)), so that Python code a value
    // runs (a Rational's numerator) cannot free what is being read.
    py::list items = py::reinterpret_steal<py::list>(PyDict_Items(v.ptr()));
    if (!items) throw py::error_already_set();
    for (std::size_t i = 0; i < items.size(); ++i) {
      py::tuple item = items[i];
      if (!py::isinstance<py::str>(item[0])) bad_input(file_, place, "a key is not a string: " + short_repr(item[0]));
      out += i ? ", " : "";
      text(item[0], place, out);
      std::string key = item[0].cast<std::string>();
      std::string at = place.empty() ? key : place + "." + key;
      out += ": ";
      value(item[1], at, depth + 1, out);
    }
    out += "}";
  } else {
    out += "[";
    // Its items as stored (a subclass's __iter__ is not run), held as above.
    py::object items = py::reinterpret_steal<py::object>(py::isinstance<py::list>(v)
                                                             ? PyList_GetSlice(v.ptr(), 0, PY_SSIZE_T_MAX)
                                                             : PyTuple_GetSlice(v.ptr(), 0, PY_SSIZE_T_MAX));
    if (!items) throw py::error_already_set();
    std::size_t i = 0;
    for (py::handle item : items) {
      out += i ? ", " : "";
      value(item, place + "[" + std::to_string(i++) + "]", depth + 1, out);
    }
    out += "]";
  }
  open_.erase(v.ptr());
}

// A str as a JSON string; one that is not Unicode text (a lone surrogate)
// is refused.
void Json_writer::text(py::handle v, const std::string& place, std::string& out)
{
  static py::object* json_dumps = new py::object(py::module_::import("json").attr("dumps"));
  Py_ssize_t size = 0;
  if (!PyUnicode_AsUTF8AndSize(v.ptr(), &size)) {
    PyErr_Clear();
    bad_input(file_, place, "a string that is not Unicode text (a lone surrogate): " + short_repr(v));
  }
  out += (*json_dumps)(v).cast<std::string>();
}

// work(cancel) run in a thread of its own while this thread, the GIL
// released, looks for signals every 50 ms (Python runs its signal handlers
// only when asked, and only in the main thread). When a handler raises
// (Ctrl-C: KeyboardInterrupt), the work is cancelled through the flag,
// awaited, and that exception is raised; otherwise the work's result or
// exception comes back. work must not touch Python objects.
template <class F>
auto interruptible(F work) -> decltype(work(std::declval<const std::atomic<bool>*>()))
{
  using Result = decltype(work(std::declval<const std::atomic<bool>*>()));
  std::atomic<bool> cancel{false};
  std::optional<Result> result;
  std::exception_ptr error;
  bool done = false, interrupted = false;
  std::mutex m;
  std::condition_variable finished;
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        result.emplace(work(&cancel));
      } catch (...) {
        error = std::current_exception();
      }
      std::lock_guard<std::mutex> lock(m);
      done = true;
      finished.notify_one();
    });
    std::unique_lock<std::mutex> lock(m);
    while (!finished.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; }))
      if (!interrupted) {
        lock.unlock();
        {
          py::gil_scoped_acquire acquire;
          interrupted = PyErr_CheckSignals() != 0;   // the handler's exception stays set
        }
        if (interrupted) cancel = true;
        lock.lock();
      }
    lock.unlock();
    worker.join();
  }
  if (interrupted) throw py::error_already_set();
  if (error) std::rethrow_exception(error);
  return std::move(*result);
}

// A clash4d.Scene is itself (its exact preparation kept); a dict is written
// as JSON and read; anything else is a path.
// mesh_folders: where mesh files may be besides the scene's folder (the
// current directory for a dict; docs/meshes.md).
c4::Scene read_scene(py::handle scene, const std::vector<std::string>& mesh_folders = {})
{
  if (py::isinstance<c4::Scene>(scene)) return scene.cast<c4::Scene>();
  if (py::isinstance<py::dict>(scene)) {
    std::string text = Json_writer("<scene>").write(scene);
    return interruptible(
        [&](const std::atomic<bool>* cancel) { return c4::Scene::parse(text, "<scene>", mesh_folders, cancel); });
  }
  static py::object* fspath = new py::object(py::module_::import("os").attr("fspath"));
  static py::object* fsdecode = new py::object(py::module_::import("os").attr("fsdecode"));
  py::object path;
  try {
    path = (*fsdecode)((*fspath)(scene));
  } catch (py::error_already_set&) {
    throw py::type_error("clash4d: a scene is a dict or a path (str or os.PathLike), not " +
                         std::string(py::str(py::type::handle_of(scene).attr("__name__"))));
  }
  std::string file = path.cast<std::string>();
  // Ctrl-C stops a long read (a mesh's decomposition) as it stops a check.
  return interruptible(
      [&](const std::atomic<bool>* cancel) { return c4::Scene::read_file(file, mesh_folders, cancel); });
}

const char* const ccd_file = "<query>";   // the file of a CCD query's InputError (c4::ccd's)

// An exact number: a Python number as number_text reads it, or a string in
// the scene format's forms ("1/3", "0.1", "-2.5e-3").
c4::Rational exact_number(py::handle v, const std::string& place, const std::string& file = ccd_file)
{
  std::optional<std::string> text = number_text(v, file, place);
  if (!text && py::isinstance<py::str>(v)) text = v.cast<std::string>();
  if (!text) bad_input(file, place, "not a number: " + short_repr(v));
  try {
    return c4::Rational(*text);
  } catch (const std::invalid_argument& e) {
    bad_input(file, place, e.what());
  }
}

// The items of a list or tuple (any sequence but a string) of n items.
std::vector<py::handle> items(py::handle v, std::size_t n, const char* what, const std::string& place,
                              const std::string& file = ccd_file)
{
  if (!py::isinstance<py::sequence>(v) || py::isinstance<py::str>(v) || py::isinstance<py::bytes>(v) ||
      py::len(v) != n)
    bad_input(file, place, "expected " + std::to_string(n) + " " + what + ", not " + short_repr(v));
  std::vector<py::handle> out;
  for (py::handle x : py::reinterpret_borrow<py::sequence>(v)) out.push_back(x);
  return out;
}

py::dict witness_dict(const c4::Colliding_pair& p)
{
  py::dict w;
  w["objects"] = py::make_tuple(p.a, p.b);
  w["point"] = point(p.witness);
  w["verified"] = p.witness_verified;
  if (p.witness_inside) w["inside"] = py::make_tuple(point((*p.witness_inside)[0]), point((*p.witness_inside)[1]));
  return w;
}

py::dict earliest_dict(const c4::Colliding_pair& p)
{
  const c4::Earliest& e = *p.earliest;
  py::dict d;
  d["objects"] = py::make_tuple(p.a, p.b);
  d["t"] = algebraic(e.t);
  d["point"] = point(e.point);
  d["at_start"] = e.at_start;
  if (e.inside) d["inside"] = py::make_tuple(point((*e.inside)[0]), point((*e.inside)[1]));   // none with rotation
  return d;
}

// A pose of check's motions=: {"t": T, "translate": [x, y, z], "rotate":
// [w, x, y, z]}, the last two optional (the scene format's pose).
c4::Pose pose(py::handle v, const std::string& place, const std::string& file)
{
  if (!py::isinstance<py::dict>(v))
    bad_input(file, place, "expected a pose {\"t\", \"translate\", \"rotate\"}, not " + short_repr(v));
  py::dict d = py::reinterpret_borrow<py::dict>(v);
  for (auto item : d) {
    std::string key = py::isinstance<py::str>(item.first) ? item.first.cast<std::string>() : "";
    if (key != "t" && key != "translate" && key != "rotate")
      bad_input(file, place, "unknown key " + short_repr(item.first) + " (t, translate, rotate)");
  }
  if (!d.contains("t")) bad_input(file, place, "missing \"t\"");
  c4::Pose p;
  p.t = exact_number(d["t"], place + ".t", file);
  auto numbers = [&](const char* key, c4::Rational* out, std::size_t n) {
    if (!d.contains(key)) return;
    std::string at = place + "." + key;
    std::vector<py::handle> xs = items(d[key], n, "numbers", at, file);
    for (std::size_t k = 0; k < n; ++k) out[k] = exact_number(xs[k], at + "[" + std::to_string(k) + "]", file);
  };
  numbers("translate", p.translate.data(), 3);
  numbers("rotate", p.rotate.data(), 4);
  return p;
}

// A motion of check's motions=: a ROBMOD str, or {"poses": [pose, ...]}
// as in a scene (its poses' values are checked by the library).
c4::Motion motion(py::handle v, const std::string& place, const std::string& file)
{
  if (py::isinstance<py::str>(v)) return c4::Motion::from_text(v.cast<std::string>());
  if (!py::isinstance<py::dict>(v) || py::len(v) != 1 || !v.contains("poses"))
    bad_input(file, place, "expected a ROBMOD string or {\"poses\": [...]}, not " + short_repr(v));
  py::object list = v["poses"];
  if (!py::isinstance<py::list>(list) && !py::isinstance<py::tuple>(list))
    bad_input(file, place + ".poses", "expected a list of poses, not " + short_repr(list));
  std::vector<c4::Pose> poses;
  for (py::handle x : py::tuple(list)) poses.push_back(pose(x, place + ".poses[" + std::to_string(poses.size()) + "]", file));
  return c4::Motion::poses(poses);
}

// check's motions=: None, or one motion per object.
std::optional<std::vector<c4::Motion>> motions_of(py::handle motions, const c4::Scene& s, const char* function)
{
  if (motions.is_none()) return std::nullopt;
  if (!py::isinstance<py::sequence>(motions) || py::isinstance<py::str>(motions) || py::isinstance<py::bytes>(motions))
    throw py::type_error(std::string("clash4d.") + function + ": motions is a list of motions (str or {\"poses\": [...]}), not " +
                         short_repr(motions));
  std::vector<c4::Motion> out;
  for (py::handle m : py::tuple(py::reinterpret_borrow<py::sequence>(motions)))
    out.push_back(motion(m, "motions[" + std::to_string(out.size()) + "]", s.file()));
  return out;
}

py::dict check(py::handle scene, const std::string& number, const std::string& semantics, bool earliest,
               bool all_pairs, double tolerance, py::handle motions, double max_seconds)
{
  c4::Check_options o;
  o.number = c4::number_from_name(number);
  o.semantics = c4::semantics_from_name(semantics);
  o.earliest = earliest;
  o.all_pairs = all_pairs;
  o.tolerance = tolerance;
  o.max_seconds = max_seconds;
  c4::Scene s = read_scene(scene);
  std::optional<std::vector<c4::Motion>> moved = motions_of(motions, s, "check");
  c4::Check_result r = interruptible([&](const std::atomic<bool>* cancel) {
    c4::Check_options run = o;
    run.cancel = cancel;
    return moved ? c4::check(s, *moved, run) : c4::check(s, run);
  });
  py::dict out;
  out["collide"] = r.collide;
  out["number"] = c4::name(r.number);
  out["semantics"] = c4::name(r.semantics);
  if (const c4::Colliding_pair* main = r.reported()) {
    out["witness"] = witness_dict(*main);
    if (main->earliest) out["earliest"] = earliest_dict(*main);
  }
  py::list pairs;
  for (const auto& p : r.pairs) {
    py::dict e;
    e["objects"] = py::make_tuple(p.a, p.b);
    e["witness"] = witness_dict(p);
    if (p.earliest) e["earliest"] = earliest_dict(p);
    pairs.append(e);
  }
  out["pairs"] = pairs;
  return out;
}

py::object located(const std::optional<c4::Located>& l)
{
  if (!l) return py::none();
  py::dict d;
  d["objects"] = py::make_tuple(l->objects[0], l->objects[1]);
  d["point"] = l->point ? py::object(point(*l->point)) : py::none();
  if (l->t) d["t"] = fraction(*l->t);
  // The comparer's text: also where a turning scene's exact t* is irrational.
  if (!l->t_text.empty()) d["t_text"] = l->t_text;
  if (!l->point_text[0].empty()) d["point_text"] = py::make_tuple(l->point_text[0], l->point_text[1], l->point_text[2], l->point_text[3]);
  return d;
}

template <class T>
py::object optional(const std::optional<T>& x)
{
  return x ? py::cast(*x) : py::none();
}

py::dict compare(py::handle scene, const std::string& semantics, const std::vector<double>& tolerances, bool earliest,
                 bool rounded, bool fcl, bool bullet, py::handle motions, double max_seconds)
{
  c4::Compare_options o;
  o.semantics = c4::semantics_from_name(semantics);
  o.tolerances = tolerances;
  o.earliest = earliest;
  o.rounded = rounded;
  o.fcl = fcl;
  o.bullet = bullet;
  o.max_seconds = max_seconds;
  c4::Scene s = read_scene(scene);
  std::optional<std::vector<c4::Motion>> moved = motions_of(motions, s, "compare");
  c4::Comparison c = interruptible([&](const std::atomic<bool>* cancel) {
    c4::Compare_options run = o;
    run.cancel = cancel;
    return moved ? c4::compare(s, *moved, run) : c4::compare(s, run);
  });
  py::dict out;
  out["file"] = c.file;
  out["name"] = c.name;
  out["agree"] = c.agree();
  out["closed_touch"] = optional(c.closed_touch);
  py::list rows;
  for (const c4::Subject_row& r : c.subjects) {
    py::dict d;
    d["subject"] = r.subject;
    d["semantics"] = r.semantics;
    d["tolerance"] = optional(r.tolerance);
    d["reference"] = r.reference;
    d["ok"] = r.ok;
    d["error"] = r.error;
    d["skipped"] = optional(r.skipped);
    d["collide"] = optional(r.collide);
    d["witness"] = located(r.witness);
    d["witness_valid"] = optional(r.witness_valid);
    d["earliest"] = located(r.earliest);
    d["t_error"] = optional(r.t_error);
    d["agrees"] = optional(r.agrees);
    d["cause"] = optional(r.cause);
    rows.append(d);
  }
  out["subjects"] = rows;
  py::list dis;
  for (const c4::Disagreement& d : c.disagreements) {
    py::dict e;
    e["subject"] = d.subject;
    e["cause"] = d.cause;
    e["detail"] = d.detail;
    e["semantics"] = d.semantics;
    dis.append(e);
  }
  out["disagreements"] = dis;
  return out;
}

py::dict validate(py::handle scene)
{
  c4::Scene s = read_scene(scene);
  py::dict out;
  out["name"] = s.name();
  out["time"] = py::make_tuple(fraction(s.t_lo()), fraction(s.t_hi()));
  out["objects"] = s.object_names();
  return out;
}

// ---------------------------------------------------------------- CCD

// Four vertices [[x, y, z], ...] at one time.
std::array<c4::Vec3, 4> vertices(py::handle v, const std::string& place)
{
  std::array<c4::Vec3, 4> out;
  std::vector<py::handle> points = items(v, 4, "points", place);
  for (std::size_t i = 0; i < 4; ++i) {
    std::string at = place + "[" + std::to_string(i) + "]";
    std::vector<py::handle> xyz = items(points[i], 3, "numbers", at);
    for (std::size_t k = 0; k < 3; ++k) out[i][k] = exact_number(xyz[k], at + "[" + std::to_string(k) + "]");
  }
  return out;
}

// A batch's query: (t0, t1), or a dict as a JSON line of `clash4d ccd`
// ({"t0", "t1"} and optionally "type", which must be the batch's, and
// "label" and "meta", not read).
c4::Ccd_query ccd_query(py::handle q, c4::Ccd_type type, const std::string& place)
{
  if (!py::isinstance<py::dict>(q)) {
    std::vector<py::handle> ends = items(q, 2, "items (t0, t1) or a dict {\"t0\", \"t1\"}", place);
    return {vertices(ends[0], place + ".t0"), vertices(ends[1], place + ".t1")};
  }
  py::dict d = py::reinterpret_borrow<py::dict>(q);
  for (auto item : d) {
    std::string key = py::isinstance<py::str>(item.first) ? item.first.cast<std::string>() : "";
    if (key != "t0" && key != "t1" && key != "type" && key != "label" && key != "meta")
      bad_input(ccd_file, place, "unknown key " + std::string(py::repr(item.first)) + " (t0, t1, type, label, meta)");
  }
  for (const char* key : {"t0", "t1"})
    if (!d.contains(key)) bad_input(ccd_file, place, std::string("missing \"") + key + "\"");
  if (d.contains("type")) {
    py::object t = d["type"];
    if (!py::isinstance<py::str>(t) || t.cast<std::string>() != c4::name(type))
      bad_input(ccd_file, place + ".type", std::string(py::repr(t)) + " is not the batch's type \"" + c4::name(type) + "\"");
  }
  return {vertices(d["t0"], place + ".t0"), vertices(d["t1"], place + ".t1")};
}

c4::Ccd_options ccd_options(const std::string& number, bool earliest, py::handle separation, double tolerance)
{
  c4::Ccd_options o;
  o.number = c4::number_from_name(number);
  o.earliest = earliest;
  if (!separation.is_none()) o.separation = exact_number(separation, "separation");
  o.tolerance = tolerance;
  return o;
}

// The form of a `clash4d ccd --json` line, without its index.
py::dict ccd_dict(const c4::Ccd_result& r, bool earliest)
{
  py::dict out;
  out["collide"] = r.collide;
  if (!earliest) return out;
  out["t"] = r.t ? algebraic(*r.t) : py::none();
  if (r.t) out["uv"] = py::make_tuple(algebraic(*r.u), algebraic(*r.v));
  return out;
}

py::dict ccd_one(c4::Ccd_type type, py::handle t0, py::handle t1, const std::string& number, bool earliest,
                 py::handle separation, double tolerance)
{
  c4::Ccd_options o = ccd_options(number, earliest, separation, tolerance);
  c4::Ccd_query q{vertices(t0, "t0"), vertices(t1, "t1")};
  c4::Ccd_result r;
  {
    py::gil_scoped_release release;
    r = c4::ccd(type, q, o);
  }
  return ccd_dict(r, earliest);
}

py::list ccd_batch(py::iterable queries, const std::string& type_name, const std::string& number, bool earliest,
                   py::object separation, double tolerance, double max_seconds)
{
  c4::Ccd_type type = c4::ccd_type_from_name(type_name);
  c4::Ccd_options o = ccd_options(number, earliest, separation, tolerance);
  o.max_seconds = max_seconds;
  std::vector<c4::Ccd_query> qs;
  for (py::handle q : queries) qs.push_back(ccd_query(q, type, "queries[" + std::to_string(qs.size()) + "]"));
  std::vector<c4::Ccd_result> rs = interruptible([&](const std::atomic<bool>* cancel) {
    c4::Ccd_options run = o;
    run.cancel = cancel;
    return c4::ccd_batch(type, qs, run);
  });
  py::list out;
  for (const c4::Ccd_result& r : rs) out.append(ccd_dict(r, earliest));
  return out;
}

// An exact Python number as a c4::Rational (int, Fraction, finite float or
// Decimal), for comparisons; none for anything else.
std::optional<c4::Rational> comparable(py::handle v)
{
  if (py::isinstance<py::bool_>(v)) return c4::Rational(v.cast<bool>() ? 1 : 0);   // as Python's int
  std::optional<std::string> text;
  try {
    text = number_text(v, ccd_file, "");
  } catch (const c4::Input_error&) {   // inf, nan: compared by the caller
  }
  if (!text) return std::nullopt;
  return c4::Rational(*text);
}

// a <op> b for a clash4d.Algebraic and another number, op on compare's
// -1, 0, 1: exact with an Algebraic, an int, a Fraction or a float (its
// exact value; +-inf beyond every number, and nan unordered: the answer is
// if_nan); NotImplemented for anything else.
template <class Op>
py::object compared(const c4::Algebraic& a, py::handle b, Op op, bool if_nan = false)
{
  if (py::isinstance<c4::Algebraic>(b)) return py::bool_(op(c4::compare(a, b.cast<const c4::Algebraic&>())));
  if (std::optional<c4::Rational> q = comparable(b)) return py::bool_(op(c4::compare(a, *q)));
  if (py::isinstance<py::float_>(b)) {
    double x = b.cast<double>();
    return py::bool_(std::isnan(x) ? if_nan : op(x > 0 ? -1 : 1));
  }
  return py::reinterpret_borrow<py::object>(Py_NotImplemented);
}

} // namespace

// The compiled half of the package clash4d (bindings/python/clash4d/__init__.py
// wraps it: typed answers); its names keep the package's "clash4d." prefix.
PYBIND11_MODULE(_core, m)
{
  m.doc() = module_doc;
  m.attr("__version__") = c4::version();
  m.attr("EXIT_INVALID") = c4::exit_invalid;
  m.attr("EXIT_LIMIT") = c4::exit_limit;

  input_error_type = PyErr_NewExceptionWithDoc(
      "clash4d.InputError",
      "Invalid input: a scene that is not valid, cannot be read, or needs more than a named limit allows.\n"
      "Attributes: file, place (e.g. 'objects[1].shape.block.min'; may be ''), message, exit_code\n"
      "(EXIT_INVALID = 2 or EXIT_LIMIT = 3, the command line's exit status). str(e) is 'file: place: message'.",
      PyExc_ValueError, nullptr);
  m.attr("InputError") = py::reinterpret_borrow<py::object>(input_error_type);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const c4::Input_error& e) {
      py::object err = py::reinterpret_borrow<py::object>(input_error_type)(e.what());
      err.attr("file") = e.file();
      err.attr("place") = e.place();
      err.attr("message") = e.message();
      err.attr("exit_code") = e.exit_code();
      PyErr_SetObject(input_error_type, err.ptr());
    }
  });

  py::class_<c4::Scene>(m, "Scene", R"(A scene read and validated once: Scene(scene), scene a dict or a path.
Passed to check in place of the dict or path, its first exact check prepares
it (model, bounds, pairs) and the next exact checks reuse that, with the
scene's motions or with others (check(..., motions=[...])): the same
answers, faster. Attributes: name, file, time (t_lo, t_hi), objects (names).)")
      .def(py::init([](py::handle scene, const std::vector<std::string>& allow_mesh_path) {
             return read_scene(scene, allow_mesh_path);
           }),
           py::arg("scene"), py::kw_only(), py::arg("allow_mesh_path") = std::vector<std::string>{})
      .def_property_readonly("name", &c4::Scene::name)
      .def_property_readonly("file", &c4::Scene::file)
      .def_property_readonly("time", [](const c4::Scene& s) { return py::make_tuple(fraction(s.t_lo()), fraction(s.t_hi())); })
      .def_property_readonly("objects", &c4::Scene::object_names);
  m.def("check", &check, py::arg("scene"), py::arg("number") = "exact", py::arg("semantics") = "regularised",
        py::arg("earliest") = false, py::arg("all_pairs") = false, py::arg("tolerance") = 0.0,
        py::arg("motions") = py::none(), py::kw_only(), py::arg("max_seconds") = 0.0,
        R"(Decides whether any pair of objects collides (`clash4d check`).

number: "exact" (filtered exact, the default), "rational" (every sign in
rationals) or "double" (plain doubles; its numbers are the exact values of
the shortest decimals of the doubles). semantics: "regularised" (touching is
not a collision) or "closed" (touching counts). earliest: also the earliest
collision (closed: first contact) time t and a contact point. all_pairs:
every colliding pair, not only the first. tolerance: double only.
motions: a motion per object, in scene order, in place of the scene's own
(the same shapes moving otherwise): a ROBMOD string or a dict {"poses":
[...]}; with a clash4d.Scene, exact keeps its preparation across such
checks (not with poses). A bad motion raises clash4d.InputError at place
"motions[i]" (or "motions[i].poses[j]..."); a count that is not the
scene's, ValueError.
Scenes where some object turns (pose motions with rotation) are decided by
time slices, as `clash4d check` does, with number "exact" or "rational":
number "double" raises clash4d.InputError (EXIT_INVALID) at the first
turning object's motion, and so does a degenerate case this release
cannot decide (its message says "not decided: ..."); too large a system of
polynomials, EXIT_LIMIT.
max_seconds (keyword only): a time limit on the check, as `clash4d check
--max-seconds` (0, the default: none; the scene's reading is not counted):
past it the check stops with no answer and raises clash4d.InputError with
place "max_seconds" and exit_code EXIT_LIMIT. Negative: ValueError.
Ctrl-C (KeyboardInterrupt, or any exception a signal handler raises) stops
the check within about 50 ms plus one step of its search, and is raised.

Returns {"collide": bool, "number", "semantics",
 "witness": {"objects": (a, b), "point": [x, y, z, t], "verified": bool},   # when collide
 "earliest": {"objects", "t", "point": [x, y, z], "at_start", "inside"},    # with earliest
 "pairs": [{"objects", "witness", "earliest"}, ...]}                           # pairs found
with every number a fractions.Fraction, or a clash4d.Algebraic where it is
irrational (t, point and a closed witness, with rotation only). With
rotation there are no "inside" points (the key is absent).)");
  m.def("compare", &compare, py::arg("scene"), py::arg("semantics") = "regularised",
        py::arg("tolerances") = std::vector<double>{1e-9}, py::arg("earliest") = false, py::arg("rounded") = true,
        py::arg("fcl") = false, py::arg("bullet") = false, py::kw_only(), py::arg("motions") = py::none(),
        py::arg("max_seconds") = 0.0,
        R"(Runs every subject (double, double with each tolerance, exact on the rounded
scene, optionally fcl and bullet) and holds each against the exact answer in
its own semantics (`clash4d compare`). Returns {"file", "name", "agree",
"closed_touch", "subjects": [{"subject", "semantics", "collide", "witness",
"witness_valid", "earliest", "t_error", "agrees", "cause", "skipped", ...}],
"disagreements": [{"subject", "cause", "detail", "semantics"}]}.
motions (keyword only): a motion per object in place of the scene's, as
for check; every subject sees the moved scene. max_seconds and Ctrl-C as
for check.)");
  m.def("validate", &validate, py::arg("scene"),
        "Raises clash4d.InputError when the scene is not valid; else returns {\"name\", \"time\": (t_lo, t_hi), "
        "\"objects\": [names]}.");
  m.def("scene_json", [](py::handle scene) { return read_scene(scene).to_json(); }, py::arg("scene"),
        "The scene (validated) as scene-format JSON text, every number an exact string.");

  py::class_<c4::Algebraic>(m, "Algebraic", R"(An irrational real algebraic number, exactly: the one root of its minimal
polynomial in an open interval. CCD answers (t, u, v) and, with rotation,
check's t*, contact points and closed witnesses are these where they are
not rational (rationals come as fractions.Fraction). Not made from Python.

    t.poly       # [-1, 0, 8]: the minimal polynomial 8x^2 - 1, integer coefficients, constant term first
    t.between    # (Fraction(0, 1), Fraction(1, 1)): the only root of poly in that open interval
    t.approx     # '0.3535533905932738': the shortest decimal of the nearest double
    float(t)     # 0.3535533905932738
    Fraction(7, 20) < t < Fraction(9, 25)   # exact comparisons with int, Fraction, float
                                            # (its exact value) and other Algebraic numbers
    repr(t)      # 'Algebraic(root of 8x^2 - 1 in (0, 1) ~ 0.3535533905932738)')")
      .def_property_readonly("poly",
                             [](const c4::Algebraic& x) {
                               py::list out;
                               for (const std::string& c : x.polynomial()) out.append(py::int_(py::str(c)));
                               return out;
                             },
                             "The minimal polynomial's integer coefficients, constant term first (the last one positive).")
      .def_property_readonly("between",
                             [](const c4::Algebraic& x) {
                               std::array<c4::Rational, 2> b = x.between();
                               return py::make_tuple(fraction(b[0]), fraction(b[1]));
                             },
                             "(lo, hi), Fractions: the open interval holding this root of poly and no other.")
      .def_property_readonly("approx", &c4::Algebraic::approx,
                             "The shortest decimal that reads back to the nearest double (a str).")
      .def("__float__", &c4::Algebraic::to_double)
      .def("__eq__", [](const c4::Algebraic& a, py::handle b) { return compared(a, b, [](int c) { return c == 0; }); })
      .def("__ne__", [](const c4::Algebraic& a, py::handle b) { return compared(a, b, [](int c) { return c != 0; }, true); })
      .def("__lt__", [](const c4::Algebraic& a, py::handle b) { return compared(a, b, [](int c) { return c < 0; }); })
      .def("__le__", [](const c4::Algebraic& a, py::handle b) { return compared(a, b, [](int c) { return c <= 0; }); })
      .def("__gt__", [](const c4::Algebraic& a, py::handle b) { return compared(a, b, [](int c) { return c > 0; }); })
      .def("__ge__", [](const c4::Algebraic& a, py::handle b) { return compared(a, b, [](int c) { return c >= 0; }); })
      .def("__hash__",   // equal numbers have one minimal polynomial
           [](const c4::Algebraic& x) {
             if (x.is_rational()) return py::hash(fraction(x.rational()));
             py::list poly;
             for (const std::string& c : x.polynomial()) poly.append(py::int_(py::str(c)));
             return py::hash(py::tuple(poly));
           })
      .def("__repr__", [](const c4::Algebraic& x) { return "Algebraic(" + x.text() + ")"; })
      .def("__str__", &c4::Algebraic::text);

  const char* const ccd_doc_tail = R"(

number: "exact" (the default), "rational" (the reference; the same answers)
or "double" (plain doubles: its numbers are the exact values of the
shortest decimals of the doubles). earliest (default True): also t*, the
first time of contact, and the contact's (u, v). separation: a minimum
separation D >= 0 (any exact number): the query collides when the closed
primitives come within distance D, and (u, v) are then a closest pair's.
tolerance: double only.

Numbers are read exactly: int, fractions.Fraction, str ("1/3", "0.1" is
1/10) and float or decimal.Decimal by their exact value. A point that is
not 3 numbers, a time that is not 4 points or a number that is not one
raises clash4d.InputError (file "<query>", place e.g. "t0[1][2]": vertex 1,
coordinate z at t = 0).

Returns {"collide": bool, "t": t*, "uv": (u, v)}, as a line of `clash4d
ccd --json` (without its index): with earliest, "t" is None when it does
not collide, and "uv" is there when it does. A number is a
fractions.Fraction when rational, else a clash4d.Algebraic.)";
  auto ccd_def = [&](const char* function, c4::Ccd_type type, const std::string& doc) {
    m.def(function,
          [type](py::object t0, py::object t1, const std::string& number, bool earliest, py::object separation,
                 double tolerance) { return ccd_one(type, t0, t1, number, earliest, separation, tolerance); },
          py::arg("t0"), py::arg("t1"), py::kw_only(), py::arg("number") = "exact", py::arg("earliest") = true,
          py::arg("separation") = py::none(), py::arg("tolerance") = 0.0, (doc + ccd_doc_tail).c_str());
  };
  ccd_def("ccd_vertex_face", c4::Ccd_type::vertex_face,
          R"(A CCD vertex-face query (docs/ccd-queries.md; closed: touching counts).

    clash4d.ccd_vertex_face(t0=[p, a, b, c], t1=[p, a, b, c])

t0 holds the vertex p and the triangle a, b, c at t = 0, t1 the same four
at t = 1, each point [x, y, z]; each moves linearly between them. It
collides when p(t) = a(t) + u (b(t) - a(t)) + v (c(t) - a(t)) for some t
in [0, 1], u, v >= 0, u + v <= 1.

    r = clash4d.ccd_vertex_face([[F(1, 4), F(1, 4), 1], [0, 0, 0], [1, 0, 0], [0, 1, 0]],
                                [[F(1, 4), F(1, 4), -1], [0, 0, 0], [1, 0, 0], [0, 1, 0]])
    r == {"collide": True, "t": F(1, 2), "uv": (F(1, 4), F(1, 4))})");
  ccd_def("ccd_edge_edge", c4::Ccd_type::edge_edge,
          R"(A CCD edge-edge query (docs/ccd-queries.md; closed: touching counts).

    clash4d.ccd_edge_edge(t0=[a0, a1, b0, b1], t1=[a0, a1, b0, b1])

t0 holds the edges a0 a1 and b0 b1 at t = 0, t1 the same four vertices at
t = 1, each point [x, y, z]; each moves linearly between them. It collides
when a0(t) + u (a1(t) - a0(t)) = b0(t) + v (b1(t) - b0(t)) for some t, u,
v in [0, 1].)");
  m.def("ccd_batch", &ccd_batch, py::arg("queries"), py::arg("type") = "vertex-face", py::kw_only(),
        py::arg("number") = "exact", py::arg("earliest") = true, py::arg("separation") = py::none(),
        py::arg("tolerance") = 0.0, py::arg("max_seconds") = 0.0,
        R"(Many CCD queries of one type, decided in parallel (the GIL released):
a list of answers in the queries' order, each as ccd_vertex_face's.

queries: an iterable of (t0, t1) pairs, or of dicts in the form of a JSON
line of `clash4d ccd` ({"t0": [...], "t1": [...]}, optionally "type",
which must be the batch's, and "label" and "meta", not read). type:
"vertex-face" (or "vf", the default) or "edge-edge" ("ee"). number,
earliest, separation and tolerance as for ccd_vertex_face. Every query is
read before any is decided; bad input raises clash4d.InputError at place
"queries[j].t0[i][k]". max_seconds (looked at once per query) and Ctrl-C
as for check.)");
}
