#include "compare/Ccd_fuzz_campaign.h"

#include "ccd/Ccd_families.h"
#include "compare/Ccd_query_files.h"
#include "compare/Shrinker.h"
#include "scene/Files.h"

#include <algorithm>
#include <filesystem>

namespace clash4d {

namespace {

using json = nlohmann::ordered_json;

json campaign_json(const Ccd_fuzz_options& o)
{
  json c = {{"format", "clash4d-fuzz/1"}, {"queries", "ccd"},         {"seed", o.seed},
            {"cases", o.cases},           {"tolerances", o.compare.tolerances}};
  if (o.compare.earliest) c["earliest"] = true, c["time_bound"] = o.compare.time_bound;
  if (!o.compare.externals.empty()) c["subjects"] = subjects_json(o.compare.externals);
  return c;
}

// DIR/findings/TYPE-case-I followed by `suffix`: the type begins a CSV
// file's name, since nothing in the file says it (docs/ccd-queries.md).
std::string csv_path(const Ccd_fuzz_options& o, const Ccd_query& q, std::uint64_t index, const char* suffix)
{
  std::filesystem::path p(finding_path(o, index, suffix));
  return (p.parent_path() / (std::string(ccd_type_name(q.type())) + "-" + p.filename().string())).string();
}

bool exact_verdict(const Comparison& c) { return c.find("exact")->collide.value_or(false); }

// Both files of a finding: the JSON line (with its provenance) and the CSV,
// each labelled with the exact verdict, so `clash4d ccd --labels` replays it.
void save(const Ccd_fuzz_options& o, const Ccd_comparison& c, json meta, std::uint64_t index, const char* json_suffix,
          const char* csv_suffix)
{
  bool label = exact_verdict(c.comparison);
  meta["comparison"] = c.reproducible().to_json();
  json line = ccd_query_json(c.query);
  line["label"] = label;
  line["meta"] = meta;
  write_file_atomically(finding_path(o, index, json_suffix), line.dump() + "\n");
  write_file_atomically(csv_path(o, c.query, index, csv_suffix), ccd_query_csv(c.query, label));
}

// Shrinks while the first disagreement (same subject, same cause) persists,
// running only the subjects that decide it.
Ccd_query shrink(const Ccd_fuzz_options& o, const Ccd_query& query, const Disagreement& first)
{
  std::string key = first.subject + ": " + first.cause;
  Ccd_compare_options narrow = narrowed_to(o.compare, first.subject);
  auto still_fails = [&](const Ccd_query& candidate) {
    std::vector<std::string> k = compare_query(candidate, "", 0, narrow).comparison.disagreement_keys();
    return std::find(k.begin(), k.end(), key) != k.end();
  };
  return shrink_query(query, still_fails, o.max_shrink_checks);
}

// Compares one case; on disagreement saves it, shrinks it, saves the minimum.
bool run_case(const Ccd_fuzz_options& o, std::uint64_t index)
{
  Ccd_case c = make_ccd_case(o.seed, index);
  c.query.line = 1;   // its line in the finding's file
  std::string name = "case-" + std::to_string(index);
  Ccd_comparison comparison = compare_query(c.query, name, 0, o.compare);
  if (!comparison.comparison.has_disagreement()) return false;
  save(o, comparison, finding_meta(o, c.family, index, comparison.comparison), index, ".json", ".csv");
  const Disagreement& first = comparison.comparison.disagreements.front();
  bool fault = is_fault(first.cause);
  Ccd_comparison again = fault ? comparison : compare_query(shrink(o, c.query, first), name + ".min", 0, o.compare);
  json meta = finding_meta(o, c.family, index, again.comparison);
  meta["shrunk_from"] = name + ".json";
  meta["disagreement"] = disagreement_meta(comparison.comparison, first);
  if (fault) meta["not_shrunk"] = "a subject's crash, time-out or protocol fault may depend on its state";
  save(o, again, meta, index, ".min.json", ".min.csv");
  return true;
}

} // namespace

Fuzz_summary run_ccd_fuzz(const Ccd_fuzz_options& o, std::ostream& err)
{
  return run_campaign(o, campaign_json(o), [&](std::uint64_t index) { return run_case(o, index); }, err);
}

} // namespace clash4d
