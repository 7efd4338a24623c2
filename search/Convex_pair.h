// Convex pairs decided by linear programs (beyond the paper). When each
// object of a pair is one convex primitive (a block, convex, prism, hull or
// half-space, moved and rotated), its extrusion on a constant-velocity
// sub-span is one convex polyhedron, and so is the pair's:
// P = { h_j <= 0 for every plane of both, lo <= t <= hi }. Then:
//  - regularised: they collide on the sub-span iff the strict system
//    h_j < 0, lo < t < hi has a solution (regularised-semantics items 1-2);
//    a solution is the point inside the witness is made from. Otherwise
//    Motzkin's multipliers lambda >= 0, not all zero, with
//    sum lambda_j n_j = 0 and sum lambda_j c_j >= 0 prove it has none
//    (touching included: the sum is 0 there);
//  - closed: they meet iff P is not empty (each object is its closed
//    polyhedron, which has interior); a point of P is the witness, and
//    Farkas' multipliers with sum lambda_j c_j > 0 prove P empty;
//  - earliest: t* = min t over P (item 5: P is the closure of its interior
//    when that is not empty), attained at a vertex where four rows meet,
//    proven least by y >= 0 on those rows with e_t + sum y_j n_j = 0.
// A double simplex on the pair's guide (the same planes in doubles, made
// from the scene's own numbers, rounding to nearest: the same doubles in
// every kernel's run) guesses the point inside, the support of the
// multipliers and the vertex's four rows. Every verdict is then made from
// the guess and checked with the kernel's signs, so every kernel takes the
// same decisions (a filtered run's are the rational run's), and a guess that
// proves nothing leaves the sub-span to the paper's cascade (undecided).
#ifndef CLASH4D_SEARCH_CONVEX_PAIR_H
#define CLASH4D_SEARCH_CONVEX_PAIR_H

