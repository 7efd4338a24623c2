// One object of a turning scene as the checker sees it: its motion pieces
// and breakpoints, and each atom's literal on a piece, four polynomials in t
// (docs/certificate-format.md, section 8.2).
#ifndef CLASH4D_VERIFY_TURNING_MODEL_H
#define CLASH4D_VERIFY_TURNING_MODEL_H

#include "verify/Object_model.h"
#include "verify/Real_time.h"

namespace clash4d::verifier {

// [n_x, n_y, n_z, e]: n_x(t) x + n_y(t) y + n_z(t) z + e(t) (< or <=) 0.
using Lit = std::array<Rational_poly, 4>;
// A point whose coordinates are polynomials in t, read at its time.
using Field_point = std::array<Rational_poly, 3>;

class Turning_model {
public:
  // m: the same object's Object_model (its ROBMOD displacement).
  Turning_model(const Scene_object& o, const Object_model& m);
  const std::string& name() const { return model_.name(); }
  const Formula& formula() const { return model_.formula(); }
  const std::vector<Atom>& atoms() const { return model_.atoms(); }
  // Piece k lies between breakpoints k-1 and k.
  int piece_of(const Real_time& lo) const;   // the piece holding (lo, hi) when no breakpoint is inside
  int piece_at(const Real_time& t) const;    // a piece whose closure holds t
  bool is_break(const mpq_class& t) const;
  bool break_between(const Real_time& lo, const Real_time& hi) const;   // strictly
  Lit literal(const Atom& h, int k) const;
  // The formula on piece k at p, time T, with strict signs.
  bool strict_true(int k, const Field_point& p, const Real_time& t) const;
  // Every literal l on piece k has l(c) = 0 or the sign of l(w) (8.4).
  bool signs_follow(int k, const Field_point& c, const Field_point& w, const Real_time& t) const;

private:
  int sign(const Atom& h, int k, const Field_point& p, const Real_time& t) const;
  bool eval(const Formula& f, int k, const Field_point& p, const Real_time& t) const;
  const Object_model& model_;
  std::vector<mpq_class> breaks_;
  std::vector<std::array<Rational_poly, 4>> q_;   // per piece: w x y z
  std::vector<std::array<Rational_poly, 3>> c_;   // per piece: the translation
};

// A literal's value at a point: a polynomial in t.
Rational_poly value(const Lit& l, const Field_point& p);

} // namespace clash4d::verifier

#endif
