// `clash4d verify SCENE CERT` (issue 15): the independent certificate
// checker of verify/ on the command line (docs/certificate-format.md).
#ifndef CLASH4D_CLI_VERIFY_COMMAND_H
#define CLASH4D_CLI_VERIFY_COMMAND_H

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace CLI { class App; }

namespace clash4d {

// Exit 0 printing the claim proved; 1 with the first failure and its JSON
// path; 2 when the scene or the certificate cannot be read; 3 when the
// certificate is larger than certificate_max_mb (MiB), left unread.
// mesh_folders: where the scene's mesh files may be besides its folder
// (--allow-mesh-path, docs/meshes.md).
int run_verify(const std::string& scene_file, const std::string& cert_file, double certificate_max_mb,
               std::ostream& out, std::ostream& err, const std::vector<std::string>& mesh_folders = {});

// Registers the subcommand; the function runs it when it was the one given
// (else returns -1), as every command of cli/Commands.cpp.
std::function<int()> add_verify(CLI::App& app, std::ostream& out, std::ostream& err);

} // namespace clash4d

#endif
