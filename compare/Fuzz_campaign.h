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

#include "compare/Comparer.h"
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace clash4d {

struct Fuzz_options {
  std::uint64_t seed = 1;
  std::uint64_t cases = 100;
  std::uint64_t shard = 1, shards = 1;     // this is shard `shard` (1-based) of `shards`
  std::string out;
  Compare_options compare;
  bool progress = false;                   // a progress line on standard error
  // Each shrinking step reruns the comparison: a bound on the steps (not on
  // time, so findings stay reproducible) keeps one stubborn case from
  // holding a campaign up.
  std::size_t max_shrink_checks = 60;
};

struct Fuzz_summary {
  std::uint64_t done = 0, findings = 0, resumed_from = 0;
};

// Runs (or resumes) the campaign. Throws std::runtime_error with a message
// naming the file on I/O problems or a DIR that holds another campaign.
Fuzz_summary run_fuzz(const Fuzz_options& options, std::ostream& err);

// The comparison saved in a finding file's meta (its JSON `finding`, read
// from `path`); throws std::runtime_error naming the file when it has none.
Comparison finding_comparison(const nlohmann::ordered_json& finding, const std::string& path);

// Joins the findings of several campaign folders into `out`, with a
// summary.json of counts by family, subject and cause.
Fuzz_summary merge_fuzz(const std::vector<std::string>& dirs, const std::string& out);

} // namespace clash4d

#endif
