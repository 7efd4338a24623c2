// The Python module `clash4d` (pybind11) on the public C++ API
// (api/clash4d/clash4d.h). A scene is a dict in the scene format or a path;
// exact numbers come back as fractions.Fraction. Documented in the module's
// docstring below and in the README ("Use it from Python").
#include <clash4d/clash4d.h>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;
namespace c4 = clash4d::api;

namespace {

const char* const module_doc = R"(clash4d: exact collision detection for moving polyhedral CSG solids.

    import clash4d
    from fractions import Fraction
    scene = {
        "format": "clash4d-scene/1", "time": [0, 10],
        "objects": [
            {"name": "a", "shape": {"block": {"min": [0, 0, 0], "max": [1, 1, 1]}}, "motion": "vel 1 0 0"},
            {"name": "b", "shape": {"block": {"min": [2, 0, 0], "max": [3, 1, 1]}}, "motion": "vel -1 0 0"},
        ],
    }
    r = clash4d.check(scene, earliest=True)
    r["collide"], r["earliest"]["t"]     # True, Fraction(1, 2)

A scene is a dict (or list/tuple-valued JSON-like structure) in the scene
format, or the path of a scene file (str or os.PathLike). Numbers in a dict
are read exactly: int, fractions.Fraction (any numbers.Rational), str
("0.1", "-2.5e-3", "1/3": the scene format's forms), and float or
decimal.Decimal by their exact value (Fraction(0.1) is
3602879701896397/36028797018963968, not 1/10: write "0.1" or Fraction(1, 10)
for a tenth). Motions are strings ("vel 1 0 0", "rest until 0 vel 1/2 0 0
until 5 rest"). Relative file paths inside a dict scene (mesh solids) are
relative to the current directory.

Answers are dicts in the form of `clash4d check --json` and
`clash4d compare --json`, with every exact number a fractions.Fraction.
Invalid input raises clash4d.InputError (a ValueError) with the attributes
file, place, message and exit_code (EXIT_INVALID = 2, EXIT_LIMIT = 3).
"Verify" (certificates) is not in the toolkit yet.)";

PyObject* input_error_type = nullptr;   // clash4d.InputError (kept for the process)

py::object fraction(const c4::Rational& r)
{
  static py::object* type = new py::object(py::module_::import("fractions").attr("Fraction"));   // never freed
  return (*type)(r.to_string());
}

py::list point(const c4::Point4& p)
{
  py::list out;
  for (const auto& x : p) out.append(fraction(x));
  return out;
}

py::list point(const c4::Vec3& p)
{
  py::list out;
  for (const auto& x : p) out.append(fraction(x));
  return out;
}

[[noreturn]] void bad_input(const std::string& file, const std::string& place, const std::string& message)
{
  throw c4::Input_error(file, place, message, c4::exit_invalid);
}

// The JSON text of a JSON-like Python value, numbers kept exact.
void write_json(py::handle v, const std::string& place, std::string& out)
{
  static py::object* json_dumps = new py::object(py::module_::import("json").attr("dumps"));
  static py::object* rational = new py::object(py::module_::import("numbers").attr("Rational"));
  static py::object* fraction_type = new py::object(py::module_::import("fractions").attr("Fraction"));
  static py::object* decimal = new py::object(py::module_::import("decimal").attr("Decimal"));
  auto exact = [&](py::handle x) {   // numbers.Rational: "p/q"
    py::int_ p = x.attr("numerator"), q = x.attr("denominator");
    out += "\"" + std::string(py::str(p)) + "/" + std::string(py::str(q)) + "\"";
  };
  if (v.is_none()) {
    out += "null";
  } else if (py::isinstance<py::bool_>(v)) {
    out += v.cast<bool>() ? "true" : "false";
  } else if (py::isinstance<py::int_>(v)) {
    out += std::string(py::str(py::int_(py::reinterpret_borrow<py::object>(v))));
  } else if (py::isinstance(v, *rational)) {
    exact(v);
  } else if (py::isinstance<py::float_>(v) || py::isinstance(v, *decimal)) {
    py::object f;
    try {
      f = (*fraction_type)(v);
    } catch (py::error_already_set&) {   // inf, nan
      bad_input("<scene>", place, "not a finite number: " + std::string(py::repr(v)));
    }
    exact(f);
  } else if (py::isinstance<py::str>(v)) {
    out += (*json_dumps)(v).cast<std::string>();
  } else if (py::isinstance<py::dict>(v)) {
    out += "{";
    bool first = true;
    for (auto item : py::reinterpret_borrow<py::dict>(v)) {
      if (!py::isinstance<py::str>(item.first))
        bad_input("<scene>", place, "a key is not a string: " + std::string(py::repr(item.first)));
      std::string key = item.first.cast<std::string>();
      out += (first ? "" : ", ") + (*json_dumps)(item.first).cast<std::string>() + ": ";
      first = false;
      write_json(item.second, place.empty() ? key : place + "." + key, out);
    }
    out += "}";
  } else if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    out += "[";
    std::size_t i = 0;
    for (auto item : v) {
      out += i ? ", " : "";
      write_json(item, place + "[" + std::to_string(i++) + "]", out);
    }
    out += "]";
  } else {
    bad_input("<scene>", place, "not a JSON value: " + std::string(py::repr(v)));
  }
}

// A clash4d.Scene is itself (its exact preparation kept); a dict is written
// as JSON and read; anything else is a path.
c4::Scene read_scene(py::handle scene)
{
  if (py::isinstance<c4::Scene>(scene)) return scene.cast<c4::Scene>();
  if (py::isinstance<py::dict>(scene)) {
    std::string text;
    write_json(scene, "", text);
    py::gil_scoped_release release;
    return c4::Scene::parse(text, "<scene>");
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
  py::gil_scoped_release release;
  return c4::Scene::read_file(file);
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
  d["t"] = fraction(e.t);
  d["point"] = point(e.point);
  d["at_start"] = e.at_start;
  d["inside"] = py::make_tuple(point(e.inside[0]), point(e.inside[1]));
  return d;
}

py::dict check(py::handle scene, const std::string& number, const std::string& semantics, bool earliest,
               bool all_pairs, double tolerance, const std::optional<std::vector<std::string>>& motions)
{
  c4::Check_options o;
  o.number = c4::number_from_name(number);
  o.semantics = c4::semantics_from_name(semantics);
  o.earliest = earliest;
  o.all_pairs = all_pairs;
  o.tolerance = tolerance;
  c4::Scene s = read_scene(scene);
  std::vector<c4::Motion> moved;
  if (motions)
    for (const std::string& m : *motions) moved.push_back(c4::Motion::from_text(m));
  c4::Check_result r;
  {
    py::gil_scoped_release release;
    r = motions ? c4::check(s, moved, o) : c4::check(s, o);
  }
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
  return d;
}

template <class T>
py::object optional(const std::optional<T>& x)
{
  return x ? py::cast(*x) : py::none();
}

py::dict compare(py::handle scene, const std::string& semantics, const std::vector<double>& tolerances, bool earliest,
                 bool rounded, bool fcl, bool bullet)
{
  c4::Compare_options o;
  o.semantics = c4::semantics_from_name(semantics);
  o.tolerances = tolerances;
  o.earliest = earliest;
  o.rounded = rounded;
  o.fcl = fcl;
  o.bullet = bullet;
  c4::Scene s = read_scene(scene);
  c4::Comparison c;
  {
    py::gil_scoped_release release;
    c = c4::compare(s, o);
  }
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

} // namespace

PYBIND11_MODULE(clash4d, m)
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
      .def(py::init([](py::handle scene) { return read_scene(scene); }), py::arg("scene"))
      .def_property_readonly("name", &c4::Scene::name)
      .def_property_readonly("file", &c4::Scene::file)
      .def_property_readonly("time", [](const c4::Scene& s) { return py::make_tuple(fraction(s.t_lo()), fraction(s.t_hi())); })
      .def_property_readonly("objects", &c4::Scene::object_names);
  m.def("check", &check, py::arg("scene"), py::arg("number") = "exact", py::arg("semantics") = "regularised",
        py::arg("earliest") = false, py::arg("all_pairs") = false, py::arg("tolerance") = 0.0,
        py::arg("motions") = py::none(),
        R"(Decides whether any pair of objects collides (`clash4d check`).

number: "exact" (filtered exact, the default), "rational" (every sign in
rationals) or "double" (plain doubles; its numbers are the exact values of
the shortest decimals of the doubles). semantics: "regularised" (touching is
not a collision) or "closed" (touching counts). earliest: also the earliest
collision (closed: first contact) time t and a contact point. all_pairs:
every colliding pair, not only the first. tolerance: double only.
motions: a motion string per object, in scene order, in place of the scene's
own (the same shapes moving otherwise); with a clash4d.Scene, exact keeps
its preparation across such checks. A bad motion raises clash4d.InputError
at place "motions[i]"; a count that is not the scene's, ValueError.

Returns {"collide": bool, "number", "semantics",
 "witness": {"objects": (a, b), "point": [x, y, z, t], "verified": bool},   # when collide
 "earliest": {"objects", "t", "point": [x, y, z], "at_start", "inside"},    # with earliest
 "pairs": [{"objects", "witness", "earliest"}, ...]}                           # pairs found
with every number a fractions.Fraction.)");
  m.def("compare", &compare, py::arg("scene"), py::arg("semantics") = "regularised",
        py::arg("tolerances") = std::vector<double>{1e-9}, py::arg("earliest") = false, py::arg("rounded") = true,
        py::arg("fcl") = false, py::arg("bullet") = false,
        R"(Runs every subject (double, double with each tolerance, exact on the rounded
scene, optionally fcl and bullet) and holds each against the exact answer in
its own semantics (`clash4d compare`). Returns {"file", "name", "agree",
"closed_touch", "subjects": [{"subject", "semantics", "collide", "witness",
"witness_valid", "earliest", "t_error", "agrees", "cause", "skipped", ...}],
"disagreements": [{"subject", "cause", "detail", "semantics"}]}.)");
  m.def("validate", &validate, py::arg("scene"),
        "Raises clash4d.InputError when the scene is not valid; else returns {\"name\", \"time\": (t_lo, t_hi), "
        "\"objects\": [names]}.");
  m.def("scene_json", [](py::handle scene) { return read_scene(scene).to_json(); }, py::arg("scene"),
        "The scene (validated) as scene-format JSON text, every number an exact string.");
}
