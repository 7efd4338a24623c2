// Interval_cell: one predicate of Cell_vertices.h, "the planes i, j, k
// meet in a vertex of the closure of w's cell", filtered, on rows with
// rational coefficients (a turning pair's planes at a rational time:
// Exact_slices::contact_point). Intervals first; the sides they cannot
// call are decided exactly on the same indices, without making the point.
#ifndef CLASH4D_ROTATION_INTERVAL_CELL_H
#define CLASH4D_ROTATION_INTERVAL_CELL_H

#include "geometry/kernel_ft4.h"
#include "numbers/Rational.h"
#include "rotation/Cell_vertices.h"
#include "rotation/Moving_planes.h"

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>

#include <array>
#include <optional>
#include <vector>

namespace clash4d {

// The rows are enclosed in intervals once. A triple whose determinant
// surely is not 0 is decided here: its enclosed point surely on the wrong
// side of some plane is surely not a vertex; a plane the intervals cannot
// call (a fourth plane through the point, or one too close) gets its exact
// side, the sign of
//   h_l(x) = det4(h_i, h_j, h_k, h_l) / det3(n_i, n_j, n_k)
// (Cramer on the 4 x 4 system whose last unknown is 1), in GMP integers on
// the rows over a common denominator. Only a triple whose determinant the
// intervals cannot sign is left to cell_vertices' decision in rationals
// (Cell_filter::unknown). The rows must outlive the predicate.
class Interval_cell {
public:
  using I = CGAL::Interval_nt<false>;

  explicit Interval_cell(const std::vector<std::array<Rational, 4>>& rows) : exact_(rows)
  {
    CGAL::Protect_FPU_rounding<true> upward;
    for (const auto& r : rows) rows_.push_back(enclosed(r));
  }

  Cell_filter operator()(std::size_t i, std::size_t j, std::size_t k, const std::vector<int>& side) const
  {
    std::vector<std::size_t> open;   // the planes the intervals leave
    int det_sign = 0;
    {
      CGAL::Protect_FPU_rounding<true> upward;
      I d = det3(rows_[i], rows_[j], rows_[k]);
      if (!(d.inf() > 0 || d.sup() < 0)) return Cell_filter::unknown;
      det_sign = d.inf() > 0 ? 1 : -1;
      std::array<I, 3> x = cramer_point(rows_[i], rows_[j], rows_[k], d);
      for (std::size_t l = 0; l < rows_.size(); ++l) {
        if (l == i || l == j || l == k || side[l] == 0) continue;
        const auto& h = rows_[l];
        I v = h[0] * x[0] + h[1] * x[1] + h[2] * x[2] + h[3];
        if (side[l] > 0 ? v.sup() < 0 : v.inf() > 0) return Cell_filter::not_vertex;
        if (!(side[l] > 0 ? v.inf() > 0 : v.sup() < 0)) open.push_back(l);
      }
    }
    if (open.empty()) return Cell_filter::vertex;
    Vector4<mpz_class> g = generalised_cross(integer_row(i), integer_row(j), integer_row(k));
    for (std::size_t l : open) {
      ++exact_sides_;
      if (side[l] * det_sign * sgn(dot(g, integer_row(l))) < 0) return Cell_filter::not_vertex;
    }
    return Cell_filter::vertex;
  }

  // How many sides the exact stage has decided (a test's path-coverage floor).
  long exact_sides() const { return exact_sides_; }

private:
  // Row l over a common denominator (positive: the signs above are kept).
  const Vector4<mpz_class>& integer_row(std::size_t l) const
  {
    if (integers_.empty()) integers_.resize(exact_.size());
    std::optional<Vector4<mpz_class>>& X = integers_[l];
    if (!X) {
      mpz_class d;
      over_common_denominator(exact_[l].data(), 4, X.emplace().data(), d);
    }
    return *X;
  }

  const std::vector<std::array<Rational, 4>>& exact_;
  std::vector<std::array<I, 4>> rows_;
  mutable std::vector<std::optional<Vector4<mpz_class>>> integers_;   // each row made on first need
  mutable long exact_sides_ = 0;
};

} // namespace clash4d

#endif
