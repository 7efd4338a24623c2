// The answer of `check` in text form, independent of the number type.
#ifndef CLASH4D_CORE_CHECK_ANSWER_H
#define CLASH4D_CORE_CHECK_ANSWER_H

#include "core/Check_stats.h"
#include <array>
#include <string>
#include <vector>

namespace clash4d {

struct Check_options {
  bool all_pairs = false;     // examine every pair instead of stopping at the first collision
  // false: the paper's "original" bounding (the objects' boxes at the
  // velocity changes, intersected; §4.1) instead of S-bounds. Reproduction only.
  bool sbounds = true;
};

struct Pair_answer {
  std::string a, b;                      // object names
  std::array<std::string, 4> witness;    // x, y, z, t
  bool witness_verified = false;
};

struct Check_answer {
  std::string number;                    // "exact" or "double"
  bool collide = false;
  std::vector<Pair_answer> pairs;        // colliding pairs, in pair order
  Check_stats stats;
};

} // namespace clash4d

#endif
