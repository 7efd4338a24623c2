// A JSON document as read: numbers keep their text so they can be read exactly.
#ifndef CLASH4D_SCENE_JSON_VALUE_H
#define CLASH4D_SCENE_JSON_VALUE_H

#include <string>
#include <utility>
#include <vector>

namespace clash4d {

struct Json_value {
  enum class Kind { Null, Boolean, Number, String, Array, Object };
  Kind kind = Kind::Null;
  bool boolean = false;
  std::string text;                                          // number text or string
  std::vector<Json_value> items;                             // array elements
  std::vector<std::pair<std::string, Json_value>> members;   // object, in file order

  const Json_value* find(const std::string& key) const
  {
    for (const auto& m : members)
      if (m.first == key) return &m.second;
    return nullptr;
  }
};

const char* kind_name(Json_value::Kind k);

} // namespace clash4d

#endif
