// A scene back to its file form, every number as an exact string, so that
// reading the text gives the same scene (used by tests and by tools that
// generate or shrink scenes). Tools put their provenance under `meta` (spec),
// so every file they write as a scene is one `check` accepts as it is.
#ifndef CLASH4D_SCENE_SCENE_WRITER_H
#define CLASH4D_SCENE_SCENE_WRITER_H

#include "scene/Scene.h"
#include <nlohmann/json.hpp>
#include <string>

namespace clash4d {

std::string motion_text(const Motion& m);
// The scene file as JSON; `meta` (when not null) is its last key.
nlohmann::ordered_json scene_json(const Scene& scene, const nlohmann::ordered_json& meta = nullptr);
std::string write_scene(const Scene& scene, const nlohmann::ordered_json& meta = nullptr);

} // namespace clash4d

#endif
