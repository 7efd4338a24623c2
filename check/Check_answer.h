// The answer of `check` in text form, independent of the number type.
#ifndef CLASH4D_CHECK_CHECK_ANSWER_H
#define CLASH4D_CHECK_CHECK_ANSWER_H

#include "search/Check_stats.h"
#include <array>
#include <string>
#include <vector>

namespace clash4d {

struct Check_options {
  bool all_pairs = false;     // examine every pair instead of stopping at the first collision
  bool earliest = false;      // find each pair's earliest collision time t* (§5)
  // false: the paper's "original" bounding (the objects' boxes at the
  // velocity changes, intersected; §4.1) instead of S-bounds. Reproduction only.
  bool sbounds = true;
  bool json = false;          // output form (used by the command line only)
};

struct Pair_answer {
  std::string a, b;                      // object names
  std::array<std::string, 4> witness;    // x, y, z, t
  bool witness_verified = false;
  bool earliest = false;                 // the three below are set
  std::string t_star;                    // exact t* (or the double's)
  std::array<std::string, 4> contact;    // (x*, t*) in the closure of the collision region
  bool at_start = false;                 // t* = tL: already overlapping when the span starts
};

struct Check_answer {
  std::string number;                    // "exact", "rational" or "double"
  bool collide = false;
  std::vector<Pair_answer> pairs;        // colliding pairs, in pair order
  int earliest_pair = -1;                // index in pairs of the smallest t* (--earliest)

  // The pair whose witness is reported: the earliest one with --earliest,
  // else the first; null when nothing collides.
  const Pair_answer* reported() const
  {
    if (pairs.empty()) return nullptr;
    return &pairs[earliest_pair >= 0 ? earliest_pair : 0];
  }
  Check_stats stats;
};

// `skeleton`: the edges of each colliding pair's collision region.
struct Skeleton_answer {
  std::string number;
  struct Pair {
    std::string a, b;
    std::vector<std::array<std::array<std::string, 4>, 2>> edges;   // (x, y, z, t) ends
  };
  std::vector<Pair> pairs;                // pairs with a non-empty region, in pair order
  Check_stats stats;
};

} // namespace clash4d

#endif
