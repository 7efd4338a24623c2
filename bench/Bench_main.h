// A benchmark's main: its run, or the message of what stopped it (a bad
// option, bench/Option_number.h; an unreadable scene file) as
// "<name>: <message>" and exit 2, never an abort.
#ifndef CLASH4D_BENCH_BENCH_MAIN_H
#define CLASH4D_BENCH_BENCH_MAIN_H

#include <cstdio>
#include <exception>

namespace clash4d {

inline int bench_main(const char* name, int (*run)(int, char**), int argc, char** argv)
{
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return 2;
  }
}

} // namespace clash4d

#endif
