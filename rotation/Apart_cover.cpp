#include "rotation/Apart_cover.h"

namespace clash4d {

// Under the caller's rounding guard: the pose's numbers enclosed once, and
// N(q(t)) and |q(t)|^2 made from them in intervals (the same formulas as
// the exact rows, so the same structural zeros: a vertical plane turning
// about z keeps an exactly zero z part).
Apart_cover::Side Apart_cover::side(const Rotating_object& o, const Rational& at, std::size_t first_row)
{
  const Pose_segment& s = segment_at(o.segments, at);
  Side out;
  std::array<Interval_poly, 4> q = {enclosed(s.q[0]), enclosed(s.q[1]), enclosed(s.q[2]), enclosed(s.q[3])};
  out.rotation = unnormalised_rotation(q);
  out.norm = squared_norm(q);
  for (int k = 0; k < 3; ++k) out.origin[k] = enclosed(s.c[k]);
  for (const auto& v : o.shape.vertices)
    out.vertices.push_back(enclosed(v));
  out.orientation.assign(o.shape.planes.size(), 0);
  if (o.shape.convex_pieces.size() == 1)
    for (auto [plane, orientation] : o.shape.convex_pieces.front()) out.orientation[plane] = orientation;
  out.first_row = first_row;
  out.edges = o.shape.edge_vertices;
  // Constant: every coefficient past the first exactly 0 (a resting pose
  // is written as a segment whose slopes are 0), so its value at any t is
  // exactly its first coefficient.
  auto constant = [](const Interval_poly& p) {
    for (int i = 1; i < p.size(); ++i)
      if (!(p[i].inf() == 0 && p[i].sup() == 0)) return false;
    return true;
  };
  bool rests = constant(out.norm);
  for (int r = 0; r < 3; ++r) {
    rests = rests && constant(out.origin[r]);
    for (int c = 0; c < 3; ++c) rests = rests && constant(out.rotation[r][c]);
  }
  if (rests) out.at_rest = vertices_at(out, I(0));
  return out;
}

// The planes' rows in intervals, from the sides' enclosed poses: no exact
// row is made before the cover leaves a run (fact 9's polynomials, bounded
// surely by interval arithmetic on enclosures of their inputs).
void Apart_cover::add_rows(const Rotating_object& o, const Side& s)
{
  for (const Plane3<Rational>& p : o.shape.planes) rows_.push_back(moved_plane(enclosed(p), s.rotation, s.norm, s.origin));
}

Apart_cover::Apart_cover(const Rotating_object& a, const Rotating_object& b, const Rational& at)
{
  CGAL::Protect_FPU_rounding<true> upward;
  a_ = side(a, at, 0);
  b_ = side(b, at, a.shape.planes.size());
  add_rows(a, a_);
  add_rows(b, b_);
}

std::vector<std::array<Apart_cover::I, 4>> Apart_cover::rows_on(const I& t) const
{
  std::vector<std::array<I, 4>> rows(rows_.size());
  for (std::size_t r = 0; r < rows_.size(); ++r)
    for (int c = 0; c < 4; ++c) rows[r][c] = rows_[r][c].at(t);
  return rows;
}

// A vertex v at rest is at N(q) v / |q|^2 + c at time t (the pose's
// rotation about the shape's origin, then its origin's path).
std::vector<Apart_cover::Point> Apart_cover::vertices_on(const Side& s, const I& t) const
{
  return s.at_rest ? *s.at_rest : vertices_at(s, t);
}

std::vector<Apart_cover::Point> Apart_cover::vertices_at(const Side& s, const I& t)
{
  std::array<std::array<I, 3>, 3> n;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) n[r][c] = s.rotation[r][c].at(t);
  I norm = s.norm.at(t);
  Point origin = {s.origin[0].at(t), s.origin[1].at(t), s.origin[2].at(t)};
  std::vector<Point> out;
  out.reserve(s.vertices.size());
  for (const Point& v : s.vertices) {
    Point x;
    for (int r = 0; r < 3; ++r) x[r] = (n[r][0] * v[0] + n[r][1] * v[1] + n[r][2] * v[2]) / norm + origin[r];
    out.push_back(x);
  }
  return out;
}

const Apart_cover::Reach& Apart_cover::reach(const Side& s, std::size_t p, std::size_t k) const
{
  const Side& other = &s == &a_ ? b_ : a_;
  std::vector<int>& index = reach_index_[&s == &a_ ? 0 : 1];
  if (index.empty()) index.assign(s.orientation.size() * other.vertices.size(), -1);
  int& at = index[p * other.vertices.size() + k];
  if (at >= 0) return reach_store_[static_cast<std::size_t>(at)];
  const std::array<Interval_poly, 4>& h = rows_[s.first_row + p];
  const Point& v = other.vertices[k];
  Interval_poly value = (h[3] + h[0] * other.origin[0] + h[1] * other.origin[1] + h[2] * other.origin[2]) * other.norm;
  for (int c = 0; c < 3; ++c)
    value += h[c] * (v[0] * other.rotation[c][0] + v[1] * other.rotation[c][1] + v[2] * other.rotation[c][2]);
  if (s.orientation[p] < 0) value = -value;
  at = static_cast<int>(reach_store_.size());
  reach_store_.push_back(Reach{value, value.derivative()});
  return reach_store_.back();
}

