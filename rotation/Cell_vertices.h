// The vertices of the closure of a generic point's cell in a plane
// arrangement at one time (Rotating_pair.h: the contact point at t* is
// where one of them goes), for any number type: the exact stage's rationals
// and the double stage's doubles. Each is three planes, none through w,
// whose meeting point is on w's side of every plane or on it.
#ifndef CLASH4D_ROTATION_CELL_VERTICES_H
#define CLASH4D_ROTATION_CELL_VERTICES_H

#include "numbers/Rational.h"

#include <algorithm>
#include <array>
#include <vector>

namespace clash4d {

template <class FT>
FT det3(const std::array<FT, 4>& a, const std::array<FT, 4>& b, const std::array<FT, 4>& c)
{
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// The point where rows a, b, c (n . x + e = 0) meet, by Cramer's rule;
// d = det3(a, b, c) != 0.
template <class FT>
std::array<FT, 3> cramer_point(const std::array<FT, 4>& a, const std::array<FT, 4>& b, const std::array<FT, 4>& c,
                               const FT& d)
{
  std::array<FT, 3> x;
  for (int col = 0; col < 3; ++col) {
    std::array<std::array<FT, 4>, 3> m = {a, b, c};
    for (auto& row : m) row[col] = -row[3];
    x[col] = det3(m[0], m[1], m[2]) / d;
  }
  return x;
}

// sign(x) as -1, 0, 1.
template <class FT>
int sign_of(const FT& x)
{
  return x < FT(0) ? -1 : FT(0) < x ? 1 : 0;
}

// The side of x of the plane h: sign(h_0 x_0 + h_1 x_1 + h_2 x_2 + h_3);
// in rationals without reducing the sum (numbers/Rational.h).
template <class FT>
int side_of(const std::array<FT, 4>& h, const std::array<FT, 3>& x)
{
  return sign_of(h[0] * x[0] + h[1] * x[1] + h[2] * x[2] + h[3]);
}
inline int side_of(const std::array<Rational, 4>& h, const std::array<Rational, 3>& x)
{
  return sign_of_sum_of_products(h.data(), x.data(), 3, &h[3]);
}

// rows: each plane's (n, e) at the time; w: a point on no plane. Calls
// found(i, j, k) for each vertex of the closure of w's cell, i < j < k,
// until it returns true: first the triples of the rows `first` names (the
// planes of the minors that vanish at t*, where the contact is: a handful
// of rows instead of every triple of the pair's), then every other triple
// in order. filter(i, j, k, side) (side: w's side of each plane), may say
// early that a triple surely is one (Cell_filter::vertex: planes of
// nonzero sides, independent, meeting on w's side of every other plane) or
// surely is not (Cell_filter::not_vertex); the triples it leaves
// (Cell_filter::unknown) are decided in FT, so it changes no answer.
enum class Cell_filter { not_vertex, unknown, vertex };

template <class FT, class Found, class Filter>
void cell_vertices(const std::vector<std::array<FT, 4>>& rows, const std::array<FT, 3>& w, Found found,
                   Filter filter, std::vector<int> first = {})
{
  std::size_t m = rows.size();
  std::vector<int> side(m);
  for (std::size_t i = 0; i < m; ++i) side[i] = side_of(rows[i], w);
  // True once found(i, j, k) has said so.
  auto vertex = [&](std::size_t i, std::size_t j, std::size_t k) {
    if (!side[i] || !side[j] || !side[k]) return false;
    Cell_filter sure = filter(i, j, k, side);
    if (sure == Cell_filter::not_vertex) return false;
    if (sure == Cell_filter::vertex) return found(static_cast<int>(i), static_cast<int>(j), static_cast<int>(k));
    FT d = det3(rows[i], rows[j], rows[k]);
    if (sign_of(d) == 0) return false;
    std::array<FT, 3> x = cramer_point(rows[i], rows[j], rows[k], d);
    for (std::size_t l = 0; l < m; ++l)
      if (side[l] * side_of(rows[l], x) < 0) return false;
    return found(static_cast<int>(i), static_cast<int>(j), static_cast<int>(k));
  };
  std::sort(first.begin(), first.end());
  first.erase(std::unique(first.begin(), first.end()), first.end());
  std::vector<bool> tried(m, false);
  for (std::size_t a = 0; a < first.size(); ++a)
    for (std::size_t b = a + 1; b < first.size(); ++b)
      for (std::size_t c = b + 1; c < first.size(); ++c)
        if (vertex(first[a], first[b], first[c])) return;
  for (int i : first) tried[i] = true;
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j)
      for (std::size_t k = j + 1; k < m; ++k)
        if (!(tried[i] && tried[j] && tried[k]) && vertex(i, j, k)) return;
}

template <class FT, class Found>
void cell_vertices(const std::vector<std::array<FT, 4>>& rows, const std::array<FT, 3>& w, Found found)
{
  cell_vertices(rows, w, found,
                [](std::size_t, std::size_t, std::size_t, const std::vector<int>&) { return Cell_filter::unknown; });
}

} // namespace clash4d

#endif
