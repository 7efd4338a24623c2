#include "rotation/Exact_slices.h"

#include "exact/Closed_in_field.h"
#include "geometry/kernel_ft4.h"
#include "numbers/Quadratic_element.h"
#include "rotation/Cell_vertices.h"
#include "rotation/Central_topes.h"
#include "rotation/Interval_cell.h"
#include "rotation/Rotating_pair.h"
#include "rotation/Simplest_rational.h"

#include <CGAL/Interval_nt.h>

#include <set>

namespace clash4d {

namespace {

using CGAL::is_zero;   // exact on Rational

Algebraic quotient_at(const Time_poly& num, const Time_poly& den, const Algebraic& t)
{
  if (t.is_rational()) return Algebraic(num.at(t.rational()) / den.at(t.rational()));
  return Algebraic::quotient_at(t, num.coefficients(), den.coefficients());
}

// Cramer's quotients of the point where rows i, j, k meet, made on the
// rows times the positive common denominators of their coefficients:
// integer polynomials, so no fraction is reduced on the way, and the same
// quotients (a row's factor multiplies numerators and denominator alike).
Quotient_point meeting_quotients(const Moving_plane& a, const Moving_plane& b, const Moving_plane& c)
{
  using Row = std::array<Integer_time_poly, 4>;
  mpz_class d;
  std::array<Row, 3> r = {integer_polys(a, d), integer_polys(b, d), integer_polys(c, d)};
  Quotient_point q;
  for (int col = 0; col < 3; ++col) {
    std::array<Row, 3> m = r;
    for (Row& row : m) row[col] = -row[3];
    q.num[col] = rational_poly(normal_minor(m[0], m[1], m[2]));
  }
  q.den = rational_poly(normal_minor(r[0], r[1], r[2]));
  return q;
}

std::array<Algebraic, 3> point_at(const std::array<Time_poly, 3>& num, const Time_poly& den, const Algebraic& t)
{
  return {quotient_at(num[0], den, t), quotient_at(num[1], den, t), quotient_at(num[2], den, t)};
}

// t's minimal polynomial over Q (t - q for a rational q), constant first.
std::vector<Rational> minimal_polynomial(const Algebraic& t)
{
  if (t.is_rational()) return {-t.rational(), Rational(1)};
  std::vector<Rational> m;
  for (const mpz_class& c : t.polynomial()) m.emplace_back(CGAL::Gmpz(c.get_mpz_t()));
  return m;
}

// p / m when m divides p in Q[t] (long division, remainder zero); p = 0
// divides as 0.
std::optional<Time_poly> divided(const Time_poly& p, const std::vector<Rational>& m)
{
  std::vector<Rational> r = p.coefficients();
  while (!r.empty() && is_zero(r.back())) r.pop_back();
  if (r.empty()) return Time_poly(Rational(0));
  if (r.size() < m.size()) return std::nullopt;
  std::vector<Rational> q(r.size() - m.size() + 1);
  for (std::size_t i = q.size(); i-- > 0;) {
    q[i] = r[i + m.size() - 1] / m.back();
    for (std::size_t j = 0; j < m.size(); ++j) r[i + j] -= q[i] * m[j];
  }
  for (const Rational& x : r)
    if (!is_zero(x)) return std::nullopt;
  return Time_poly(q);
}

// lim num(t) / den(t) as t -> t*, den not identically zero: with m the
// minimal polynomial of t* and m^k the largest power dividing den, the
// limit is (num / m^k)(t*) / (den / m^k)(t*) when m^k divides each num
// (L'Hopital, exactly); otherwise the point runs off to infinity (none).
std::optional<std::array<Algebraic, 3>> limit_at(std::array<Time_poly, 3> num, Time_poly den, const Algebraic& t)
{
  std::vector<Rational> m = minimal_polynomial(t);
  while (sign_at(den, t) == CGAL::ZERO) {
    std::optional<Time_poly> d = divided(den, m);
    if (!d) return std::nullopt;   // not reached: m divides every p with p(t*) = 0
    den = *d;
    for (Time_poly& n : num) {
      std::optional<Time_poly> q = divided(n, m);
      if (!q) return std::nullopt;
      n = *q;
    }
  }
  return point_at(num, den, t);
}

// The side of each row at the point x(r) = num(r) / den(r), r irrational,
// asked row by row (one predicate, filtered): 0 for the rows the point is
// made on (and the vanishing minor's fourth, through the same point); else
// the sign of an interval evaluation at r's isolating interval when it is
// sure; else the exact sign in Q(r).
class Point_signs {
public:
  using I = CGAL::Interval_nt<false>;

