#include "scene/Child_process.h"
#include "scene/Input_error.h"

#include <cerrno>
#include <csignal>
#include <new>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace clash4d {
namespace {

// The child's report on the pipe: a status line, then what it says.
//   "ok\n" TEXT | "input CODE\n" PLACE "\n" MESSAGE | "memory\n" | "error\n" WHAT
void write_all(int fd, const std::string& s)
{
  for (std::size_t done = 0; done < s.size();) {
    ssize_t n = ::write(fd, s.data() + done, s.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;   // the parent stopped listening: nobody to tell
    done += static_cast<std::size_t>(n);
  }
}

[[noreturn]] void be_the_child(int fd, const std::function<std::string()>& work)
{
  std::string report;
  try {
    report = "ok\n" + work();
  } catch (const Input_error& e) {
    report = "input " + std::to_string(e.exit_code()) + "\n" + e.place() + "\n" + e.what();
  } catch (const std::bad_alloc&) {
    report = "memory\n";
  } catch (const std::exception& e) {
    report = std::string("error\n") + e.what();
  } catch (...) {
    report = "error\nan exception that is not a std::exception";
  }
  write_all(fd, report);
  ::_exit(0);   // no destructor, atexit handler or stream flush of the parent's state
}

// The parent's hold on the child: killed and reaped unless it ended.
struct Child {
  pid_t pid;
  int fd;
  Child(pid_t p, int f) : pid(p), fd(f) {}
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  ~Child()
  {
    if (fd >= 0) ::close(fd);
    if (pid > 0) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, nullptr, 0);
    }
  }
};

// The report read to its end, poll() called every 50 ms meanwhile.
std::string report_of(Child& child, const std::function<void()>& poll, const std::string& place)
{
  std::string report;
  char buffer[1 << 16];
  for (;;) {
    pollfd p{child.fd, POLLIN, 0};
    int ready = ::poll(&p, 1, 50);
    if (ready < 0 && errno != EINTR) throw Input_error(place, "internal error: poll failed on the child's pipe", 4);
    if (ready > 0) {
      ssize_t n = ::read(child.fd, buffer, sizeof buffer);
      if (n == 0) break;
      if (n > 0) report.append(buffer, static_cast<std::size_t>(n));
      else if (errno != EINTR) throw Input_error(place, "internal error: reading the child's pipe failed", 4);
    }
    poll();
  }
  int status = 0;
  ::waitpid(child.pid, &status, 0);
  child.pid = -1;
  if (WIFSIGNALED(status))
    throw Input_error(place, "internal error: the process making the solid ended by signal " +
                                 std::to_string(WTERMSIG(status)) + " (out of memory?)", 4);
  return report;
}

} // namespace

std::string text_of_child(const std::function<std::string()>& work, const std::function<void()>& poll,
                          const std::string& place)
{
  int fds[2];
  if (::pipe(fds) != 0) throw Input_error(place, "internal error: no pipe for the child process", 4);
  pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    be_the_child(fds[1], work);
  }
  ::close(fds[1]);
  if (pid < 0) {
    ::close(fds[0]);
    throw Input_error(place, "internal error: no child process could be made", 4);
  }
  Child child(pid, fds[0]);
  std::string report = report_of(child, poll, place);
  std::size_t eol = report.find('\n');
  std::string status = report.substr(0, eol), rest = eol == std::string::npos ? "" : report.substr(eol + 1);
  if (status == "ok") return rest;
  if (status == "memory") throw std::bad_alloc();
  if (status.rfind("input ", 0) == 0) {
    std::size_t cut = rest.find('\n');
    int code = std::stoi(status.substr(6));
    throw Input_error(rest.substr(0, cut), cut == std::string::npos ? "" : rest.substr(cut + 1), code);
  }
  throw Input_error(place, "internal error making the solid: " + (status == "error" ? rest : "no report"), 4);
}

} // namespace clash4d
