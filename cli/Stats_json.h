// `check --stats` and `skeleton --stats` as JSON: the statistics are numbers
// (search/Check_stats.h, numbers/Stat_number.h) until here, where they are
// written as the answers write numbers.
#ifndef CLASH4D_CLI_STATS_JSON_H
#define CLASH4D_CLI_STATS_JSON_H

#include "search/Check_stats.h"
#include <nlohmann/json.hpp>
#include <string>

namespace clash4d {

// An exact rational p/q, the shortest decimal that reads back to a double,
// an enclosure's point as the exact rational it is, otherwise "~[lo, hi]".
std::string stat_text(const Stat_number& x);

nlohmann::ordered_json stats_json(const Check_stats& s);

} // namespace clash4d

#endif
