// A scene back to its file form, every number as an exact string, so that
// reading the text gives the same scene (used by tests and by tools that
// generate or shrink scenes).
#ifndef CLASH4D_SCENE_SCENE_WRITER_H
#define CLASH4D_SCENE_SCENE_WRITER_H

#include "scene/Scene.h"
#include <string>

namespace clash4d {

std::string motion_text(const Motion& m);
std::string write_scene(const Scene& scene);

} // namespace clash4d

#endif
