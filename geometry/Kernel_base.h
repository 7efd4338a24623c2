// What every kernel provides, written once. A kernel bundles a number type
// with its sign decision; the stages ask the kernel for every sign, never the
// number type directly, so a filtered kernel (interval arithmetic with an
// exact fallback, as CGAL's Filtered_predicate) can override the predicates
// below without touching a stage.
#ifndef CLASH4D_GEOMETRY_KERNEL_BASE_H
#define CLASH4D_GEOMETRY_KERNEL_BASE_H

#include "numbers/Number_ops.h"
#include "geometry/Hyperplane4.h"
#include "geometry/kernel_ft4.h"
#include <CGAL/Uncertain.h>
#include <CGAL/enum.h>

namespace clash4d {

template <class Derived, class FT_>
class Kernel_base {
public:
  using FT = FT_;
  // The ring in_ring writes planes in (+ - *, no division): FT itself
  // unless a kernel refines it (the rational kernel: GMP integers), with
  // sign on it.
  using RT = FT_;

  const Derived& derived() const { return static_cast<const Derived&>(*this); }

  // The dyadic grid of the search: multiples of 2^-grid_bits. Choices that
  // are heuristics (when to stop the S-bound passes, which frame to fit a
  // region in) are made on grid points, so that every kernel certifies them
  // alike and an interval run takes the rational run's path.
  static constexpr int grid_bits = 20;

  // The grid point nearest to x. Rounding jumps halfway between grid points,
  // away from the integers and short binary fractions scene values sit on,
  // so an interval around such a value still has one grid point.
  FT grid_point(const FT& x) const { return round_to_grid(x, grid_bits); }
  bool same_on_grid(const FT& a, const FT& b) const
  {
    return Number_ops<FT>::same(a, b) || derived().compare(grid_point(a), grid_point(b)) == CGAL::ZERO;
  }
  bool less_on_grid(const FT& a, const FT& b) const { return derived().less(grid_point(a), grid_point(b)); }

  // The index of a largest |v_q|, for a choice any answer is right for (the
  // coordinate a base point is solved on); an approximate kernel may pick
  // any of near ties.
  template <std::size_t N>
  int largest_component(const std::array<FT, N>& v) const
  {
    int k = 0;
    for (int q = 1; q < static_cast<int>(N); ++q)
      if (derived().less(Number_ops<FT>::magnitude(v[k]), Number_ops<FT>::magnitude(v[q]))) k = q;
    return k;
  }

  // x rounded to the nearest multiple of 2^-bits (bits >= 0).
  FT round_to_grid(const FT& x, int bits) const
  {
    return derived().floor_to_grid(x + derived().power_of_two(-bits - 1), bits);
  }

  // 2^e for the far bound R of a pair unbounded along an axis
  // (model/Far_bound.h, search/Span_region.h). A kernel whose numbers cannot
  // hold R with room for the search refines it: the interval kernel hands
  // the pair to the rationals, the double kernel refuses (exit 3).
  FT far_power_of_two(int e) const { return derived().power_of_two(e); }

  // For conservative filters only (the pair sweep): true unless x is known
  // not to be positive. An interval kernel answers true when unsure.
  bool possibly_positive(const FT& x) const { return derived().sign(x) == CGAL::POSITIVE; }
  // The same for x >= 0 (closed semantics: touching boxes meet).
  bool possibly_nonnegative(const FT& x) const { return derived().sign(x) != CGAL::NEGATIVE; }

  // The sign where the kernel can certify it, indeterminate otherwise,
  // without throwing: for a policy that has another way to decide a single
  // sign (a convex pair's, search/No_filter.h convex_certain), where a
  // throw costs more than the sign. Exact and double kernels: sign(x).
  template <class T>   // FT, or the ring RT
  CGAL::Uncertain<CGAL::Sign> uncertain_sign(const T& x) const { return derived().sign(x); }

