#include "rotation/Rotating_pair.h"

#include "rotation/Critical_times.h"
#include "rotation/Moving_planes.h"
#include "rotation/Simplest_rational.h"

#include <algorithm>

namespace clash4d {

namespace {

using Point3 = std::array<Rational, 3>;

bool is_zero(const Rational& x) { return CGAL::sign(x) == CGAL::ZERO; }

// s under a transform solid (rotate or translate) with these numbers.
Solid wrapped(Solid::Kind kind, const Rational* numbers, int count, Solid s)
{
  Solid w;
  w.kind = kind;
  w.path = s.path;
  w.numbers.assign(numbers, numbers + count);
  w.children.push_back(std::move(s));
  return w;
}

// The shape where the pose puts it at time t: rotated about its origin,
// then translated (spec: Motion with rotation (poses)), as the scene's own
// rotate and translate solids, so the static pipeline reads it unchanged.
Solid posed_solid(const Solid& shape, const Pose_segment& s, const Rational& t)
{
  Solid out = shape;
  std::array<Rational, 4> q = {s.q[0].at(t), s.q[1].at(t), s.q[2].at(t), s.q[3].at(t)};
  if (!is_zero(q[1]) || !is_zero(q[2]) || !is_zero(q[3])) out = wrapped(Solid::Kind::Rotate, q.data(), 4, std::move(out));
  Point3 c = {s.c[0].at(t), s.c[1].at(t), s.c[2].at(t)};
  if (!is_zero(c[0]) || !is_zero(c[1]) || !is_zero(c[2])) out = wrapped(Solid::Kind::Translate, c.data(), 3, std::move(out));
  approximate_numbers(out);
  return out;
}

CGAL::Sign sign_at(const Time_poly& p, const Algebraic& t)
{
  if (t.is_rational()) return CGAL::sign(p.at(t.rational()));
  return t.sign_of(p.coefficients());
}

Algebraic quotient_at(const Time_poly& num, const Time_poly& den, const Algebraic& t)
{
  if (t.is_rational()) return Algebraic(num.at(t.rational()) / den.at(t.rational()));
  return Algebraic::quotient_at(t, num.coefficients(), den.coefficients());
}

// Cramer's numerators of the point where rows i, j, k meet: column c of
// the normals replaced by -e.
std::array<Time_poly, 3> cramer_numerators(const Moving_plane& a, const Moving_plane& b, const Moving_plane& c)
{
  std::array<Time_poly, 3> out;
  for (int col = 0; col < 3; ++col) {
    std::array<Moving_plane, 3> m = {a, b, c};
    for (auto& row : m) row[col] = -row[3];
    out[col] = normal_minor(m[0], m[1], m[2]);
  }
  return out;
}

struct Static_hit {
  bool collide = false;
  Point3 x;
  bool verified = false;
};

Static_hit probe(const Rotating_object& a, const Rotating_object& b, const Rational& t, Semantics semantics,
                 Static_check check)
{
  Check_options o;
  o.semantics = semantics;
  Check_answer answer = check(posed_pair(a, b, t), o);
  Static_hit hit;
  if (!answer.collide) return hit;
  hit.collide = true;
  const Pair_answer& p = answer.pairs.front();
  for (int i = 0; i < 3; ++i) hit.x[i] = rational_from_string(p.witness[i]);
  hit.verified = p.witness_verified;
  return hit;
}

// The time boundaries of the pair inside the span: where either motion
// changes its polynomials, with the span's ends.
std::vector<Rational> piece_ends(const Rotating_object& a, const Rotating_object& b, const Rational& lo,
                                 const Rational& hi)
{
  std::vector<Rational> t = {lo, hi};
  for (const auto* o : {&a, &b})
    for (const Pose_segment& s : o->segments) {
      if (!s.from_minus_infinity && lo < s.lo && s.lo < hi) t.push_back(s.lo);
      if (!s.to_plus_infinity && lo < s.hi && s.hi < hi) t.push_back(s.hi);
    }
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

std::vector<Moving_plane> pair_rows(const Rotating_object& a, const Rotating_object& b, const Rational& at)
{
  std::vector<Moving_plane> rows = moving_planes(a.shape.planes, segment_at(a.segments, at));
  std::vector<Moving_plane> more = moving_planes(b.shape.planes, segment_at(b.segments, at));
  rows.insert(rows.end(), more.begin(), more.end());
  return rows;
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

std::array<Algebraic, 4> with_time(const Point3& x, const Rational& t)
{
  return {Algebraic(x[0]), Algebraic(x[1]), Algebraic(x[2]), Algebraic(t)};
}

// A point of the closure of the regularised collision region at t*, the
// left end of the first colliding critical interval whose sample s has the
// generic witness w. The closure of w's cell at s, P(t) = { x : h_i(x, t)
// is 0 or of the sign of h_i(w, s) },
// keeps its vertices' planes on the whole interval (fact 10), so a vertex
// x(t) of P(s) (Cramer's quotients) is a point of the closure for every t
// in (t*, s], and so is its limit at t*: the quotients at t*, or, where the
// vertex's three planes become dependent at t*, the limit of the quotients
// when it is finite (limit_at).
std::array<Algebraic, 3> contact_point(const std::vector<Moving_plane>& rows, const Point3& w, const Rational& s,
                                       const Algebraic& t_star)
{
  std::size_t m = rows.size();
  std::vector<std::array<Rational, 4>> at(m);
  std::vector<int> side(m);
  for (std::size_t i = 0; i < m; ++i) {
    for (int c = 0; c < 4; ++c) at[i][c] = rows[i][c].at(s);
    side[i] = CGAL::sign(at[i][0] * w[0] + at[i][1] * w[1] + at[i][2] * w[2] + at[i][3]);
  }
  auto det3 = [](const std::array<Rational, 4>& a, const std::array<Rational, 4>& b, const std::array<Rational, 4>& c,
                 int col, bool replace) {
    auto e = [&](const std::array<Rational, 4>& r, int k) { return replace && k == col ? Rational(-r[3]) : r[k]; };
    return e(a, 0) * (e(b, 1) * e(c, 2) - e(b, 2) * e(c, 1)) - e(a, 1) * (e(b, 0) * e(c, 2) - e(b, 2) * e(c, 0)) +
           e(a, 2) * (e(b, 0) * e(c, 1) - e(b, 1) * e(c, 0));
  };
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j)
      for (std::size_t k = j + 1; k < m; ++k) {
        if (!side[i] || !side[j] || !side[k]) continue;
        Rational d = det3(at[i], at[j], at[k], 0, false);
        if (is_zero(d)) continue;
        Point3 x = {det3(at[i], at[j], at[k], 0, true) / d, det3(at[i], at[j], at[k], 1, true) / d,
                    det3(at[i], at[j], at[k], 2, true) / d};
        bool in_cell = true;
        for (std::size_t l = 0; l < m && in_cell; ++l)
          in_cell = side[l] * CGAL::sign(at[l][0] * x[0] + at[l][1] * x[1] + at[l][2] * x[2] + at[l][3]) >= 0;
        if (!in_cell) continue;
        Time_poly den = normal_minor(rows[i], rows[j], rows[k]);
        if (auto x = limit_at(cramer_numerators(rows[i], rows[j], rows[k]), den, t_star)) return *x;
      }
  throw Rotation_unsupported("the contact point at t*: every vertex of the witness's cell runs off to infinity "
                             "at t* (a degenerate contact this release does not resolve)");
}

// Whether the point x(r) = num / den lies in the closed object: in some
// convex piece of it (a union of bounded convex pieces), all rows <= 0.
bool in_closed_pieces(const std::vector<Moving_plane>& rows, std::size_t offset, const Shape_planes& shape,
                      const std::array<Time_poly, 3>& num, const Time_poly& den, CGAL::Sign den_sign, const Algebraic& r)
{
  for (const auto& piece : shape.convex_pieces) {
    bool inside = true;
    for (auto [plane, orientation] : piece) {
      const Moving_plane& h = rows[offset + plane];
      // h(x(t), t) den(t) = n . num + e den.
      Time_poly v = h[0] * num[0] + h[1] * num[1] + h[2] * num[2] + h[3] * den;
      inside = orientation * sign_at(v, r) * den_sign <= 0;
      if (!inside) break;
    }
    if (inside) return true;
  }
  return false;
}

// Whether x(r) = num / den is in the closed regular set of a CSG shape
// whose planes are rows[offset ...]: some open cell next to the point is
// inside. The planes through the point must be at most three and
// independent there, so that every choice of their sides is a cell.
bool in_closed_cells(const std::vector<Moving_plane>& rows, std::size_t offset, const Rotating_object& o,
                     const std::array<Time_poly, 3>& num, const Time_poly& den, CGAL::Sign den_sign, const Algebraic& r)
{
  std::size_t m = o.shape.planes.size();
  std::vector<int> side(m), zero;
  for (std::size_t p = 0; p < m; ++p) {
    const Moving_plane& h = rows[offset + p];
    side[p] = sign_at(h[0] * num[0] + h[1] * num[1] + h[2] * num[2] + h[3] * den, r) * den_sign;
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
  if (!independent)
    throw Rotation_unsupported("closed semantics at an irrational critical time: a contact point on more than three "
                               "planes of '" + o.name + "', or on dependent ones (a degenerate contact this "
                               "release does not resolve)");
  for (unsigned mask = 0; mask < (1u << zero.size()); ++mask) {
    for (std::size_t k = 0; k < zero.size(); ++k) side[zero[k]] = (mask >> k) & 1 ? 1 : -1;
    if (inside_at_generic(o.shape, side)) return true;
  }
  return false;
}

bool in_closed_object(const std::vector<Moving_plane>& rows, std::size_t offset, const Rotating_object& o,
                      const std::array<Time_poly, 3>& num, const Time_poly& den, CGAL::Sign den_sign, const Algebraic& r)
{
  if (!o.shape.convex_pieces.empty()) return in_closed_pieces(rows, offset, o.shape, num, den, den_sign, r);
  return in_closed_cells(rows, offset, o, num, den, den_sign, r);
}

// The closed question at an irrational critical time r (fact 12): closed
// objects that meet at r and at no time near it meet in a vertex-face or
// edge-edge contact, a point on the four planes of a minor that vanishes
// at r, three of them independent there (docs/rotation.md). Each such point
// is tried against both objects, exactly in Q(r).
std::optional<std::array<Algebraic, 3>> closed_at_irrational(const std::vector<Moving_plane>& rows, const Rotating_object& a,
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
      Time_poly den = normal_minor(rows[t[0]], rows[t[1]], rows[t[2]]);
      CGAL::Sign ds = sign_at(den, c.t);
      if (ds == CGAL::ZERO) continue;
      auto num = cramer_numerators(rows[t[0]], rows[t[1]], rows[t[2]]);
      if (in_closed_object(rows, 0, a, num, den, ds, c.t) && in_closed_object(rows, offset, b, num, den, ds, c.t))
        return point_at(num, den, c.t);
    }
  }
  return std::nullopt;
}

} // namespace

Rotating_object Rotating_object::make(const Scene_object& o)
{
  return {o.name, &o.shape, shape_planes(o.shape), pose_segments(o.motion)};
}

Rotating_object Rotating_object::piece(const Scene_object& o, const Solid& piece)
{
  return {o.name, &piece, shape_planes(piece), pose_segments(o.motion)};
}

Scene posed_pair(const Rotating_object& a, const Rotating_object& b, const Rational& t)
{
  Scene s;
  s.name = "posed";
  s.t_lo = Rational(0);
  s.t_hi = Rational(1);
  for (const auto* o : {&a, &b}) {
    Scene_object so;
    so.name = o->name;
    so.shape = posed_solid(*o->solid, segment_at(o->segments, t), t);
    so.motion.velocities.push_back({Rational(0), Rational(0), Rational(0)});
    approximate_numbers(so.motion);
    s.objects.push_back(std::move(so));
  }
  return s;
}

} // namespace clash4d

