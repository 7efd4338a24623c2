// Whether a subject's tolerance, as it declares it, is what made it differ
// from exact (the comparer's cause `tolerance`, compare/Comparer.h). A
// distance tolerance EPS is judged by moving one object: when exact, on the
// scene with that object moved by some vector no longer than EPS, gives the
// subject's verdict, the objects come within EPS of meeting (or of parting),
// so the subject answered its own question rightly. Only the 26 directions
// of a cube are tried (scaled to length at most EPS, rational), so the
// judge proves "within EPS" when it says so and may miss a case between
// about 0.57 EPS and EPS: that case keeps the cause `arithmetic`.
#ifndef CLASH4D_COMPARE_TOLERANCE_JUDGE_H
#define CLASH4D_COMPARE_TOLERANCE_JUDGE_H

#include "numbers/Rational.h"
#include "scene/Scene.h"
#include "search/Semantics.h"
#include <array>
#include <string>
#include <vector>

namespace clash4d {

// The 26 rational vectors tried, each of Euclidean length <= eps:
// eps e_i, (7/10) eps (e_i +- e_j), (57/100) eps (+-1, +-1, +-1).
std::vector<std::array<Rational, 3>> tolerance_moves(const Rational& eps);

// Does exact, in `semantics`, say `collide` on the scene with one of
// `movable` (object names; every object when empty) moved by one of
// tolerance_moves(eps)? A moved scene that is not valid is not counted.
bool verdict_within_tolerance(const Scene& scene, Semantics semantics, bool collide, const Rational& eps,
                              const std::vector<std::string>& movable);

} // namespace clash4d

#endif
