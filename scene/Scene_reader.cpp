#include "scene/Scene_reader.h"
#include "geometry/Polytope_ft.h"
#include "scene/Exact_validation.h"
#include "scene/Hull_solid.h"
#include "scene/Mesh_solid.h"
#include "scene/Input_error.h"
#include "scene/Json_fields.h"
#include "scene/Json_reader.h"
#include "scene/Number_text.h"
#include "scene/Pose_motion.h"
#include "scene/Scene_builder.h"

#include <filesystem>
#include <map>
#include <set>
#include <sstream>

namespace clash4d {

const char* solid_key(Solid::Kind k)
{
  switch (k) {
    case Solid::Kind::Halfspace: return "halfspace";
    case Solid::Kind::Block: return "block";
    case Solid::Kind::Convex: return "convex";
    case Solid::Kind::Prism: return "prism";
    case Solid::Kind::Hull: return "hull";
    case Solid::Kind::Union: return "union";
    case Solid::Kind::Intersection: return "intersection";
    case Solid::Kind::Difference: return "difference";
    case Solid::Kind::Translate: return "translate";
    case Solid::Kind::Rotate: return "rotate";
  }
  return "?";
}

namespace {

using Kind = Json_value::Kind;

using namespace json_field;

// What one read of a scene shares: the directory mesh paths are relative to,
// the folders a mesh file may be in (that directory and the user's
// --allow-mesh-path folders, canonical), and each mesh file's solid, made
// once however often the file is used.
struct Reader_context {
  std::filesystem::path base;
  std::vector<std::filesystem::path> allowed;
  std::map<std::string, Solid> meshes;   // by canonical path and options
  std::vector<Mesh_record> records;      // Scene::meshes, in the order first used
};

// The path with its links resolved as far as it exists, absolute.
std::filesystem::path resolved(const std::filesystem::path& p)
{
  std::error_code ec;
  std::filesystem::path r = std::filesystem::weakly_canonical(std::filesystem::absolute(p, ec), ec);
  return ec ? std::filesystem::absolute(p, ec).lexically_normal() : r;
}

bool is_under(const std::filesystem::path& file, const std::filesystem::path& folder)
{
  auto f = file.begin();
  for (auto d = folder.begin(); d != folder.end(); ++d, ++f)
    if (!d->empty() && (f == file.end() || *f != *d)) return false;
  return true;
}

// docs/meshes.md, "Where a mesh file may be": a scene reaches only files
// under its own folder, links resolved (an absolute path, a "../" or a link
// out of the folder is refused), unless the user allowed another folder.
void check_mesh_place(const std::filesystem::path& file, const std::string& name, const std::string& path,
                      const Reader_context& ctx)
{
  for (const auto& folder : ctx.allowed)
    if (is_under(file, folder)) return;
  throw Input_error(path, "the mesh file \"" + name + "\" is outside the scene's folder " +
                              ctx.allowed.front().string() +
                              " (a scene reaches only files under its folder; --allow-mesh-path DIR allows another)");
}

Solid read_solid(const Json_value& v, const std::string& path, Reader_context& ctx);

void read_children(const Json_value& list, Solid& s, std::size_t min_count, const std::string& path, Reader_context& ctx)
{
  expect_kind(list, Kind::Array, path);
  if (list.items.size() < min_count)
    throw Input_error(path, "expected at least " + std::to_string(min_count) + " solid" + (min_count > 1 ? "s" : "") +
                                ", found " + std::to_string(list.items.size()));
  for (std::size_t i = 0; i < list.items.size(); ++i) s.children.push_back(read_solid(list.items[i], at(path, i), ctx));
}

void read_block(const Json_value& v, Solid& s, const std::string& path)
{
  expect_kind(v, Kind::Object, path);
  expect_keys(v, {"min", "max"}, path);
  auto lo = read_array<3>(required(v, "min", path), dot(path, "min"));
  auto hi = read_array<3>(required(v, "max", path), dot(path, "max"));
  const char* axis = "xyz";
  for (int k = 0; k < 3; ++k)
    if (!(lo[k] < hi[k]))
      throw Input_error(path, std::string("min must be less than max on every axis (") + axis[k] +
                                  ": " + to_string(lo[k]) + " >= " + to_string(hi[k]) + ")");
  s.numbers.assign(lo.begin(), lo.end());
  s.numbers.insert(s.numbers.end(), hi.begin(), hi.end());
}

void read_halfspace(const Json_value& v, Solid& s, const std::string& path)
{
  auto h = read_array<4>(v, path);
  if (CGAL::is_zero(h[0]) && CGAL::is_zero(h[1]) && CGAL::is_zero(h[2]))
    throw Input_error(path, "normal (a,b,c) must not be all zero");
  s.numbers.assign(h.begin(), h.end());
}

void read_convex(const Json_value& v, Solid& s, const std::string& path)
{
  expect_kind(v, Kind::Array, path);
  if (v.items.size() > CLASH4D_MAX_CONVEX_HALFSPACES)
    throw Input_error(path, "more than the limit of " + std::to_string(CLASH4D_MAX_CONVEX_HALFSPACES) + " half-spaces", CLASH4D_EXIT_LIMIT);
  std::vector<Rational4> planes;
  for (std::size_t i = 0; i < v.items.size(); ++i) {
    Solid h;
    read_halfspace(v.items[i], h, at(path, i));
    planes.push_back({h.numbers[0], h.numbers[1], h.numbers[2], h.numbers[3]});
    s.numbers.insert(s.numbers.end(), h.numbers.begin(), h.numbers.end());
  }
  if (planes.size() < 4) throw Input_error(path, "a bounded convex solid needs at least 4 half-spaces, found " + std::to_string(planes.size()));
  std::string problem = convex_problem(planes);
  if (!problem.empty()) throw Input_error(path, problem);
  Polytope_combinatorics c = convex_vertex_triples(planes);
  s.triples = c.triples;
  s.corners = c.corners.empty() ? nullptr : std::make_shared<const Corners>(std::move(c.corners));
  for (const auto& t : s.triples) {
    Rational3 v = vertex_of(planes[t[0]], planes[t[1]], planes[t[2]]);
    s.constructed.insert(s.constructed.end(), v.begin(), v.end());
  }
}

void read_prism(const Json_value& v, Solid& s, const std::string& path)
{
  expect_kind(v, Kind::Object, path);
  expect_keys(v, {"base", "z"}, path);
  const Json_value& base = required(v, "base", path);
  std::string base_path = dot(path, "base");
  expect_kind(base, Kind::Array, base_path);
  if (base.items.size() > CLASH4D_MAX_HULL_POINTS)
    throw Input_error(base_path, "more than the limit of " + std::to_string(CLASH4D_MAX_HULL_POINTS) + " vertices", CLASH4D_EXIT_LIMIT);
  std::vector<std::array<Rational, 2>> polygon;
  for (std::size_t i = 0; i < base.items.size(); ++i) polygon.push_back(read_array<2>(base.items[i], at(base_path, i)));
  std::string problem = prism_base_problem(polygon);
  if (!problem.empty()) throw Input_error(base_path, problem);
  auto z = read_array<2>(required(v, "z", path), dot(path, "z"));
  if (!(z[0] < z[1])) throw Input_error(dot(path, "z"), "z0 must be less than z1");
  for (const auto& p : polygon) s.numbers.insert(s.numbers.end(), p.begin(), p.end());
  s.numbers.insert(s.numbers.end(), z.begin(), z.end());
}

void read_hull(const Json_value& v, Solid& s, const std::string& path)
{
  expect_kind(v, Kind::Array, path);
  if (v.items.size() > CLASH4D_MAX_HULL_POINTS)
    throw Input_error(path, "more than the limit of " + std::to_string(CLASH4D_MAX_HULL_POINTS) + " points", CLASH4D_EXIT_LIMIT);
  std::vector<Rational3> points;
  for (std::size_t i = 0; i < v.items.size(); ++i) points.push_back(read_array<3>(v.items[i], at(path, i)));
  try {
    make_hull_solid(points, s);
  } catch (const std::invalid_argument& e) {
    throw Input_error(path, e.what());
  }
}

void set_paths(Solid& s, const std::string& path)
{
  s.path = path;
  for (std::size_t i = 0; i < s.children.size(); ++i) set_paths(s.children[i], at(path, i));
}

// {"mesh": "FILE", options...}: a hull or a union of hulls
// (scene/Mesh_solid.h), scaled and repaired as the options say.
Solid read_mesh_body(const Json_value& v, const Mesh_options& options, const std::string& path, Reader_context& ctx)
{
  expect_kind(v, Kind::String, path);
  if (v.text.empty()) throw Input_error(path, "the mesh file name must not be empty");
  namespace fs = std::filesystem;
  fs::path file = fs::path(v.text).is_absolute() ? fs::path(v.text) : ctx.base / v.text;
  fs::path canonical = resolved(file);
  check_mesh_place(canonical, v.text, path, ctx);
  std::string key = canonical.string() + "\n" + options.key();
  auto found = ctx.meshes.find(key);
  if (found == ctx.meshes.end()) {
    try {
      Mesh_record record;
      record.file = v.text;
      record.place = path;
      Mesh_limits limits;
      limits.pieces = options.max_pieces;
      found = ctx.meshes.emplace(key, read_mesh_solid(file.string(), v.text, options, record, limits)).first;
      ctx.records.push_back(std::move(record));
    } catch (const Input_error& e) {
      throw Input_error(path, e.place() + ": " + e.what(), e.exit_code());
    } catch (const std::bad_alloc&) {
      throw Input_error(path, v.text + ": out of memory", CLASH4D_EXIT_LIMIT);
    } catch (const std::exception& e) {
      // A failure of CGAL on a mesh the checks accepted is ours: exit 4, the
      // internal error status of cli/Commands.cpp, with CGAL's message.
      throw Input_error(path, v.text + ": internal error making the solid: " + e.what(), 4);
    }
  }
  Solid s = found->second;
  set_paths(s, path);
  return s;
}

Solid read_solid(const Json_value& v, const std::string& path, Reader_context& ctx)
{
  expect_kind(v, Kind::Object, path);
  static const std::pair<const char*, Solid::Kind> kinds[] = {
      {"halfspace", Solid::Kind::Halfspace}, {"block", Solid::Kind::Block}, {"convex", Solid::Kind::Convex},
      {"prism", Solid::Kind::Prism}, {"hull", Solid::Kind::Hull}, {"union", Solid::Kind::Union},
      {"intersection", Solid::Kind::Intersection}, {"difference", Solid::Kind::Difference},
      {"translate", Solid::Kind::Translate}, {"rotate", Solid::Kind::Rotate}, {"mesh", Solid::Kind::Hull}};
  Solid s;
  s.path = path;
  const Json_value* body = nullptr;
  std::string key;
  for (const auto& m : v.members) {
    for (const auto& k : kinds) {
      if (m.first != k.first) continue;
      if (body) throw Input_error(path, "a solid has exactly one kind, found \"" + key + "\" and \"" + m.first + "\"");
      body = &m.second;
      key = m.first;
      s.kind = k.second;
    }
  }
  if (!body) {
    if (v.members.empty()) throw Input_error(path, "empty solid: expected one of halfspace, block, convex, prism, hull, mesh, union, intersection, difference, translate, rotate");
    throw Input_error(path, "unknown solid \"" + v.members.front().first + "\" (expected halfspace, block, convex, prism, hull, mesh, union, intersection, difference, translate or rotate)");
  }
  std::string body_path = dot(path, key);
  if (key == "mesh") return read_mesh_body(*body, read_mesh_options(v, path), body_path, ctx);
  bool transform = s.kind == Solid::Kind::Translate || s.kind == Solid::Kind::Rotate;
  if (transform) expect_keys(v, {key.c_str(), "solid"}, path);
  else expect_keys(v, {key.c_str()}, path);
  switch (s.kind) {
    case Solid::Kind::Halfspace: read_halfspace(*body, s, body_path); break;
    case Solid::Kind::Block: read_block(*body, s, body_path); break;
    case Solid::Kind::Convex: read_convex(*body, s, body_path); break;
    case Solid::Kind::Prism: read_prism(*body, s, body_path); break;
    case Solid::Kind::Hull: read_hull(*body, s, body_path); break;
    case Solid::Kind::Union:
    case Solid::Kind::Intersection: read_children(*body, s, 1, body_path, ctx); break;
    case Solid::Kind::Difference: read_children(*body, s, 2, body_path, ctx); break;
    case Solid::Kind::Translate: {
      auto d = read_array<3>(*body, body_path);
      s.numbers.assign(d.begin(), d.end());
      s.children.push_back(read_solid(required(v, "solid", path), dot(path, "solid"), ctx));
      break;
    }
    case Solid::Kind::Rotate: {
      auto q = read_array<4>(*body, body_path);
      if (CGAL::is_zero(q[0]) && CGAL::is_zero(q[1]) && CGAL::is_zero(q[2]) && CGAL::is_zero(q[3]))
        throw Input_error(body_path, "the quaternion must not be zero");
      s.numbers.assign(q.begin(), q.end());
      s.constructed = rotation_rows(q);   // its matrix once, exactly, for the kernels that read it
      s.children.push_back(read_solid(required(v, "solid", path), dot(path, "solid"), ctx));
      break;
    }
  }
  return s;
}

std::vector<std::string> tokens_of(const std::string& text)
{
  std::istringstream in(text);
  std::vector<std::string> out;
  std::string t;
  while (in >> t) out.push_back(t);
  return out;
}

} // namespace

Motion parse_motion(const std::string& text, const std::string& place)
{
  // Grammar: segment ("until" T segment)*, segment = "rest" | "vel" vx vy vz.
  std::vector<std::string> tok = tokens_of(text);
  Motion m;
  std::size_t i = 0;
  auto where = [&](std::size_t k) { return " at word " + std::to_string(k + 1) + " of \"" + text + "\""; };
  auto number = [&](const std::string& what) {
    if (i >= tok.size()) throw Input_error(place, "expected " + what + where(i));
    Number_parse p = parse_number_text(tok[i], true);
    if (!p.ok) throw Input_error(place, "expected " + what + ", found '" + tok[i] + "'" + where(i) + ": " + p.error,
                                 p.limit ? CLASH4D_EXIT_LIMIT : CLASH4D_EXIT_INVALID);
    ++i;
    return p.value;
  };
  auto segment = [&]() {
    if (i >= tok.size()) throw Input_error(place, "expected \"rest\" or \"vel\"" + where(i));
    std::array<Rational, 3> v{Rational(0), Rational(0), Rational(0)};
    if (tok[i] == "rest") ++i;
    else if (tok[i] == "vel") {
      ++i;
      for (int k = 0; k < 3; ++k) v[k] = number("a velocity component");
    } else throw Input_error(place, "expected \"rest\" or \"vel\", found '" + tok[i] + "'" + where(i));
    m.velocities.push_back(v);
  };
  if (tok.empty()) throw Input_error(place, "empty motion: expected e.g. \"rest\" or \"vel 1 0 0\"");
  segment();
  while (i < tok.size()) {
    if (tok[i] != "until") throw Input_error(place, "expected \"until\", found '" + tok[i] + "'" + where(i));
    ++i;
    std::size_t at_time = i;
    Rational t = number("a time after \"until\"");
    if (!m.times.empty() && !(m.times.back() < t))
      throw Input_error(place, "times must be strictly increasing" + where(at_time));
    m.times.push_back(t);
    if (m.times.size() > CLASH4D_MAX_MOTION_SEGMENTS)
      throw Input_error(place, "more than the limit of " + std::to_string(CLASH4D_MAX_MOTION_SEGMENTS) + " motion segments", CLASH4D_EXIT_LIMIT);
    segment();
  }
  return m;
}

// {"poses": [{"t": T, "translate": [x,y,z], "rotate": [w,x,y,z]}, ...]}
// (spec: Motion with rotation (poses)), numbers read exactly; the checks
// on their values are check_poses'.
static std::vector<Pose> read_poses(const Json_value& motion, const std::string& place)
{
  expect_keys(motion, {"poses"}, place);
  std::string list_place = dot(place, "poses");
  const Json_value& list = required(motion, "poses", place);
  if (list.kind != Kind::Array || list.items.empty())
    throw Input_error(list_place, "expected a non-empty list of poses");
  if (list.items.size() > CLASH4D_MAX_POSES)
    throw Input_error(list_place, "more than the limit of " + std::to_string(CLASH4D_MAX_POSES) + " poses",
                      CLASH4D_EXIT_LIMIT);
  std::vector<Pose> poses;
  for (std::size_t i = 0; i < list.items.size(); ++i) {
    const Json_value& p = list.items[i];
    std::string pose_place = at(list_place, i);
    expect_kind(p, Kind::Object, pose_place);
    expect_keys(p, {"t", "translate", "rotate"}, pose_place);
    Pose pose;
    pose.t = read_number(required(p, "t", pose_place), dot(pose_place, "t"));
    if (const Json_value* c = p.find("translate")) pose.translate = read_array<3>(*c, dot(pose_place, "translate"));
    if (const Json_value* q = p.find("rotate")) pose.rotate = read_array<4>(*q, dot(pose_place, "rotate"));
    poses.push_back(std::move(pose));
  }
  return poses;
}

// objects[i]: a uniquely named solid with its motion (default: at rest).
static Scene_object read_object(const Json_value& o, const std::string& path, std::set<std::string>& names,
                                Reader_context& ctx)
{
  expect_kind(o, Kind::Object, path);
  expect_keys(o, {"name", "shape", "motion"}, path);
  Scene_object obj;
  const Json_value& name = required(o, "name", path);
  expect_kind(name, Kind::String, dot(path, "name"));
  if (name.text.empty()) throw Input_error(dot(path, "name"), "the name must not be empty");
  if (!names.insert(name.text).second) throw Input_error(dot(path, "name"), "duplicate object name \"" + name.text + "\"");
  obj.name = name.text;
  obj.shape = read_solid(required(o, "shape", path), dot(path, "shape"), ctx);
  if (const Json_value* motion = o.find("motion")) {
    std::string place = dot(path, "motion");
    if (motion->kind == Kind::Object) set_pose_motion(obj, read_poses(*motion, place), place);
    else if (motion->kind == Kind::String) obj.motion = parse_motion(motion->text, place);
    else throw Input_error(place, "expected a ROBMOD string or an object {\"poses\": [...]}");
  } else {
    obj.motion.velocities.push_back({Rational(0), Rational(0), Rational(0)});
  }
  return obj;
}

// ignore: pairs of names of the scene's objects, each pair of two objects.
static void read_ignore(const Json_value& ignore, Scene& scene)
{
  expect_kind(ignore, Kind::Array, "ignore");
  for (std::size_t i = 0; i < ignore.items.size(); ++i) {
    std::string path = at("ignore", i);
    const Json_value& pair = ignore.items[i];
    expect_kind(pair, Kind::Array, path);
    if (pair.items.size() != 2) throw Input_error(path, "expected a pair of object names");
    int idx[2];
    for (int k = 0; k < 2; ++k) {
      std::string p = at(path, static_cast<std::size_t>(k));
      expect_kind(pair.items[k], Kind::String, p);
      idx[k] = -1;
      for (std::size_t j = 0; j < scene.objects.size(); ++j)
        if (scene.objects[j].name == pair.items[k].text) idx[k] = static_cast<int>(j);
      if (idx[k] < 0) throw Input_error(p, "no object is named \"" + pair.items[k].text + "\"");
    }
    if (idx[0] == idx[1]) throw Input_error(path, "an object cannot be ignored against itself");
    scene.ignore.emplace_back(std::min(idx[0], idx[1]), std::max(idx[0], idx[1]));
  }
}

Scene read_scene(const Json_value& root, const std::string& base_directory,
                 const std::vector<std::string>& allowed_mesh_folders)
{
  Reader_context ctx;
  ctx.base = base_directory.empty() ? std::filesystem::path(".") : std::filesystem::path(base_directory);
  ctx.allowed.push_back(resolved(ctx.base));
  for (const std::string& folder : allowed_mesh_folders) ctx.allowed.push_back(resolved(folder));
  expect_kind(root, Kind::Object, "");
  // meta: provenance written by tools (spec), any JSON value, never read here.
  expect_keys(root, {"format", "name", "time", "objects", "ignore", "meta"}, "");
  Scene scene;
  const Json_value& format = required(root, "format", "");
  expect_kind(format, Kind::String, "format");
  if (format.text != "clash4d-scene/1")
    throw Input_error("format", "expected \"clash4d-scene/1\", found \"" + format.text + "\"");
  if (const Json_value* name = root.find("name")) {
    expect_kind(*name, Kind::String, "name");
    scene.name = name->text;
  }
  auto span = read_array<2>(required(root, "time", ""), "time");
  if (!(span[0] < span[1])) throw Input_error("time", "expected [tL, tH] with tL < tH");
  scene.t_lo = span[0];
  scene.t_hi = span[1];

  const Json_value& objects = required(root, "objects", "");
  expect_kind(objects, Kind::Array, "objects");
  if (objects.items.size() < 2)
    throw Input_error("objects", "expected at least two objects, found " + std::to_string(objects.items.size()));
  std::set<std::string> names;
  for (std::size_t i = 0; i < objects.items.size(); ++i)
    scene.objects.push_back(read_object(objects.items[i], at("objects", i), names, ctx));
  if (const Json_value* ignore = root.find("ignore")) read_ignore(*ignore, scene);
  scene.meshes = std::move(ctx.records);
  for (Scene_object& o : scene.objects) {
    approximate_numbers(o.shape);
    approximate_numbers(o.motion);
  }
  return scene;
}

void approximate_numbers(Solid& s)
{
  s.numbers_approximated = approximations(s.numbers);
  s.constructed_approximated = approximations(s.constructed);
  for (Solid& c : s.children) approximate_numbers(c);
}

void approximate_numbers(Motion& m)
{
  m.times_approximated = approximations(m.times);
  m.velocities_approximated.clear();
  m.velocities_approximated.reserve(3 * m.velocities.size());
  for (const auto& v : m.velocities)
    for (const Rational& x : v) m.velocities_approximated.emplace_back(x);
}

Scene read_scene_file(const std::string& path, const std::vector<std::string>& allowed_mesh_folders)
{
  std::string base = std::filesystem::path(path).parent_path().string();
  return read_scene(read_json_file(path), base, allowed_mesh_folders);
}

} // namespace clash4d