namespace clash4d {

namespace {

// The time slices of one pair, in time order: each piece between the
// motions' breakpoints, its critical times, and the static question at
// each sample (and, closed, at each critical time); the first answer ends
// the search, so with --earliest it is the earliest.
class Slice_search {
public:
  Slice_search(const Rotating_object& a, const Rotating_object& b, const Check_options& o, Static_check check)
    : a_(a), b_(b), options_(o), check_(check), closed_(o.semantics == Semantics::closed)
  {
  }

  Rotating_answer run(const Rational& t_lo, const Rational& t_hi)
  {
    std::vector<Rational> ends = piece_ends(a_, b_, t_lo, t_hi);
    t_lo_ = t_lo;
    for (std::size_t p = 0; p + 1 < ends.size(); ++p)
      if (piece(ends[p], ends[p + 1])) return answer_;
    if (closed_) at_rational(t_hi);   // the span's end, closed only
    return answer_;
  }

private:
  // True once the piece [lo, hi] has answered.
  bool piece(const Rational& lo, const Rational& hi)
  {
    Rational mid = (lo + hi) / 2;
    // A verdict alone: one sample first, for the common case where the
    // pair collides there, before any minor is made.
    if (!options_.earliest && in_interval({}, Algebraic(lo), Algebraic(hi))) return true;
    std::vector<Moving_plane> rows = pair_rows(a_, b_, mid);
    bool low_rank = !a_.shape.spans_space && !b_.shape.spans_space;
    Critical_times critical(rows, a_.shape.planes.size(), lo, hi, low_rank);
    const auto& c = critical.times();
    if (closed_ && at_rational(lo)) return true;
    for (std::size_t k = 0; k <= c.size(); ++k) {
      Algebraic left = k == 0 ? Algebraic(lo) : c[k - 1].t;
      Algebraic right = k == c.size() ? Algebraic(hi) : c[k].t;
      if (closed_ && k > 0 && at_critical(rows, c[k - 1])) return true;
      if (in_interval(rows, left, right)) return true;
    }
    return false;
  }