bool Apart_cover::outside(const Side& s, std::size_t p, const std::vector<std::array<I, 4>>& rows,
                          const std::vector<Point>& points, std::size_t k, const I& t, const I& mid) const
{
  const std::array<I, 4>& h = rows[s.first_row + p];
  const Point& x = points[k];
  I v = h[0] * x[0] + h[1] * x[1] + h[2] * x[2] + h[3];
  if (s.orientation[p] < 0) v = -v;
  if (v.inf() > 0) return true;
  if (v.sup() <= 0) return false;
  const Reach& r = reach(s, p, k);
  return (r.value.at(mid) + r.slope.at(t) * (t - mid)).inf() > 0;
}

// Row p of s, oriented outward (orientation * (n.x + e) > 0 outside),
// with every point strictly outside: the closed convex hull of the points
// and s's piece are then on the two sides of the plane.
bool Apart_cover::separates(const Side& s, const std::vector<std::array<I, 4>>& rows, const std::vector<Point>& points,
                            const I& t, const I& mid) const
{
  for (std::size_t p = 0; p < s.orientation.size(); ++p) {
    if (s.orientation[p] == 0) continue;
    bool all = true;
    for (std::size_t k = 0; k < points.size() && all; ++k) all = outside(s, p, rows, points, k, t, mid);
    if (all) return true;
  }
  return false;
}

std::vector<bool> Apart_cover::far_parts(const Side& s, const std::vector<std::array<I, 4>>& rows,
                                         const std::vector<Point>& points, const std::vector<std::vector<int>>& edges,
                                         const I& t, const I& mid) const
{
  std::size_t n = s.orientation.size();
  std::vector<bool> beyond(points.size() * n, false);   // [point * n + plane]
  for (std::size_t p = 0; p < n; ++p) {
    if (s.orientation[p] == 0) continue;
    for (std::size_t k = 0; k < points.size(); ++k) beyond[k * n + p] = outside(s, p, rows, points, k, t, mid);
  }
  auto far = [&](const std::vector<int>& part) {
    for (std::size_t p = 0; p < n; ++p) {
      bool all = true;
      for (int k : part) all = all && beyond[k * n + p];
      if (all) return true;
    }
    return false;
  };
  std::vector<bool> out;
  out.reserve(points.size() + edges.size());
  for (std::size_t k = 0; k < points.size(); ++k) out.push_back(far({static_cast<int>(k)}));
  for (const auto& e : edges) out.push_back(far(e));
  return out;
}

Pair_features Apart_cover::near_features(const Pair_features& all, const Rational& lo, const Rational& hi) const
{
  Pair_features out;
  out.sides = all.sides;
  std::vector<bool> far_a, far_b;
  {
    CGAL::Protect_FPU_rounding<true> upward;
    auto [t, mid] = times(lo, hi);
    std::vector<std::array<I, 4>> rows = rows_on(t);
    far_a = far_parts(b_, rows, vertices_on(a_, t), a_.edges, t, mid);
    far_b = far_parts(a_, rows, vertices_on(b_, t), b_.edges, t, mid);
  }
  for (std::size_t f = 0; f < all.minors.size(); ++f) {
    auto [pa, pb] = all.parts[f];
    if ((pa >= 0 && far_a[pa]) || (pb >= 0 && far_b[pb])) continue;
    out.minors.push_back(all.minors[f]);
    out.parts.push_back(all.parts[f]);
  }
  return out;
}

bool Apart_cover::apart_on(const Rational& lo, const Rational& hi) const
{
  if (a_.vertices.empty() || b_.vertices.empty()) return false;
  CGAL::Protect_FPU_rounding<true> upward;
  auto [t, mid] = times(lo, hi);
  std::vector<std::array<I, 4>> rows = rows_on(t);
  return separates(a_, rows, vertices_on(b_, t), t, mid) || separates(b_, rows, vertices_on(a_, t), t, mid);
}

std::pair<Apart_cover::I, Apart_cover::I> Apart_cover::times(const Rational& lo, const Rational& hi)
{
  I t(enclosing_interval(lo).first, enclosing_interval(hi).second);
  double m = t.inf() + (t.sup() - t.inf()) / 2;   // rounded: kept only if it lies in t
  return {t, I(t.inf() <= m && m <= t.sup() ? m : t.inf())};
}

} // namespace clash4d
