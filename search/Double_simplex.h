// Small linear programs in doubles, for guesses only: which few rows carry
// the multipliers of a Motzkin proof (search/Motzkin_lp.h), and where a
// convex pair's programs are optimal (search/Convex_pair.h). What is
// answered is always made from the guess and checked in exact arithmetic.
#ifndef CLASH4D_SEARCH_DOUBLE_SIMPLEX_H
#define CLASH4D_SEARCH_DOUBLE_SIMPLEX_H

#include <boost/container/small_vector.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

namespace clash4d {

// The pivot on a rows x width tableau (row-major): row `leave` divided by
// its entry in column `enter`, then that column eliminated from every other
// row (r <- r - r[enter] leave, skipped where r[enter] is zero). Built for
// AVX2 as well as the base instruction set, chosen when loaded: the same
// roundings either way (each product and difference rounded on its own, no
// fused multiply-add: -ffp-contract=off), only more of them at a time.
void pivot_tableau(double* T, int rows, int width, int leave, int enter);

// row <- row - row[column] * with (rows of `width` entries), skipped
// where row[column] is zero: pivot_tableau's step, and phase 2's on the
// objective row.
inline void eliminate_row(double* row, const double* with, int width, int column)
{
  double f = row[column];
  if (f == 0.0) return;
  for (int c = 0; c < width; ++c) row[c] -= f * with[c];
}

// maximise cost . y  subject to  A y = b, y >= 0, with A of at most six
// rows (five for a convex pair's programs and a Motzkin guess, six for a
// plane parting two sets of points in space-time: certify/Split_prover.cpp): a two-phase simplex on a dense tableau with Bland's rule. Only a
// guess: nothing here is exact, and a caller checks what it takes from it.
class Double_simplex {
public:
  static constexpr int max_rows = 6;
  using Row_vector = std::array<double, max_rows>;
  // An optimum's few entries without the heap (a program per query of a
  // convex pair). The tableau stays a std::vector: on the stack (boost's
  // small_vector) hull-hull queries measured 5% slower.
  template <class T, std::size_t N> using Small = boost::container::small_vector<T, N>;

  // rows <= max_rows equality rows with right-hand side b; columns y_j.
  // eps: reduced costs and pivots below it count as zero (columns of
  // entries at most 1: a constraint of the primal may be missed by eps).
  Double_simplex(int rows, int columns, const Row_vector& b, double eps = 1e-9)
      : eps_(eps), R_(checked_rows(rows)), m_(columns), W_(m_ + R_ + 1),
        T_(static_cast<std::size_t>((R_ + 1) * W_), 0.0), cost_(static_cast<std::size_t>(columns), 0.0), b_(b), flip_{}
  {
    // Rows with b < 0 are negated, so that the artificials start feasible.
    for (int i = 0; i < R_; ++i) {
      flip_[i] = b[i] < 0 ? -1.0 : 1.0;
      at(i, m_ + i) = 1.0;
      at(i, W_ - 1) = flip_[i] * b[i];
      basis_[static_cast<std::size_t>(i)] = m_ + i;
    }
  }

  // Column j: its `rows` entries a and its cost.
  void column(int j, const double* a, double cost)
  {
    for (int i = 0; i < R_; ++i) at(i, j) = flip_[i] * a[i];
    cost_[static_cast<std::size_t>(j)] = cost;
  }

  struct Optimum {
    Small<int, max_rows> basis;   // the basic y columns (artificials at zero left out)
    Small<double, max_rows> y;    // their values
    Row_vector pi{};          // row multipliers: pi . a_j >= cost_j, with equality on the basis
    double value = 0;         // pi . b, the optimum of cost . y
  };

