#include "scene/Mesh_options.h"
#include "scene/Input_error.h"
#include "scene/Json_fields.h"

#include <set>
#include <utility>

namespace clash4d {
namespace {

using namespace json_field;

// "units": the length of the file's unit in metres, exactly (an inch is
// 25.4 mm by definition, a foot 12 inches).
Rational unit_in_metres(const Json_value& v, const std::string& path)
{
  expect_kind(v, Kind::String, path);
  static const std::pair<const char*, Rational> units[] = {
      {"m", Rational(1)},        {"dm", Rational(1, 10)},        {"cm", Rational(1, 100)}, {"mm", Rational(1, 1000)},
      {"um", Rational(1, 1000000)}, {"in", Rational(127, 5000)}, {"ft", Rational(381, 1250)}};
  for (const auto& [name, factor] : units)
    if (v.text == name) return factor;
  throw Input_error(path, "unknown unit \"" + v.text + "\" (expected m, dm, cm, mm, um, in or ft)");
}

void read_repairs(const Json_value& v, const std::string& path, Mesh_options& o)
{
  expect_kind(v, Kind::Array, path);
  std::set<std::string> seen;
  for (std::size_t i = 0; i < v.items.size(); ++i) {
    const Json_value& r = v.items[i];
    expect_kind(r, Kind::String, at(path, i));
    if (!seen.insert(r.text).second) throw Input_error(at(path, i), "\"" + r.text + "\" is listed twice");
    if (r.text == "triangulate") o.triangulate = true;
    else if (r.text == "drop-zero-area") o.drop_zero_area = true;
    else if (r.text == "orient") o.orient = true;
    else if (r.text == "split-pinched") o.split_pinched = true;
    else
      throw Input_error(at(path, i), "unknown repair \"" + r.text +
                                         "\" (expected triangulate, drop-zero-area, orient or split-pinched)");
  }
}

// One string member chosen from two words: the first is the default.
bool second_word(const Json_value& obj, const char* key, const char* first, const char* second, const std::string& path)
{
  const Json_value* v = obj.find(key);
  if (!v) return false;
  std::string where = dot(path, key);
  expect_kind(*v, Kind::String, where);
  if (v->text == first) return false;
  if (v->text == second) return true;
  throw Input_error(where, "expected \"" + std::string(first) + "\" or \"" + second + "\", found \"" + v->text + "\"");
}

// "max_pieces": a whole number from 1 to CLASH4D_MAX_MESH_PIECES_ALLOWED,
// read exactly (100.5 or 1e9 is refused, not rounded or clamped).
std::size_t max_pieces(const Json_value& v, const std::string& path)
{
  Rational n = read_number(v, path);
  if (n.denominator() != 1 || n < 1 || n > Rational(static_cast<long>(CLASH4D_MAX_MESH_PIECES_ALLOWED)))
    throw Input_error(path, "expected a whole number of pieces from 1 to " +
                                std::to_string(CLASH4D_MAX_MESH_PIECES_ALLOWED) + ", found " + to_string(n));
  return static_cast<std::size_t>(mpz_get_ui(n.numerator().mpz()));
}

} // namespace

using namespace json_field;

Mesh_options read_mesh_options(const Json_value& solid, const std::string& path)
{
  expect_keys(solid, {"mesh", "scale", "units", "repair", "shells", "as", "max_pieces", "decomposition"}, path);
  Mesh_options o;
  if (const Json_value* s = solid.find("scale")) {
    o.scale = read_number(*s, dot(path, "scale"));
    if (o.scale <= 0) throw Input_error(dot(path, "scale"), "the scale must be positive, found " + to_string(o.scale));
  }
  if (const Json_value* u = solid.find("units")) o.scale *= unit_in_metres(*u, dot(path, "units"));
  if (const Json_value* r = solid.find("repair")) read_repairs(*r, dot(path, "repair"), o);
  if (const Json_value* m = solid.find("max_pieces")) o.max_pieces = max_pieces(*m, dot(path, "max_pieces"));
  if (second_word(solid, "shells", "odd", "union", path)) o.rule = Mesh_options::Solid_rule::Union_of_shells;
  if (second_word(solid, "decomposition", "bsp", "nef", path)) o.decomposition = Mesh_decomposition::nef;
  if (second_word(solid, "as", "solid", "hull", path)) {
    for (const char* key : {"repair", "shells", "decomposition"})
      if (solid.find(key))
        throw Input_error(dot(path, key), "has no effect with \"as\": \"hull\" (the hull is made from the vertices alone)");
    o.rule = Mesh_options::Solid_rule::Hull;
  }
  return o;
}

} // namespace clash4d
