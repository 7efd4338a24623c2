// A CCD query's answer (docs/ccd-queries.md, Output): the verdict and, with
// earliest, t* and the contact's (u, v). Exact kernels give real algebraic
// numbers, the double kernel doubles; text is made only at the edges (cli/).
#ifndef CLASH4D_CCD_CCD_ANSWER_H
#define CLASH4D_CCD_CCD_ANSWER_H

#include "ccd/Ccd_contact.h"
#include "numbers/Algebraic.h"
#include "numbers/Rational.h"
#include <optional>
#include <variant>

namespace clash4d {

struct Ccd_options {
  bool earliest = false;   // also t* and (u, v)
  double tolerance = 0;    // double only: |value| <= tolerance is zero
  // Minimum separation D >= 0 (docs/ccd-queries.md): a query collides when
  // the primitives come within distance D; 0 is the plain contract.
  Rational separation = 0;
};

// A number of an answer: exact (an algebraic number, rational or not) or a
// double's.
using Ccd_number = std::variant<Algebraic, double>;

struct Ccd_earliest {
  Ccd_number t, u, v;
  // Exact kernels: how the primitives meet at t* (which branch of the
  // static test held) and (u, v) as quotients of polynomials in t, so that
  // a check can redo the contact in Q(t*) (tests, certificates).
  Ccd_contact contact;
  std::optional<Ccd_uv_fraction<Rational>> uv;
};

struct Ccd_answer {
  bool collide = false;
  std::optional<Ccd_earliest> earliest;   // with Ccd_options::earliest, when collide
};

} // namespace clash4d

#endif
