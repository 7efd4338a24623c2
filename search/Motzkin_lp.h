// Multipliers that prove a system of half-spaces infeasible, found by one
// exact linear program (CGAL's QP solver): the conflicts of a certificate
// (docs/certificate-format.md, section 4).
#ifndef CLASH4D_SEARCH_MOTZKIN_LP_H
#define CLASH4D_SEARCH_MOTZKIN_LP_H

#include "numbers/Rational.h"
#include <array>
#include <optional>
#include <vector>

namespace clash4d {

// a x + b y + c z + e_t t + e, integer coefficients (a literal of the format).
using Literal_coefficients = std::array<Rational, 5>;

struct Motzkin_row {
  const Literal_coefficients* h;
  bool strict;                 // h < 0 (true) or h <= 0
};

// Motzkin's transposition theorem: the system has no solution iff some
// lambda >= 0, not all zero, has sum lambda_i (a_i, b_i, c_i, e_t,i) = 0 and
// sum lambda_i e_i > 0, or = 0 with lambda positive on a strict row. The
// dual LP  max sum lambda_i e_i  s.t. sum lambda_i a_i = 0, sum lambda_i = 1,
// lambda >= 0  finds such lambda when one exists (then a basic, so sparse,
// one: at most five non-zero); a second LP asks for a strict row's weight
// when the first optimum is 0. Returns lambda (one per row, zeros included),
// checked exactly, or nothing when the system is feasible.
// complete: where the double simplex's guess at the support proves
// nothing, the exact LP over every row (about a millisecond) decides, so
// nothing returned means feasible; quick: only the basic solution on the
// guessed support is tried (one small exact solve), and nothing returned
// means only "not found", for a caller that can decide another way (a
// search handing a long run over, exact/Interval_filter.h). Multipliers
// returned are checked exactly either way.
enum class Lp_effort { complete, quick };

// The double simplex's other answer: its multipliers are the point x that
// minimises max_j h_j(x) / big_j (big_j: row j's largest |coefficient|, at
// least 1), a centre of the rows; `found` when that maximum is below zero,
// every row negative there in doubles. A guess: a caller checks it exactly.
struct Inside_guess {
  std::array<double, 4> x{};
  bool found = false;
};

// inside: the guess, filled when no multipliers are returned.
std::optional<std::vector<Rational>> motzkin_multipliers(const std::vector<Motzkin_row>& rows,
                                                        Lp_effort effort = Lp_effort::complete,
                                                        Inside_guess* inside = nullptr);

// Whether lambda proves rows infeasible, by the rule above (exact).
bool proves_infeasible(const std::vector<Motzkin_row>& rows, const std::vector<Rational>& lambda);

} // namespace clash4d

#endif
