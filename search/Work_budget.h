// A bound on a run's time (--max-seconds; issue 16, "A work budget"). The
// search looks at it once per region of the division (§4.1) and once per
// line of generate-and-test (§4.2), so a run stops within about one line's
// work of the deadline, whatever the kernel. Past it, Budget_exceeded is
// thrown and the command answers exit 3 naming the limit, with nothing
// partial printed as an answer.
#ifndef CLASH4D_SEARCH_WORK_BUDGET_H
#define CLASH4D_SEARCH_WORK_BUDGET_H

#include <atomic>
#include <chrono>
#include <cstdint>

namespace clash4d {

// Deliberately not a std::exception: the handlers that turn one subject's
// failure into a row of a comparison (compare/Comparer.cpp) must not
// swallow the run's budget, or a comparison would be partial.
struct Budget_exceeded {
  double seconds;   // the budget that ran out
};

// One budget per process, set by the command line before a command runs.
class Work_budget {
public:
  // seconds from now; 0 (the default) is unlimited.
  static void start(double seconds)
  {
    seconds_().store(seconds);
    std::int64_t deadline = 0;
    if (seconds > 0)
      deadline = now_ns() + static_cast<std::int64_t>(seconds * 1e9 < 9e18 ? seconds * 1e9 : 9e18);
    deadline_().store(deadline);
  }
  // Throws Budget_exceeded past the deadline.
  static void check()
  {
    std::int64_t deadline = deadline_().load(std::memory_order_relaxed);
    if (deadline != 0 && now_ns() > deadline) throw Budget_exceeded{seconds_().load()};
  }

private:
  static std::int64_t now_ns()
  {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }
  static std::atomic<std::int64_t>& deadline_()
  {
    static std::atomic<std::int64_t> d{0};
    return d;
  }
  static std::atomic<double>& seconds_()
  {
    static std::atomic<double> s{0};
    return s;
  }
};

} // namespace clash4d

#endif
