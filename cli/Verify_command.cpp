#include "cli/Verify_command.h"
#include "scene/Input_error.h"
#include "scene/Scene_reader.h"
#include "verify/Certificate_checker.h"

#include <CLI/CLI.hpp>
#include <fstream>
#include <memory>
#include <ostream>

namespace clash4d {

using namespace verifier;

int run_verify(const std::string& scene_file, const std::string& cert_file, std::ostream& out, std::ostream& err)
{
  Scene scene;
  try {
    scene = read_scene_file(scene_file);
  } catch (const Input_error& e) {   // a scene beyond the reader's limits cannot be read either
    err << "clash4d verify: " << e.format(scene_file) << "\n";
    return CLASH4D_VERIFY_UNREADABLE;
  } catch (const std::exception& e) {
    err << "clash4d verify: " << scene_file << ": " << e.what() << "\n";
    return CLASH4D_VERIFY_UNREADABLE;
  }
  Json cert;
  try {
    std::ifstream in(cert_file, std::ios::binary);
    if (!in) {
      err << "clash4d verify: " << cert_file << ": cannot open the certificate\n";
      return CLASH4D_VERIFY_UNREADABLE;
    }
    cert = Json::parse(in);
  } catch (const std::exception& e) {   // bad JSON, a file cut short: the parser says where
    err << "clash4d verify: " << cert_file << ": " << e.what() << "\n";
    return CLASH4D_VERIFY_UNREADABLE;
  }
  Verify_result r = verify_certificate(scene, cert);
  if (r.ok) {
    out << r.claim << "\n";
    return 0;
  }
  err << "clash4d verify: " << cert_file << ": " << (r.where.empty() ? "" : r.where + ": ") << r.reason << "\n";
  return r.exit_code;
}

std::function<int()> add_verify(CLI::App& app, std::ostream& out, std::ostream& err)
{
  auto files = std::make_shared<std::pair<std::string, std::string>>();
  CLI::App* cmd = app.add_subcommand("verify", "Check a certificate written by check --certificate against the scene, "
                                               "independently of the decision (docs/certificate-format.md); exit 0 "
                                               "when it proves its claim, 1 when not, 2 on unreadable input.");
  cmd->add_option("SCENE", files->first, "scene file")->required();
  cmd->add_option("CERT", files->second, "certificate file")->required();
  return [cmd, files, &out, &err] { return cmd->parsed() ? run_verify(files->first, files->second, out, err) : -1; };
}

} // namespace clash4d
