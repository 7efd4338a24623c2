// Exact numbers as the scene format writes them in answers: a rational as
// "p/q" (or "p") in lowest terms, an irrational real algebraic number as
// {"poly": [...], "between": [lo, hi], "approx": "..."} (scene-format.md,
// "Exact numbers that are not rational"); a double as its shortest decimal.
#ifndef CLASH4D_SCENE_NUMBER_JSON_H
#define CLASH4D_SCENE_NUMBER_JSON_H

#include "numbers/Algebraic.h"
#include <nlohmann/json.hpp>
#include <string>

namespace clash4d {

nlohmann::ordered_json number_json(const Algebraic& x);
// The shortest decimal that reads back to the same double.
std::string shortest_decimal(double x);

} // namespace clash4d

#endif