  Point_signs(const std::vector<Moving_plane>& rows, const std::array<Time_poly, 3>& num, const Time_poly& den,
              CGAL::Sign den_sign, const Algebraic& r, const std::vector<int>& on_rows)
    : rows_(rows), num_(num), den_(den), den_sign_(den_sign), r_(r), side_(rows.size(), unknown)
  {
    for (int i : on_rows) side_[i] = 0;
    r.narrow_in_doubles();
    CGAL::Protect_FPU_rounding<true> upward;
    t_ = r.to_interval();
    I d = at(den);
    enclosed_ = d.inf() > 0 || d.sup() < 0;
    if (enclosed_)
      for (int c = 0; c < 3; ++c) x_[c] = at(num[c]) / d;
  }

  int operator()(std::size_t row)
  {
    if (side_[row] != unknown) return side_[row];
    const Moving_plane& h = rows_[row];
    if (enclosed_) {
      CGAL::Protect_FPU_rounding<true> upward;
      I v = at(h[0]) * x_[0] + at(h[1]) * x_[1] + at(h[2]) * x_[2] + at(h[3]);
      if (v.inf() > 0) return side_[row] = 1;
      if (v.sup() < 0) return side_[row] = -1;
    }
    // h(x(t), t) den(t) = n . num + e den.
    Time_poly v = h[0] * num_[0] + h[1] * num_[1] + h[2] * num_[2] + h[3] * den_;
    return side_[row] = sign_at(v, r_) * den_sign_;
  }

private:
  static constexpr int unknown = 2;
  I at(const Time_poly& p) const
  {
    I v(0);
    for (int i = p.size() - 1; i >= 0; --i) v = v * t_ + I(enclosing_interval(p[i]));
    return v;
  }

