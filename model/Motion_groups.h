// Which planes of a plane table move together: one object's planes, sheared
// into the region's frame, all move with the object's velocity r relative to
// that frame. Their normals are (n, -n.r), so every one of them contains the
// direction (r, 1); so does a region face x_q = c on an axis where the
// object is still (r_q = 0: measured in its own frame). A line where three
// planes containing (r, 1) meet runs along it.
// And which planes meet at a corner of a primitive (four or more planes
// through one point, Primitive::corners): in space-time they share the
// corner's path, a line along (r, 1). A line made of three of them is that
// path, and every other plane of the corner contains it; a line made of two
// of them meets the path at one point, where every plane of the corner cuts
// it.
// These are zeros and ties of the exact arithmetic; generate-and-test writes
// them so instead of computing them, because an interval run would only
// enclose them and could not certify their sign.
#ifndef CLASH4D_MODEL_MOTION_GROUPS_H
#define CLASH4D_MODEL_MOTION_GROUPS_H

#include "geometry/kernel_ft4.h"
#include <vector>

namespace clash4d {

template <class FT>
struct Motion_groups {
  std::vector<int> of;                  // per table entry: its group, or -1
  std::vector<Vector3<FT>> velocity;    // per group: r, relative to the frame
  std::vector<std::array<bool, 3>> still;   // per group and axis: r_q is a written zero
  std::vector<std::vector<int>> corners;    // per table entry: the corners it passes through (ids), sorted
  int corner_count = 0;

  int group(std::size_t entry) const { return entry < of.size() ? of[entry] : -1; }
  const std::vector<int>& corners_of(std::size_t entry) const
  {
    static const std::vector<int> none;
    return entry < corners.size() ? corners[entry] : none;
  }
};

} // namespace clash4d

#endif
