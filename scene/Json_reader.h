// Strict JSON reading on nlohmann's SAX parser (iterative, so deep input cannot
// overflow the stack): duplicate keys are errors and number text is kept.
#ifndef CLASH4D_SCENE_JSON_READER_H
#define CLASH4D_SCENE_JSON_READER_H

#include "scene/Json_value.h"
#include <string>

namespace clash4d {

constexpr std::size_t CLASH4D_MAX_JSON_DEPTH = 256;
constexpr std::size_t CLASH4D_MAX_FILE_BYTES = 64u << 20;

// Throws Input_error with a line/column place on malformed text.
Json_value read_json_text(const std::string& text);

// Reads a file (size-limited) and parses it.
Json_value read_json_file(const std::string& path);

} // namespace clash4d

#endif
