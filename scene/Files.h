// The two file operations every command shares: writing a file so that no
// reader ever sees half of it, and reading a JSON document (not a scene:
// campaign.json, progress, findings' meta) with errors naming the file.
#ifndef CLASH4D_SCENE_FILES_H
#define CLASH4D_SCENE_FILES_H

#include <nlohmann/json.hpp>
#include <string>

namespace clash4d {

// Writes text so that no reader sees half of it: to a new hidden file beside
// path (DIR/.NAME.PID.N.RANDOM.tmp, created with O_EXCL | O_NOFOLLOW) renamed
// over path, which keeps a replaced file's permissions; the temporary is
// removed on failure. Only a regular file, or nothing, is replaced: a
// symbolic link is written through to the file it names, a device or a pipe
// (/dev/null) is written to as it is, and a folder is refused. Safe from
// several threads and processes at once. Throws std::runtime_error naming
// the file.
void write_file_atomically(const std::string& path, const std::string& text);

// Parses a JSON file; throws std::runtime_error "PATH: cannot read" or
// "PATH: not valid JSON (...)". Scenes are read by scene/Scene_reader.h,
// which keeps every number's text.
nlohmann::ordered_json read_json_document(const std::string& path);

} // namespace clash4d

#endif
