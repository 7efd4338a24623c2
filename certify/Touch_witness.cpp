#include "certify/Touch_witness.h"

#include "certify/Coefficients.h"
#include "certify/Turning_prover.h"
#include "rotation/Critical_times.h"
#include "rotation/Exact_slices.h"
#include "rotation/Simplest_rational.h"
#include "scene/Number_json.h"
#include <algorithm>
#include <cmath>

namespace clash4d {
namespace {

using json = nlohmann::ordered_json;
using coefficients::Poly;
using coefficients::add;
using coefficients::mul;
using coefficients::scaled;
using Field_point = std::array<Poly, 3>;   // coordinates in Q(r), as polynomials in r

// l(x) = n . x + e for a row and a point in Q(r), as a polynomial in r.
Poly value(const Moving_plane& h, const Field_point& x)
{
  Poly v = h[3].coefficients();
  for (int k = 0; k < 3; ++k) v = add(v, mul(h[k].coefficients(), x[k]));
  return v;
}

// n(r) . d for a rational direction d.
Poly slope(const Moving_plane& h, const std::array<Rational, 3>& d)
{
  Poly v;
  for (int k = 0; k < 3; ++k) v = add(v, scaled(h[k].coefficients(), d[k]));
  return v;
}

double at_double(const Time_poly& p, double t)
{
  double v = 0;
  for (int i = p.size() - 1; i >= 0; --i) v = v * t + CGAL::to_double(p[i]);
  return v;
}

// A direction with sigma_p n_p . d > 0 for the rows listed, guessed by the
// perceptron in doubles at r and then checked exactly; none when the guess
// fails.
std::optional<std::array<Rational, 3>> direction(const std::vector<const Moving_plane*>& rows,
                                                 const std::vector<int>& sigma, const Algebraic& r)
{
  double t = r.to_double();
  std::vector<std::array<double, 3>> n;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::array<double, 3> v;
    double len = 0;
    for (int k = 0; k < 3; ++k) len += (v[k] = sigma[i] * at_double((*rows[i])[k], t)) * v[k];
    for (double& x : v) x /= std::sqrt(len);
    n.push_back(v);
  }
  std::array<double, 3> d = {0, 0, 0};
  for (int round = 0; round < 2000; ++round) {
    std::size_t worst = n.size();
    for (std::size_t i = 0; i < n.size() && worst == n.size(); ++i)
      if (n[i][0] * d[0] + n[i][1] * d[1] + n[i][2] * d[2] <= 1e-6) worst = i;
    if (worst == n.size()) break;
    for (int k = 0; k < 3; ++k) d[k] += n[worst][k];
  }
  std::array<Rational, 3> exact;
  for (int k = 0; k < 3; ++k) exact[k] = Rational(std::round(d[k] * 1024) / 1024);
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (r.sign_of(slope(*rows[i], exact)) != (sigma[i] > 0 ? CGAL::POSITIVE : CGAL::NEGATIVE)) return std::nullopt;
  return exact;
}

// C + delta d with delta halved until every row not through C keeps C's
// sign (signs: each row's at C).
std::optional<Field_point> nearby(const std::vector<Moving_plane>& rows, const std::vector<CGAL::Sign>& signs,
                                  const Field_point& c, const std::array<Rational, 3>& d, const Algebraic& r)
{
  Rational delta(1);
  for (int halving = 0; halving < 200; ++halving, delta /= 2) {
    Field_point w;
    for (int k = 0; k < 3; ++k) w[k] = add(c[k], Poly{delta * d[k]});
    bool kept = true;
    for (std::size_t p = 0; p < rows.size() && kept; ++p)
      kept = signs[p] == CGAL::ZERO || r.sign_of(value(rows[p], w)) == signs[p];
    if (kept) return w;
  }
  return std::nullopt;
}

// A generic witness of c for the object whose rows these are (8.4).
std::optional<Field_point> generic_witness(const std::vector<Moving_plane>& rows, const Shape_planes& shape,
                                           const Field_point& c, const Algebraic& r)
{
  std::vector<CGAL::Sign> signs;
  std::vector<int> side(rows.size()), through;
  for (std::size_t p = 0; p < rows.size(); ++p) {
    signs.push_back(r.sign_of(value(rows[p], c)));
    side[p] = signs.back() == CGAL::POSITIVE ? 1 : -1;
    if (signs.back() == CGAL::ZERO) through.push_back(static_cast<int>(p));
  }
  if (through.size() > 12) return std::nullopt;
  for (unsigned mask = 0; mask < (1u << through.size()); ++mask) {
    std::vector<const Moving_plane*> on;
    std::vector<int> sigma;
    for (std::size_t k = 0; k < through.size(); ++k) {
      side[through[k]] = (mask >> k) & 1 ? 1 : -1;
      on.push_back(&rows[through[k]]);
      sigma.push_back(side[through[k]]);
    }
    if (!inside_at_generic(shape, side)) continue;
    std::optional<std::array<Rational, 3>> d = on.empty() ? std::array<Rational, 3>{} : direction(on, sigma, r);
    if (!d) continue;
    if (auto w = nearby(rows, signs, c, *d, r)) return w;
  }
  return std::nullopt;
}

json field_json(const Poly& p)
{
  Poly c = p;
  while (c.size() > 1 && CGAL::sign(c.back()) == CGAL::ZERO) c.pop_back();
  if (c.size() <= 1) return to_string(c.empty() ? Rational(0) : c[0]);
  json out = json::array();
  for (const Rational& x : c) out.push_back(to_string(x));
  return json{{"at_t", out}};
}

json point_json(const Field_point& x, const json& t)
{
  return json::array({field_json(x[0]), field_json(x[1]), field_json(x[2]), t});
}

// The piece between breakpoints (or the span's ends) that holds r.
std::pair<Rational, Rational> piece_around(const Rotating_object& a, const Rotating_object& b, const Algebraic& r,
                                           const Rational& t_lo, const Rational& t_hi)
{
  Rational lo = t_lo, hi = t_hi;
  for (const auto* o : {&a, &b})
    for (const Pose_segment& s : o->segments)
      for (const Rational& t : {s.lo, s.hi}) {
        if (Algebraic(t) < r && lo < t) lo = t;
        if (r < Algebraic(t) && t < hi) hi = t;
      }
  return {lo, hi};
}

// The common point at r (closed_point_at), from the minors vanishing at r:
// sought only on r's isolating interval within the piece, where the
// interval filter of Critical_times leaves most minors unsolved, and pair
// of convex pieces by pair when the objects are unions of them (the
// closed objects meet where two closed pieces do); two convex pieces'
// feature minors first (a closed touch's point is on the four planes of
// one of them, Rotating_pair.cpp, feature_minors), then the pair's every
// mixed minor. Before, every mixed minor of the whole objects on the whole
// piece: 2 s of writing for a 0.08 s check of two hulls, and past the
// minor limit for two unions of 74 planes each.
std::optional<Quotient_point> common_point(const Object_parts& a, const Object_parts& b, const Algebraic& r,
                                           const Rational& lo, const Rational& hi, const Rational& mid)
{
  Rational l = std::max(lo, r.lower()), u = std::min(hi, r.upper());
  std::optional<Quotient_point> q;
  auto at_r = [&](const std::vector<Moving_plane>& rows, const Rotating_object& pa, const Rotating_object& pb,
                  const Critical_times& critical) {
    for (const Critical_time& c : critical.times())
      if (c.t == r && (q = closed_point_at(rows, pa, pb, c))) return true;
    return false;
  };
  for_parts_that_may_meet(a, b, [&](const Rotating_object& pa, const Rotating_object& pb) {
    std::vector<Moving_plane> rows = pair_rows(pa, pb, mid);
    Critical_times critical = part_pair_times(pa, pb, rows, l, u, true);
    return at_r(rows, pa, pb, critical) ||
           (critical.restricted() && at_r(rows, pa, pb, part_pair_times(pa, pb, rows, l, u, false)));
  });
  return q;
}

} // namespace