  const std::vector<Moving_plane>& rows_;
  const std::array<Time_poly, 3>& num_;
  const Time_poly& den_;
  CGAL::Sign den_sign_;
  const Algebraic& r_;
  std::vector<int> side_;
  I t_;
  bool enclosed_ = false;
  std::array<I, 3> x_;
};

// Where the planes `ids` meet at the rational time t, when they are
// independent there (Cramer's rule on their values at t).
std::optional<std::array<Rational, 3>> meeting_point_at(const std::vector<Moving_plane>& rows, std::array<int, 3> ids,
                                                        const Rational& t)
{
  std::array<std::array<Rational, 4>, 3> r = {plane_at(rows[ids[0]], t), plane_at(rows[ids[1]], t),
                                              plane_at(rows[ids[2]], t)};
  Rational d = det3(r[0], r[1], r[2]);
  if (is_zero(d)) return std::nullopt;
  return cramer_point(r[0], r[1], r[2], d);
}

// The same at an irrational quadratic t (the usual irrational t* of a
// turning pair): Cramer's rule on the planes' values in Q(t), a few
// products where the quotients as polynomials (meeting_quotients, then
// quotient_at) make 4 minors of degree 6 and read each at t.
std::optional<std::array<Algebraic, 3>> meeting_point_in(const Quadratic_element& field,
                                                         const std::vector<Moving_plane>& rows, std::array<int, 3> ids)
{
  std::array<std::array<Quadratic_element, 4>, 3> r;
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 4; ++c) {
      const Time_poly& g = rows[ids[k]][c];
      r[k][c] = field.at(g.size() > 0 ? &g[0] : nullptr, static_cast<std::size_t>(g.size()));
    }
  // Cramer's rule by the normals' cross products, u = n1 x n2, v = n2 x n0,
  // w = n0 x n1: d = n0 . u, and x = -(e0 u + e1 v + e2 w) / d (fewer
  // products in Q(t) than four 3 x 3 determinants, and one inverse).
  std::array<Vector3<Quadratic_element>, 3> n;
  for (int k = 0; k < 3; ++k) n[k] = {r[k][0], r[k][1], r[k][2]};
  Vector3<Quadratic_element> u = cross(n[1], n[2]), v = cross(n[2], n[0]), w = cross(n[0], n[1]);
  Quadratic_element d = r[0][0] * u[0] + r[0][1] * u[1] + r[0][2] * u[2];
  if (d.is_zero()) return std::nullopt;
  Quadratic_element minus_inverse = (-d).inverse();
  std::array<Algebraic, 3> x;
  for (int c = 0; c < 3; ++c) x[c] = ((r[0][3] * u[c] + r[1][3] * v[c] + r[2][3] * w[c]) * minus_inverse).value();
  return x;
}

// Whether the point lies in the closed object whose planes are rows[offset
// ...]: in some convex piece of it (a union of bounded convex pieces), all
// rows <= 0.
bool in_closed_pieces(std::size_t offset, const Shape_planes& shape, Point_signs& side)
{
  for (const auto& piece : shape.convex_pieces) {
    bool inside = true;
    for (auto [plane, orientation] : piece) {
      inside = orientation * side(offset + plane) <= 0;
      if (!inside) break;
    }
    if (inside) return true;
  }
  return false;
}

// Whether the point is in the closed regular set of a CSG shape whose
// planes are rows[offset ...]: some open cell next to the point is inside.
// When at most three planes pass through it and they are independent there,
// every choice of their sides is a cell; otherwise the cells are the topes
// of their normals (a vertex of four faces, a plane through an edge).
bool in_closed_cells(const std::vector<Moving_plane>& rows, std::size_t offset, const Rotating_object& o,
                     Point_signs& signs, const Algebraic& r)
{
  std::size_t m = o.shape.planes.size();
  std::vector<int> side(m), zero;
  for (std::size_t p = 0; p < m; ++p) {
    side[p] = signs(offset + p);
    if (side[p] == 0) zero.push_back(static_cast<int>(p));
  }
  bool independent = zero.size() < 2;
  if (zero.size() == 3)
    independent = sign_at(normal_minor(rows[offset + zero[0]], rows[offset + zero[1]], rows[offset + zero[2]]), r) != CGAL::ZERO;
  if (zero.size() == 2) {
    const Moving_plane &u = rows[offset + zero[0]], &v = rows[offset + zero[1]];
    for (int i = 0; i < 3 && !independent; ++i)
      independent = sign_at(u[i] * v[(i + 1) % 3] - u[(i + 1) % 3] * v[i], r) != CGAL::ZERO;
  }
  std::set<std::vector<int>> cells;
  if (independent) {
    for (unsigned mask = 0; mask < (1u << zero.size()); ++mask) {
      std::vector<int> sides;
      for (std::size_t k = 0; k < zero.size(); ++k) sides.push_back((mask >> k) & 1 ? 1 : -1);
      cells.insert(sides);
    }
  } else {
    std::vector<Time_direction> normals;
    for (int p : zero) normals.push_back({rows[offset + p][0], rows[offset + p][1], rows[offset + p][2]});
    cells = central_topes(normals, r);
  }
  for (const std::vector<int>& sides : cells) {
    for (std::size_t k = 0; k < zero.size(); ++k) side[zero[k]] = sides[k];
    if (inside_at_generic(o.shape, side)) return true;
  }
  return false;
}

bool in_closed_object(const std::vector<Moving_plane>& rows, std::size_t offset, const Rotating_object& o,
                      Point_signs& signs, const Algebraic& r)
{
  if (!o.shape.convex_pieces.empty()) return in_closed_pieces(offset, o.shape, signs);
  return in_closed_cells(rows, offset, o, signs, r);
}

// The closed question at an irrational critical time r (fact 12): closed
// objects that meet at r and at no time near it meet in a vertex-face or
// edge-edge contact, a point on the four planes of a minor that vanishes
// at r, three of them independent there (docs/rotation.md). Each such point
// is tried against both objects, exactly in Q(r).
std::optional<Quotient_point> common_point_at(const std::vector<Moving_plane>& rows, const Rotating_object& a,
                                              const Rotating_object& b, const Critical_time& c)
{
  std::size_t offset = a.shape.planes.size();
  for (const Minor_rows& m : c.vanishing) {
    std::vector<int> ids;
    for (int i : m)
      if (i >= 0) ids.push_back(i);
    if (ids.size() < 3) continue;   // a low-rank 2 x 2 minor: no point
    for (std::size_t skip = 0; skip < (ids.size() == 4 ? 4u : 1u); ++skip) {
      std::vector<int> t;
      for (std::size_t i = 0; i < ids.size(); ++i)
        if (i != skip || ids.size() == 3) t.push_back(ids[i]);
      Quotient_point x = meeting_quotients(rows[t[0]], rows[t[1]], rows[t[2]]);
      CGAL::Sign ds = sign_at(x.den, c.t);
      if (ds == CGAL::ZERO) continue;
      Point_signs signs(rows, x.num, x.den, ds, c.t, ids);
      if (in_closed_object(rows, 0, a, signs, c.t) && in_closed_object(rows, offset, b, signs, c.t)) return x;
    }
  }
  return std::nullopt;
}


} // namespace

