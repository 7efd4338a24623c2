#include "certify/Witness_path.h"

#include "certify/Coefficients.h"
#include "certify/Positivity.h"
#include "certify/Turning_prover.h"
#include "rotation/Cell_vertices.h"
#include "rotation/Critical_times.h"
#include "rotation/Exact_slices.h"
#include "rotation/Simplest_rational.h"
#include <optional>

namespace clash4d {
namespace {

using json = nlohmann::ordered_json;
using coefficients::Poly;
using coefficients::add;
using coefficients::mul;
using coefficients::scaled;
using coefficients::at;

Poly of(const Time_poly& p) { return p.coefficients(); }


// t*'s minimal polynomial (t - t* when rational), scaled to 1 at s.
Poly vanishing_at(const Algebraic& t_star, const Rational& s)
{
  Poly p;
  if (t_star.is_rational()) p = {-t_star.rational(), Rational(1)};
  else
    for (const mpz_class& c : t_star.polynomial()) p.emplace_back(CGAL::Gmpz(c.get_mpz_t()));
  return scaled(p, 1 / at(p, s));   // P(s) = 1: c is then the step at s
}

struct Path {
  std::array<Poly, 3> num;
  Poly den;
};

// The row's value along the path, times w(t).
Poly along(const Moving_plane& h, const Path& p)
{
  Poly v = mul(of(h[3]), p.den);
  for (int k = 0; k < 3; ++k) v = add(v, mul(of(h[k]), p.num[k]));
  return v;
}

// Every row keeps a side on (t*, t1] and both formulas hold strictly at
// W(t1) (8.4), with w > 0 on (t*, t1].
bool holds(const Path& p, const std::vector<Moving_plane>& rows, std::size_t split, const Rotating_object& a,
           const Rotating_object& b, const Algebraic& t_star, const Rational& t1)
{
  if (!positive_after(p.den, t_star, Algebraic(t1))) return false;
  std::vector<int> side_a, side_b;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    Poly v = along(rows[i], p);
    CGAL::Sign sign = CGAL::sign(at(v, t1));
    if (sign == CGAL::ZERO || !positive_after(sign == CGAL::POSITIVE ? v : scaled(v, Rational(-1)), t_star, Algebraic(t1)))
      return false;
    (i < split ? side_a : side_b).push_back(sign == CGAL::POSITIVE ? 1 : -1);
  }
  return inside_at_generic(a.shape, side_a) && inside_at_generic(b.shape, side_b);
}

// The vertex of rows i, j, k as quotients, w(s) > 0, stepping by c P D.
Path vertex_path(const std::vector<Moving_plane>& rows, int i, int j, int k, const Rational& s,
                 const std::array<int, 3>& sigma, const Poly& P, const Rational& c)
{
  Path p;
  p.den = of(normal_minor(rows[i], rows[j], rows[k]));
  for (int col = 0; col < 3; ++col) {
    std::array<Moving_plane, 3> m = {rows[i], rows[j], rows[k]};
    for (auto& row : m) row[col] = -row[3];
    p.num[col] = of(normal_minor(m[0], m[1], m[2]));
  }
  Rational d = at(p.den, s);
  if (CGAL::sign(d) == CGAL::NEGATIVE) {
    p.den = scaled(p.den, Rational(-1));
    for (Poly& n : p.num) n = scaled(n, Rational(-1));
  }
  // D solves n_q(s) . D = sigma_q for the three planes (Cramer at s).
  std::array<std::array<Rational, 4>, 3> m;
  for (int r = 0; r < 3; ++r) {
    const Moving_plane& h = rows[r == 0 ? i : r == 1 ? j : k];
    m[r] = {h[0].at(s), h[1].at(s), h[2].at(s), Rational(-sigma[r])};
  }
  std::array<Rational, 3> D = cramer_point(m[0], m[1], m[2], det3(m[0], m[1], m[2]));
  for (int col = 0; col < 3; ++col) p.num[col] = add(p.num[col], mul(scaled(P, c * D[col]), p.den));
  return p;
}

json poly_json(Poly p)
{
  while (p.size() > 1 && CGAL::sign(p.back()) == CGAL::ZERO) p.pop_back();
  json out = json::array();
  for (const Rational& x : p) out.push_back(to_string(x));
  if (out.empty()) out.push_back("0");
  return out;
}

} // namespace

namespace {

// A path from a vertex of the closure of w's cell among `starts` at s (the
// pair's rows, or those and cuts across their lineality) that keeps its
// side of every one of `rows` (the objects' own planes, a's first `split`).
std::optional<json> path_from_vertices(const std::vector<Moving_plane>& starts, const std::vector<Moving_plane>& rows,
                                       std::size_t split, const Rotating_object& a, const Rotating_object& b,
                                       const Algebraic& t_star, const std::array<Rational, 3>& w, const Rational& s)
{
  std::vector<std::array<Rational, 4>> now = planes_at(starts, s);
  Poly P = vanishing_at(t_star, s);
  std::optional<json> found;
  cell_vertices(now, w, [&](int i, int j, int k) {
    std::array<int, 3> sigma;
    for (int r = 0; r < 3; ++r) {
      const auto& h = now[r == 0 ? i : r == 1 ? j : k];
      sigma[r] = sign_of(h[0] * w[0] + h[1] * w[1] + h[2] * w[2] + h[3]);
    }
    // The step c P^power D: a plane the vertex leaves to second order as
    // the cell is born needs the step to vanish faster than it.
    Poly step = P;
    for (int power = 1; power <= 3 && !found; ++power, step = mul(step, P)) {
      Rational t1 = s;
      for (int shorter = 0; shorter < 4 && !found; ++shorter, t1 = simplest_between(t_star, Algebraic(t1))) {
        Rational c(1);
        for (int halving = 0; halving < 100 && !found; ++halving, c /= 2) {
          Path p = vertex_path(starts, i, j, k, s, sigma, step, c);
          if (holds(p, rows, split, a, b, t_star, t1))
            found = json{{"x", poly_json(p.num[0])}, {"y", poly_json(p.num[1])}, {"z", poly_json(p.num[2])},
                         {"w", poly_json(p.den)}, {"to", to_string(t1)}};
        }
      }
    }
    return found.has_value();
  });
  return found;
}

} // namespace

// From the pair's cells first; where w's has no vertex (normals of rank 2
// or 1), from the cell cut across its lineality (lineality_cuts).
json witness_path(const Rotating_object& a, const Rotating_object& b, const Algebraic& t_star,
                  const std::array<Rational, 3>& w, const Rational& s)
{
  std::vector<Moving_plane> rows = moving_planes(a.shape.planes, segment_at(a.segments, s));
  std::size_t split = rows.size();
  std::vector<Moving_plane> more = moving_planes(b.shape.planes, segment_at(b.segments, s));
  rows.insert(rows.end(), more.begin(), more.end());
  std::optional<json> found = path_from_vertices(rows, rows, split, a, b, t_star, w, s);
  if (!found) {
    std::vector<Moving_plane> cuts = lineality_cuts(rows, planes_at(rows, s), s, w);
    if (!cuts.empty()) {
      std::vector<Moving_plane> cut_rows = rows;
      cut_rows.insert(cut_rows.end(), cuts.begin(), cuts.end());
      found = path_from_vertices(cut_rows, rows, split, a, b, t_star, w, s);
    }
  }
  if (!found)
    throw Turning_proof_missing("objects '" + a.name + "' and '" + b.name + "': no path inside both was found after t* = " +
                                t_star.to_text());
  return *found;
}

} // namespace clash4d
