// `clash4d fuzz --ccd`: the campaign of compare/Fuzz_campaign.h (the same
// determinism, sharding, resumption and progress) over CCD queries: case I
// is make_ccd_case(seed, I) (ccd/Ccd_families.h, every family in turn),
// compared across subjects (compare/Ccd_comparer.h); every disagreement is
// saved at once and then shrunk.
//
// Layout of DIR, beside campaign.json ("queries": "ccd") and the progress
// files:
//   findings/case-I.json           the query as one JSON line (docs/ccd-queries.md):
//                                  type, t0, t1, label = the exact verdict, and
//                                  under `meta` the family, seed, index,
//                                  disagreements (subject, cause, detail,
//                                  tolerance) and the comparison
//   findings/TYPE-case-I.csv       the same query in the benchmark's CSV, label
//                                  column = the exact verdict; TYPE
//                                  (vertex-face or edge-edge) begins the name
//                                  because a CSV file's name is its type
//   findings/case-I.min.json,
//   findings/TYPE-case-I.min.csv   the same disagreement on a shrunk query (meta
//                                  also: disagreement, shrunk_from); a fault
//                                  of an external subject is not shrunk
// `clash4d ccd findings/TYPE-case-I.min.csv --labels` (or the .min.json)
// replays a finding: exit 0, the exact answer is its label.
#ifndef CLASH4D_COMPARE_CCD_FUZZ_CAMPAIGN_H
#define CLASH4D_COMPARE_CCD_FUZZ_CAMPAIGN_H

#include "compare/Ccd_comparer.h"
#include "compare/Fuzz_campaign.h"
#include <iosfwd>

namespace clash4d {

struct Ccd_fuzz_options : Campaign_options {
  Ccd_compare_options compare;
};

// Runs (or resumes) the campaign. Throws std::runtime_error with a message
// naming the file on I/O problems or a DIR that holds another campaign.
Fuzz_summary run_ccd_fuzz(const Ccd_fuzz_options& options, std::ostream& err);

} // namespace clash4d

#endif