  // An optimum, or nothing when the program looks infeasible or unbounded
  // (or the run fails to settle in doubles).
  std::optional<Optimum> solve()
  {
    // Phase 1: the artificials' sum, minimised. Each column's sum is
    // 0 + row 0 + row 1 + ..., in that order, as a column at a time made it
    // (the same doubles), but added a row at a time across the columns, so
    // that no addition waits for the one before.
    double* sum = &at(R_, 0);
    std::fill(sum, sum + W_, 0.0);
    for (int r = 0; r < R_; ++r) {
      const double* row = &at(r, 0);
      for (int c = 0; c < W_; ++c) sum[c] += row[c];
    }
    for (int c = 0; c < W_; ++c) sum[c] = c >= m_ && c < m_ + R_ ? 0.0 : -sum[c];
    double scale = 1.0;
    for (int r = 0; r < R_; ++r) scale = std::max(scale, std::abs(at(r, W_ - 1)));
    if (!run() || std::abs(at(R_, W_ - 1)) > 1e-7 * scale) return std::nullopt;
    // Artificials left in the basis (at zero) leave it, so that phase 2's
    // ratio tests see every row; a row with no y entry is redundant.
    for (int r = 0; r < R_; ++r)
      if (basis_[static_cast<std::size_t>(r)] >= m_) {
        int c = 0;
        while (c < m_ && std::abs(at(r, c)) <= eps_) ++c;
        if (c < m_) pivot(r, c);
      }
    // Phase 2: cost . y maximised (its negation minimised). An artificial
    // column's reduced cost is then its row's multiplier.
    for (int c = 0; c < W_; ++c) at(R_, c) = c < m_ ? -cost_[static_cast<std::size_t>(c)] : 0.0;
    for (int r = 0; r < R_; ++r) {
      int basic = basis_[static_cast<std::size_t>(r)];
      if (basic < m_) eliminate_row(&at(R_, 0), &at(r, 0), W_, basic);
    }
    if (!run()) return std::nullopt;
    Optimum o;
    o.basis.reserve(static_cast<std::size_t>(R_));
    o.y.reserve(static_cast<std::size_t>(R_));
    for (int r = 0; r < R_; ++r)
      if (basis_[static_cast<std::size_t>(r)] < m_) {
        o.basis.push_back(basis_[static_cast<std::size_t>(r)]);
        o.y.push_back(at(r, W_ - 1));
      }
    for (int i = 0; i < R_; ++i) {
      o.pi[i] = flip_[i] * at(R_, m_ + i);
      o.value += o.pi[i] * b_[i];
    }
    return o;
  }

private:
  double eps_;
  int R_, m_, W_;                      // rows; y columns; columns with artificials and rhs
  std::vector<double> T_, cost_;
  Row_vector b_, flip_;
  std::array<int, max_rows> basis_{};

  static int checked_rows(int rows)
  {
    if (rows < 1 || rows > max_rows) throw std::logic_error("Double_simplex: between 1 and 6 rows");
    return rows;
  }

  double& at(int r, int c) { return T_[static_cast<std::size_t>(r * W_ + c)]; }

  void pivot(int leave, int enter)
  {
    pivot_tableau(T_.data(), R_ + 1, W_, leave, enter);
    basis_[static_cast<std::size_t>(leave)] = enter;
  }

  // Pivots until no y column has a negative reduced cost; false when the
  // run looks unbounded or cycles (it cannot, in exact arithmetic).
  bool run()
  {
    for (int iteration = 0; iteration < 50 * (m_ + R_); ++iteration) {
      int enter = -1;
      for (int c = 0; c < m_ && enter < 0; ++c)
        if (at(R_, c) < -eps_) enter = c;
      if (enter < 0) return true;
      int leave = -1;
      double best = 0;
      for (int r = 0; r < R_; ++r)
        if (at(r, enter) > eps_) {
          double ratio = at(r, W_ - 1) / at(r, enter);
          if (leave < 0 || ratio < best - eps_ || (ratio <= best + eps_ && basis_[static_cast<std::size_t>(r)] <
                                                                            basis_[static_cast<std::size_t>(leave)]))
            leave = r, best = ratio;
        }
      if (leave < 0) return false;
      pivot(leave, enter);
    }
    return false;
  }
};

} // namespace clash4d

#endif
