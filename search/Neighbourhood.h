// Regularised neighbourhood classification of a point on a line in space-time
// (Appendix A). All hyperplanes through the point contain the line direction l,
// so the neighbourhood is a central arrangement in the 3D quotient by l. We
// enumerate one direction inside every open cell of that arrangement and ask
// the caller whether the formula holds there.
//
// Square-root free: Appendix A's orthonormal basis and Gram-Schmidt are
// replaced by generalised cross products, which span the same subspaces.
//  - no plane through the point: the point itself is generic (step 0 of A);
//  - three planes with independent normals: the 8 sign vectors (A.2);
//  - all normals parallel: the two directions +-n (A.2, n <= 2 in effect);
//  - otherwise every cell is a cone with an extreme ray r = l x n_i x n_j
//    (A.4 and A.5: "crawling along all possible edges leading from that
//    vertex"); around r the planes through r cut sectors, and r + eps * s with
//    s the sum of two consecutive sector rays lies inside one cell. Every cell
//    has an extreme ray, so every cell is visited (A.3's counting shortcut is
//    subsumed: it is this enumeration for coplanar normals).
// find_inside_around does the same at a point that is not on a common line
// (a vertex, for closed semantics): with four independent planes through it
// every one of the 16 sign vectors is a cell; otherwise every cell around a
// vertex is a pointed cone with an extreme ray on three of the planes, and
// its cells are found around that ray as above (A.5 one dimension up); when
// the normals do not span space-time they share a line, and the 3D case
// applies along it.
#ifndef CLASH4D_SEARCH_NEIGHBOURHOOD_H
#define CLASH4D_SEARCH_NEIGHBOURHOOD_H

#include "numbers/Number_ops.h"
#include "geometry/kernel_ft4.h"
#include <CGAL/enum.h>
#include <algorithm>
#include <optional>
#include <vector>

namespace clash4d {

template <class K>
class Neighbourhood {
public:
  using FT = typename K::FT;
  using V = Vector4<FT>;

  explicit Neighbourhood(const K& k) : k_(k) {}

  // The cells around a line that find_inside enumerated, in its order: a
  // direction into each and the signs there. Every point of a line between
  // two cuts has the same planes through it, hence the same cells; only
  // the formula's answer (inside) differs from one edge to the next. So
  // the caller may keep one per line and planes through it, and each later
  // point of it asks inside over these, in the same order, instead of
  // constructing the rays and sectors again: the same first cell inside,
  // the same direction. complete: every cell is there.
  struct Memo {
    std::vector<std::pair<V, std::vector<int>>> cells;
    bool complete = false;
  };

  // normals: the planes through the point. inside(signs) says whether the
  // formula holds in the open cell where plane i has sign signs[i] (+1/-1).
  // Returns a direction into the first cell found inside, or nothing.
  // memo: the cells found for the same line and normals before, or empty.
  template <class Inside>
  std::optional<V> find_inside(const V& l, const std::vector<V>& normals, Inside inside, Memo* memo = nullptr)
  {
    std::size_t n = normals.size();
    std::vector<int> signs(n);
    if (n == 0) {
      if (inside(signs)) return V{FT(0), FT(0), FT(0), FT(0)};
      return std::nullopt;
    }
    if (n == 3 && k_.orientation4(l, normals[0], normals[1], normals[2]) != CGAL::ZERO)
      return three_independent(l, normals, inside);
    if (all_parallel(normals)) {
      for (int s : {1, -1}) {
        V d = scaled(normals[0], s);
        if (test(normals, d, signs, inside)) return d;
      }
      return std::nullopt;
    }
    if (!memo) return around_extreme_rays(l, normals, inside, nullptr);
    for (const auto& cell : memo->cells) {
      ++tested_;
      if (inside(cell.second)) return cell.first;
    }
    if (memo->complete) return std::nullopt;
    memo->cells.clear();   // a prefix: enumerate again, recording every cell
    std::optional<V> d = around_extreme_rays(l, normals, inside, memo);
    memo->complete = !d;
    return d;
  }

