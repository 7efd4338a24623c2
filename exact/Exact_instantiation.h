// The generic pipeline instantiated on the exact kernel.
#ifndef CLASH4D_EXACT_EXACT_INSTANTIATION_H
#define CLASH4D_EXACT_EXACT_INSTANTIATION_H

#include "core/Check_answer.h"
#include "scene/Scene.h"
#include <nlohmann/json.hpp>

namespace clash4d {

Check_answer check_exact(const Scene& scene, const Check_options& options);
nlohmann::ordered_json extrude_exact(const Scene& scene);

Skeleton_answer skeleton_exact(const Scene& scene);

} // namespace clash4d

#endif
