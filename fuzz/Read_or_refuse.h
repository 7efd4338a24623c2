// The fuzz targets' one rule for a reader on arbitrary bytes: it reads, or
// it refuses with Input_error and exit 2 or 3. Anything else escaping (exit
// 4 included: CGAL failing inside) is a finding: the target says what, then
// aborts, and libFuzzer saves the input.
#ifndef CLASH4D_FUZZ_READ_OR_REFUSE_H
#define CLASH4D_FUZZ_READ_OR_REFUSE_H

#include "scene/Input_error.h"
#include <cstdlib>
#include <exception>
#include <iostream>

namespace clash4d {

// True when read() returned, false when it refused as it should.
template <class Read>
bool read_or_refuse(Read read)
{
  try {
    read();
    return true;
  } catch (const Input_error& e) {
    if (e.exit_code() == CLASH4D_EXIT_INVALID || e.exit_code() == CLASH4D_EXIT_LIMIT) return false;
    std::cerr << "an input error with exit code " << e.exit_code() << ": " << e.format("input") << "\n";
    std::abort();
  } catch (const std::exception& e) {
    std::cerr << "an exception other than Input_error escaped the reader: " << e.what() << "\n";
    std::abort();
  }
}

} // namespace clash4d

#endif
