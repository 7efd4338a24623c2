// Interval_cell: the interval filter of one predicate of Cell_vertices.h,
// "the planes i, j, k meet in a vertex of the closure of w's cell", on
// rows with rational coefficients (a turning pair's planes at a rational
// time: Exact_slices::contact_point).
#ifndef CLASH4D_ROTATION_INTERVAL_CELL_H
#define CLASH4D_ROTATION_INTERVAL_CELL_H

#include "numbers/Rational.h"
#include "rotation/Cell_vertices.h"
#include "rotation/Moving_planes.h"

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>

#include <array>
#include <vector>

namespace clash4d {

// The rows are enclosed in intervals once. A triple whose enclosed point
// is surely on the wrong side of some plane is surely not a vertex; one
// whose determinant surely is not 0 and whose point is surely on w's side
// of every other plane surely is. Any other triple (a fourth plane through
// the point, or too close to call) is left to the exact decision.
class Interval_cell {
public:
  using I = CGAL::Interval_nt<false>;

  explicit Interval_cell(const std::vector<std::array<Rational, 4>>& rows)
  {
    CGAL::Protect_FPU_rounding<true> upward;
    for (const auto& r : rows) rows_.push_back(enclosed(r));
  }

  Cell_filter operator()(std::size_t i, std::size_t j, std::size_t k, const std::vector<int>& side) const
  {
    CGAL::Protect_FPU_rounding<true> upward;
    I d = det3(rows_[i], rows_[j], rows_[k]);
    if (!(d.inf() > 0 || d.sup() < 0)) return Cell_filter::unknown;
    std::array<I, 3> x = cramer_point(rows_[i], rows_[j], rows_[k], d);
    bool sure = true;   // every other plane surely on w's side so far
    for (std::size_t l = 0; l < rows_.size(); ++l) {
      if (l == i || l == j || l == k || side[l] == 0) continue;
      const auto& h = rows_[l];
      I v = h[0] * x[0] + h[1] * x[1] + h[2] * x[2] + h[3];
      if (side[l] > 0 ? v.sup() < 0 : v.inf() > 0) return Cell_filter::not_vertex;
      sure = sure && (side[l] > 0 ? v.inf() > 0 : v.sup() < 0);
    }
    return sure ? Cell_filter::vertex : Cell_filter::unknown;
  }

private:
  std::vector<std::array<I, 4>> rows_;
};

} // namespace clash4d

#endif
