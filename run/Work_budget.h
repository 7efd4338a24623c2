// A bound on a run's time (--max-seconds; issue 16, "A work budget"), and
// the API's cancellation. It is the bottom of the folder graph, so every
// step of a run can look at it, the scene reader's mesh decomposition too
// (scene/Child_process.h). The search looks at it once per region of the
// division (§4.1) and once per line of generate-and-test (§4.2), so a run
// stops within about one line's work of the deadline, whatever the kernel.
// Past it, Budget_exceeded is thrown and the command answers exit 3 naming
// the limit, with nothing partial printed as an answer.
#ifndef CLASH4D_RUN_WORK_BUDGET_H
#define CLASH4D_RUN_WORK_BUDGET_H

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>

namespace clash4d {

// Deliberately not a std::exception: the handlers that turn one subject's
// failure into a row of a comparison (compare/Comparer.cpp) must not
// swallow the run's budget, or a comparison would be partial.
struct Budget_exceeded {
  double seconds;   // the budget that ran out
};

// Thrown, past the same places, when a run's cancel flag is set (the API's
// cancellation: Ctrl-C in Python). Not a std::exception either.
struct Run_cancelled {};

// The budget of one run of the public API (its max_seconds and cancel flag),
// which the threads doing that run look at (this_thread_run) instead of
// the process's: concurrent runs keep their own limits.
struct Run_budget {
  double seconds = 0;                            // 0: no deadline
  std::int64_t deadline = 0;                     // Work_budget::deadline_after(seconds)
  const std::atomic<bool>* cancel = nullptr;     // set from another thread to stop the run
};

// One budget per process, set by the command line before a command runs.
class Work_budget {
public:
  // seconds from now; 0 (the default) is unlimited.
  static void start(double seconds)
  {
    seconds_().store(seconds);
    deadline_().store(deadline_after(seconds));
  }
  // Throws Budget_exceeded past the deadline (Run_cancelled when cancelled).
  static void check()
  {
    if (std::shared_ptr<const Run_budget> run = this_thread_run().lock()) {
      if (run->cancel && run->cancel->load(std::memory_order_relaxed)) throw Run_cancelled{};
      if (run->deadline != 0 && now_ns() > run->deadline) throw Budget_exceeded{run->seconds};
      return;
    }
    std::int64_t deadline = deadline_().load(std::memory_order_relaxed);
    if (deadline != 0 && now_ns() > deadline) throw Budget_exceeded{seconds_().load()};
  }
  // Whether check() can ever throw on this thread: a deadline or a cancel
  // flag (a step that cannot look at it often runs where it can be stopped
  // from outside: scene/Child_process.h).
  static bool limited()
  {
    if (std::shared_ptr<const Run_budget> run = this_thread_run().lock()) return run->cancel || run->deadline != 0;
    return deadline_().load(std::memory_order_relaxed) != 0;
  }
  // The steady-clock deadline `seconds` from now; 0 when seconds <= 0.
  static std::int64_t deadline_after(double seconds)
  {
    if (!(seconds > 0)) return 0;
    return now_ns() + static_cast<std::int64_t>(seconds * 1e9 < 9e18 ? seconds * 1e9 : 9e18);
  }
  // This thread's run (none: the process's budget). Held weakly, so a worker
  // thread that outlives the run falls back to the process's budget.
  static std::weak_ptr<const Run_budget>& this_thread_run()
  {
    static thread_local std::weak_ptr<const Run_budget> run;
    return run;
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
