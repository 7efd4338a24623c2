// `check --stats` and `skeleton --stats` as JSON: the statistics are numbers
// (search/Check_stats.h, numbers/Stat_number.h) until here, where they are
// written as the answers write numbers.
#ifndef CLASH4D_CLI_STATS_JSON_H
#define CLASH4D_CLI_STATS_JSON_H

#include "scene/Mesh_record.h"
#include "search/Check_stats.h"
#include <nlohmann/json.hpp>
#include <string>

namespace clash4d {

// An exact rational p/q, the shortest decimal that reads back to a double,
// an enclosure's point as the exact rational it is, otherwise "~[lo, hi]".
std::string stat_text(const Stat_number& x);

nlohmann::ordered_json stats_json(const Check_stats& s);

// The scene's mesh files (Scene::meshes), one object each: what was read,
// what it became, and what its decomposition cost ("meshes" of --stats).
nlohmann::ordered_json meshes_json(const std::vector<Mesh_record>& meshes);

// The same as text, one line per mesh file, indented by `indent`.
std::string meshes_text(const std::vector<Mesh_record>& meshes, const std::string& indent);

} // namespace clash4d

#endif
