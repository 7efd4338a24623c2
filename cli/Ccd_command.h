// `clash4d ccd FILE...`: exact answers to the standard CCD queries,
// vertex-face and edge-edge under linear vertex motion (docs/ccd-queries.md).
#ifndef CLASH4D_CLI_CCD_COMMAND_H
#define CLASH4D_CLI_CCD_COMMAND_H

#include <functional>
#include <iosfwd>

namespace CLI { class App; }

namespace clash4d {

// Registers the subcommand; the function runs it when it was the one given
// (else returns -1), as every command of cli/Commands.cpp.
std::function<int()> add_ccd(CLI::App& app, std::ostream& out, std::ostream& err);

} // namespace clash4d

#endif
