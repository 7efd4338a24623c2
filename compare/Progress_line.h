// Progress of a long command on standard error (issue 60: compare, report
// and fuzz show progress on a terminal and in logs): on a terminal one line
// rewritten in place; in a log (a Slurm job's, a pipe) a line of its own at
// most every ten seconds, and always the last.
#ifndef CLASH4D_COMPARE_PROGRESS_LINE_H
#define CLASH4D_COMPARE_PROGRESS_LINE_H

#include <chrono>
#include <ostream>
#include <string>

namespace clash4d {

enum class Progress_mode { none, terminal, log };

// Where standard error goes: a terminal, or a log.
Progress_mode progress_mode_of_stderr();

class Progress_line {
public:
  // `command` prefixes each log line ("clash4d fuzz").
  Progress_line(Progress_mode mode, std::ostream& err, std::string command)
    : mode_(mode), err_(err), command_(std::move(command))
  {}
  Progress_line(const Progress_line&) = delete;
  Progress_line& operator=(const Progress_line&) = delete;
  ~Progress_line();

  void show(const std::string& text, bool last = false);
  // Blanks the terminal's line, so that what is printed next starts clean.
  void clear();
  double seconds() const { return std::chrono::duration<double>(clock::now() - began_).count(); }

private:
  using clock = std::chrono::steady_clock;
  Progress_mode mode_;
  std::ostream& err_;
  std::string command_;
  std::size_t width_ = 0;   // of the line on the terminal, to blank what a shorter one leaves
  bool shown_any_ = false;
  clock::time_point began_ = clock::now(), shown_ = began_;
};

} // namespace clash4d

#endif
