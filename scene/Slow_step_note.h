// Standard error's note of a step that turns out slow (a mesh's convex
// decomposition; issue 58: progress on a terminal and in logs). On a
// terminal: after a second, "TEXT...", then the seconds it took when it ends.
// In a log or a pipe: a line after 10 s and every 30 s, and one when it ends.
// Nothing for a quick step. scene/ has its own (compare/'s
// Progress_line is above it: dependencies go one way).
#ifndef CLASH4D_SCENE_SLOW_STEP_NOTE_H
#define CLASH4D_SCENE_SLOW_STEP_NOTE_H

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace clash4d {

class Slow_step_note {
public:
  // When lines are written: on a terminal after `terminal_after`; in a log
  // after `log_after`, then every `log_every`.
  struct Delays {
    std::chrono::milliseconds terminal_after{1000}, log_after{10000}, log_every{30000};
  };

  explicit Slow_step_note(std::string text) : Slow_step_note(std::move(text), Delays{}) {}
  Slow_step_note(std::string text, Delays delays);
  Slow_step_note(const Slow_step_note&) = delete;
  Slow_step_note& operator=(const Slow_step_note&) = delete;
  ~Slow_step_note();   // ends the line if it was begun

private:
  void note_on_terminal();
  void note_in_log();
  double seconds() const;

  std::string text_;
  Delays delays_;
  bool terminal_;   // standard error is a terminal, else a log
  std::chrono::steady_clock::time_point began_ = std::chrono::steady_clock::now();
  std::mutex mutex_;
  std::condition_variable done_changed_;
  bool done_ = false, shown_ = false;
  std::thread waiter_;
};

} // namespace clash4d

#endif
