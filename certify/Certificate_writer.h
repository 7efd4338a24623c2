// The certificate of exactly the answer `check` printed
// (docs/certificate-format.md): witnesses and generic points from the
// answer, apart proofs (certify/Apart_prover.h) for every pair the claim
// says does not collide (or not before t*), written atomically within a
// size limit. Every certificate is first checked whole by the checker of
// verify/ (check_before_writing): an error, never a file, if it were
// refused.
#ifndef CLASH4D_CERTIFY_CERTIFICATE_WRITER_H
#define CLASH4D_CERTIFY_CERTIFICATE_WRITER_H

#include "check/Check_answer.h"
#include "scene/Scene.h"
#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace clash4d {

// The certificate would pass a limit (size, or the checker's step limit):
// exit 3 naming it, and no file.
struct Certificate_limit : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Certificate_stats {
  std::size_t pairs_apart = 0, conflicts = 0, bytes = 0;
  std::uint64_t steps = 0;
};

// Throws Certificate_limit, or std::logic_error when the answer cannot be
// proved (a wrong answer or a certifier bug: never written).
nlohmann::ordered_json make_certificate(const Scene& scene, const Check_answer& answer, const Check_options& options,
                                        Certificate_stats* stats = nullptr);

// The checker of verify/ on the whole certificate, in the process: throws
// Certificate_limit past its step limit, std::logic_error if it refuses a
// proof. Both writers call it: no certificate is written unchecked.
void check_before_writing(const Scene& scene, const nlohmann::ordered_json& certificate);

// The certificate's text into path (temporary name, then rename); throws
// Certificate_limit past max_bytes.
void write_certificate(const std::string& path, const nlohmann::ordered_json& certificate, std::size_t max_bytes,
                       Certificate_stats* stats = nullptr);

// The checker's limit on term enumeration (docs/certificate-format.md, 4).
constexpr std::uint64_t certificate_step_limit = 10000000;

} // namespace clash4d

#endif
