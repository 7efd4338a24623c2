// The CCD sweep (ccd/Ccd_sweep.h) instantiated on the double time kernel:
// the float subject the comparer holds against exact.
#ifndef CLASH4D_FLOAT_CCD_DOUBLE_INSTANTIATION_H
#define CLASH4D_FLOAT_CCD_DOUBLE_INSTANTIATION_H

#include "ccd/Ccd_answer.h"
#include "ccd/Ccd_query.h"

namespace clash4d {

// options.tolerance: |value| <= tolerance counts as zero (0: plain signs).
// Throws std::range_error for a number beyond the double range.
Ccd_answer ccd_double(const Ccd_query& query, const Ccd_options& options);

} // namespace clash4d

#endif
