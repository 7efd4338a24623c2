// The signs an interval witness cannot tell near a closed contact
// (search/Witness_signs.h), answered in EK: object M's planes on the
// sub-span, extruded one primitive at a time as they are asked for, at the
// exact contact point and against the steps' exact directions. The
// interval witness asking them makes EK's point or none (search/Witness.h).
#ifndef CLASH4D_EXACT_EXACT_WITNESS_SIGNS_H
#define CLASH4D_EXACT_EXACT_WITNESS_SIGNS_H

#include "search/Witness.h"
#include <CGAL/FPU.h>
#include <algorithm>
#include <vector>

namespace clash4d {

template <class EK>
class Exact_witness_signs : public Witness_signs {
public:
  using FT = typename EK::FT;
  using H = Hyperplane4<FT>;
  using V4 = Vector4<FT>;

  // p and d as near_in_space takes them: the contact point and the step
  // into M's cell, in the frame x' = x - shear t.
  Exact_witness_signs(const EK& k, const Moving_object<FT>& M, V4 p, V4 d, const Vector3<FT>& shear)
    : k_(k), M_(M), extruded_(M.object->csg.primitives.size())
  {
    Witness<EK>::in_space(p, d, shear, M.v);
    p_ = p;
    d_ = d;
    for (const auto& prim : M.object->csg.primitives) {
      first_.push_back(count_);
      count_ += prim.planes.size();
    }
  }

  // How many planes M has (Witness::object_planes' count).
  std::size_t plane_count() const { return count_; }

  bool through_contact(std::size_t i) const override
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    return k_.sign(plane(i).value(p_)) == CGAL::ZERO;
  }

  bool parallel(std::size_t i, int direction) const override
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    return k_.dot_sign(plane(i).n, direction == 0 ? d_ : Witness<EK>::generic_direction(direction, 3)) == CGAL::ZERO;
  }

private:
  const EK& k_;
  const Moving_object<FT>& M_;
  V4 p_, d_;
  std::vector<std::size_t> first_;               // per primitive, its first plane's number
  std::size_t count_ = 0;
  mutable std::vector<std::vector<H>> extruded_;   // per primitive, once asked

  const H& plane(std::size_t i) const
  {
    std::size_t prim = static_cast<std::size_t>(std::upper_bound(first_.begin(), first_.end(), i) - first_.begin()) - 1;
    std::vector<H>& planes = extruded_[prim];
    if (planes.empty()) planes = Extrusion<EK>::primitive_planes(M_.object->csg.primitives[prim], M_.v, M_.o);
    return planes.at(i - first_[prim]);
  }
};

} // namespace clash4d

#endif
