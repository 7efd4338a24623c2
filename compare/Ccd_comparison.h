// The result of comparing one CCD query across subjects
// (compare/Ccd_comparer.h), as a typed value; JSON only at the edges
// (`compare --json`, report.json, the `meta` of fuzz --ccd findings). The
// rows are the scene comparison's (Subject_row): verdict, t* in `earliest`
// (its text: "p/q", a double's shortest decimal, or an irrational t* as
// Algebraic::to_text), t error, time, agreement and cause; every row is in
// closed semantics, the only question a CCD query asks. The JSON form is
// documented in compare/README.md.
#ifndef CLASH4D_COMPARE_CCD_COMPARISON_H
#define CLASH4D_COMPARE_CCD_COMPARISON_H

#include "ccd/Ccd_query.h"
#include "compare/Comparison.h"
#include <cstddef>
#include <string>

namespace clash4d {

struct Ccd_comparison {
  std::size_t index = 0;     // the query's place in its file, from 0
  std::size_t line = 0;      // its first line there
  Ccd_query query;
  // file and name ("query I (line L)"), the rows, the disagreements; never
  // closed_touch (there is one semantics).
  Comparison comparison;

  // Drops the timings, which differ from run to run.
  Ccd_comparison reproducible() const;

  nlohmann::ordered_json to_json() const;
  // Reads what to_json wrote; throws std::runtime_error naming the key.
  static Ccd_comparison from_json(const nlohmann::ordered_json& j);
};

// "query I (line L)": how text output and the report name a query.
std::string ccd_query_name(std::size_t index, std::size_t line);

} // namespace clash4d

#endif
