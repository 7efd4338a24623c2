// The signs a filter's witness cannot tell near a closed contact, answered
// exactly by another kernel (search/Witness.h, near_in_space): whether a
// plane of the object passes through the contact point, and whether it is
// parallel to one of the steps taken from there. Planes are numbered as
// Witness::object_planes lists them; direction 0 is the step into the
// object's cell (near_in_space's d), direction j >= 1 is (1, j, j^2, 0)
// (make_generic's). An exact kernel's witness never asks.
#ifndef CLASH4D_SEARCH_WITNESS_SIGNS_H
#define CLASH4D_SEARCH_WITNESS_SIGNS_H

#include <cstddef>

namespace clash4d {

class Witness_signs {
public:
  virtual ~Witness_signs() = default;
  virtual bool through_contact(std::size_t plane) const = 0;
  virtual bool parallel(std::size_t plane, int direction) const = 0;
};

} // namespace clash4d

#endif
