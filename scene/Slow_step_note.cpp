#include "scene/Slow_step_note.h"

#include <cstdio>
#include <unistd.h>

namespace clash4d {

Slow_step_note::Slow_step_note(std::string text, Delays delays)
  : text_(std::move(text)), delays_(delays), terminal_(isatty(STDERR_FILENO) != 0)
{
  // A waiter, so that the lines appear while the step runs, not after.
  waiter_ = std::thread([this] { terminal_ ? note_on_terminal() : note_in_log(); });
}

void Slow_step_note::note_on_terminal()
{
  std::unique_lock<std::mutex> lock(mutex_);
  if (done_changed_.wait_for(lock, delays_.terminal_after, [this] { return done_; })) return;
  std::fprintf(stderr, "%s...", text_.c_str());
  std::fflush(stderr);
  shown_ = true;
}

// A log (a pipe, a batch job's file) gets whole lines: one after 10 s, then
// one every 30 s, so that a job that seems stuck says what it is doing.
void Slow_step_note::note_in_log()
{
  std::unique_lock<std::mutex> lock(mutex_);
  auto wait = delays_.log_after;
  while (!done_changed_.wait_for(lock, wait, [this] { return done_; })) {
    std::fprintf(stderr, "clash4d: %s: %.0f s so far\n", text_.c_str(), seconds());
    std::fflush(stderr);
    shown_ = true;
    wait = delays_.log_every;
  }
}

double Slow_step_note::seconds() const
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count();
}

Slow_step_note::~Slow_step_note()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  done_changed_.notify_one();
  waiter_.join();
  if (!shown_) return;
  if (terminal_)
    std::fprintf(stderr, " %.1f s\n", seconds());
  else
    std::fprintf(stderr, "clash4d: %s: done in %.1f s\n", text_.c_str(), seconds());
  std::fflush(stderr);
}

} // namespace clash4d
