// Commands that do not decide rotation yet refuse a scene with a rotating
// pose motion, exit 2 naming the object (issue 61): never an answer as if
// the object were at rest.
#ifndef CLASH4D_SCENE_ROTATION_REFUSAL_H
#define CLASH4D_SCENE_ROTATION_REFUSAL_H

#include "scene/Input_error.h"
#include "scene/Scene.h"
#include <string>

namespace clash4d {

// Throws Input_error at "objects[i].motion" for the first object whose
// motion rotates: "object \"NAME\": " + what, e.g. "motions with rotation
// are not supported by skeleton yet".
inline void refuse_rotation(const Scene& scene, const std::string& what)
{
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].motion.rotates())
      throw Input_error("objects[" + std::to_string(i) + "].motion",
                        "object \"" + scene.objects[i].name + "\": " + what);
}

// The message of a command that does not support rotation.
inline std::string rotation_unsupported_by(const std::string& command)
{
  return "motions with rotation are not supported by " + command + " yet";
}

} // namespace clash4d

#endif
