// Text from a file, made safe to print on one line: a name or an excerpt may
// hold any character JSON allows, NUL and line feeds included (issue 59, 14).
#ifndef CLASH4D_SCENE_PRINTABLE_H
#define CLASH4D_SCENE_PRINTABLE_H

#include <cstdio>
#include <string>
#include <string_view>

namespace clash4d {

// Control characters (U+0000 to U+001F and U+007F) written as JSON writes
// them, \u0000; every other byte as it is (JSON text is UTF-8).
inline std::string printable(std::string_view text)
{
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    unsigned char u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u != 0x7F) {
      out += c;
      continue;
    }
    char code[8];
    std::snprintf(code, sizeof code, "\\u%04x", u);
    out += code;
  }
  return out;
}

} // namespace clash4d

#endif
