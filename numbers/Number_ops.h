// Minimum, maximum, magnitude and sameness of numbers, as constructions
// rather than decisions. On a totally ordered number type they are the usual ones; the
// interval kernel specialises them (exact/Interval_kernel.h) to enclose the
// exact minimum and maximum without asking which operand is smaller, so a
// box meet or join never fails the filter (CGAL's Min/Max on Interval_nt).
#ifndef CLASH4D_NUMBERS_NUMBER_OPS_H
#define CLASH4D_NUMBERS_NUMBER_OPS_H

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

namespace clash4d {

template <class FT>
struct Number_ops {
  static FT lower(const FT& a, const FT& b) { return b < a ? b : a; }
  static FT upper(const FT& a, const FT& b) { return a < b ? b : a; }
  // Compared with the integer 0, not a made zero (in rationals, an
  // allocation per call); a nonnegative a is returned as it is (shared).
  static FT magnitude(const FT& a) { return a < 0 ? -a : a; }
  // Identical values (a shortcut before a decision, see
  // Kernel_base::same_on_grid); intervals: the same enclosure.
  static bool same(const FT& a, const FT& b) { return a == b; }
};

// A zero to copy from, for members that start at zero: in rationals a copy
// shares one number (CGAL's handles, copy on write), where a zero made per
// member is an allocation each (a pair's result holds nine).
template <class FT>
const FT& shared_zero()
{
  static const FT zero(0);
  return zero;
}

// A zero to start a member or a variable at: a copy of the shared one
// where a zero owns memory (rationals), else made in place (doubles,
// intervals: no static to look up).
template <class FT>
FT zero_value()
{
  if constexpr (std::is_trivially_destructible_v<FT>) return FT(0);
  else return shared_zero<FT>();
}

// N copies of it, each made as a copy (a default array would make N
// zeros first): coordinates that start at zero.
template <class FT, std::size_t... I>
std::array<FT, sizeof...(I)> shared_zeros(std::index_sequence<I...>)
{
  return {{((void)I, zero_value<FT>())...}};
}
template <class FT, std::size_t N>
std::array<FT, N> shared_zeros()
{
  return shared_zeros<FT>(std::make_index_sequence<N>());
}

// Exchanges two numbers without copying either. A rational is a handle
// (CGAL's Gmpq declares a destructor, so it has no move: std::swap, and a
// defaulted move, copy it, a reference count each way); its own swap
// exchanges the pointers. Other numbers by std::swap.
template <class FT, class = void>
struct Has_member_swap : std::false_type {};
template <class FT>
struct Has_member_swap<FT, std::void_t<decltype(std::declval<FT&>().swap(std::declval<FT&>()))>> : std::true_type {};

template <class FT>
void swap_numbers(FT& a, FT& b) noexcept
{
  if constexpr (Has_member_swap<FT>::value) a.swap(b);
  else std::swap(a, b);
}
template <class FT, std::size_t N>
void swap_numbers(std::array<FT, N>& a, std::array<FT, N>& b) noexcept
{
  for (std::size_t i = 0; i < N; ++i) swap_numbers(a[i], b[i]);
}

} // namespace clash4d

#endif
