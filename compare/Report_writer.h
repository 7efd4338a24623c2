// The verification report of `clash4d report`: comparison objects (schema in
// compare/README.md) rendered as a self-contained HTML page with q-t diagrams
// (paper figures 1 and 5: each object's extent along one axis over time) or,
// for a CCD query, its rows, a machine-readable report.json and a JUnit XML
// file for CI.
#ifndef CLASH4D_COMPARE_REPORT_WRITER_H
#define CLASH4D_COMPARE_REPORT_WRITER_H

#include "compare/Ccd_comparison.h"
#include "compare/Comparison.h"
#include "scene/Scene.h"
#include <optional>
#include <string>
#include <vector>

namespace clash4d {

struct Report_case {
  std::string file;                   // scene (or query file) path as given
  Scene scene;                        // the parsed scene (exact rationals), for drawing; empty for a CCD query
  Comparison comparison;              // the rows every case has (a CCD query's: ccd->comparison)
  std::string family;                 // a fuzz finding's family (its meta), else empty
  // A CCD query's comparison: shown with the query's rows instead of q-t
  // diagrams, and written to report.json in its own form.
  std::optional<Ccd_comparison> ccd = std::nullopt;
  // A minimised fuzz finding: the scene it was shrunk from, as given (linked
  // from the case, so a fuzz folder lists each finding once); else empty.
  std::string original = {};
};

// The case of a CCD query.
Report_case ccd_report_case(const std::string& file, const Ccd_comparison& c, const std::string& family);

// Escapes for HTML text and attributes and for XML; control characters that
// XML 1.0 forbids become U+FFFD.
std::string escape_markup(const std::string& s);

// Writes DIR/index.html, DIR/report.json, DIR/junit.xml. Each file is written to
// a temporary name in DIR and renamed, so no half-written file is ever left.
// Creates DIR if missing. Throws std::runtime_error with a clear message on I/O failure.
void write_report(const std::vector<Report_case>& cases, const std::string& dir);

} // namespace clash4d

#endif
