// Axis-aligned boxes, possibly unbounded: the S-bounds of §4.3.1 (3D) and the
// regions of the division stage (4D, always bounded).
#ifndef CLASH4D_GEOMETRY_BOX_H
#define CLASH4D_GEOMETRY_BOX_H

#include "numbers/Number_ops.h"
#include <CGAL/enum.h>
#include <array>
#include <cstddef>
#include <type_traits>

namespace clash4d {

template <class FT, std::size_t D>
struct Box {
  std::array<FT, D> lo = zeros(), hi = zeros();
  std::array<bool, D> has_lo{}, has_hi{};   // false: unbounded on that side
  bool empty = false;

  static Box whole() { return Box(); }      // Omega
  static Box nothing() { Box b; b.empty = true; return b; }

  bool bounded() const
  {
    for (std::size_t i = 0; i < D; ++i)
      if (!has_lo[i] || !has_hi[i]) return false;
    return true;
  }
  void set(std::size_t axis, const FT& l, const FT& h)
  {
    lo[axis] = l; hi[axis] = h; has_lo[axis] = has_hi[axis] = true;
  }

private:
  // Copies of one zero: a rational zero made per coordinate is an
  // allocation, and the S-bounds make empty and whole boxes by the
  // thousand (GMP numbers share their representation and are never
  // written through it).
  static std::array<FT, D> zeros()
  {
    if constexpr (std::is_trivially_copyable_v<FT>) return {};   // doubles, intervals
    else return shared_zeros<FT, D>();
  }
};

// The S-bound operators of §4.3.1: meet (the box intersection, sqcap) and
// join (the smallest box containing both, sqcup). They are constructions, not
// decisions, so they take plain minima and maxima (no tolerance).
template <class FT, std::size_t D>
Box<FT, D> meet(const Box<FT, D>& a, const Box<FT, D>& b)
{
  if (a.empty || b.empty) return Box<FT, D>::nothing();
  Box<FT, D> r = a;
  for (std::size_t i = 0; i < D; ++i) {
    if (b.has_lo[i]) r.lo[i] = r.has_lo[i] ? Number_ops<FT>::upper(r.lo[i], b.lo[i]) : b.lo[i];
    if (b.has_hi[i]) r.hi[i] = r.has_hi[i] ? Number_ops<FT>::lower(r.hi[i], b.hi[i]) : b.hi[i];
    r.has_lo[i] = r.has_lo[i] || b.has_lo[i];
    r.has_hi[i] = r.has_hi[i] || b.has_hi[i];
  }
  return r;
}

template <class FT, std::size_t D>
Box<FT, D> join(const Box<FT, D>& a, const Box<FT, D>& b)
{
  if (a.empty) return b;
  if (b.empty) return a;
  Box<FT, D> r = a;
  for (std::size_t i = 0; i < D; ++i) {
    r.has_lo[i] = a.has_lo[i] && b.has_lo[i];
    r.has_hi[i] = a.has_hi[i] && b.has_hi[i];
    if (r.has_lo[i]) r.lo[i] = Number_ops<FT>::lower(r.lo[i], b.lo[i]);
    if (r.has_hi[i]) r.hi[i] = Number_ops<FT>::upper(r.hi[i], b.hi[i]);
  }
  return r;
}

// A box with no interior bounds only a null regularised set: a regular closed
// set inside it has empty interior, hence is empty. So touching bounds
// (hi == lo) prune, which is what makes contact cases cheap.
template <class K, class FT, std::size_t D>
bool has_no_interior(const K& k, const Box<FT, D>& b)
{
  if (b.empty) return true;
  for (std::size_t i = 0; i < D; ++i)
    if (b.has_lo[i] && b.has_hi[i] && k.compare(b.hi[i], b.lo[i]) != CGAL::POSITIVE) return true;
  return false;
}

// Closed semantics keeps boxes without interior: closed objects that touch
// meet in one. Only a side with hi < lo makes a box empty.
template <class K, class FT, std::size_t D>
bool is_empty_box(const K& k, const Box<FT, D>& b)
{
  if (b.empty) return true;
  for (std::size_t i = 0; i < D; ++i)
    if (b.has_lo[i] && b.has_hi[i] && k.compare(b.hi[i], b.lo[i]) == CGAL::NEGATIVE) return true;
  return false;
}

// Same contents on the grid of kernel k (Kernel_base::same_on_grid): the
// S-bound passes stop when a pass moved no bound by a grid step.
template <class K, class FT, std::size_t D>
bool same_on_grid(const K& k, const Box<FT, D>& a, const Box<FT, D>& b)
{
  if (a.empty || b.empty) return a.empty == b.empty;
  for (std::size_t i = 0; i < D; ++i) {
    if (a.has_lo[i] != b.has_lo[i] || a.has_hi[i] != b.has_hi[i]) return false;
    if (a.has_lo[i] && !k.same_on_grid(a.lo[i], b.lo[i])) return false;
    if (a.has_hi[i] && !k.same_on_grid(a.hi[i], b.hi[i])) return false;
  }
  return true;
}

} // namespace clash4d

#endif
