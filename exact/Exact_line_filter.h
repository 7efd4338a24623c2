// The search policy of a rational conquer that decides single lines for an
// interval run (exact/Exact_span.h): only verdicts are wanted there, so the
// neighbourhood of a point is classified in intervals first, on enclosures
// of the exact normals and direction (CGAL's Filtered_predicate pattern),
// and in rationals only when the intervals cannot certify a sign.
#ifndef CLASH4D_EXACT_EXACT_LINE_FILTER_H
#define CLASH4D_EXACT_EXACT_LINE_FILTER_H

#include "exact/Interval_kernel.h"
#include "search/Neighbourhood.h"
#include "search/No_filter.h"

namespace clash4d {

// A neighbourhood's verdict in intervals (find: on a Neighbourhood of the
// interval kernel ak), or nothing when they leave a sign open; the cells it
// tested are added to `tested`. Shared by the filter's policies.
template <class Find>
std::optional<bool> interval_verdict(const Interval_kernel& ak, std::size_t& tested, Find find)
{
  Neighbourhood<Interval_kernel> hood(ak);
  try {
    bool found = find(hood);
    tested += hood.cells_tested();
    return found;
  } catch (const CGAL::Uncertain_conversion_exception&) {
    return std::nullopt;
  }
}

struct Exact_line_filter : No_filter {
  // Whether some open cell around the point is inside; nothing when the
  // intervals cannot tell. The direction into the cell is the intervals',
  // so it is not returned.
  template <class FT, class Inside>
  std::optional<bool> verdict_first(const Vector4<FT>& l, const std::vector<Vector4<FT>>& normals, Inside& inside,
                                    std::size_t& tested)
  {
    return on_enclosures(normals, tested, [&](auto& hood, const auto& near, auto enclose) {
      return hood.find_inside(enclose(l), near, inside).has_value();
    });
  }
  // The same around a closed touch point (Null_object_test::test_touch).
  template <class FT, class Inside>
  std::optional<bool> verdict_around(const std::vector<Vector4<FT>>& normals, Inside inside, std::size_t& tested)
  {
    return on_enclosures(normals, tested, [&](auto& hood, const auto& near, auto) {
      return hood.find_inside_around(near, inside).has_value();
    });
  }

private:
  template <class FT, class Find>
  static std::optional<bool> on_enclosures(const std::vector<Vector4<FT>>& normals, std::size_t& tested, Find find)
  {
    Interval_kernel::Protector protect;
    Interval_kernel ak;
    auto enclose = [&](const Vector4<FT>& v) {
      return Vector4<Interval>{ak.from_rational(v[0]), ak.from_rational(v[1]), ak.from_rational(v[2]),
                               ak.from_rational(v[3])};
    };
    std::vector<Vector4<Interval>> near;
    for (const auto& n : normals) near.push_back(enclose(n));
    return interval_verdict(ak, tested, [&](auto& hood) { return find(hood, near, enclose); });
  }
};

} // namespace clash4d

#endif
