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

// A file's bytes, or a pipe's (`check <(cat scene.json)`), read as a stream
// up to max_bytes. Opened without blocking, so that a named pipe nobody
// writes to reads as empty instead of hanging. Throws Input_error (no place:
// the caller names the file), exit 3 beyond max_bytes; `noun` names the
// file in the messages ("cannot open the mesh file").
std::string read_file_text(const std::string& path, std::size_t max_bytes, const std::string& noun = "file");

// Reads a file (within CLASH4D_MAX_FILE_BYTES) and parses it; a folder is
// named as such.
Json_value read_json_file(const std::string& path);

} // namespace clash4d

#endif
