// CGAL's linear programs solved exactly by Bland's rule. CGAL's default
// pricing may cycle on a degenerate program (its manual's cycling.cpp), and
// ours are degenerate by nature: many planes through one vertex of a mesh
// piece, a witness at a contact, a split tree's cut through a corner (one
// of fixtures/certificates/split/star_into_bowl.json's ran for minutes).
// Bland's rule terminates. Only the optimum's status, value and a solution
// are read, all exact, whatever the pivots.
#ifndef CLASH4D_NUMBERS_EXACT_LP_H
#define CLASH4D_NUMBERS_EXACT_LP_H

#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>
#include <CGAL/QP_options.h>

namespace clash4d {

template <class Program, class ET>
CGAL::Quadratic_program_solution<ET> solve_exact_lp(const Program& lp, const ET& et)
{
  CGAL::Quadratic_program_options options;
  options.set_pricing_strategy(CGAL::QP_BLAND);
  return CGAL::solve_linear_program(lp, et, options);
}

} // namespace clash4d

#endif
