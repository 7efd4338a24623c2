// The generic pipeline instantiated on the double kernel.
#ifndef CLASH4D_FLOAT_DOUBLE_INSTANTIATION_H
#define CLASH4D_FLOAT_DOUBLE_INSTANTIATION_H

#include "check/Check_answer.h"
#include "scene/Scene.h"
#include <nlohmann/json.hpp>

namespace clash4d {

// tolerance: |value| <= tolerance counts as zero (0: plain sign tests).
Check_answer check_double(const Scene& scene, double tolerance, const Check_options& options);
nlohmann::ordered_json extrude_double(const Scene& scene);

Skeleton_answer skeleton_double(const Scene& scene);

} // namespace clash4d

#endif
