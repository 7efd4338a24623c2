// The regularised earliest time of a turning pair, proved by a path
// (docs/certificate-format.md, 8.4): a point W(t) = (x, y, z)(t) / w(t)
// inside both objects at every t in (t*, T1]. It starts from a vertex x(t)
// of the closure of the witness's cell (Cramer's quotients of three
// planes; the cell keeps its vertices on the critical interval after t*,
// regularised-semantics.md fact 10) and steps into the cell by
// c P(t)^k D, where P is t*'s minimal polynomial (zero at t*, so the step
// vanishes where the cell is born; k = 2 or 3 where the cell is born
// tangent to a plane) and D points into the cell at the vertex. c is
// halved, and T1 moved towards t*, until every plane keeps its side along
// the path, checked exactly.
#ifndef CLASH4D_CERTIFY_WITNESS_PATH_H
#define CLASH4D_CERTIFY_WITNESS_PATH_H

#include "rotation/Rotating_pair.h"
#include <nlohmann/json.hpp>

namespace clash4d {

// The PATH of a pair whose earliest time is t_star, with w a generic
// witness inside both at the rational time s > t_star of t_star's
// critical interval. Throws Turning_proof_missing when none is found.
nlohmann::ordered_json witness_path(const Rotating_object& a, const Rotating_object& b, const Algebraic& t_star,
                                    const std::array<Rational, 3>& w, const Rational& s);

} // namespace clash4d

#endif