std::vector<Moving_plane> Exact_slices::rows(const Rotating_object& a, const Rotating_object& b,
                                             const Rational& at) const
{
  return integer_pair_rows(a, b, at);
}

// Between rational ends (a piece between pose times, before any critical
// time is known) the midpoint: a verdict is asked there first
// (Rotating_pair.cpp), and an end-heavy simplest rational (1/11 in (0,
// 1/10)) misses more overlaps in the middle of a piece. Between algebraic
// ends the simplest rational, whose numbers stay small.
std::optional<Rational> Exact_slices::sample(const Algebraic& left, const Algebraic& right) const
{
  if (left.is_rational() && right.is_rational()) return (left.rational() + right.rational()) / 2;
  return simplest_between(left, right);
}

namespace {

Vector3<Time_poly> moving_normal(const Moving_plane& row) { return {row[0], row[1], row[2]}; }

// The plane d(t).x + e = 0 through the origin (e = 0), so that a contact
// point on it has small coordinates where the pair's planes pass near the
// origin; e = 1 where w lies on that plane at s. Either way w is off it,
// and w's side of it names w's cut cell.
Moving_plane cut_through(const Vector3<Time_poly>& d, const Rational& s, const std::array<Rational, 3>& w)
{
  Rational at_w(0);
  for (int c = 0; c < 3; ++c) at_w += d[c].at(s) * w[c];
  return Moving_plane{d[0], d[1], d[2], Time_poly(Rational(is_zero(at_w) ? 1 : 0))};
}

// Rank 1: every row's normal is a multiple of n = n_i(t) for all t (the
// rows' cross products with it vanish as polynomials, not only at s), so
// every cell is a slab across n and each point of a face's plane has that
// face's signs for every other row. Two cuts d1 = n x c and d2 = n x d1,
// c the axis least along n(s), both through the origin, meet a face's
// plane in one point wherever d1 is not zero (their minor with n is
// |n|^2 |d1|^2): a point of the face for every t where it is defined.
// None when the normals are not parallel as polynomials.
std::vector<Moving_plane> slab_cuts(const std::vector<Moving_plane>& rows, std::size_t i,
                                    const std::array<Rational, 4>& at_s, const Rational& s,
                                    const std::array<Rational, 3>& w)
{
  Vector3<Time_poly> n = moving_normal(rows[i]);
  for (const Moving_plane& row : rows) {
    Vector3<Time_poly> x = cross(n, moving_normal(row));
    if (!is_zero_polynomial(x[0]) || !is_zero_polynomial(x[1]) || !is_zero_polynomial(x[2])) return {};
  }
  int axis = 0;
  for (int c = 1; c < 3; ++c)
    if (CGAL::abs(at_s[c]) < CGAL::abs(at_s[axis])) axis = c;
  Vector3<Time_poly> c{Time_poly(Rational(0)), Time_poly(Rational(0)), Time_poly(Rational(0))};
  c[axis] = Time_poly(Rational(1));
  Vector3<Time_poly> d1 = cross(n, c), d2 = cross(n, d1);
  return {cut_through(d1, s, w), cut_through(d2, s, w)};
}

} // namespace