  // For box simplification (§4.1), which may always be skipped
  // (regularised-semantics.md, item 4): whether x >= 0 (x > 0 when strict).
  // An approximate kernel answers indeterminate when it cannot tell; the
  // caller then keeps the leaf, which costs work, never a wrong answer.
  CGAL::Uncertain<bool> is_nonnegative(const FT& x, bool strict) const
  {
    CGAL::Sign s = derived().sign(x);
    return strict ? s == CGAL::POSITIVE : s != CGAL::NEGATIVE;
  }

  // a / b for b of known sign sb != 0 (an interval kernel uses the sign to
  // skip the cases of a general division).
  FT quotient(const FT& a, const FT& b, CGAL::Sign) const { return a / b; }

  // The sign of a - b (a kernel may refine it: the rational kernel
  // compares without making a - b).
  CGAL::Sign compare(const FT& a, const FT& b) const { return derived().sign(a - b); }
  bool less(const FT& a, const FT& b) const { return derived().compare(a, b) == CGAL::NEGATIVE; }

  // Sign of n.p + c: which side of a hyperplane a point lies on.
  template <std::size_t N>
  CGAL::Sign side(const std::array<FT, N>& n, const FT& c, const std::array<FT, N>& p) const
  {
    return derived().sign(dot_plus(n, p, c));
  }
  // The same where the kernel can certify it, indeterminate otherwise
  // (uncertain_sign: no throw).
  template <std::size_t N>
  CGAL::Uncertain<CGAL::Sign> uncertain_side(const std::array<FT, N>& n, const FT& c, const std::array<FT, N>& p) const
  {
    return derived().uncertain_sign(dot_plus(n, p, c));
  }

  // Sign of a dot product: orientation of a direction against a normal.
  template <std::size_t N>
  CGAL::Sign dot_sign(const std::array<FT, N>& a, const std::array<FT, N>& b) const
  {
    return derived().sign(dot(a, b));
  }

  CGAL::Sign orientation4(const Vector4<FT>& a, const Vector4<FT>& b, const Vector4<FT>& c, const Vector4<FT>& d) const
  {
    return derived().sign(determinant4(a, b, c, d));
  }

  // A positive multiple of h in the numbers this kernel computes with most
  // cheaply (the same half-space): h itself, unless a kernel refines it
  // (the rational kernel: coprime integers, whose products need no gcd).
  Hyperplane4<FT> in_lowest_terms(const Hyperplane4<FT>& h) const { return h; }
  // The same in the ring RT, for division-free elimination.
  Hyperplane4<RT> in_ring(const Hyperplane4<FT>& h) const { return derived().in_lowest_terms(h); }

  // The solution of the N x N system [M | rhs] whose matrix is known
  // regular, by elimination with the largest pivot the kernel sees (any
  // pivot gives the same exact solution; the largest keeps an approximate
  // kernel's error small). The rational kernel refines it (fraction-free).
  template <std::size_t N>
  std::array<FT, N> solve_regular(std::array<std::array<FT, N + 1>, N> M) const
  {
    for (std::size_t c = 0; c < N; ++c) {
      std::array<FT, N> column;
      for (std::size_t r = 0; r < N; ++r) column[r] = r < c ? FT(0) : M[r][c];
      std::swap(M[c], M[static_cast<std::size_t>(derived().largest_component(column))]);
      for (std::size_t r = c + 1; r < N; ++r) {
        FT f = M[r][c] / M[c][c];
        for (std::size_t cc = c + 1; cc <= N; ++cc) M[r][cc] -= f * M[c][cc];
      }
    }
    std::array<FT, N> x;
    for (std::size_t r = N; r-- > 0;) {
      FT s = M[r][N];
      for (std::size_t cc = r + 1; cc < N; ++cc) s -= M[r][cc] * x[cc];
      x[r] = s / M[r][r];
    }
    return x;
  }

  // Zero vector test, as a predicate so tolerances apply consistently.
  template <std::size_t N>
  bool is_zero(const std::array<FT, N>& v) const
  {
    for (const FT& x : v)
      if (derived().sign(x) != CGAL::ZERO) return false;
    return true;
  }
};

} // namespace clash4d

#endif
