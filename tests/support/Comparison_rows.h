// A subject's row in a comparison's JSON (compare --json, report.json,
// findings' meta): how the tests find one, failing the test when it is absent.
#ifndef CLASH4D_TESTS_SUPPORT_COMPARISON_ROWS_H
#define CLASH4D_TESTS_SUPPORT_COMPARISON_ROWS_H

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>
#include <string>

namespace clash4d {

inline const nlohmann::ordered_json& subject_row(const nlohmann::ordered_json& comparison, const std::string& subject)
{
  for (const auto& s : comparison["subjects"])
    if (s["subject"] == subject) return s;
  BOOST_FAIL("no row " << subject);
  return comparison;
}

} // namespace clash4d

#endif