std::vector<Moving_plane> lineality_cuts(const std::vector<Moving_plane>& rows,
                                         const std::vector<std::array<Rational, 4>>& at, const Rational& s,
                                         const std::array<Rational, 3>& w)
{
  auto normal = [&](std::size_t i) { return Vector3<Rational>{at[i][0], at[i][1], at[i][2]}; };
  std::optional<std::size_t> some;   // a row whose normal is not zero at s
  for (std::size_t i = 0; i < at.size(); ++i) {
    if (!some && !(is_zero(at[i][0]) && is_zero(at[i][1]) && is_zero(at[i][2]))) some = i;
    for (std::size_t j = i + 1; j < at.size(); ++j) {
      Vector3<Rational> d = cross(normal(i), normal(j));
      if (is_zero(d[0]) && is_zero(d[1]) && is_zero(d[2])) continue;
      for (std::size_t k = 0; k < at.size(); ++k)
        if (!is_zero(dot(d, normal(k)))) return {};   // rank 3: the cells have vertices
      return {cut_through(cross(moving_normal(rows[i]), moving_normal(rows[j])), s, w)};
    }
  }
  if (!some) return {};
  return slab_cuts(rows, *some, at[*some], s, w);
}


// The closure of w's cell at s, P(t) = { x : h_i(x, t) is 0 or of the sign
// of h_i(w, s) }, keeps its vertices' planes on the whole interval (fact
// 10), so a vertex x(t) of P(s) (Cramer's quotients) is a point of the
// closure of the collision region for every t in (t*, s], and so is its
// limit at t*: the quotients at t*, or, where the vertex's three planes
// become dependent at t*, the limit of the quotients when it is finite
// (limit_at).
namespace {

// A vertex of the closure of w's cell among `rows` at s whose quotients
// have a finite limit at t*, that limit; none when every vertex runs off
// (or the cell has none).
std::optional<std::array<Algebraic, 3>> vertex_limit(const std::vector<Moving_plane>& rows,
                                                     const std::array<Rational, 3>& w, const Rational& s,
                                                     const Algebraic& t_star, const std::vector<int>& near_rows)
{
  std::vector<std::array<Rational, 4>> at = planes_at(rows, s);
  Interval_cell filter(at);
  std::optional<Quadratic_element> field;
  if (!t_star.is_rational() && t_star.polynomial().size() == 3) field.emplace(t_star);
  std::optional<std::array<Algebraic, 3>> x;
  cell_vertices(
      at, w,
      [&](int i, int j, int k) {
        // At a rational or quadratic t* where the three planes stay
        // independent the limit is their meeting point there (the same
        // quotients, evaluated first): no polynomial is made.
        if (t_star.is_rational())
          if (auto p = meeting_point_at(rows, {i, j, k}, t_star.rational())) {
            x = std::array<Algebraic, 3>{Algebraic((*p)[0]), Algebraic((*p)[1]), Algebraic((*p)[2])};
            return true;
          }
        if (field && (x = meeting_point_in(*field, rows, {i, j, k}))) return true;
        Quotient_point q = meeting_quotients(rows[i], rows[j], rows[k]);
        x = limit_at(q.num, q.den, t_star);
        return x.has_value();
      },
      filter, near_rows);
  return x;
}

} // namespace

