#include "verify/Turning_model.h"

#include "scene/Pose_motion.h"
#include <algorithm>

namespace clash4d::verifier {
namespace {

mpq_class rat(const Rational& r) { return mpq_class(r.mpq()); }

// The line through (t0, a) and (t1, b) as a polynomial in t.
Rational_poly interpolate(const mpq_class& t0, const mpq_class& t1, const mpq_class& a, const mpq_class& b)
{
  mpq_class slope = (b - a) / (t1 - t0);
  return Rational_poly::linear(a - slope * t0, slope);
}

std::array<Rational_poly, 4> constant_q(const std::array<Rational, 4>& q)
{
  std::array<Rational_poly, 4> out;
  for (int i = 0; i < 4; ++i) out[i] = Rational_poly::constant(rat(q[i]));
  return out;
}

std::array<Rational_poly, 3> constant_c(const std::array<Rational, 3>& c)
{
  std::array<Rational_poly, 3> out;
  for (int i = 0; i < 3; ++i) out[i] = Rational_poly::constant(rat(c[i]));
  return out;
}

} // namespace

// Section 8.2: pose times cut a pose motion (constant pose before the first
// and after the last); a ROBMOD motion is q = (1, 0, 0, 0), c = D(t).
Turning_model::Turning_model(const Scene_object& o, const Object_model& m) : model_(m)
{
  const auto& poses = o.motion.poses;
  if (poses.empty()) {
    breaks_ = m.times();
    for (std::size_t k = 0; k <= breaks_.size(); ++k) {
      q_.push_back({Rational_poly::constant(1), {}, {}, {}});
      std::array<Rational_poly, 3> c;
      for (int i = 0; i < 3; ++i) c[i] = Rational_poly::linear(m.offset(int(k))[i], m.velocity(int(k))[i]);
      c_.push_back(c);
    }
    return;
  }
  for (const Pose& p : poses) breaks_.push_back(rat(p.t));
  q_.push_back(constant_q(poses.front().rotate)), c_.push_back(constant_c(poses.front().translate));
  for (std::size_t i = 0; i + 1 < poses.size(); ++i) {
    const Pose &a = poses[i], &b = poses[i + 1];
    std::array<Rational_poly, 4> q;
    std::array<Rational_poly, 3> c;
    for (int k = 0; k < 4; ++k) q[k] = interpolate(rat(a.t), rat(b.t), rat(a.rotate[k]), rat(b.rotate[k]));
    for (int k = 0; k < 3; ++k) c[k] = interpolate(rat(a.t), rat(b.t), rat(a.translate[k]), rat(b.translate[k]));
    q_.push_back(q), c_.push_back(c);
  }
  q_.push_back(constant_q(poses.back().rotate)), c_.push_back(constant_c(poses.back().translate));
  // The scene reader gives a pose motion that does not rotate its shape
  // already placed at c(0) (scene/Pose_motion.h, written_shape), which the
  // atoms here are read from: its origin then moves by c(t) - c(0), and the
  // literals are those of the shape as written under c(t).
  if (!o.motion.rotates()) {
    std::array<Rational, 3> c0 = pose_origin_at_zero(poses);
    for (auto& c : c_)
      for (int k = 0; k < 3; ++k) c[k] = c[k] - Rational_poly::constant(rat(c0[k]));
  }
}

int Turning_model::piece_of(const Real_time& lo) const
{
  // Breakpoints <= lo (binary search: they increase strictly).
  auto it = std::partition_point(breaks_.begin(), breaks_.end(), [&](const mpq_class& b) { return less_equal(Real_time(b), lo); });
  return static_cast<int>(it - breaks_.begin());
}

int Turning_model::piece_at(const Real_time& t) const
{
  auto it = std::partition_point(breaks_.begin(), breaks_.end(), [&](const mpq_class& b) { return less(Real_time(b), t); });
  return static_cast<int>(it - breaks_.begin());
}

bool Turning_model::is_break(const mpq_class& t) const { return std::binary_search(breaks_.begin(), breaks_.end(), t); }

bool Turning_model::break_between(const Real_time& lo, const Real_time& hi) const
{
  std::size_t k = static_cast<std::size_t>(piece_of(lo));   // the first breakpoint > lo
  return k < breaks_.size() && less(Real_time(breaks_[k]), hi);
}

// Section 8.2: N(q) n . x + (|q|^2 d - (N(q) n) . c) <= 0, N(q) = |q|^2 R(q).
Lit Turning_model::literal(const Atom& h, int k) const
{
  const auto& [w, x, y, z] = q_[k];
  mpq_class two = 2;
  Rational_poly ww = w * w, xx = x * x, yy = y * y, zz = z * z;
  Rational_poly N[3][3] = {{ww + xx - yy - zz, two * (x * y - w * z), two * (x * z + w * y)},
                           {two * (x * y + w * z), ww - xx + yy - zz, two * (y * z - w * x)},
                           {two * (x * z - w * y), two * (y * z + w * x), ww - xx - yy + zz}};
  Lit l;
  for (int r = 0; r < 3; ++r) l[r] = h[0] * N[r][0] + h[1] * N[r][1] + h[2] * N[r][2];
  l[3] = h[3] * (ww + xx + yy + zz) - (l[0] * c_[k][0] + l[1] * c_[k][1] + l[2] * c_[k][2]);
  return l;
}

Rational_poly value(const Lit& l, const Field_point& p) { return l[0] * p[0] + l[1] * p[1] + l[2] * p[2] + l[3]; }

int Turning_model::sign(const Atom& h, int k, const Field_point& p, const Real_time& t) const
{
  return sign_at(value(literal(h, k), p), t);
}

bool Turning_model::eval(const Formula& f, int k, const Field_point& p, const Real_time& t) const
{
  if (f.op == Formula::Op::Atom) return sign(f.atom, k, p, t) < 0;
  bool is_and = f.op == Formula::Op::And;
  for (const Formula& g : f.kids)
    if (eval(g, k, p, t) != is_and) return !is_and;
  return is_and;
}

bool Turning_model::strict_true(int k, const Field_point& p, const Real_time& t) const { return eval(formula(), k, p, t); }

bool Turning_model::signs_follow(int k, const Field_point& c, const Field_point& w, const Real_time& t) const
{
  for (const Atom& h : model_.atoms()) {
    int sc = sign(h, k, c, t), sw = sign(h, k, w, t);
    if (sc != 0 && sc != sw) return false;
  }
  return true;
}

} // namespace clash4d::verifier
