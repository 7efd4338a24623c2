// The `clash4d` command line: every command (run_cli), its options and its
// output; exit status as ../shared/spec/scene-format.md says.
#ifndef CLASH4D_CLI_COMMANDS_H
#define CLASH4D_CLI_COMMANDS_H

#include <iosfwd>

namespace clash4d {

// Runs the tool as `clash4d ARGS`; returns the exit status. Output goes to
// out and err so tests can run commands in-process.
int run_cli(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

} // namespace clash4d

#endif
