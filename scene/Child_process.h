// A step that cannot look at the work budget (run/Work_budget.h) itself,
// run in a child process that can be stopped from outside: CGAL's Nef
// convex decomposition (scene/Mesh_solid.h) has no place to stop, and on a
// real part it takes minutes (issue 58 item 3: --max-seconds and the API's
// cancel flag must cover it). The child shares nothing with the run but
// the text it returns, so stopping it loses nothing and leaks nothing.
#ifndef CLASH4D_SCENE_CHILD_PROCESS_H
#define CLASH4D_SCENE_CHILD_PROCESS_H

#include <functional>
#include <string>

namespace clash4d {

// work() in a forked child; its text, or its Input_error rethrown here
// (place, message, exit code), or Input_error(place, "internal error ...",
// 4) for any other failure of the child; std::bad_alloc as such.
// Every 50 ms of waiting, poll() is called: when it throws, the child is
// killed and reaped, and the exception goes on.
// The caller starts no thread just before: a thread still starting when
// fork() copies the process can hold the allocator's lock, and the child
// then waits on it for ever (AddressSanitizer's allocator has no fork
// handler; stop 71's CI hung so). Start such a thread in poll() instead.
std::string text_of_child(const std::function<std::string()>& work, const std::function<void()>& poll,
                          const std::string& place);

} // namespace clash4d

#endif