  bool in_interval(const std::vector<Moving_plane>& rows, const Algebraic& left, const Algebraic& right)
  {
    Rational s = simplest_between(left, right);
    Static_hit hit = probe(a_, b_, s, options_.semantics, check_);
    if (!hit.collide) return false;
    if (closed_ && options_.earliest)
      // The closed contact set is closed: had it met this interval first,
      // it would have met its left end, which was asked before. An
      // irrational left end whose contact point the minors did not give is
      // named, never answered with a later time.
      throw Rotation_unsupported("the first contact is at a critical time where no contact point was found "
                                 "(a degenerate contact this release does not resolve)");
    answer_.collide = true;
    answer_.witness = with_time(hit.x, s);
    answer_.witness_verified = hit.verified;
    if (options_.earliest) {
      answer_.earliest = true;
      answer_.t_star = left;
      answer_.at_start = left == Algebraic(t_lo_);
      answer_.contact = contact_point(rows, hit.x, s, left);
    }
    return true;
  }

  bool at_rational(const Rational& t)
  {
    Static_hit hit = probe(a_, b_, t, Semantics::closed, check_);
    if (!hit.collide) return false;
    std::array<Algebraic, 4> w = with_time(hit.x, t);
    found_closed(w, hit.verified);
    return true;
  }

