// Which question the search answers (scene-format.md, "What counts as a
// collision" and "Closed semantics"): regularised, the default, asks for a
// generic point strictly inside both objects with tL < t < tH (touching is
// not a collision); closed asks for a point of both closed regular sets
// (each object's closure of its interior) with tL <= t <= tH.
// regularised-semantics.md item 6: they differ exactly on contact.
#ifndef CLASH4D_SEARCH_SEMANTICS_H
#define CLASH4D_SEARCH_SEMANTICS_H

#include <optional>
#include <ostream>
#include <string>

namespace clash4d {

enum class Semantics { regularised, closed };

inline const char* semantics_name(Semantics s) { return s == Semantics::closed ? "closed" : "regularised"; }

inline std::ostream& operator<<(std::ostream& out, Semantics s) { return out << semantics_name(s); }

inline std::optional<Semantics> semantics_from_name(const std::string& name)
{
  if (name == "regularised") return Semantics::regularised;
  if (name == "closed") return Semantics::closed;
  return std::nullopt;
}

} // namespace clash4d

#endif
