// A CCD answer as the line `clash4d ccd --json` prints for it
// (docs/ccd-queries.md, Output): {"index", "collide"} and, with earliest,
// "t" (null when it does not collide) and "uv".
#ifndef CLASH4D_CCD_CCD_ANSWER_JSON_H
#define CLASH4D_CCD_CCD_ANSWER_JSON_H

#include "ccd/Ccd_answer.h"
#include <nlohmann/json.hpp>

namespace clash4d {

nlohmann::ordered_json ccd_number_json(const Ccd_number& x);
nlohmann::ordered_json ccd_answer_json(std::size_t index, const Ccd_answer& a, bool earliest);

} // namespace clash4d

#endif
