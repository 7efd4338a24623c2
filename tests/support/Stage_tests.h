// Shared by the per-stage unit tests (test_s_bounds, test_formula,
// test_neighbourhood, test_null_object_test): the two kernels every case runs
// on, exact small numbers in either, and the seed convention of the campaign
// tests (CLASH4D_SEED overrides; one splitmix64 seed per case).
#ifndef CLASH4D_TESTS_SUPPORT_STAGE_TESTS_H
#define CLASH4D_TESTS_SUPPORT_STAGE_TESTS_H

#include "exact/Rational_kernel.h"
#include "float/Double_kernel.h"
#include <boost/mpl/list.hpp>
#include <cstdint>
#include <cstdlib>
#include <random>

namespace clash4d::stage_tests {

// Every hand-derived case uses small integers and halves, exact in doubles
// too, so the double kernel (tolerance 0) must give the same answers.
using Kernels = boost::mpl::list<Rational_kernel, Double_kernel>;

// n / d in the kernel's number type (exact for the values used here).
template <class FT>
FT num(long n, long d = 1)
{
  return FT(n) / FT(d);
}

inline std::uint64_t env_number(const char* name, std::uint64_t fallback)
{
  const char* v = std::getenv(name);
  return v && *v ? std::strtoull(v, nullptr, 10) : fallback;
}

// One engine per case, so a case is reproducible from its own seed.
inline std::uint64_t case_seed(std::uint64_t seed, std::uint64_t index)
{
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ull * (index + 1);   // splitmix64
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// A uniform integer in [lo, hi] from the engine's raw output (not
// uniform_int_distribution, which differs between standard libraries).
inline long pick(std::mt19937_64& rng, long lo, long hi)
{
  return lo + static_cast<long>(rng() % static_cast<std::uint64_t>(hi - lo + 1));
}

} // namespace clash4d::stage_tests

#endif
