// The planes of a one-primitive solid, each made as asked: read from the
// scene's primitive in its own frame (its numbers, converted) and moved by
// the solid's transforms only when first read. A stage
// that reads a few planes in rationals (a filter's signs of a convex pair,
// search/Convex_pair.h) pays for those few, not for the whole model
// (Model_builder moves every plane and vertex at once).
#ifndef CLASH4D_MODEL_PRIMITIVE_PLANES_H
#define CLASH4D_MODEL_PRIMITIVE_PLANES_H

#include "model/Model_builder.h"
#include <optional>
#include <vector>

namespace clash4d {

template <class K>
class Primitive_planes {
public:
  using FT = typename K::FT;

  // shape: a primitive under translations and rotations only; it (the
  // scene's) outlives this.
  Primitive_planes(const K& k, const Solid& shape)
    : k_(k), T_(Affine3<FT>::identity()), solid_(Model_builder<K>(k).peel(shape, T_)),
      planes_(Model_builder<K>(k).local_plane_count(solid_))
  {}

  std::size_t size() const { return planes_.size(); }

  // Plane i in the world (Model_builder's primitive plane i).
  const Plane3<FT>& operator[](std::size_t i)
  {
    if (!planes_[i]) {
      Plane3<FT> local = Model_builder<K>(k_).local_plane(solid_, i);
      planes_[i] = T_.is_identity ? local : T_.apply(local);
    }
    return *planes_[i];
  }

private:
  const K& k_;
  Affine3<FT> T_;
  const Solid& solid_;   // the primitive, in the scene
  std::vector<std::optional<Plane3<FT>>> planes_;
};

} // namespace clash4d

#endif
