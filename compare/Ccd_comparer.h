// The comparer on CCD queries (docs/ccd-queries.md, "Compare and fuzz"):
// every subject answers the query and is held against the exact answer, in
// the one semantics a query has (closed: touching counts; t in [0, 1]).
// Subjects:
//   exact           the reference (ccd_exact: rationals, real algebraic t*);
//   double          the same sweep on doubles, plain signs (ccd_double);
//   double tol=EPS  the same with |value| <= EPS taken as zero (each
//                   --tolerance);
//   exact-rounded   exact on the query with every number rounded to its
//                   nearest double: the question a subject reading doubles
//                   is really asked (separates input rounding);
//   NAME            each --subject NAME=COMMAND, sent a CCD request
//                   (docs/subject-protocol.md): "unsupported" is skipped; a
//                   crash, time-out or answer out of protocol is a fault
//                   with that cause ("crash", "timeout", "protocol").
// Every disagreement is classified by the first cause that holds:
//   input rounding  the verdicts differ and exact-rounded gives the
//                   subject's verdict (exact-rounded itself: always);
//   tolerance       the verdicts differ, the subject has a tolerance EPS
//                   (double tol=EPS's, or the one its hello declares) and
//                   the exact answer with minimum separation EPS (do the
//                   primitives come within EPS?) gives its verdict;
//   arithmetic      the verdicts differ otherwise;
//   time            (--earliest) both say collision and the subject's t*
//                   differs from the exact t* by more than the time bound
//                   (absolute, default 1e-9), decided exactly.
#ifndef CLASH4D_COMPARE_CCD_COMPARER_H
#define CLASH4D_COMPARE_CCD_COMPARER_H

#include "compare/Ccd_comparison.h"
#include <memory>
#include <string>
#include <vector>

namespace clash4d {

class External_pool;

struct Ccd_compare_options {
  std::vector<double> tolerances{1e-9};   // one "double tol=EPS" subject each
  bool earliest = false;                  // also compare t* (cause "time")
  double time_bound = 1e-9;               // |t - t*| above this (its exact value) is "time"
  bool rounded = true;                    // run the exact-rounded subject
  // External subjects (--subject NAME=COMMAND), shared with the scenes' options.
  std::vector<std::shared_ptr<External_pool>> externals;
};

// The comparison of every subject with exact on query `index` of `file`.
// Throws std::runtime_error when the exact subject fails, Budget_exceeded
// past --max-seconds.
Ccd_comparison compare_query(const Ccd_query& query, const std::string& file, std::size_t index,
                             const Ccd_compare_options& options);

// The query with every number replaced by the exact value of its nearest
// double; throws std::range_error for a number beyond the double range.
Ccd_query rounded_query(const Ccd_query& query);

} // namespace clash4d

#endif
