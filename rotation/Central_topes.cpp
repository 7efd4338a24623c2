#include "rotation/Central_topes.h"

#include <algorithm>

namespace clash4d {

namespace {

// Evaluation at r is a ring map from Q[t] to Q(r): p and p mod r's
// minimal polynomial have one sign at r. So the normals, and each cross
// product made of them, are kept below r's degree (a rational r: their
// values), and a product never has the degree 8 of the normals' own.
Time_poly reduced(const Time_poly& p, const Algebraic& r)
{
  std::size_t degree = r.is_rational() ? 1 : r.polynomial().size() - 1;
  if (static_cast<std::size_t>(p.size()) <= degree) return p;
  return Time_poly(Algebraic::field_element(r, p.coefficients(), {Rational(1)}));
}

Time_direction reduced(const Time_direction& d, const Algebraic& r)
{
  return {reduced(d[0], r), reduced(d[1], r), reduced(d[2], r)};
}

Time_direction cross(const Time_direction& a, const Time_direction& b, const Algebraic& r)
{
  return reduced(Time_direction{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}, r);
}

int dot_sign(const Time_direction& a, const Time_direction& b, const Algebraic& r)
{
  return sign_at(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], r);
}

bool vanishes_at(const Time_direction& d, const Algebraic& r)
{
  return sign_at(d[0], r) == CGAL::ZERO && sign_at(d[1], r) == CGAL::ZERO && sign_at(d[2], r) == CGAL::ZERO;
}

// The cells next to the line v (not zero at r): on v's side of the planes
// not through it, and in each sector of those through it, found as the
// sum of two of their rays +-(v x n_a). Sums that fall on a plane (two rays
// of one line) are no cell and are dropped.
void cells_along(const std::vector<Time_direction>& normals, const Time_direction& v, const Algebraic& r,
                 std::set<std::vector<int>>& out)
{
  std::size_t k = normals.size();
  std::vector<int> along(k);   // each plane's side of v, 0 for the planes through it
  std::vector<Time_direction> rays;
  for (std::size_t a = 0; a < k; ++a) {
    along[a] = dot_sign(normals[a], v, r);
    if (along[a] != 0) continue;
    Time_direction w = cross(v, normals[a], r);
    rays.push_back(w);
    rays.push_back({-w[0], -w[1], -w[2]});
  }
  for (std::size_t x = 0; x < rays.size(); ++x)
    for (std::size_t y = x + 1; y < rays.size(); ++y) {
      Time_direction w = {rays[x][0] + rays[y][0], rays[x][1] + rays[y][1], rays[x][2] + rays[y][2]};
      std::vector<int> sides = along;
      for (std::size_t a = 0; a < k; ++a)
        if (along[a] == 0) sides[a] = dot_sign(normals[a], w, r);
      if (std::find(sides.begin(), sides.end(), 0) == sides.end()) out.insert(sides);
    }
}

} // namespace

CGAL::Sign sign_at(const Time_poly& p, const Algebraic& t)
{
  if (t.is_rational()) return CGAL::sign(p.at(t.rational()));
  return t.sign_of(p.coefficients());
}

std::set<std::vector<int>> central_topes(const std::vector<Time_direction>& given, const Algebraic& r)
{
  std::vector<Time_direction> normals;
  for (const Time_direction& n : given) normals.push_back(reduced(n, r));
  std::set<std::vector<int>> out;
  bool rank_one = true;
  for (std::size_t i = 0; i < normals.size(); ++i)
    for (std::size_t j = i + 1; j < normals.size(); ++j) {
      Time_direction v = cross(normals[i], normals[j], r);
      if (vanishes_at(v, r)) continue;
      rank_one = false;
      cells_along(normals, v, r, out);
      cells_along(normals, {-v[0], -v[1], -v[2]}, r, out);
    }
  if (rank_one && !normals.empty())
    for (int sense : {1, -1}) {
      std::vector<int> sides;
      for (const Time_direction& n : normals) sides.push_back(sense * dot_sign(n, normals[0], r));
      out.insert(sides);   // no zero: parallel normals, none zero
    }
  return out;
}

} // namespace clash4d