  bool at_critical(const std::vector<Moving_plane>& rows, const Critical_time& c)
  {
    if (c.t.is_rational()) return at_rational(c.t.rational());
    std::optional<std::array<Algebraic, 3>> x = closed_at_irrational(rows, a_, b_, c);
    if (!x) return false;
    found_closed({(*x)[0], (*x)[1], (*x)[2], c.t}, true);
    return true;
  }

  void found_closed(const std::array<Algebraic, 4>& w, bool verified)
  {
    answer_.collide = true;
    answer_.witness = w;
    answer_.witness_verified = verified;
    if (!options_.earliest) return;
    answer_.earliest = true;
    answer_.t_star = w[3];
    answer_.contact = {w[0], w[1], w[2]};
    answer_.at_start = w[3] == Algebraic(t_lo_);
  }

  const Rotating_object &a_, &b_;
  const Check_options& options_;
  Static_check check_;
  bool closed_;
  Rational t_lo_;
  Rotating_answer answer_;
};

} // namespace

Rotating_answer decide_rotating_pair(const Rotating_object& a, const Rotating_object& b, const Rational& t_lo,
                                     const Rational& t_hi, const Check_options& options, Static_check check)
{
  return Slice_search(a, b, options, check).run(t_lo, t_hi);
}

} // namespace clash4d
