// The planes of a one-primitive solid, each made as asked: the primitive in
// its own frame is read from the scene (its numbers, converted), and a
// plane is moved by the solid's transforms only when first read. A stage
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

  // shape: a primitive under translations and rotations only.
  Primitive_planes(const K& k, const Solid& shape) : T_(Affine3<FT>::identity())
  {
    Model_builder<K> builder(k);
    local_ = builder.local(builder.peel(shape, T_));
    planes_.resize(local_.planes.size());
  }

  std::size_t size() const { return planes_.size(); }

  // Plane i in the world (Model_builder's primitive plane i).
  const Plane3<FT>& operator[](std::size_t i)
  {
    if (!planes_[i]) planes_[i] = T_.is_identity ? local_.planes[i] : T_.apply(local_.planes[i]);
    return *planes_[i];
  }

private:
  Affine3<FT> T_;
  Primitive<FT> local_;
  std::vector<std::optional<Plane3<FT>>> planes_;
};

} // namespace clash4d

#endif
