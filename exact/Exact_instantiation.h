// The generic pipeline instantiated on the two exact kernels: the filtered
// one (`--number exact`, what users run) and the pure rational one
// (`--number rational`, the reference). Their answers are identical.
#ifndef CLASH4D_EXACT_EXACT_INSTANTIATION_H
#define CLASH4D_EXACT_EXACT_INSTANTIATION_H

#include "check/Check_answer.h"
#include "scene/Scene.h"
#include <nlohmann/json.hpp>
#include <memory>
#include <optional>

namespace clash4d {

Check_answer check_exact(const Scene& scene, const Check_options& options);
// --earliest on unions of convex pieces by piece pairs in rationals
// (check/Piece_pairs.h), labelled exact; none when the query is not one
// that path answers (check_exact and a prepared scene's checks then run
// the filtered cascade: both give this answer where it is given).
// model: where a prepared scene keeps the rational model of `scene` made by
// the first such check (type-erased; reset it when motions change).
std::optional<Check_answer> check_exact_by_pieces(const Scene& scene, const Check_options& options,
                                                  std::shared_ptr<void>* model = nullptr);
nlohmann::ordered_json extrude_exact(const Scene& scene);
Skeleton_answer skeleton_exact(const Scene& scene);

Check_answer check_rational(const Scene& scene, const Check_options& options);
nlohmann::ordered_json extrude_rational(const Scene& scene);
Skeleton_answer skeleton_rational(const Scene& scene);

} // namespace clash4d

#endif
