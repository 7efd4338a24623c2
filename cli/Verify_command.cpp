#include "cli/Verify_command.h"
#include "scene/Input_error.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include "verify/Certificate_checker.h"

#include <CLI/CLI.hpp>
#include <memory>
#include <ostream>

namespace clash4d {

using namespace verifier;

// The certificate's text, within max_mb (exit 3 beyond it: a certificate
// takes 10 to 16 times its size in memory as JSON), or the exit status.
static int read_certificate(const std::string& cert_file, double max_mb, Json& cert, std::ostream& err)
{
  try {
    cert = parse_certificate(read_file_text(cert_file, static_cast<std::size_t>(max_mb * 1048576.0)));
  } catch (const Cert_failure& e) {   // section 1's reading rules, at their place
    err << "clash4d verify: " << cert_file << ": " << e.where() << ": " << e.what() << "\n";
    return e.exit_code();
  } catch (const Input_error& e) {
    err << "clash4d verify: " << cert_file << ": "
        << (e.exit_code() == CLASH4D_EXIT_LIMIT ? std::string(e.what()) + " (--certificate-max-mb)" : e.what()) << "\n";
    return e.exit_code() == CLASH4D_EXIT_LIMIT ? CLASH4D_EXIT_LIMIT : CLASH4D_VERIFY_UNREADABLE;
  } catch (const std::bad_alloc&) {
    err << "clash4d verify: " << cert_file << ": out of memory reading the certificate\n";
    return CLASH4D_VERIFY_LIMIT;
  }
  return 0;
}

int run_verify(const std::string& scene_file, const std::string& cert_file, double certificate_max_mb,
               std::ostream& out, std::ostream& err, const std::vector<std::string>& mesh_folders)
{
  Scene scene;
  try {
    scene = read_scene_file(scene_file, mesh_folders);
  } catch (const Input_error& e) {   // a scene beyond the reader's limits cannot be read either
    err << "clash4d verify: " << e.format(scene_file) << "\n";
    return CLASH4D_VERIFY_UNREADABLE;
  } catch (const std::exception& e) {
    err << "clash4d verify: " << scene_file << ": " << e.what() << "\n";
    return CLASH4D_VERIFY_UNREADABLE;
  }
  Json cert;
  if (int status = read_certificate(cert_file, certificate_max_mb, cert, err)) return status;
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
  struct Args {
    std::string scene, certificate;
    double certificate_max_mb = 256;
    std::vector<std::string> mesh_folders;
  };
  auto a = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("verify", "Check a certificate written by check --certificate against the scene, "
                                               "independently of the decision (docs/certificate-format.md); exit 0 "
                                               "when it proves its claim, 1 when not, 2 on unreadable input, 3 "
                                               "when the certificate is larger than --certificate-max-mb.");
  cmd->add_option("SCENE", a->scene, "scene file")->required();
  cmd->add_option("CERT", a->certificate, "certificate file")->required();
  cmd->add_option("--certificate-max-mb", a->certificate_max_mb,
                  "refuse (exit 3) a certificate larger than this, unread (default 256, as check writes)")
      ->check(CLI::PositiveNumber)->check(CLI::Range(0.0, 1048576.0));
  cmd->add_option("--allow-mesh-path", a->mesh_folders,
                  "let the scene's mesh files be under DIR too (repeatable; docs/meshes.md)")
      ->type_name("DIR")->allow_extra_args(false)->check(CLI::ExistingDirectory.description(""));
  return [cmd, a, &out, &err] {
    return cmd->parsed() ? run_verify(a->scene, a->certificate, a->certificate_max_mb, out, err, a->mesh_folders) : -1;
  };
}

} // namespace clash4d
