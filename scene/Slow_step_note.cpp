#include "scene/Slow_step_note.h"

#include <cstdio>
#include <unistd.h>

namespace clash4d {

Slow_step_note::Slow_step_note(std::string text) : text_(std::move(text))
{
  if (isatty(STDERR_FILENO) == 0) return;
  // A waiter, so that the line appears while the step runs, not after.
  waiter_ = std::thread([this] {
    std::unique_lock<std::mutex> lock(mutex_);
    if (done_changed_.wait_for(lock, std::chrono::seconds(1), [this] { return done_; })) return;
    std::fprintf(stderr, "%s...", text_.c_str());
    std::fflush(stderr);
    shown_ = true;
  });
}

Slow_step_note::~Slow_step_note()
{
  if (!waiter_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  done_changed_.notify_one();
  waiter_.join();
  if (!shown_) return;
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count();
  std::fprintf(stderr, " %.1f s\n", seconds);
  std::fflush(stderr);
}

} // namespace clash4d
