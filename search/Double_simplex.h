// The dual LP of search/Motzkin_lp.h in doubles, for a guess at which few
// rows carry the multipliers.
#ifndef CLASH4D_SEARCH_DOUBLE_SIMPLEX_H
#define CLASH4D_SEARCH_DOUBLE_SIMPLEX_H

#include "search/Motzkin_lp.h"
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace clash4d {

// A guess at the support of an optimal lambda: the dual LP solved in
// doubles, a two-phase simplex on a dense tableau with Bland's rule. Only a
// guess: the exact solution on the guessed columns decides, and the full
// exact LP runs when it does not prove the system infeasible.
class Double_simplex {
public:
  explicit Double_simplex(const std::vector<Motzkin_row>& rows)
      : m_(static_cast<int>(rows.size())), W_(m_ + R + 1), T_(static_cast<std::size_t>((R + 1) * W_), 0.0),
        cost_(rows.size()), basis_{m_, m_ + 1, m_ + 2, m_ + 3, m_ + 4}
  {
    for (int j = 0; j < m_; ++j) {
      double big = 1.0;
      for (int i = 0; i < 4; ++i) big = std::max(big, std::abs(CGAL::to_double((*rows[j].h)[i])));
      // The normalisation sum lambda_j big_j = 1 instead of sum lambda_j = 1
      // (any positive weights exclude lambda = 0 alike): every scaled column
      // has entries of at most 1, and a 1 in the last row.
      for (int i = 0; i < 4; ++i) at(i, j) = CGAL::to_double((*rows[j].h)[i]) / big;
      at(4, j) = 1.0;
      cost_[static_cast<std::size_t>(j)] = CGAL::to_double((*rows[j].h)[4]) / big;
    }
    for (int i = 0; i < R; ++i) at(i, m_ + i) = 1.0;
    at(4, W_ - 1) = 1.0;
  }

  // The basic lambda columns of an optimum, or nothing when unsure.
  std::optional<std::vector<int>> support()
  {
    // Phase 1: the artificials' sum, minimised.
    for (int c = 0; c < W_; ++c) {
      double sum = 0;
      for (int r = 0; r < R; ++r) sum += at(r, c);
      at(R, c) = c >= m_ && c < m_ + R ? 0.0 : -sum;
    }
    if (!run() || std::abs(at(R, W_ - 1)) > 1e-7) return std::nullopt;
    // Artificials left in the basis (at zero) leave it, so that phase 2's
    // ratio tests see every row; a row with no lambda entry is redundant.
    for (int r = 0; r < R; ++r)
      if (basis_[r] >= m_) {
        int c = 0;
        while (c < m_ && std::abs(at(r, c)) <= eps) ++c;
        if (c < m_) pivot(r, c);
      }
    // Phase 2: sum lambda e maximised (its negation minimised).
    for (int c = 0; c < W_; ++c) at(R, c) = c < m_ ? -cost_[static_cast<std::size_t>(c)] : 0.0;
    for (int r = 0; r < R; ++r)
      if (basis_[r] < m_) eliminate(R, r, basis_[r]);
    if (!run()) return std::nullopt;
    std::vector<int> out;
    for (int b : basis_)
      if (b < m_) out.push_back(b);
    return out;
  }

private:
  static constexpr int R = 5;          // rows: a_x, a_y, a_z, a_t, the normalisation
  static constexpr double eps = 1e-9;
  int m_, W_;                          // lambda columns; columns with artificials and rhs
  std::vector<double> T_, cost_;
  std::vector<int> basis_;

  double& at(int r, int c) { return T_[static_cast<std::size_t>(r * W_ + c)]; }

  void eliminate(int r, int with, int c)
  {
    double f = at(r, c);
    if (f == 0.0) return;
    for (int k = 0; k < W_; ++k) at(r, k) -= f * at(with, k);
  }

  void pivot(int leave, int enter)
  {
    double p = at(leave, enter);
    for (int c = 0; c < W_; ++c) at(leave, c) /= p;
    for (int r = 0; r <= R; ++r)
      if (r != leave) eliminate(r, leave, enter);
    basis_[leave] = enter;
  }

  // Pivots until no lambda column has a negative reduced cost; false when
  // the run looks unbounded or cycles (it cannot, in exact arithmetic).
  bool run()
  {
    for (int iteration = 0; iteration < 50 * (m_ + R); ++iteration) {
      int enter = -1;
      for (int c = 0; c < m_ && enter < 0; ++c)
        if (at(R, c) < -eps) enter = c;
      if (enter < 0) return true;
      int leave = -1;
      double best = 0;
      for (int r = 0; r < R; ++r)
        if (at(r, enter) > eps) {
          double ratio = at(r, W_ - 1) / at(r, enter);
          if (leave < 0 || ratio < best - eps || (ratio <= best + eps && basis_[r] < basis_[leave])) leave = r, best = ratio;
        }
      if (leave < 0) return false;
      pivot(leave, enter);
    }
    return false;
  }
};

} // namespace clash4d

#endif
