#include "scene/Json_fields.h"

#include "scene/Input_error.h"
#include "scene/Number_text.h"

namespace clash4d {
namespace json_field {

void expect_kind(const Json_value& v, Kind k, const std::string& path)
{
  if (v.kind != k)
    throw Input_error(path, std::string("expected ") + kind_name(k) + ", found " + kind_name(v.kind));
}

void expect_keys(const Json_value& obj, std::initializer_list<const char*> allowed, const std::string& path)
{
  for (const auto& m : obj.members) {
    bool known = false;
    for (const char* a : allowed) known = known || m.first == a;
    if (!known) {
      std::string list;
      for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
      throw Input_error(path, "unknown key \"" + m.first + "\" (expected " + list + ")");
    }
  }
}

const Json_value& required(const Json_value& obj, const char* key, const std::string& path)
{
  const Json_value* v = obj.find(key);
  if (!v) throw Input_error(path, std::string("missing key \"") + key + "\"");
  return *v;
}

Rational number_from_text(const std::string& text, bool is_string, const std::string& path)
{
  Number_parse p = parse_number_text(text, is_string);
  if (!p.ok) {
    std::string shown = text.size() > 40 ? text.substr(0, 40) + "..." : text;
    if (p.limit) throw Input_error(path, "'" + shown + "' is refused: " + p.error, CLASH4D_EXIT_LIMIT);
    throw Input_error(path, "'" + shown + "' is not a number: " + p.error);
  }
  return p.value;
}

Rational read_number(const Json_value& v, const std::string& path)
{
  if (v.kind != Kind::Number && v.kind != Kind::String)
    throw Input_error(path, std::string("expected a number, found ") + kind_name(v.kind));
  return number_from_text(v.text, v.kind == Kind::String, path);
}

std::vector<Rational> read_numbers(const Json_value& v, std::size_t count, const std::string& path)
{
  expect_kind(v, Kind::Array, path);
  if (v.items.size() != count)
    throw Input_error(path, "expected " + std::to_string(count) + " numbers, found " + std::to_string(v.items.size()));
  std::vector<Rational> out;
  for (std::size_t i = 0; i < count; ++i) out.push_back(read_number(v.items[i], at(path, i)));
  return out;
}

} // namespace json_field
} // namespace clash4d
