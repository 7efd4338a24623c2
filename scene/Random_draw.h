// Seeded draws that are the same on every platform and standard library:
// only std::mt19937_64's raw output is used (its sequence is fixed by the
// C++ standard), never std::uniform_*_distribution or std::shuffle, whose
// algorithms differ between libraries. A seed names one scene sequence.
#ifndef CLASH4D_SCENE_RANDOM_DRAW_H
#define CLASH4D_SCENE_RANDOM_DRAW_H

#include <cstdint>
#include <initializer_list>
#include <random>
#include <utility>
#include <vector>

namespace clash4d {

class Random_draw {
public:
  explicit Random_draw(std::uint64_t seed) : own_(seed), g_(&own_) {}
  // Draws from a generator the caller keeps (successive scenes of one stream).
  explicit Random_draw(std::mt19937_64& shared) : g_(&shared) {}
  Random_draw(const Random_draw&) = delete;
  Random_draw& operator=(const Random_draw&) = delete;

  // 0 .. n-1 (n > 0); the slight bias of the remainder is irrelevant here and
  // keeps the draw a one-liner anyone can reimplement.
  std::uint64_t below(std::uint64_t n) { return (*g_)() % n; }
  // lo .. hi inclusive.
  long range(long lo, long hi) { return lo + static_cast<long>(below(static_cast<std::uint64_t>(hi - lo + 1))); }
  bool percent(int p) { return below(100) < static_cast<std::uint64_t>(p); }
  int sign() { return percent(50) ? 1 : -1; }
  template <class T>
  T pick(std::initializer_list<T> xs) { return xs.begin()[below(xs.size())]; }
  // Fisher-Yates from the back.
  template <class T>
  void shuffle(std::vector<T>& xs)
  {
    for (std::size_t i = xs.size(); i > 1; --i) std::swap(xs[i - 1], xs[below(i)]);
  }

private:
  std::mt19937_64 own_;
  std::mt19937_64* g_;
};

// A well-mixed 64-bit value from a counter (SplitMix64), for deriving one
// generator seed per (campaign seed, case index).
inline std::uint64_t splitmix64(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

} // namespace clash4d

#endif
