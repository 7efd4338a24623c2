// How deep a regularised collision is at its witness (issue 58 item 6;
// docs/semantics.md, "Depth"), so that a 2.4 um overlap reads as one: the
// largest d such that an axis-aligned cube of half-width d fits inside both
// objects' witness cells at the witness's time. No square root: the cube
// with centre y fits in n.x + e <= 0 exactly when n.y + e + d |n|_1 <= 0
// (its corner farthest along n), so d is an exact linear program.
#ifndef CLASH4D_EXACT_WITNESS_DEPTH_H
#define CLASH4D_EXACT_WITNESS_DEPTH_H

#include "exact/Rational_kernel.h"
#include "model/Scene_model.h"
#include "numbers/Rational.h"
#include "scene/Scene.h"
#include <memory>
#include <array>
#include <optional>

namespace clash4d {

// On a scene without rotation: the depth at w = (x, y, z, t) strictly
// inside objects a and b. An object's witness cell is the convex set of one
// term of its CSG formula true at w: a primitive's planes, a difference's
// subtracted parts each by one plane that w is outside of, one true child
// of a union. The depth is a lower bound of the deepest cube in the
// objects' overlap at that time, and exact when both are convex. nullopt
// when d is unbounded (both cells unbounded along a common direction) or w
// is not strictly inside both.
class Witness_depth {
public:
  explicit Witness_depth(const Scene& scene);
  std::optional<Rational> operator()(int a, int b, const std::array<Rational, 4>& w) const;

private:
  std::shared_ptr<const Scene_model<Rational_kernel>> model_;   // built once for every pair asked
};

} // namespace clash4d

#endif
