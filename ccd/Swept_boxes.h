// The quick "no" of a CCD query: each primitive lies, at every t in [0, 1],
// in the box of its vertices' eight (or four) end positions (each vertex
// moves on a segment, inside the box of its ends). When those two boxes do
// not meet on some axis, neither do the closed primitives; boxes that only
// touch are not apart (a contact may be there).
#ifndef CLASH4D_CCD_SWEPT_BOXES_H
#define CLASH4D_CCD_SWEPT_BOXES_H

#include "ccd/Ccd_query.h"
#include "geometry/kernel_ft4.h"
#include "numbers/Number_ops.h"
#include <array>

namespace clash4d {

// On one axis: the lowest and highest end coordinates of the first
// primitive's vertices (vertex 0, or 0 and 1) and of the second's; the
// ends are enclosed (Number_ops), not decided.
template <class FT>
struct Swept_extent {
  FT lo[2], hi[2];
};

template <class FT>
Swept_extent<FT> swept_extent(Ccd_type type, const std::array<Vector3<FT>, 8>& rows, int axis)
{
  using Ops = Number_ops<FT>;
  int first_count = type == Ccd_type::vertex_face ? 1 : 2;
  Swept_extent<FT> e;
  for (int side = 0; side < 2; ++side) {
    int from = side == 0 ? 0 : first_count, to = side == 0 ? first_count : 4;
    e.lo[side] = e.hi[side] = rows[static_cast<std::size_t>(from)][axis];
    for (int v = from; v < to; ++v)
      for (int when : {0, 4}) {
        const FT& x = rows[static_cast<std::size_t>(v + when)][axis];
        e.lo[side] = Ops::lower(e.lo[side], x);
        e.hi[side] = Ops::upper(e.hi[side], x);
      }
  }
  return e;
}

// less(a, b): the kernel's a < b.
template <class FT, class Less>
bool swept_boxes_apart(Ccd_type type, const std::array<Vector3<FT>, 8>& rows, Less less)
{
  for (int axis = 0; axis < 3; ++axis) {
    Swept_extent<FT> e = swept_extent(type, rows, axis);
    if (less(e.hi[0], e.lo[1]) || less(e.hi[1], e.lo[0])) return true;
  }
  return false;
}

} // namespace clash4d

#endif