// The pair's cells first; where w's has no vertex (normals of rank 2 or 1),
// the same on the cell cut across its lineality (lineality_cuts).
std::array<Algebraic, 3> Exact_slices::contact_point(const std::vector<Moving_plane>& rows,
                                                     const std::array<Rational, 3>& w, const Rational& s,
                                                     const Algebraic& t_star, const std::vector<int>& near_rows) const
{
  std::optional<std::array<Algebraic, 3>> x = vertex_limit(rows, w, s, t_star, near_rows);
  if (!x) {
    std::vector<Moving_plane> cuts = lineality_cuts(rows, planes_at(rows, s), s, w);
    if (!cuts.empty()) {
      std::vector<Moving_plane> cut_rows = rows;
      cut_rows.insert(cut_rows.end(), cuts.begin(), cuts.end());
      x = vertex_limit(cut_rows, w, s, t_star, near_rows);
    }
  }
  if (!x)
    throw Rotation_unsupported("the contact point at t*: every vertex of the witness's cell runs off to infinity "
                               "at t* (a degenerate contact this release does not resolve)");
  return *x;
}

namespace {

// The pose segment whose interval holds the irrational r (never a pose
// time, which is rational).
const Pose_segment& segment_holding(const std::vector<Pose_segment>& segments, const Algebraic& r)
{
  for (const Pose_segment& s : segments)
    if ((s.from_minus_infinity || compare(r, s.lo) > 0) && (s.to_plus_infinity || compare(r, s.hi) < 0)) return s;
  throw std::logic_error("internal error: no pose segment holds a critical time");
}

} // namespace

Field_posed posed_at(const Rotating_object& o, const Algebraic& r)
{
  const Pose_segment& s = segment_holding(o.segments, r);
  Field_posed p;
  p.shape = o.solid;
  for (int i = 0; i < 4; ++i) p.q[i] = s.q[i].coefficients();
  for (int i = 0; i < 3; ++i) p.c[i] = s.c[i].coefficients();
  return p;
}

namespace {

// The closed question at an irrational critical time, as quotients in t:
// a point, none, or not decided (the reason).
using Closed_quotients = Closed_at_critical<Quotient_point>;

// The closed question at the irrational r asked of the static pipeline in
// Q(r) (exact/Closed_in_field.h); its point as quotients over 1.
Closed_quotients field_point_at(const Rotating_object& a, const Rotating_object& b, const Algebraic& r)
{
  Field_answer x = closed_point_in_field(r, posed_at(a, r), posed_at(b, r));
  if (!x.refused.empty()) return {std::nullopt, "the closed question at an irrational critical time: " + x.refused};
  if (!x.meet) return {};
  return {Quotient_point{{Time_poly(x.point[0]), Time_poly(x.point[1]), Time_poly(x.point[2])}, Time_poly(Rational(1))},
          {}};
}

// The closed question at an irrational critical time (fact 12). Two
// bounded shapes that meet at r and at no time just before meet in a
// vertex-face or edge-edge point (common_point_at), so its candidates
// decide. A contact of unbounded shapes may have no vertex in it (the edge
// line of a wedge settling on a half-space), so where either is unbounded
// and no candidate holds, the static pipeline in Q(r) decides.
Closed_quotients closed_quotients(const std::vector<Moving_plane>& rows, const Rotating_object& a,
                                  const Rotating_object& b, const Critical_time& c)
{
  if (std::optional<Quotient_point> x = common_point_at(rows, a, b, c)) return {x, {}};
  if (a.shape.reach && b.shape.reach) return {};
  return field_point_at(a, b, c.t);
}

} // namespace

Contact_at_critical Exact_slices::closed_at_irrational(const std::vector<Moving_plane>& rows, const Rotating_object& a,
                                                       const Rotating_object& b, const Critical_time& c) const
{
  Closed_quotients x = closed_quotients(rows, a, b, c);
  if (!x.point) return {std::nullopt, x.undecided};
  return {point_at(x.point->num, x.point->den, c.t), {}};
}

// The certificate's writer asks only where check found a point, so an
// undecided question here is a refusal of the certificate.
std::optional<Quotient_point> closed_point_at(const std::vector<Moving_plane>& rows, const Rotating_object& a,
                                              const Rotating_object& b, const Critical_time& c)
{
  Closed_quotients x = closed_quotients(rows, a, b, c);
  if (!x.decided()) throw Rotation_unsupported(x.undecided);
  return x.point;
}

} // namespace clash4d
