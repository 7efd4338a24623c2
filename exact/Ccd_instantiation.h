// The CCD sweep (ccd/Ccd_sweep.h) instantiated on the two exact time
// kernels: the filtered one (`--number exact`, what users run) and the
// rational one (`--number rational`, the reference). Their answers are
// identical.
#ifndef CLASH4D_EXACT_CCD_INSTANTIATION_H
#define CLASH4D_EXACT_CCD_INSTANTIATION_H

#include "ccd/Ccd_answer.h"
#include "ccd/Ccd_query.h"

namespace clash4d {

Ccd_answer ccd_exact(const Ccd_query& query, const Ccd_options& options);
Ccd_answer ccd_rational(const Ccd_query& query, const Ccd_options& options);

} // namespace clash4d

#endif
