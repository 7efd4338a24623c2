// The seconds a stage took, for `check --stats` (Check_stats::seconds_*),
// read only when the run was asked for them (Check_stats::timed). A clock
// read costs about 20 ns (clock_gettime through the vDSO), and a convex
// pair's query reads it about ten times in a few microseconds: 5% of
// the query, for figures nobody prints without --stats.
#ifndef CLASH4D_SEARCH_STAGE_CLOCK_H
#define CLASH4D_SEARCH_STAGE_CLOCK_H

#include <chrono>

namespace clash4d {

class Stage_clock {
public:
  using Clock = std::chrono::steady_clock;

  // Started now when on; off, it reads no clock and every figure is 0.
  explicit Stage_clock(bool on) : on_(on)
  {
    if (on_) start_ = Clock::now();
  }

  // Seconds since the start (0 when off).
  double seconds() const { return on_ ? std::chrono::duration<double>(Clock::now() - start_).count() : 0.0; }

  // Seconds since the start, and a new start now (the next stage's).
  double lap()
  {
    if (!on_) return 0.0;
    Clock::time_point now = Clock::now();
    double s = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    return s;
  }

private:
  bool on_;
  Clock::time_point start_{};
};

} // namespace clash4d

#endif
