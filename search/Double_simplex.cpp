#include "search/Double_simplex.h"

namespace clash4d {

// Multiversioned (GCC's target_clones): the loops below are most of a
// convex pair's query (search/Convex_pair.h), and AVX2 does four of their
// operations where the base x86-64 set does two. Each operation rounds the
// same in both (IEEE), so the guesses, and every answer, are the same.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(CLASH4D_NO_CLONES)
__attribute__((target_clones("avx2", "default")))
#endif
void pivot_tableau(double* T, int rows, int width, int leave, int enter)
{
  double* pivot_row = T + static_cast<std::ptrdiff_t>(leave) * width;
  double p = pivot_row[enter];
  for (int c = 0; c < width; ++c) pivot_row[c] /= p;
  for (int r = 0; r < rows; ++r)
    if (r != leave) eliminate_row(T + static_cast<std::ptrdiff_t>(r) * width, pivot_row, width, enter);
}

} // namespace clash4d