  // normals: every plane through the point, in no particular relation.
  // Returns a direction into the first cell found inside, or nothing.
  template <class Inside>
  std::optional<V> find_inside_around(const std::vector<V>& normals, Inside inside)
  {
    std::size_t n = normals.size();
    if (n == 0) return find_inside(V{FT(0), FT(0), FT(0), FT(1)}, normals, inside);
    if (n == 4 && k_.orientation4(normals[0], normals[1], normals[2], normals[3]) != CGAL::ZERO)
      return four_independent(normals, inside);
    std::optional<V> common = common_line(normals);
    if (common) return find_inside(*common, normals, inside);
    return around_vertex_rays(normals, inside);
  }

  std::size_t cells_tested() const { return tested_; }

private:
  const K& k_;
  std::size_t tested_ = 0;

  static V scaled(const V& v, int s) { return {v[0] * FT(s), v[1] * FT(s), v[2] * FT(s), v[3] * FT(s)}; }
  static V sum(const V& a, const V& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]}; }

  template <class Inside>
  bool test(const std::vector<V>& normals, const V& d, std::vector<int>& signs, Inside& inside)
  {
    for (std::size_t i = 0; i < normals.size(); ++i) signs[i] = static_cast<int>(k_.dot_sign(normals[i], d));
    ++tested_;
    return inside(signs);
  }

  template <class Inside>
  std::optional<V> three_independent(const V& l, const std::vector<V>& N, Inside& inside)
  {
    // g_i is orthogonal to l and the other two normals, oriented so n_i.g_i > 0:
    // sum sigma_i g_i has sign sigma_i against n_i.
    V g[3];
    for (int i = 0; i < 3; ++i) {
      g[i] = generalised_cross(l, N[(i + 1) % 3], N[(i + 2) % 3]);
      if (k_.dot_sign(N[i], g[i]) == CGAL::NEGATIVE) g[i] = scaled(g[i], -1);
    }
    std::vector<int> signs(3);
    for (int mask = 0; mask < 8; ++mask) {
      for (int i = 0; i < 3; ++i) signs[i] = (mask >> i & 1) ? -1 : 1;
      ++tested_;
      if (!inside(signs)) continue;
      V d = scaled(g[0], signs[0]);
      d = sum(d, scaled(g[1], signs[1]));
      return sum(d, scaled(g[2], signs[2]));
    }
    return std::nullopt;
  }

  bool parallel(const V& a, const V& b) const
  {
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (k_.sign(minor2(a, b, i, j)) != CGAL::ZERO) return false;
    return true;
  }
  bool same_direction(const V& a, const V& b) const { return parallel(a, b) && k_.dot_sign(a, b) == CGAL::POSITIVE; }
  bool all_parallel(const std::vector<V>& N) const
  {
    for (std::size_t i = 1; i < N.size(); ++i)
      if (!parallel(N[0], N[i])) return false;
    return true;
  }

  // Appends +v and -v unless already there. The two are compared with the
  // earlier entries only: with each other they are opposite by construction
  // (a zero an interval kernel could not certify).
  void add_both_ways(std::vector<V>& out, const V& v) const
  {
    std::size_t earlier = out.size();
    for (int s : {1, -1}) {
      V w = scaled(v, s);
      bool seen = false;
      for (std::size_t q = 0; q < earlier && !seen; ++q) seen = same_direction(out[q], w);
      if (!seen) out.push_back(w);
    }
  }

  // memo: records every cell tested, in order.
  template <class Inside>
  std::optional<V> around_extreme_rays(const V& l, const std::vector<V>& N, Inside& inside, Memo* memo)
  {
    struct Ray {
      V r;
      std::size_t i, j;   // two planes known to contain it
    };
    std::vector<Ray> rays;
    std::vector<V> directions;
    for (std::size_t i = 0; i < N.size(); ++i)
      for (std::size_t j = i + 1; j < N.size(); ++j) {
        V r = generalised_cross(l, N[i], N[j]);
        if (k_.is_zero(r)) continue;
        std::size_t before = directions.size();
        add_both_ways(directions, r);
        for (std::size_t q = before; q < directions.size(); ++q) rays.push_back({directions[q], i, j});
      }
    std::vector<int> signs(N.size());
    for (const Ray& ray : rays) {
      const V& r = ray.r;
      std::vector<char> on_r;
      std::vector<V> sector = sector_rays(l, r, N, ray.i, ray.j, on_r);
      if (sector.size() < 3) continue;   // only when rounding (double) breaks the geometry
      for (std::size_t a = 0; a < sector.size(); ++a) {
        V s = sum(sector[a], sector[(a + 1) % sector.size()]);
        V d = sum(r, scaled_by(s, epsilon(r, s, N, on_r)));
        bool in = test(N, d, signs, inside);
        if (memo) memo->cells.emplace_back(d, signs);
        if (in) return d;
      }
    }
    return std::nullopt;
  }

  // The rays in the planes through r, orthogonal to r (and l), sorted by angle
  // around r, duplicates removed.
  // Planes i and j define r, so they contain it whatever rounding says.
  // on_r: per plane, whether it contains r.
  std::vector<V> sector_rays(const V& l, const V& r, const std::vector<V>& N, std::size_t i, std::size_t j,
                             std::vector<char>& on_r) const
  {
    std::vector<V> out;
    on_r.assign(N.size(), 0);
    for (std::size_t t = 0; t < N.size(); ++t) {
      const V& n = N[t];
      if (t != i && t != j && k_.dot_sign(n, r) != CGAL::ZERO) continue;
      on_r[t] = 1;
      add_both_ways(out, generalised_cross(l, r, n));
    }
    // Sorted by angle from out[0]: quadrant classes, then orientation within
    // one. out[0] and out[1] are that ray and its opposite (add_both_ways):
    // their classes are known, and no ray is compared with itself, so no
    // decision is a zero by construction.
    std::vector<int> cls(out.size());
    std::vector<std::size_t> order(out.size());
    for (std::size_t a = 0; a < out.size(); ++a) {
      order[a] = a;
      if (a < 2) { cls[a] = 2 * static_cast<int>(a); continue; }
      CGAL::Sign o = k_.orientation4(l, r, out[0], out[a]);
      cls[a] = o == CGAL::POSITIVE ? 1 : o == CGAL::NEGATIVE ? 3 : (k_.dot_sign(out[0], out[a]) == CGAL::POSITIVE ? 0 : 2);
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      if (cls[a] != cls[b]) return cls[a] < cls[b];
      return a != b && k_.orientation4(l, r, out[a], out[b]) == CGAL::POSITIVE;
    });
    std::vector<V> sorted;
    for (std::size_t a : order) sorted.push_back(out[a]);
    return sorted;
  }

  // Four independent normals: g_i orthogonal to the other three, oriented
  // so n_i.g_i > 0; sum sigma_i g_i is in the cell of signs sigma.
  template <class Inside>
  std::optional<V> four_independent(const std::vector<V>& N, Inside& inside)
  {
    V g[4];
    for (int i = 0; i < 4; ++i) {
      g[i] = generalised_cross(N[(i + 1) % 4], N[(i + 2) % 4], N[(i + 3) % 4]);
      if (k_.dot_sign(N[i], g[i]) == CGAL::NEGATIVE) g[i] = scaled(g[i], -1);
    }
    std::vector<int> signs(4);
    for (int mask = 0; mask < 16; ++mask) {
      for (int i = 0; i < 4; ++i) signs[i] = (mask >> i & 1) ? -1 : 1;
      ++tested_;
      if (!inside(signs)) continue;
      V d = scaled(g[0], signs[0]);
      for (int i = 1; i < 4; ++i) d = sum(d, scaled(g[i], signs[i]));
      return d;
    }
    return std::nullopt;
  }

  // A non-zero direction every plane contains, when the normals do not span
  // space-time: orthogonal to three independent ones (rank 3), or to an
  // independent pair, or a single normal, and one or two coordinate axes.
  std::optional<V> common_line(const std::vector<V>& N) const
  {
    std::size_t n = N.size();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        for (std::size_t m = j + 1; m < n; ++m) {
          V r = generalised_cross(N[i], N[j], N[m]);
          if (k_.is_zero(r)) continue;
          for (const V& x : N)
            if (k_.dot_sign(x, r) != CGAL::ZERO) return std::nullopt;   // rank 4
          return r;
        }
    const V* a = &N[0];
    const V* b = nullptr;
    for (std::size_t i = 1; i < n && !b; ++i)
      if (!parallel(N[0], N[i])) b = &N[i];
    for (int p = 0; p < 4; ++p)
      for (int q = p + 1; q < 4; ++q) {
        V ep{FT(0), FT(0), FT(0), FT(0)}, eq = ep;
        ep[p] = FT(1);
        eq[q] = FT(1);
        V r = b ? generalised_cross(*a, *b, ep) : generalised_cross(*a, ep, eq);
        if (!k_.is_zero(r)) return r;
      }
    return std::nullopt;   // only with a tolerance
  }

  // Rank 4 with more than four planes: every cell has an extreme ray on
  // three independent planes; around each such ray r (both ways) the cells
  // of the planes containing r are those of the 3D case, and r + e d, for
  // the direction d found there and e small enough that no plane off r
  // changes sign, leads into the cell from the vertex.
  template <class Inside>
  std::optional<V> around_vertex_rays(const std::vector<V>& N, Inside& inside)
  {
    std::vector<V> rays;
    for (std::size_t i = 0; i < N.size(); ++i)
      for (std::size_t j = i + 1; j < N.size(); ++j)
        for (std::size_t m = j + 1; m < N.size(); ++m) {
          V r = generalised_cross(N[i], N[j], N[m]);
          if (!k_.is_zero(r)) add_both_ways(rays, r);
        }
    std::vector<int> signs(N.size());
    for (const V& r : rays) {
      std::vector<V> on;
      std::vector<std::size_t> which;
      std::vector<char> on_r(N.size(), 0);
      for (std::size_t t = 0; t < N.size(); ++t) {
        int s = static_cast<int>(k_.dot_sign(N[t], r));
        signs[t] = s;
        if (s == 0) { on.push_back(N[t]); which.push_back(t); on_r[t] = 1; }
      }
      auto inside_here = [&](const std::vector<int>& sub) {
        for (std::size_t t = 0; t < which.size(); ++t) signs[which[t]] = sub[t];
        return inside(signs);
      };
      std::optional<V> d = find_inside(r, on, inside_here);   // counts its own cells
      if (d) return sum(r, scaled_by(*d, epsilon(r, *d, N, on_r)));
    }
    return std::nullopt;
  }

  V scaled_by(const V& v, const FT& e) const { return {v[0] * e, v[1] * e, v[2] * e, v[3] * e}; }

  // Small enough that no plane off r changes sign between r and r + eps s:
  // half the least |n.r / n.s| over the planes off r (on_r, from
  // sector_rays: their zeros are not computed again), a minimum taken as a
  // construction (no decision, so ties cost an approximate kernel nothing).
  FT epsilon(const V& r, const V& s, const std::vector<V>& N, const std::vector<char>& on_r) const
  {
    bool any = false;
    FT best(1);
    for (std::size_t t = 0; t < N.size(); ++t) {
      if (on_r[t]) continue;
      FT nr = dot(N[t], r), ns = dot(N[t], s);
      if (k_.sign(ns) == CGAL::ZERO) continue;
      FT q = Number_ops<FT>::magnitude(nr / ns);
      best = any ? Number_ops<FT>::lower(best, q) : q;
      any = true;
    }
    return any ? best / FT(2) : FT(1);
  }
};

} // namespace clash4d

#endif
