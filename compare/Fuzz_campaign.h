// `clash4d fuzz`: a deterministic, shardable, resumable campaign of contact
// cases (compare/Contact_families.h), each compared across subjects
// (compare/Comparer.h); every disagreement is saved at once and then shrunk.
//
// Layout of DIR:
//   campaign.json                 seed, cases, tolerances (and "fcl": true with
//                                 --fcl, "semantics": "closed" with --semantics
//                                 closed): a rerun must match
//   progress-K-of-S.json          the next case index of shard K of S
//   findings/case-I.json          the scene of case I; under its `meta` key the
//                                 family, seed, index, disagreements (subject,
//                                 its semantics, cause) and the comparison
//   findings/case-I.min.json      the same disagreement on a shrunk scene
//                                 (meta also: disagreement, shrunk_from)
// Both are scene files: `clash4d check findings/case-I.min.json` replays one.
// Every file is written to a temporary name and renamed. A killed run loses
// no saved finding; rerunning with the same arguments redoes at most the
// batch in flight (writing the same files) and goes on.
#ifndef CLASH4D_COMPARE_FUZZ_CAMPAIGN_H
#define CLASH4D_COMPARE_FUZZ_CAMPAIGN_H

#include "compare/Ccd_comparison.h"
#include "compare/Comparer.h"
#include "compare/Progress_line.h"
#include "compare/External_subject.h"
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace clash4d {

// What every campaign has, of scenes or of CCD queries
// (compare/Ccd_fuzz_campaign.h): its cases, its shard, its folder.
struct Campaign_options {
  std::uint64_t seed = 1;
  std::uint64_t cases = 100;
  std::uint64_t shard = 1, shards = 1;     // this is shard `shard` (1-based) of `shards`
  std::string out;
  // Progress on standard error: none, a line rewritten after each batch on
  // a terminal, or a line every ten seconds in a log (a Slurm job's).
  using Progress = Progress_mode;
  Progress progress = Progress::none;
  // Each shrinking step reruns the comparison: a bound on the steps (not on
  // time, so findings stay reproducible) keeps one stubborn case from
  // holding a campaign up.
  std::size_t max_shrink_checks = 60;
};

struct Fuzz_options : Campaign_options {
  Compare_options compare;
  // The families: the contact families (Contact_families.h), or with
  // `rotation` the turning parts' (Rotation_families.h).
  bool rotation = false;
};

struct Fuzz_summary {
  std::uint64_t done = 0, findings = 0, resumed_from = 0;
};

// Runs (or resumes) the campaign. Throws std::runtime_error with a message
// naming the file on I/O problems or a DIR that holds another campaign.
Fuzz_summary run_fuzz(const Fuzz_options& options, std::ostream& err);

// ---------------------------------------------------------------- for every campaign

// Runs (or resumes) this shard of a campaign whose campaign.json is
// `description` (a rerun must match it): `run_case(I)` compares case I and
// saves it when it is a finding (then true), in parallel batches, the
// progress saved after each whole batch.
Fuzz_summary run_campaign(const Campaign_options& o, const nlohmann::ordered_json& description,
                          const std::function<bool(std::uint64_t)>& run_case, std::ostream& err);

// DIR/findings/case-I followed by `suffix` (".json", ".min.json").
std::string finding_path(const Campaign_options& o, std::uint64_t index, const std::string& suffix);

// A finding's provenance, kept under its `meta` key: tool, family, seed,
// index and the disagreements (subject, semantics, cause, detail,
// tolerance). The caller adds the comparison, in its own JSON form.
nlohmann::ordered_json finding_meta(const Campaign_options& o, const std::string& family, std::uint64_t index,
                                    const Comparison& comparison);
nlohmann::ordered_json disagreement_meta(const Comparison& c, const Disagreement& d);
// The external subjects as campaign.json lists them (name, command).
nlohmann::ordered_json subjects_json(const std::vector<std::shared_ptr<External_pool>>& externals);

// A crash, time-out or protocol fault of an external subject: saved, not
// shrunk (it may depend on the process's history, and each retry of a
// time-out costs the time limit).
bool is_fault(const std::string& cause);

// The options with only the subjects a disagreement of `subject` needs
// (exact and exact-rounded, which classify it, always run): its own
// "double tol=EPS" or external subject. Compare_options and
// Ccd_compare_options alike.
template <class Options>
Options narrowed_to(const Options& o, const std::string& subject)
{
  Options narrow = o;
  narrow.tolerances.clear();
  for (double tol : o.tolerances)
    if (subject == tolerance_subject(tol)) narrow.tolerances.push_back(tol);
  narrow.externals.clear();
  for (const auto& pool : o.externals)
    if (pool->spec().name == subject) narrow.externals.push_back(pool);
  return narrow;
}

// The comparison saved in a finding file's meta (its JSON `finding`, read
// from `path`; a CCD query's rows for fuzz --ccd findings); throws
// std::runtime_error naming the file when it has none.
Comparison finding_comparison(const nlohmann::ordered_json& finding, const std::string& path);
// A fuzz --ccd finding (a query: its JSON has "t0"), and its whole comparison.
bool is_ccd_finding(const nlohmann::ordered_json& finding);
Ccd_comparison finding_ccd_comparison(const nlohmann::ordered_json& finding, const std::string& path);

// Joins the findings of several campaign folders into `out` (scene
// campaigns' and fuzz --ccd's, CSV files included, each copied as it is),
// with a summary.json of counts by family, subject and cause.
Fuzz_summary merge_fuzz(const std::vector<std::string>& dirs, const std::string& out);

} // namespace clash4d

#endif
