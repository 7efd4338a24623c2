// One object of the scene as the checker sees it: its formula, its motion
// and their extrusion to space-time (docs/certificate-format.md, 2.1-2.2).
#ifndef CLASH4D_VERIFY_OBJECT_MODEL_H
#define CLASH4D_VERIFY_OBJECT_MODEL_H

#include "verify/Solid_formula.h"
#include <string>

namespace clash4d::verifier {

using Point4 = std::array<mpq_class, 4>;     // x y z t
using Literal = std::array<mpz_class, 5>;    // a b c e_t e, coprime (section 2.2)

// The coprime integer form k (a, b, c, e_t, e), k > 0; the zero vector stays zero.
Literal coprime(const std::array<mpq_class, 5>& v);

class Object_model {
public:
  explicit Object_model(const Scene_object& o);
  const std::string& name() const { return name_; }
  const Formula& formula() const { return formula_; }
  const std::vector<Atom>& atoms() const { return atoms_; }
  // Whether a pose of its motion turns it (section 8): then its literals are
  // polynomials in t (Turning_model), never the resting ones of this class.
  bool turns() const { return turns_; }
  const std::vector<mpq_class>& times() const { return times_; }
  const std::array<mpq_class, 3>& velocity(int k) const { return v_[k]; }
  const std::array<mpq_class, 3>& offset(int k) const { return o_[k]; }
  // Motion segment k lies between times[k-1] and times[k] (scene format).
  int segment_at(const mpq_class& t) const;   // for a t that is no velocity change
  bool is_change(const mpq_class& t) const;
  bool change_between(const mpq_class& a, const mpq_class& b) const;   // strictly
  // Atom h on segment k: (n, -(n.v), d - n.o), with D(t) = v t + o there.
  std::array<mpq_class, 5> extrude(const Atom& h, int k) const;
  mpq_class value(const Atom& h, int k, const Point4& p) const;
  // The formula on segment k at p with strict signs (l < 0 is true).
  bool strict_true(int k, const Point4& p) const;
  // Every literal l on segment k has l(c) = 0 or the sign of l(w) (section 3).
  bool signs_follow(int k, const Point4& c, const Point4& w) const;

private:
  bool eval(const Formula& f, int k, const Point4& p) const;
  std::string name_;
  bool turns_ = false;
  Formula formula_;
  std::vector<Atom> atoms_;
  std::vector<mpq_class> times_;
  std::vector<std::array<mpq_class, 3>> v_, o_;   // per segment
};

} // namespace clash4d::verifier

#endif
