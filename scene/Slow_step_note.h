// One line on standard error for a step that turns out slow (a mesh's
// convex decomposition): after a second, "TEXT..." when standard error is a
// terminal, then the seconds it took when it ends. Nothing in a log or a
// pipe, and nothing for a quick step. scene/ has its own (compare/'s
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
  explicit Slow_step_note(std::string text);
  Slow_step_note(const Slow_step_note&) = delete;
  Slow_step_note& operator=(const Slow_step_note&) = delete;
  ~Slow_step_note();   // ends the line if it was begun

private:
  std::string text_;
  std::chrono::steady_clock::time_point began_ = std::chrono::steady_clock::now();
  std::mutex mutex_;
  std::condition_variable done_changed_;
  bool done_ = false, shown_ = false;
  std::thread waiter_;   // only on a terminal
};

} // namespace clash4d

#endif
