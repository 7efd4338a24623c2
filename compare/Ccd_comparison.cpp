#include "compare/Ccd_comparison.h"

#include "compare/Ccd_query_files.h"
#include "scene/Input_error.h"

#include <stdexcept>

namespace clash4d {

namespace {

using json = nlohmann::ordered_json;

// A scene row without what a CCD query has not (witness and its check),
// with t* as "t" in the place of "earliest".
json ccd_row_json(const Subject_row& s)
{
  json out, row = row_json(s);
  for (const auto& item : row.items()) {
    if (item.key() == "witness" || item.key() == "witness_valid") continue;
    if (item.key() == "earliest") out["t"] = s.earliest ? json(s.earliest->t) : json();
    else out[item.key()] = item.value();
  }
  return out;
}

std::size_t count_of(const json& j, const char* key)
{
  auto it = j.find(key);
  if (it == j.end() || it->is_null()) return 0;
  if (!it->is_number_unsigned()) throw std::runtime_error(std::string("comparison: ") + key + ": expected a count");
  return it->get<std::size_t>();
}

} // namespace

std::string ccd_query_name(std::size_t index, std::size_t line)
{
  return "query " + std::to_string(index) + " (line " + std::to_string(line) + ")";
}

Ccd_comparison Ccd_comparison::reproducible() const
{
  Ccd_comparison c = *this;
  c.comparison = comparison.reproducible();
  return c;
}

json Ccd_comparison::to_json() const
{
  json rows = json::array();
  for (const Subject_row& s : comparison.subjects) rows.push_back(ccd_row_json(s));
  return {{"file", comparison.file}, {"index", index}, {"line", line}, {"query", ccd_query_json(query)},
          {"subjects", rows}, {"disagreements", comparison.to_json()["disagreements"]}};
}

Ccd_comparison Ccd_comparison::from_json(const json& j)
{
  if (!j.is_object() || !j.contains("query")) throw std::runtime_error("comparison: not a CCD query's (no query)");
  Ccd_comparison c;
  c.comparison = Comparison::from_json(j);   // file, rows, disagreements: the same keys
  c.index = count_of(j, "index");
  c.line = count_of(j, "line");
  c.comparison.name = ccd_query_name(c.index, c.line);
  try {
    c.query = ccd_query_from_json(j["query"]);
  } catch (const Input_error& e) {
    throw std::runtime_error("comparison: " + e.format("query"));
  }
  for (std::size_t i = 0; i < c.comparison.subjects.size(); ++i) {   // rows read: "subjects" is there
    const json& row = j.at("subjects").at(i);
    json t = row.contains("t") ? row.at("t") : json();
    if (t.is_null()) continue;
    if (!t.is_string()) throw std::runtime_error("comparison: subjects[" + std::to_string(i) + "].t: expected a string");
    c.comparison.subjects[i].earliest = Located{{"", ""}, std::nullopt, t.get<std::string>()};
  }
  return c;
}

} // namespace clash4d
