#include "rotation/Critical_times.h"

#include <algorithm>
#include <map>

namespace clash4d {

Time_poly normal_minor(const Moving_plane& a, const Moving_plane& b, const Moving_plane& c)
{
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

std::vector<Rational> monic(const Time_poly& p)
{
  std::vector<Rational> c = p.coefficients();
  while (!c.empty() && CGAL::sign(c.back()) == CGAL::ZERO) c.pop_back();
  if (c.empty()) return c;
  Rational lead = c.back();
  for (Rational& x : c) x /= lead;
  return c;
}

namespace {

using Poly_key = std::vector<Rational>;

struct Key_less {
  bool operator()(const Poly_key& a, const Poly_key& b) const
  {
    if (a.size() != b.size()) return a.size() < b.size();
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (a[i] < b[i]) return true;
      if (b[i] < a[i]) return false;
    }
    return false;
  }
};

// The minors by their monic polynomial: each distinct one is solved once.
class Minor_table {
public:
  void add(const Time_poly& p, const Minor_rows& rows)
  {
    Poly_key k = monic(p);
    if (k.size() < 2) return;   // a non-zero constant, or identically zero
    table_[k].push_back(rows);
  }
  const std::map<Poly_key, std::vector<Minor_rows>, Key_less>& table() const { return table_; }

private:
  std::map<Poly_key, std::vector<Minor_rows>, Key_less> table_;
};

// The 4 x 4 determinant of rows i < j < k < l by the last column: the
// offsets e against the minors of the normals.
Time_poly full_minor(const std::vector<Moving_plane>& r, const Minor_rows& m,
                     const std::map<std::array<int, 3>, Time_poly>& normals)
{
  auto D = [&](int a, int b, int c) -> const Time_poly& { return normals.at({a, b, c}); };
  auto [i, j, k, l] = m;
  return r[j][3] * D(i, k, l) - r[i][3] * D(j, k, l) + r[l][3] * D(i, j, k) - r[k][3] * D(i, j, l);
}

// The 2 x 2 minors of rows (i, j) over each two of the four columns.
void pair_minors(const std::vector<Moving_plane>& r, int i, int j, Minor_table& table)
{
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) table.add(r[i][a] * r[j][b] - r[i][b] * r[j][a], {i, j, -1, -1});
}

// The 3 x 3 minors of rows (i, j, k) over each three of the four columns.
void low_rank_minors(const std::vector<Moving_plane>& r, int i, int j, int k, Minor_table& table)
{
  for (int drop = 0; drop < 3; ++drop) {
    std::array<Moving_plane, 3> rows = {r[i], r[j], r[k]};
    for (auto& row : rows) row[drop] = row[3];   // column `drop` replaced by e
    table.add(normal_minor(rows[0], rows[1], rows[2]), {i, j, k, -1});
  }
}

} // namespace

Critical_times::Critical_times(const std::vector<Moving_plane>& rows, std::size_t first_count, const Rational& lo,
                               const Rational& hi, bool low_rank)
{
  int m = static_cast<int>(rows.size()), split = static_cast<int>(first_count);
  auto mixed = [&](std::initializer_list<int> ids) {
    bool a = false, b = false;
    for (int i : ids) (i < split ? a : b) = true;
    return a && b;
  };
  std::map<std::array<int, 3>, Time_poly> normals;
  Minor_table table;
  if (low_rank)
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j)
        if (mixed({i, j})) pair_minors(rows, i, j, table);
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k) {
        Time_poly d = normal_minor(rows[i], rows[j], rows[k]);
        if (mixed({i, j, k})) {
          table.add(d, {i, j, k, -1});   // with v_inf: parallel or meeting at infinity
          if (low_rank) low_rank_minors(rows, i, j, k, table);
        }
        normals.emplace(std::array<int, 3>{i, j, k}, std::move(d));
      }
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k)
        for (int l = k + 1; l < m; ++l)
          if (mixed({i, j, k, l})) table.add(full_minor(rows, {i, j, k, l}, normals), {i, j, k, l});
  for (const auto& [key, minors] : table.table()) {
    minor_count_ += minors.size();
    for (Algebraic& r : Algebraic::real_roots(key, lo, hi)) {
      if (compare(r, lo) <= 0 || compare(r, hi) >= 0) continue;
      times_.push_back({std::move(r), minors});
    }
  }
  std::sort(times_.begin(), times_.end(), [](const Critical_time& a, const Critical_time& b) { return a.t < b.t; });
  // Equal roots of different polynomials: one critical time.
  std::vector<Critical_time> merged;
  for (Critical_time& c : times_) {
    if (!merged.empty() && merged.back().t == c.t) {
      merged.back().vanishing.insert(merged.back().vanishing.end(), c.vanishing.begin(), c.vanishing.end());
      continue;
    }
    merged.push_back(std::move(c));
  }
  times_ = std::move(merged);
}

} // namespace clash4d
