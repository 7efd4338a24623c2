// Per-query time of a check, shared by the benchmarks: the query is repeated
// until min_seconds have passed (at most 100000 times, after a first query
// left out), so short queries are timed over many runs. time_in_turns
// times several queries that are compared with each other (exact, double,
// FCL on one scene) repeat times, taking turns, and keeps each one's least
// time: on a shared machine one measurement moves by a third, and the
// ratios then hold queries measured under the same load.
#ifndef CLASH4D_BENCH_TIMING_H
#define CLASH4D_BENCH_TIMING_H

#include <array>
#include <chrono>

namespace clash4d {

struct Timing {
  double seconds_per_query;
  bool collide;
};

// run() returns the verdict (collide or not) of one query. The first query
// pays the process's one-time costs (the first scene of a run measured
// 10 ms for a query of 9 us: libraries' first use, the allocator growing):
// it is timed alone, and left out when it is shorter than min_seconds, so
// a slow query is still run only once.
template <class Run>
Timing time_it(Run run, double min_seconds)
{
  auto since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  auto start = std::chrono::steady_clock::now();
  bool collide = run();
  double elapsed = since(start);
  if (elapsed >= min_seconds) return {elapsed, collide};
  start = std::chrono::steady_clock::now();
  long reps = 0;
  do {
    collide = run();
    ++reps;
    elapsed = since(start);
  } while (elapsed < min_seconds && reps < 100000);
  return {elapsed / reps, collide};
}

// runs...: each returns one query's verdict; their timings, in order.
template <class... Run>
std::array<Timing, sizeof...(Run)> time_in_turns(int repeat, double min_seconds, Run... runs)
{
  std::array<Timing, sizeof...(Run)> best{};
  for (int r = 0; r < repeat; ++r) {
    std::size_t i = 0;
    auto take = [&](auto& run) {
      Timing t = time_it(run, min_seconds);
      if (r == 0 || t.seconds_per_query < best[i].seconds_per_query) best[i] = t;
      ++i;
    };
    (take(runs), ...);   // left to right: the order given
  }
  return best;
}

} // namespace clash4d

#endif