#include "model/Extrusion.h"
#include "model/Model_builder.h"
#include "search/Double_simplex.h"
#include "search/Search_goal.h"
#include <CGAL/FPU.h>
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace clash4d {

// The guide's numbers: a scene's rationals rounded to the nearest double,
// plain signs (what Model_builder and Motion_path need). Guesses only.
struct Guide_numbers {
  using FT = double;
  static constexpr bool reads_exact_constructions = true;   // the reader's exact hull planes, rounded
  double from_rational(const Rational& q) const { return nearest_double(q); }
  CGAL::Sign sign(double x) const { return CGAL::sign(x); }
};

template <class K>
class Convex_pair {
public:
  using FT = typename K::FT;
  using H = Hyperplane4<FT>;
  using V4 = Vector4<FT>;
  using Moving = Moving_object<FT>;
  using G = Hyperplane4<double>;

  enum class Verdict { undecided, apart, collide };

  // Each object one primitive, one of them bounded (so the programs are
  // bounded), in a model that knows its scene (the guide's numbers).
  static bool applies(const Scene_model<K>& model, int a, int b)
  {
    auto single = [&](int i) {
      const Csg_model<FT>& csg = model.objects[i].csg;
      return csg.nodes.size() == 1 && csg.nodes[0].op == Csg_node::Op::Primitive;
    };
    auto bounded = [&](int i) { return !model.objects[i].csg.primitives[0].vertices.empty(); };
    return model.scene && single(a) && single(b) && (bounded(a) || bounded(b));
  }

  Convex_pair(const K& k, const Scene_model<K>& model, int a, int b) : k_(k), model_(model), a_(a), b_(b)
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    Guide_numbers g;
    for (int i : {a, b}) {
      const Scene_object& o = model.scene->objects[static_cast<std::size_t>(i)];
      guide_[i == a ? 0 : 1] = {o.name, Model_builder<Guide_numbers>(g).build(o.shape),
                                Motion_path<double>::build(g, o.motion)};
    }
  }

  // The sub-span where A and B move as given: apart, or collide with the
  // goal holding what the cascade would record (the point inside, or the
  // closed point with directions into each object; earliest, the least
  // time and its vertex), or undecided (nothing recorded).
  Verdict decide(const Moving& A, const Moving& B, const Time_span<FT>& span, Search_goal<FT>& goal)
  {
    if (!span.exact_lo || !span.exact_hi) return Verdict::undecided;
    start_span(A, B, span);
    std::optional<Double_simplex::Optimum> margin = widest_margin();
    if (!margin) return Verdict::undecided;
    if (!goal.closed()) {
      if (margin->value < 0 && inside(guess_point(margin->pi)))
        return goal.earliest ? earliest_inside(goal) : record_inside(goal, inside_);
      return proves_empty(*margin, false) ? Verdict::apart : Verdict::undecided;
    }
    // Closed, any point: the guess itself when it lies in P (a float
    // kernel's tolerance takes a thin overlap for a touch), tried on the
    // rows it holds tight first.
    if (!goal.earliest && in_closed(guess_point(margin->pi), margin->basis)) {
      goal.record_touch(k_, inside_, into(0, inside_), into(1, inside_));
      return Verdict::collide;
    }
    if (margin->value >= 0 && proves_empty(*margin, true)) return Verdict::apart;
    return touch(goal);
  }

private:
  const K& k_;
  const Scene_model<K>& model_;
  int a_, b_;
  Object_model<double> guide_[2];
  std::vector<G> guide_rows_;              // the sub-span's rows in doubles, in the order of rows_
  std::vector<H> rows_;                    // A's planes, B's, t >= lo, t <= hi: extruded on first use
  std::vector<char> made_;
  const Moving* moving_[2] = {nullptr, nullptr};
  std::size_t count_a_ = 0, count_b_ = 0;
  FT lo_{}, hi_{};
  V4 inside_{};

  void start_span(const Moving& A, const Moving& B, const Time_span<FT>& span)
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    moving_[0] = &A, moving_[1] = &B;
    lo_ = span.lo, hi_ = span.hi;
    guide_rows_.clear();
    for (int o = 0; o < 2; ++o) {
      const Object_model<double>& m = guide_[o];
      std::size_t seg = model_.segment_on(o == 0 ? a_ : b_, span);   // the kernel's, the same in every run
      for (const auto& plane : m.csg.primitives[0].planes)
        guide_rows_.push_back(extrude(plane, m.motion.velocity[seg], m.motion.offset[seg]));
    }
    count_a_ = A.object->csg.primitives[0].planes.size();
    count_b_ = B.object->csg.primitives[0].planes.size();
    guide_rows_.push_back(time_at_least(nearest_double(*span.exact_lo)));
    guide_rows_.push_back(time_at_most(nearest_double(*span.exact_hi)));
    rows_.assign(guide_rows_.size(), H{});
    made_.assign(guide_rows_.size(), 0);
  }

  // Row j in the kernel's numbers (equation (4) on the sub-span's motion).
  const H& row(std::size_t j)
  {
    if (!made_[j]) {
      if (j < count_a_ + count_b_) {
        const Moving& m = *moving_[j < count_a_ ? 0 : 1];
        std::size_t i = j < count_a_ ? j : j - count_a_;
        rows_[j] = extrude(m.object->csg.primitives[0].planes[i], m.v, m.o);
      } else {
        rows_[j] = j == count_a_ + count_b_ ? time_at_least(lo_) : time_at_most(hi_);
      }
      made_[j] = 1;
    }
    return rows_[j];
  }

  // Each row scaled by its largest normal coordinate, so that the margin
  // below is the same in every row's units.
  static double scale_of(const G& g)
  {
    double big = 0;
    for (double x : g.n) big = std::max(big, std::abs(x));
    return big;
  }

  // The guide's  max s  s.t.  h_j + s big_j <= 0  as its dual, Motzkin's LP:
  // max sum y_j c_j / big_j  s.t.  sum y_j n_j / big_j = 0, sum y_j = 1,
  // y >= 0. Its optimum is -s*; its row multipliers pi give the point,
  // p = -(pi_x, pi_y, pi_z, pi_t), with h_j(p) <= value big_j; its basis
  // the rows of a proof of emptiness when the value is not negative.
  std::optional<Double_simplex::Optimum> widest_margin() const
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    Double_simplex lp(5, static_cast<int>(guide_rows_.size()), {0, 0, 0, 0, 1});
    for (std::size_t j = 0; j < guide_rows_.size(); ++j) {
      const G& g = guide_rows_[j];
      double big = scale_of(g), a[5] = {g.n[0] / big, g.n[1] / big, g.n[2] / big, g.n[3] / big, 1.0};
      lp.column(static_cast<int>(j), a, g.c / big);
    }
    return lp.solve();
  }

  // The guide's  min t  over P as its dual: max sum y_j c_j / big_j  s.t.
  // sum y_j n_j / big_j = -e_t, y >= 0; its basis is the vertex's rows.
  std::optional<std::vector<int>> least_time_rows() const
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    Double_simplex lp(4, static_cast<int>(guide_rows_.size()), {0, 0, 0, -1, 0});
    for (std::size_t j = 0; j < guide_rows_.size(); ++j) {
      const G& g = guide_rows_[j];
      double big = scale_of(g), a[4] = {g.n[0] / big, g.n[1] / big, g.n[2] / big, g.n[3] / big};
      lp.column(static_cast<int>(j), a, g.c / big);
    }
    std::optional<Double_simplex::Optimum> o = lp.solve();
    if (!o || o->basis.size() != 4) return std::nullopt;
    return o->basis;
  }

  static V4 guess_point(const Double_simplex::Row_vector& pi)
  {
    return {FT(-pi[0]), FT(-pi[1]), FT(-pi[2]), FT(-pi[3])};
  }

  // Whether p is strictly inside every row (the kernel's signs); kept.
  bool inside(const V4& p)
  {
    for (std::size_t j = 0; j < rows_.size(); ++j)
      if (k_.sign(row(j).value(p)) != CGAL::NEGATIVE) return false;
    inside_ = p;
    return true;
  }

  // Whether p lies in P (no row positive), rows `first` first; kept.
  bool in_closed(const V4& p, const std::vector<int>& first)
  {
    for (int j : first)
      if (k_.sign(row(static_cast<std::size_t>(j)).value(p)) == CGAL::POSITIVE) return false;
    for (std::size_t j = 0; j < rows_.size(); ++j)
      if (k_.sign(row(j).value(p)) == CGAL::POSITIVE) return false;
    inside_ = p;
    return true;
  }

  Verdict record_inside(Search_goal<FT>& goal, const V4& lowest)
  {
    if (!goal.can_improve(k_, lowest[3])) return Verdict::apart;   // past the ceiling: nothing to record
    goal.record(k_, inside_, lowest);
    return Verdict::collide;
  }

  // Regularised, earliest: the least time of P (the closure of its
  // interior, where inside_ lies), at a vertex proven least.
  Verdict earliest_inside(Search_goal<FT>& goal)
  {
    std::optional<V4> v = least_vertex(true);
    return v ? record_inside(goal, *v) : Verdict::undecided;
  }

  // Closed: a point of P (earliest: the least time's vertex), with
  // directions into each object there.
  Verdict touch(Search_goal<FT>& goal)
  {
    std::optional<V4> v = least_vertex(goal.earliest);
    if (!v) return Verdict::undecided;
    if (!goal.can_improve(k_, (*v)[3])) return Verdict::apart;
    goal.record_touch(k_, *v, into(0, *v), into(1, *v));
    return Verdict::collide;
  }

  // A direction from p (a point of object o's closed set at p's time) into
  // its interior, at fixed time: toward the mean of its vertices, moved
  // with it (a bounded primitive's vertex mean is interior), or against a
  // half-space's normal.
  V4 into(int o, const V4& p) const
  {
    const Moving& m = *moving_[o];
    const Primitive<FT>& prim = m.object->csg.primitives[0];
    if (prim.vertices.empty()) return {-prim.planes[0][0], -prim.planes[0][1], -prim.planes[0][2], FT(0)};
    Vector3<FT> mean = prim.vertices[0];
    for (std::size_t i = 1; i < prim.vertices.size(); ++i)
      for (int q = 0; q < 3; ++q) mean[q] += prim.vertices[i][q];
    FT count(static_cast<int>(prim.vertices.size()));
    V4 d{FT(0), FT(0), FT(0), FT(0)};
    for (int q = 0; q < 3; ++q) d[q] = mean[q] / count + m.v[q] * p[3] + m.o[q] - p[q];
    return d;
  }

  // The vertex of the guide's least-time rows, when it lies in P and
  // (proven: multipliers y >= 0 on its rows) has the least time of P.
  std::optional<V4> least_vertex(bool proven)
  {
    std::optional<std::vector<int>> basis = least_time_rows();
    if (!basis) return std::nullopt;
    std::array<H, 4> B;
    for (int i = 0; i < 4; ++i) B[i] = row(static_cast<std::size_t>((*basis)[i]));
    FT den = determinant4(B[0].n, B[1].n, B[2].n, B[3].n);
    CGAL::Sign sd = k_.sign(den);
    if (sd == CGAL::ZERO) return std::nullopt;
    // Cramer: v_q = det(N with column q replaced by -c) / det N.
    V4 v;
    for (int q = 0; q < 4; ++q) {
      std::array<V4, 4> M;
      for (int i = 0; i < 4; ++i) (M[i] = B[i].n)[q] = -B[i].c;
      v[q] = k_.quotient(determinant4(M[0], M[1], M[2], M[3]), den, sd);
    }
    for (std::size_t j = 0; j < rows_.size(); ++j)
      if (std::find(basis->begin(), basis->end(), static_cast<int>(j)) == basis->end() &&
          k_.sign(row(j).value(v)) == CGAL::POSITIVE)
        return std::nullopt;
    // y solves sum_i y_i n_i = -e_t: y_i = -det(N with row i = e_t) / det N.
    for (int i = 0; i < 4 && proven; ++i) {
      std::array<V4, 4> M{B[0].n, B[1].n, B[2].n, B[3].n};
      M[i] = {FT(0), FT(0), FT(0), FT(1)};
      if (k_.sign(determinant4(M[0], M[1], M[2], M[3])) == sd) return std::nullopt;   // y_i < 0
    }
    return v;
  }

  // Whether multipliers on the guide's support (its basic rows with weight)
  // prove the strict system empty (regularised: sum lambda c >= 0) or P
  // empty (strict: sum lambda c > 0).
  bool proves_empty(const Double_simplex::Optimum& o, bool strict)
  {
    std::vector<std::size_t> support;
    double most = 0;
    for (double y : o.y) most = std::max(most, y);
    for (std::size_t i = 0; i < o.basis.size(); ++i)
      if (o.y[i] > 1e-9 * most) support.push_back(static_cast<std::size_t>(o.basis[i]));
    std::optional<std::vector<FT>> lambda = null_vector(support);
    if (!lambda) return false;
    FT sum(0);
    for (std::size_t i = 0; i < support.size(); ++i) {
      if (k_.sign((*lambda)[i]) == CGAL::NEGATIVE) return false;
      sum += (*lambda)[i] * row(support[i]).c;
    }
    CGAL::Sign s = k_.sign(sum);
    return strict ? s == CGAL::POSITIVE : s != CGAL::NEGATIVE;
  }

  // lambda with sum lambda_i n_i = 0 over the rows `which`, the last free
  // column's lambda 1, when the normals' dependencies are one line
  // (Gaussian elimination with the kernel's signs choosing pivots).
  std::optional<std::vector<FT>> null_vector(const std::vector<std::size_t>& which)
  {
    std::size_t n = which.size();
    if (n < 2) return std::nullopt;
    std::vector<std::array<FT, 5>> M(4);   // M[q][i] = n_i[q]
    for (std::size_t i = 0; i < n; ++i)
      for (int q = 0; q < 4; ++q) M[q][i] = row(which[i]).n[q];
    std::vector<std::size_t> pivot_col;
    std::size_t rank = 0, free = n;
    for (std::size_t c = 0; c < n; ++c) {
      std::size_t r = rank;
      while (r < 4 && k_.sign(M[r][c]) == CGAL::ZERO) ++r;
      if (r == 4) {
        if (free != n) return std::nullopt;   // two free columns: more than one line
        free = c;
        continue;
      }
      std::swap(M[r], M[rank]);
      for (std::size_t below = rank + 1; below < 4; ++below) {
        FT f = M[below][c] / M[rank][c];
        for (std::size_t cc = c; cc < n; ++cc) M[below][cc] -= f * M[rank][cc];
        M[below][c] = FT(0);
      }
      pivot_col.push_back(c);
      ++rank;
    }
    if (free == n) return std::nullopt;   // independent normals
    std::vector<FT> lambda(n, FT(0));
    lambda[free] = FT(1);
    for (std::size_t r = rank; r-- > 0;) {
      std::size_t c = pivot_col[r];
      if (c > free) continue;   // columns after the free one: their lambda is 0
      FT s(0);
      for (std::size_t cc = c + 1; cc < n; ++cc) s += M[r][cc] * lambda[cc];
      lambda[c] = -s / M[r][c];
    }
    return lambda;
  }
};

} // namespace clash4d

#endif
