// CCD query files as compare, fuzz and report meet them (docs/ccd-queries.md,
// Input): telling them from scene files, reading all of a file's queries,
// and writing a query back in the benchmark's CSV and as a JSON line, its
// numbers exact.
#ifndef CLASH4D_COMPARE_CCD_QUERY_FILES_H
#define CLASH4D_COMPARE_CCD_QUERY_FILES_H

#include "ccd/Ccd_query.h"
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace clash4d {

// A file of CCD queries rather than a scene: .csv, .jsonl and .ndjson always;
// another file when its first line is a JSON object with a "t0" key (a
// scene's first line is never a whole object with one).
bool is_ccd_query_file(const std::string& path);

// Every query of the file, in order (Ccd_reader; `type` is --type's).
// Throws Input_error with the place and no file name (the caller adds it).
std::vector<Ccd_query> read_ccd_queries(const std::string& path, std::optional<Ccd_type> type);

// The query as the benchmark's 8 rows "xn,xd,yn,yd,zn,zd,label", each
// ending in a newline; `label` in column 7.
std::string ccd_query_csv(const Ccd_query& q, bool label);
// {"type": ..., "t0": [[x, y, z] x 4], "t1": [...]}, numbers as exact strings.
nlohmann::ordered_json ccd_query_json(const Ccd_query& q);
// The query of such an object (extra keys "label" and "meta" allowed), read
// by Ccd_reader itself; throws Input_error with the place.
Ccd_query ccd_query_from_json(const nlohmann::ordered_json& j);

} // namespace clash4d

#endif
