#include "compare/Progress_line.h"

#include <cstdio>
#include <unistd.h>

namespace clash4d {

Progress_mode progress_mode_of_stderr()
{
  return isatty(fileno(stderr)) != 0 ? Progress_mode::terminal : Progress_mode::log;
}

void Progress_line::show(const std::string& text, bool last)
{
  auto now = clock::now();
  if (mode_ == Progress_mode::none || (mode_ == Progress_mode::log && !last && now - shown_ < std::chrono::seconds(10)))
    return;
  shown_ = now;
  shown_any_ = true;
  if (mode_ == Progress_mode::log) {
    err_ << command_ << ": " << text << "\n" << std::flush;
    return;
  }
  std::string line = text.size() < width_ ? text + std::string(width_ - text.size(), ' ') : text;
  width_ = text.size();
  err_ << "\r" << line << std::flush;
}

void Progress_line::clear()
{
  if (mode_ != Progress_mode::terminal || width_ == 0) return;
  err_ << "\r" << std::string(width_, ' ') << "\r" << std::flush;
  width_ = 0;
  shown_any_ = false;
}

Progress_line::~Progress_line()
{
  if (mode_ == Progress_mode::terminal && shown_any_) err_ << "\n" << std::flush;
}

} // namespace clash4d
