#include "scene/Hull_solid.h"
#include "geometry/Polytope_ft.h"

namespace clash4d {

Rational make_hull_solid(const std::vector<Rational3>& points, Solid& s)
{
  if (points.size() < 4)
    throw std::invalid_argument("a hull needs at least 4 points not in one plane, found " + std::to_string(points.size()));
  Polytope_combinatorics c = hull_facets(points);
  s.kind = Solid::Kind::Hull;
  s.triples = c.triples;
  s.corners = c.corners.empty() ? nullptr : std::make_shared<const Corners>(std::move(c.corners));
  s.numbers.clear();
  s.constructed.clear();
  for (const auto& p : points) s.numbers.insert(s.numbers.end(), p.begin(), p.end());
  for (const auto& t : s.triples) {
    Rational4 plane = facet_plane(points[t[0]], points[t[1]], points[t[2]]);
    s.constructed.insert(s.constructed.end(), plane.begin(), plane.end());
  }
  return c.six_volume;
}

} // namespace clash4d
