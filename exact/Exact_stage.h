// A sub-span's region stage made in rationals for an interval run that
// could not certify it (exact/Exact_span.h, region_stage): the rational
// run's own stage and the CSG nodes its S-bounds emptied in each object.
// Kept per sub-span, so that the rational run replaying the interval run's
// trail (exact/Earliest_replay.h) adopts it instead of making it again.
#ifndef CLASH4D_EXACT_EXACT_STAGE_H
#define CLASH4D_EXACT_EXACT_STAGE_H

#include "search/Span_region.h"
#include <cstddef>
#include <map>
#include <vector>

namespace clash4d {

template <class FT>
struct Exact_stage {
  Region_stage<FT> stage;
  std::vector<char> empty_a, empty_b;   // per CSG node of each object

  // The stage onto a run in the same numbers: A's and B's emptied nodes.
  template <class M>
  void adopt(M& A, M& B, Region_stage<FT>& st) const
  {
    for (std::size_t n = 0; n < A.beta.size(); ++n) A.beta[n].empty = empty_a[n];
    for (std::size_t n = 0; n < B.beta.size(); ++n) B.beta[n].empty = empty_b[n];
    st = stage;
  }
};

// Per sub-span index, the stages one pair's interval run had made.
template <class FT>
using Exact_stages = std::map<std::size_t, Exact_stage<FT>>;

} // namespace clash4d

#endif
