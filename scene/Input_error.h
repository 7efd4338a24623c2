// The one exception type for bad input: where, what, and which exit status.
#ifndef CLASH4D_SCENE_INPUT_ERROR_H
#define CLASH4D_SCENE_INPUT_ERROR_H

#include "scene/Printable.h"
#include <stdexcept>
#include <string>

namespace clash4d {

// Exit status 2 for invalid input, 3 for a resource limit (spec: check).
constexpr int CLASH4D_EXIT_INVALID = 2;
constexpr int CLASH4D_EXIT_LIMIT = 3;

// Its place and message are printable (scene/Printable.h): a name or token
// quoted from the file can neither cut the message at a NUL nor break the
// one line of an error (spec: check, exit status 2).
class Input_error : public std::runtime_error {
public:
  Input_error(const std::string& place, const std::string& message, int exit_code = CLASH4D_EXIT_INVALID)
    : std::runtime_error(printable(message)), place_(printable(place)), exit_code_(exit_code) {}
  const std::string& place() const { return place_; }
  int exit_code() const { return exit_code_; }
  // "file: place: message", the form every command prints.
  std::string format(const std::string& file) const
  {
    return file + ": " + (place_.empty() ? "" : place_ + ": ") + what();
  }
private:
  std::string place_;
  int exit_code_;
};

} // namespace clash4d

#endif
