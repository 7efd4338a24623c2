// The certificate of exactly the answer `check` printed on a scene where
// some object turns (docs/certificate-format.md, section 8): the regularised
// witness or the closed touch of each colliding pair the claim names (with
// --earliest: the witness path after t*, certify/Witness_path.h, or the
// touch at t*), and an apart proof (certify/Turning_prover.h) for every pair
// it says does not collide, or not before t*.
#ifndef CLASH4D_CERTIFY_TURNING_CERTIFICATE_H
#define CLASH4D_CERTIFY_TURNING_CERTIFICATE_H

#include "certify/Certificate_writer.h"
#include "rotation/Rotating_check.h"

namespace clash4d {

// Throws Certificate_limit, Turning_proof_missing (a proof this release
// cannot make: refused, exit 2), or std::logic_error when the answer cannot
// be proved (never written).
nlohmann::ordered_json make_turning_certificate(const Scene& scene, const Rotating_check_answer& answer,
                                                const Check_options& options, Certificate_stats* stats = nullptr);

} // namespace clash4d

#endif
