// Whether a subject's point holds in the true scene, exactly, in the
// subject's semantics: regularised, strictly inside both objects with
// tL < t < tH; closed, in both closed objects with tL <= t <= tH. On a
// scene where something turns the objects are placed where their poses put
// them at the point's (rational) time, and the question is the static one
// there (rotation/Rotating_pair.h, posed_pair).
#ifndef CLASH4D_COMPARE_WITNESS_JUDGE_H
#define CLASH4D_COMPARE_WITNESS_JUDGE_H

#include "exact/Rational_kernel.h"
#include "model/Scene_model.h"
#include "rotation/Rotating_pair.h"
#include "scene/Scene.h"
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace clash4d {

class Witness_judge {
public:
  explicit Witness_judge(const Scene& scene);

  bool holds(int a, int b, const Vector4<Rational>& w, bool closed) const;
  // The pair (names) whose objects both hold the point, or two empty names:
  // an external subject gives a point, not a pair.
  std::array<std::string, 2> pair_holding(const Vector4<Rational>& w, bool closed) const;

private:
  const Scene& scene_;
  std::optional<Scene_model<Rational_kernel>> model_;   // a scene without rotation
  std::vector<Rotating_object> turning_;                // a scene where something turns
};

} // namespace clash4d

#endif
