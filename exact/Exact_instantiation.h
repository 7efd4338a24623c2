// The generic pipeline instantiated on the two exact kernels: the filtered
// one (`--number exact`, what users run) and the pure rational one
// (`--number rational`, the reference). Their answers are identical.
#ifndef CLASH4D_EXACT_EXACT_INSTANTIATION_H
#define CLASH4D_EXACT_EXACT_INSTANTIATION_H

#include "check/Check_answer.h"
#include "scene/Scene.h"
#include <nlohmann/json.hpp>

namespace clash4d {

Check_answer check_exact(const Scene& scene, const Check_options& options);
nlohmann::ordered_json extrude_exact(const Scene& scene);
Skeleton_answer skeleton_exact(const Scene& scene);

Check_answer check_rational(const Scene& scene, const Check_options& options);
nlohmann::ordered_json extrude_rational(const Scene& scene);
Skeleton_answer skeleton_rational(const Scene& scene);

} // namespace clash4d

#endif
