#include "verify/Object_model.h"
#include <algorithm>
#include <stdexcept>

namespace clash4d::verifier {

Literal coprime(const std::array<mpq_class, 5>& v)
{
  mpz_class den = 1, g = 0;
  for (const mpq_class& q : v) mpz_lcm(den.get_mpz_t(), den.get_mpz_t(), q.get_den_mpz_t());
  Literal out;
  for (int i = 0; i < 5; ++i) {
    out[i] = v[i].get_num() * (den / v[i].get_den());
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), out[i].get_mpz_t());
  }
  if (g != 0)
    for (mpz_class& c : out) c /= g;
  return out;
}

Object_model::Object_model(const Scene_object& o) : name_(o.name), turns_(o.motion.rotates()), formula_(solid_formula(o.shape))
{
  collect_atoms(formula_, atoms_);
  for (const auto& t : o.motion.times) times_.emplace_back(t.mpq());
  for (const auto& v : o.motion.velocities)
    v_.push_back({mpq_class(v[0].mpq()), mpq_class(v[1].mpq()), mpq_class(v[2].mpq())});
  if (v_.size() != times_.size() + 1) v_.assign(times_.size() + 1, {0, 0, 0});   // at rest
  // D(t) = v_k t + o_k on segment k; D(0) = 0 on the segment whose closure
  // holds 0, and continuity at each time carries o to the others.
  o_.assign(v_.size(), {0, 0, 0});
  std::size_t k0 = std::count_if(times_.begin(), times_.end(), [](const mpq_class& t) { return t < 0; });
  for (std::size_t k = k0; k + 1 < v_.size(); ++k)
    for (int c = 0; c < 3; ++c) o_[k + 1][c] = o_[k][c] + (v_[k][c] - v_[k + 1][c]) * times_[k];
  for (std::size_t k = k0; k > 0; --k)
    for (int c = 0; c < 3; ++c) o_[k - 1][c] = o_[k][c] + (v_[k][c] - v_[k - 1][c]) * times_[k - 1];
}

int Object_model::segment_at(const mpq_class& t) const
{
  // times_ increase strictly (the scene reader's rule): binary searches, so
  // a motion of many segments costs a logarithm per piece, not a scan.
  return static_cast<int>(std::lower_bound(times_.begin(), times_.end(), t) - times_.begin());
}

bool Object_model::is_change(const mpq_class& t) const
{
  return std::binary_search(times_.begin(), times_.end(), t);
}

bool Object_model::change_between(const mpq_class& a, const mpq_class& b) const
{
  const mpq_class& lo = a < b ? a : b;
  const mpq_class& hi = a < b ? b : a;
  auto first_above = std::upper_bound(times_.begin(), times_.end(), lo);
  return first_above != times_.end() && *first_above < hi;
}

// A point p at time t is in the object when p - D(t) is in the shape, so
// n.(x - v t - o) + d <= 0 (section 2.2).
std::array<mpq_class, 5> Object_model::extrude(const Atom& h, int k) const
{
  // A turning object has no times or velocities: never read it as resting.
  if (turns_) throw std::logic_error("the literals of turning object " + name_ + " are not linear (section 8)");
  const auto& v = v_[k];
  const auto& o = o_[k];
  return {h[0], h[1], h[2], -(h[0] * v[0] + h[1] * v[1] + h[2] * v[2]), h[3] - (h[0] * o[0] + h[1] * o[1] + h[2] * o[2])};
}

mpq_class Object_model::value(const Atom& h, int k, const Point4& p) const
{
  std::array<mpq_class, 5> l = extrude(h, k);
  return l[0] * p[0] + l[1] * p[1] + l[2] * p[2] + l[3] * p[3] + l[4];
}

bool Object_model::eval(const Formula& f, int k, const Point4& p) const
{
  if (f.op == Formula::Op::Atom) return value(f.atom, k, p) < 0;
  bool is_and = f.op == Formula::Op::And;
  for (const Formula& g : f.kids)
    if (eval(g, k, p) != is_and) return !is_and;
  return is_and;
}

bool Object_model::strict_true(int k, const Point4& p) const { return eval(formula_, k, p); }

bool Object_model::signs_follow(int k, const Point4& c, const Point4& w) const
{
  for (const Atom& h : atoms_) {
    int sc = sgn(value(h, k, c)), sw = sgn(value(h, k, w));
    if (sc != 0 && sc != sw) return false;
  }
  return true;
}

} // namespace clash4d::verifier
