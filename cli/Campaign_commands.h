// The commands that run many comparisons: fuzz (and its merge) and report.
#ifndef CLASH4D_CLI_CAMPAIGN_COMMANDS_H
#define CLASH4D_CLI_CAMPAIGN_COMMANDS_H

#include "compare/Fuzz_campaign.h"
#include <iosfwd>
#include <string>
#include <vector>

namespace clash4d {

int fuzz_command(const Fuzz_options& options, std::ostream& out, std::ostream& err);
int merge_command(const std::vector<std::string>& dirs, const std::string& out_dir, std::ostream& out, std::ostream& err);
// INPUT: scene files, folders of scene files, or fuzz output folders.
int report_command(const std::vector<std::string>& inputs, const std::string& out_dir, const Compare_options& compare,
                   std::ostream& out, std::ostream& err);

} // namespace clash4d

#endif