json touch_at_irrational(const Object_parts& parts_a, const Object_parts& parts_b, const Algebraic& r,
                         const Rational& t_lo, const Rational& t_hi)
{
  const Rotating_object &a = parts_a.whole, &b = parts_b.whole;
  std::string where = "objects '" + a.name + "' and '" + b.name + "' touching at t = " + r.to_text();
  auto [lo, hi] = piece_around(a, b, r, t_lo, t_hi);
  Rational mid = simplest_between(Algebraic(lo), Algebraic(hi));
  std::vector<Moving_plane> rows_a = moving_planes(a.shape.planes, segment_at(a.segments, mid));
  std::vector<Moving_plane> rows_b = moving_planes(b.shape.planes, segment_at(b.segments, mid));
  std::optional<Quotient_point> q = common_point(parts_a, parts_b, r, lo, hi, mid);
  if (!q) throw Turning_proof_missing(where + ": no common point was found at that critical time");
  Field_point c;
  for (int k = 0; k < 3; ++k) c[k] = Algebraic::field_element(r, q->num[k].coefficients(), q->den.coefficients());
  std::optional<Field_point> wa = generic_witness(rows_a, a.shape, c, r);
  std::optional<Field_point> wb = generic_witness(rows_b, b.shape, c, r);
  if (!wa || !wb) throw Turning_proof_missing(where + ": no generic witness was found near the common point");
  json t = number_json(r);
  return json{{"point", point_json(c, t)}, {"inside", json::array({point_json(*wa, t), point_json(*wb, t)})}};
}

} // namespace clash4d
