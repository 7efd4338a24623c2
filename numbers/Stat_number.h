// A number the statistics report (`check --stats`), as the kernel that made
// it has it: an exact rational, a double, or an interval run's enclosure
// [lo, hi] (a point when lo = hi). Numbers, not text: the kernels make them
// (to_stat) on the search's path, and the command line writes them.
#ifndef CLASH4D_NUMBERS_STAT_NUMBER_H
#define CLASH4D_NUMBERS_STAT_NUMBER_H

#include "numbers/Rational.h"

namespace clash4d {

struct Stat_number {
  enum class Kind { Exact, Double, Enclosure };
  Kind kind = Kind::Exact;
  Rational exact;                         // Kind::Exact
  double lo = 0, hi = 0;                  // Kind::Double: lo; Kind::Enclosure: [lo, hi]
};

// [lo, hi] of one axis or of a time span.
struct Stat_range {
  Stat_number lo, hi;
};

} // namespace clash4d

#endif
