#include "rotation/Moving_planes.h"

#include <algorithm>

namespace clash4d {

namespace {

using Int_poly = Integer_time_poly;

Time_poly divided(const Int_poly& p, const mpz_class& d)
{
  std::vector<Rational> c;
  c.reserve(p.size());
  for (int i = 0; i < p.size(); ++i) c.push_back(quotient_of_integers(p[i], d));
  return Time_poly(c);
}


// In integers: with q = Q / D, c = C / E and a plane p = P / L (integer
// numerators over common denominators), n = P N(Q) / (L D^2) and e = (E
// P_3 |Q|^2 - n'.C) / (L D^2 E), n' = P N(Q): the same polynomials as
// moved_plane makes in rationals, coefficient by coefficient, with one
// fraction reduced per coefficient instead of one per operation; or, with
// reduce false, the row times L D^2 E > 0, no fraction reduced at all.
template <bool reduce>
std::vector<Moving_plane> planes_under(const std::vector<Plane3<Rational>>& planes, const Pose_segment& s)
{
  mpz_class D, E;
  std::array<Int_poly, 4> Q = integer_polys(s.q, D);
  std::array<Int_poly, 3> C = integer_polys(s.c, E);
  auto N = unnormalised_rotation(Q);
  Int_poly scaled_norm = mpz_class(E) * squared_norm(Q);
  std::vector<Moving_plane> out;
  out.reserve(planes.size());
  for (const Plane3<Rational>& p : planes) {
    std::array<mpz_class, 4> P;
    mpz_class L;
    over_common_denominator(p.data(), 4, P.data(), L);
    // (n', E P_3 |Q|^2 - n'.C): moved_plane with the norm times E.
    std::array<Int_poly, 4> h = moved_plane(P, N, scaled_norm, C);
    if constexpr (reduce) {
      mpz_class dn = L * D * D, de = dn * E;
      out.push_back({divided(h[0], dn), divided(h[1], dn), divided(h[2], dn), divided(h[3], de)});
    } else {
      out.push_back({rational_poly(h[0], E), rational_poly(h[1], E), rational_poly(h[2], E), rational_poly(h[3])});
    }
  }
  return out;
}

} // namespace

std::vector<Moving_plane> moving_planes(const std::vector<Plane3<Rational>>& planes, const Pose_segment& s)
{
  return planes_under<true>(planes, s);
}

std::vector<Moving_plane> integer_moving_planes(const std::vector<Plane3<Rational>>& planes, const Pose_segment& s)
{
  return planes_under<false>(planes, s);
}

Time_poly rational_poly(const Integer_time_poly& p, const mpz_class& factor)
{
  std::vector<Rational> c(p.size());   // new numbers: written through mpq(), integers
  for (int i = 0; i < p.size(); ++i) {
    mpz_ptr x = mpq_numref(c[i].mpq());
    p.coefficient_into(i, x);
    if (factor != 1) mpz_mul(x, x, factor.get_mpz_t());
  }
  return Time_poly(std::move(c));
}

namespace {

// The weights n^i d^(k - i) of d^k p(n / d), t = n / d, for each length
// k + 1 of the polynomials read at t: made once per length, and shared by
// all the rows read at t (planes_at).
class Weights_at {
public:
  explicit Weights_at(const Rational& t) : n_(mpq_numref(t.mpq())), d_(mpq_denref(t.mpq())) {}

  const std::vector<mpz_class>& of(int size)
  {
    if (static_cast<int>(by_size_.size()) <= size) by_size_.resize(size + 1);
    std::vector<mpz_class>& weight = by_size_[size];
    if (!weight.empty() || size == 0) return weight;
    weight.resize(size);
    mpz_class d_power = 1;
    for (int i = size; i-- > 0;) {
      weight[i] = d_power;
      d_power *= d_;
    }
    mpz_class n_power = 1;
    for (int i = 1; i < size; ++i) {
      n_power *= n_;
      weight[i] *= n_power;
    }
    return weight;
  }

private:
  mpz_class n_, d_;
  std::vector<std::vector<mpz_class>> by_size_;
};

std::array<Rational, 4> plane_at(const Moving_plane& h, const Rational& t, Weights_at& weights)
{
  int size = 0;
  bool integers = true;
  for (const Time_poly& p : h) {
    size = std::max(size, p.size());
    integers = integers && has_integer_coefficients(p);
  }
  std::array<Rational, 4> out;
  if (!integers) {
    for (int c = 0; c < 4; ++c) out[c] = h[c].at(t);
    return out;
  }
  // sum c_i n^i d^(k - i), k = size - 1: d^k p(n / d).
  const std::vector<mpz_class>& weight = weights.of(size);
  for (int c = 0; c < 4; ++c) {
    Rational v;   // a new number: written through mpq(), an integer
    for (int i = 0; i < h[c].size(); ++i)
      mpz_addmul(mpq_numref(v.mpq()), mpq_numref(h[c][i].mpq()), weight[i].get_mpz_t());
    out[c] = v;
  }
  return out;
}

} // namespace

std::array<Rational, 4> plane_at(const Moving_plane& h, const Rational& t)
{
  Weights_at weights(t);
  return plane_at(h, t, weights);
}

std::vector<std::array<Rational, 4>> planes_at(const std::vector<Moving_plane>& rows, const Rational& t)
{
  Weights_at weights(t);
  std::vector<std::array<Rational, 4>> out;
  out.reserve(rows.size());
  for (const Moving_plane& h : rows) out.push_back(plane_at(h, t, weights));
  return out;
}

Rational plane_value(const Moving_plane& h, const std::array<Rational, 3>& x, const Rational& t)
{
  return h[0].at(t) * x[0] + h[1].at(t) * x[1] + h[2].at(t) * x[2] + h[3].at(t);
}

Interval_poly enclosed(const Time_poly& p)
{
  std::vector<CGAL::Interval_nt<false>> c;
  for (int i = 0; i < p.size(); ++i) c.emplace_back(enclosing_interval(p[i]));
  return Interval_poly(c);
}

} // namespace clash4d
