// When an interval run hands its pair's long search over to an apart proof
// (exact/Interval_filter.h, decides_here; Filtered_runner::proves_apart),
// and what the proofs so far proved: the pair apart on [tL, until], and
// whether that covers the sub-span searched now, whose search then stops.
#ifndef CLASH4D_EXACT_APART_HAND_OVER_H
#define CLASH4D_EXACT_APART_HAND_OVER_H

#include "numbers/Rational.h"
#include "search/Semantics.h"
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>

namespace clash4d {

class Apart_hand_over {
public:
  // A regularised search hands over after 128 lines' work: looking for
  // any point, the proof ends it either way (apart, or the open term's
  // point is the witness); with --earliest, the sub-spans it proves apart
  // before an open term are still cut short (apart_spans). A closed search
  // waits for 512: its open terms are touches, which answer nothing, and a
  // touching pair's search mostly finds its touch before. Measured over
  // clash4d_bench's families (contact, fuzz, paper, random, with and
  // without --earliest) against 512 everywhere: the same or less, a
  // quarter to a third less on filled cavities and union seams (32 no
  // better); 128 in closed searches too cost the weaving late stop's
  // closed earliest run a third more (a wasted attempt at a touch).
  explicit Apart_hand_over(Semantics semantics = Semantics::regularised)
    : after_(semantics == Semantics::closed ? 512 : 128) {}

  // Whether a search that did `work` (Interval_filter::search_work) asks
  // now. A search of a few hundred lines costs about as much as a small
  // pair's proof (tens of exact LPs), and most pairs are decided before.
  bool due(std::size_t work) const { return work >= after_; }
  // The proof's step bound.
  std::uint64_t steps() const { return steps_; }

  // Out of steps: ask again at 16 times the work with 16 times the steps,
  // so the asking costs a bounded share of the search.
  void out_of_steps()
  {
    after_ *= 16;
    steps_ *= 16;
  }
  // A term left open would be met again, and a point found answers the
  // search: never ask again.
  void never() { after_ = std::numeric_limits<std::size_t>::max(); }

  // A proof's outcome: the pair apart on [tL, until], which covers the
  // sub-span searched now or not.
  void proved_until(Rational until, bool covers_span)
  {
    until_ = std::move(until);
    span_apart_ = covers_span;
  }
  const std::optional<Rational>& until() const { return until_; }
  bool span_apart() const { return span_apart_; }
  void new_span() { span_apart_ = false; }

private:
  std::size_t after_;
  std::uint64_t steps_ = 32768;
  std::optional<Rational> until_;
  bool span_apart_ = false;
};

} // namespace clash4d

#endif
