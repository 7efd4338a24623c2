// A solid as a Boolean formula over 3D half-spaces, built from the scene
// alone (docs/certificate-format.md, section 2.1).
#ifndef CLASH4D_VERIFY_SOLID_FORMULA_H
#define CLASH4D_VERIFY_SOLID_FORMULA_H

#include "scene/Scene.h"
#include <gmpxx.h>
#include <array>
#include <vector>

namespace clash4d::verifier {

// a x + b y + c z + d <= 0, (a, b, c) != 0.
using Atom = std::array<mpq_class, 4>;

// Negation is pushed to the atoms, so only AND and OR remain (section 2.1).
struct Formula {
  enum class Op { Atom, And, Or };
  Op op = Op::And;
  Atom atom;                    // when op is Atom
  std::vector<Formula> kids;    // when op is And or Or
};

// The formula of a solid of the scene (a mesh arrives from the reader as a
// hull or a union of hulls: section 7). Throws std::invalid_argument on a
// solid the reader should have refused.
Formula solid_formula(const Solid& s);

// Every atom of f, in order (for the generic-witness check of section 3).
void collect_atoms(const Formula& f, std::vector<Atom>& out);

} // namespace clash4d::verifier

#endif
