// Per-query time of a check, shared by the benchmarks: the query is repeated
// until min_seconds have passed (at most 100000 times), so short queries are
// timed over many runs.
#ifndef CLASH4D_BENCH_TIMING_H
#define CLASH4D_BENCH_TIMING_H

#include <chrono>

namespace clash4d {

struct Timing {
  double seconds_per_query;
  bool collide;
};

// run() returns the verdict (collide or not) of one query.
template <class Run>
Timing time_it(Run run, double min_seconds)
{
  auto start = std::chrono::steady_clock::now();
  long reps = 0;
  bool collide = false;
  double elapsed = 0;
  do {
    collide = run();
    ++reps;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } while (elapsed < min_seconds && reps < 100000);
  return {elapsed / reps, collide};
}

} // namespace clash4d

#endif
