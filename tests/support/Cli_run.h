// Runs the clash4d command line in-process, as a user would type it.
#ifndef CLASH4D_TESTS_SUPPORT_CLI_RUN_H
#define CLASH4D_TESTS_SUPPORT_CLI_RUN_H

#include "cli/Commands.h"
#include <sstream>
#include <string>
#include <vector>

namespace clash4d {

struct Cli_run {
  int status;
  std::string out, err;
};

// args without the program name: {"check", "scene.json", "--json"}.
inline Cli_run run_clash4d(std::vector<std::string> args)
{
  args.insert(args.begin(), "clash4d");
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  int status = run_cli(static_cast<int>(argv.size()), argv.data(), out, err);
  return {status, out.str(), err.str()};
}

} // namespace clash4d

#endif
