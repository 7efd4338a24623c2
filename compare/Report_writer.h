// The verification report of `clash4d report`: comparison objects (schema in
// compare/README.md) rendered as a self-contained HTML page with q-t diagrams
// (paper figures 1 and 5: each object's extent along one axis over time), a
// machine-readable report.json and a JUnit XML file for CI.
#ifndef CLASH4D_COMPARE_REPORT_WRITER_H
#define CLASH4D_COMPARE_REPORT_WRITER_H

#include "compare/Comparison.h"
#include "scene/Scene.h"
#include <string>
#include <vector>

namespace clash4d {

struct Report_case {
  std::string file;                   // scene path as given
  Scene scene;                        // the parsed scene (exact rationals), for drawing
  Comparison comparison;
  std::string family;                 // a fuzz finding's family (its meta), else empty
};

// Writes DIR/index.html, DIR/report.json, DIR/junit.xml. Each file is written to
// a temporary name in DIR and renamed, so no half-written file is ever left.
// Creates DIR if missing. Throws std::runtime_error with a clear message on I/O failure.
void write_report(const std::vector<Report_case>& cases, const std::string& dir);

} // namespace clash4d

#endif
