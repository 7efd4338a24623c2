// The commands that run many comparisons: fuzz (and its merge) and report.
#ifndef CLASH4D_CLI_CAMPAIGN_COMMANDS_H
#define CLASH4D_CLI_CAMPAIGN_COMMANDS_H

#include "compare/Ccd_fuzz_campaign.h"
#include "compare/Fuzz_campaign.h"
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace clash4d {

// --subject NAME=COMMAND (repeatable) and --subject-timeout, shared by
// compare, fuzz and report.
struct Subject_args {
  std::vector<std::string> subjects;
  double timeout_seconds = 10;
};
void add_subject_options(CLI::App& command, Subject_args& args);
// Adds the subjects to o (external processes; "fcl" is the built-in FCL
// subject, as --fcl); false after a message naming the argument when one is wrong.
bool apply_subject_args(const Subject_args& args, Compare_options& o, const char* command, std::ostream& err);

// --type vf|ee (CSV files whose path names no type) and --time-bound, for
// the CCD query files of compare and report.
// The built-in subjects a comparison of scenes runs (compare, fuzz, report):
// the double subjects, exact-rounded and fcl.
struct Builtin_subject_args {
  std::vector<double> tolerances;
  bool fcl = false, no_rounded = false, no_doubles = false;
};
void add_builtin_subject_options(CLI::App& command, Builtin_subject_args& args);
void apply_builtin_subject_args(const Builtin_subject_args& args, Compare_options& o);

struct Ccd_compare_args {
  std::string type;
  double time_bound = 1e-9;
};
void add_ccd_options(CLI::App& command, Ccd_compare_args& args);
// The options of CCD queries from the scenes' (tolerances, earliest and
// external subjects are shared) and the CCD arguments.
Ccd_compare_options ccd_options_of(const Compare_options& o, const Ccd_compare_args& args);
std::optional<Ccd_type> ccd_type_of(const Ccd_compare_args& args);

// Which shard this process runs: --shard K/S when given; else, under a
// scheduler, K from SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN + 1 or
// JOB_COMPLETION_INDEX + 1 and S from --shard-count (Slurm: or
// SLURM_ARRAY_TASK_COUNT); else 1/1 (docs/campaigns.md). `env` reads a
// variable (std::getenv; tests pass their own). False after a message.
bool resolve_shard(const std::string& shard, std::uint64_t shard_count, const std::function<const char*(const char*)>& env,
                   Campaign_options& o, std::ostream& err);

int fuzz_command(const Fuzz_options& options, std::ostream& out, std::ostream& err);
int fuzz_command(const Ccd_fuzz_options& options, std::ostream& out, std::ostream& err);
int merge_command(const std::vector<std::string>& dirs, const std::string& out_dir, std::ostream& out, std::ostream& err);

// What report compares: its INPUTs (scene files, CCD query files, folders
// of them, or fuzz output folders) and the options for each kind.
struct Report_inputs {
  std::vector<std::string> paths;
  Compare_options scenes;
  Ccd_compare_options queries;
  std::optional<Ccd_type> type;   // --type
  std::vector<std::string> mesh_folders;   // --allow-mesh-path (docs/meshes.md)
  bool fresh = false;                      // --fresh: compare again what DIR/cases keeps (compare/Report_cache.h)
  Progress_mode progress = Progress_mode::none;
};
int report_command(const Report_inputs& inputs, const std::string& out_dir, std::ostream& out, std::ostream& err);

} // namespace clash4d

#endif
