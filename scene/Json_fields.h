// Reading the fields of a strict JSON document (scene/Json_reader.h) with
// errors that name their place: the scene reader's and the CCD query
// reader's (ccd/) one way of asking for a kind, a key or an exact number.
#ifndef CLASH4D_SCENE_JSON_FIELDS_H
#define CLASH4D_SCENE_JSON_FIELDS_H

#include "numbers/Rational.h"
#include "scene/Json_value.h"
#include <array>
#include <initializer_list>
#include <string>
#include <vector>

namespace clash4d {
namespace json_field {

using Kind = Json_value::Kind;

// "path[i]" and "path.key": the places errors name.
inline std::string at(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }
inline std::string dot(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

// Each throws Input_error naming the place.
void expect_kind(const Json_value& v, Kind k, const std::string& path);
// Every key must be one of `allowed`: a typo must not silently change a verdict.
void expect_keys(const Json_value& obj, std::initializer_list<const char*> allowed, const std::string& path);
const Json_value& required(const Json_value& obj, const char* key, const std::string& path);
// A number read exactly from its text (a JSON number, or a string that may
// also be p/q); a number refused for its size is exit 3.
Rational number_from_text(const std::string& text, bool is_string, const std::string& path);
Rational read_number(const Json_value& v, const std::string& path);
std::vector<Rational> read_numbers(const Json_value& v, std::size_t count, const std::string& path);

template <std::size_t N>
std::array<Rational, N> read_array(const Json_value& v, const std::string& path)
{
  std::vector<Rational> xs = read_numbers(v, N, path);
  std::array<Rational, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = xs[i];
  return out;
}

} // namespace json_field
} // namespace clash4d

#endif
