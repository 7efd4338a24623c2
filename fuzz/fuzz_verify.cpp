// libFuzzer target: verify's certificate reader and checker (verify/) on
// arbitrary bytes as the certificate, against two fixed small scenes of the
// fixtures (two blocks apart; a moving block against a hull). Every input
// must end in an answer: proved, rejected (1), unreadable (2) or a limit (3).
// An internal failure (4), any exception escaping, a crash, a leak or a hang
// is a finding.
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include "verify/Certificate_checker.h"
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {

using namespace clash4d;
using namespace clash4d::verifier;

const char* const scene_texts[2] = {
  R"({"format":"clash4d-scene/1","time":[0,10],"objects":[
    {"name":"A","shape":{"block":{"min":[0,0,0],"max":[1,1,1]}}},
    {"name":"B","shape":{"block":{"min":[2,0,0],"max":[3,1,1]}}}]})",
  R"({"format":"clash4d-scene/1","time":[0,4],"objects":[
    {"name":"A","shape":{"hull":[[0,0,0],[1,0,0],[0,1,0],[0,0,1],[1,1,1],[0.5,0.5,0]]}},
    {"name":"B","shape":{"block":{"min":[3,0,0],"max":[4,1,1]}},"motion":"vel -1/2 0 0 until 2 vel 1 0 0"}]})"};

const Scene& fixed_scene(int i)
{
  static const Scene scenes[2] = {read_scene(read_json_text(scene_texts[0])), read_scene(read_json_text(scene_texts[1]))};
  return scenes[i];
}

} // namespace

// The first byte picks the scene; the rest is the certificate's text.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size == 0) return 0;
  const Scene& scene = fixed_scene(data[0] & 1);
  std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    Verify_result r = verify_certificate(scene, parse_certificate(text));
    if (!r.ok && (r.exit_code < 1 || r.exit_code > 3)) {
      std::cerr << "verify answered exit " << r.exit_code << ": " << r.where << ": " << r.reason << "\n";
      std::abort();
    }
  } catch (const Cert_failure& e) {
    if (e.exit_code() != CLASH4D_VERIFY_UNREADABLE && e.exit_code() != CLASH4D_VERIFY_LIMIT) {
      std::cerr << "the certificate reader failed with exit " << e.exit_code() << ": " << e.what() << "\n";
      std::abort();
    }
  } catch (const std::exception& e) {
    std::cerr << "an exception escaped the certificate reader: " << e.what() << "\n";
    std::abort();
  }
  return 0;
}
