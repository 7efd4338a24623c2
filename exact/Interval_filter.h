// The search policy of a pair's interval run, the approximate half of the
// filtered exact kernel (exact/Filtered_runner.h). The interval kernel
// throws CGAL::Uncertain_conversion_exception for a sign it cannot
// certify; this policy is where that is caught:
//  - a line of generate-and-test with such a sign is decided in rationals
//    alone (exact/Exact_span.h) and the run goes on;
//  - two planes the intervals cannot tell apart are compared on the
//    rational planes;
//  - a witness the intervals cannot make is left to a rational run;
//  - once a line of a sub-span was uncertain, generate-and-test gets the
//    normals of the sub-span's rational planes in lowest terms
//    (normal_keys, Exact_span::normal_keys): small integers, on which
//    intervals are exact, so planes that are parallel after a rational
//    rotation (and lines of dependent normals) are zeros it writes.
// Anything else uncertain stops the run, and the runner redoes the pair in
// rationals. For an any-witness search it records where the first point
// inside was found (exact/Search_trail.h), so a rational run can go
// straight there (exact/Trail_replay.h).
#ifndef CLASH4D_EXACT_INTERVAL_FILTER_H
#define CLASH4D_EXACT_INTERVAL_FILTER_H

#include "exact/Exact_span.h"
#include "exact/Search_trail.h"
#include <type_traits>

namespace clash4d {

template <class Runner>
class Interval_filter {
public:
  using AK = typename Runner::Approximate_kernel;
  using AFT = typename AK::FT;

  Interval_filter() = default;   // only as a stage's unused default
  // record: an any-witness search, whose trail and witness are wanted.
  // closed: the pair is searched in closed semantics.
  Interval_filter(Runner& runner, Search_trail& trail, Check_stats& stats, bool record, bool closed = false)
    : exact_(std::make_unique<Exact_span<Runner>>(runner, closed)), trail_(&trail), stats_(&stats), record_(record),
      closed_(closed) {}

  bool skips_span(std::size_t) const { return false; }
  void search_span(int a, int b, std::size_t index, const std::array<bool, 3>& frame_of_a)
  {
    a_ = a, b_ = b, span_ = index, frame_ = frame_of_a;
    lines_.reset();   // a new search: its conquers count from zero again
    keyed_ = false;
    keys_.clear();
    plane_keys_.clear();
  }
  void found_in_span(std::size_t index)
  {
    if (record_) trail_->span = index;
  }
  bool stops_after(std::size_t) const { return false; }
  // The point is the rational run's own when the path was certified (the
  // trail is not approximate) and the intervals found it themselves. A
  // closed witness (a touching point, any rational) is made too: the runner
  // keeps it only when every coordinate is a point interval, that is the
  // rational run's number (Filtered_runner::exact_copy).
  bool witness_certified() const { return record_ && !trail_->approximate && !found_in_rationals_; }
  template <class F>
  void attempt(F make)
  {
    try {
      make();
    } catch (const CGAL::Uncertain_conversion_exception&) {
      // No witness: the pair goes to a rational run.
    }
  }

  // The leaf was kept: the path may now differ from the rational run's.
  void uncertain_simplification() { trail_->approximate = true; }
  bool takes_child(std::size_t, int) const { return true; }
  bool decides_here(std::size_t, bool) const { return true; }
  void found_at(const std::vector<int>& path, bool on_line)
  {
    if (!record_ || trail_->complete) return;
    trail_->path = path;
    trail_->on_line = on_line;
    trail_->complete = true;
  }

  const std::array<std::size_t, 3>* replay_line() const { return nullptr; }
  void replayed(bool) {}

  // Earliest mode (t* is any rational) is not decided line by line: an
  // uncertain sign there stops the run.
  template <class G>
  void test_line(G& g, const Pair_formula& f, std::size_t i, std::size_t j, std::size_t m, Search_goal<AFT>& goal)
  {
    bool before = goal.found;
    if (goal.earliest) {
      g.test_line(f, i, j, m, goal);
      return;
    }
    try {
      g.test_line(f, i, j, m, goal);
    } catch (const CGAL::Uncertain_conversion_exception&) {
      decide_in_rationals(g, f, i, j, m, goal);
    }
    if (record_ && !before && goal.found) trail_->line = {i, j, m};
  }

  int same_plane(const AK& k, const Hyperplane4<AFT>& h, const Hyperplane4<AFT>& g, long eh, int fh, long eg, int fg,
                 const Box<AFT, 4>& region)
  {
    try {
      return proportional(k, h, g);
    } catch (const CGAL::Uncertain_conversion_exception&) {
      return exact_->proportional(a_, b_, span_, frame_, eh, fh, eg, fg, region);
    }
  }

  // The normal keys of the sub-span's table, once it had an uncertain line.
  template <class FT>
  const std::vector<Vector4<FT>>* normal_keys() const
  {
    static_assert(std::is_same_v<FT, AFT>, "normal keys are the interval run's");
    return keyed_ ? &keys_ : nullptr;
  }
  template <class FT>
  const std::vector<Hyperplane4<FT>>* plane_keys() const
  {
    static_assert(std::is_same_v<FT, AFT>, "plane keys are the interval run's");
    return keyed_ ? &plane_keys_ : nullptr;
  }

  template <class V, class Inside>
  std::optional<bool> verdict_first(const V&, const std::vector<V>&, Inside&, std::size_t&)
  {
    return std::nullopt;
  }

private:
  std::unique_ptr<Exact_span<Runner>> exact_;
  Search_trail* trail_ = nullptr;
  Check_stats* stats_ = nullptr;
  bool record_ = false;
  bool closed_ = false;
  int a_ = -1, b_ = -1;
  std::size_t span_ = 0;
  std::array<bool, 3> frame_{};
  std::shared_ptr<typename Exact_span<Runner>::Lines> lines_;   // this conquer's, once one is needed
  std::size_t lines_conquer_ = 0;                               // which conquer they are for
  bool found_in_rationals_ = false;                             // the point is for a rational run to make
  bool keyed_ = false;                                          // keys_ made for this sub-span
  std::vector<Vector4<AFT>> keys_;
  std::vector<Hyperplane4<AFT>> plane_keys_;

  // One line the intervals could not decide; the same rational conquer
  // serves the rest of this conquer's lines.
  template <class G>
  void decide_in_rationals(G& g, const Pair_formula& f, std::size_t i, std::size_t j, std::size_t m, Search_goal<AFT>& goal)
  {
    if (!lines_ || lines_conquer_ != g.conquers()) {
      lines_ = exact_->lines(a_, b_, span_, frame_, g.layout(), g.region());
      lines_conquer_ = g.conquers();
    }
    if (!keyed_) {
      exact_->keys(a_, b_, span_, frame_, keys_, plane_keys_);
      keyed_ = true;
    }
    ++stats_->exact_lines;
    bool known = false;
    if (lines_->has_inside(f, i, j, m, goal.semantics, known)) {
      goal.found = goal.improved = true;
      found_in_rationals_ = true;
      if (record_) trail_->line_known = known;
    }
  }
};

} // namespace clash4d

#endif
