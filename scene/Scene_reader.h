// Reading and validating a scene file (../shared/spec/scene-format.md).
#ifndef CLASH4D_SCENE_SCENE_READER_H
#define CLASH4D_SCENE_SCENE_READER_H

#include "scene/Json_value.h"
#include "scene/Scene.h"
#include <string>
#include <vector>

namespace clash4d {

// Limits on what a scene may ask for (exit 3 when exceeded).
constexpr std::size_t CLASH4D_MAX_CONVEX_HALFSPACES = 100;
constexpr std::size_t CLASH4D_MAX_HULL_POINTS = 1000;
constexpr std::size_t CLASH4D_MAX_MOTION_SEGMENTS = 10000;

// Every check of the spec, decided exactly. Throws Input_error naming the
// JSON path of the first problem. Mesh solids' file names are relative to
// base_directory (empty: the current directory); read_scene_file takes the
// scene file's own directory. A mesh file must lie under base_directory or
// one of allowed_mesh_folders, links resolved (docs/meshes.md).
Scene read_scene(const Json_value& root, const std::string& base_directory = "",
                 const std::vector<std::string>& allowed_mesh_folders = {});
Scene read_scene_file(const std::string& path, const std::vector<std::string>& allowed_mesh_folders = {});

// Parses a ROBMOD motion string ("rest until 0 vel 1 2 3 until 5 rest").
Motion parse_motion(const std::string& text, const std::string& place);

} // namespace clash4d

#endif
