#include "compare/Subject_processes.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <mutex>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#include <sys/syscall.h>
#endif

extern char** environ;

namespace clash4d::subject_processes {
namespace {

// The live leaders, readable from a signal handler (no lock, no allocation).
constexpr int max_leaders = 1024;
std::atomic<pid_t> leaders[max_leaders];
std::atomic<bool> ending{false};   // a signal is ending clash4d: start no subject
// Fork and register as one step, so a sweep never takes a leader not yet
// registered for an orphan; sweeps outside signal handlers hold it too.
std::mutex fork_mutex;

void remember(pid_t leader)
{
  for (auto& slot : leaders) {
    pid_t none = 0;
    if (slot.compare_exchange_strong(none, leader)) return;
  }
}

void forget(pid_t leader)
{
  for (auto& slot : leaders) {
    pid_t it = leader;
    if (slot.compare_exchange_strong(it, 0)) return;
  }
}

bool is_leader(pid_t pid)
{
  for (const auto& slot : leaders)
    if (slot.load() == pid) return true;
  return false;
}

void pause_ms(long ms)
{
  struct timespec t {0, ms * 1000000L};
  while (::nanosleep(&t, &t) != 0 && errno == EINTR) {}
}

void reap(pid_t pid, int* status)
{
  while (::waitpid(pid, status, 0) < 0 && errno == EINTR) {}
}

#ifdef __linux__
// "CLASH4D_SUBJECT_OF=<pid>", written without allocating.
std::size_t mark_text(pid_t pid, char* out)
{
  const char prefix[] = "CLASH4D_SUBJECT_OF=";
  std::size_t n = sizeof prefix - 1;
  std::memcpy(out, prefix, n);
  char digits[24];
  int k = 0;
  for (long v = pid; v > 0 || k == 0; v /= 10) digits[k++] = char('0' + v % 10);
  while (k > 0) out[n++] = digits[--k];
  out[n] = '\0';
  return n;
}

// /proc/PID/NAME read into buf (at most size - 1 bytes, NUL-terminated);
// its length, or -1.
long read_proc(const char* pid, const char* name, char* buf, std::size_t size)
{
  char path[64] = "/proc/";
  std::size_t n = 6;
  for (const char* c = pid; *c && n < 40; ++c) path[n++] = *c;
  path[n++] = '/';
  for (const char* c = name; *c && n < 62; ++c) path[n++] = *c;
  path[n] = '\0';
  int fd = ::open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) return -1;
  long total = 0;
  for (ssize_t got; total + 1 < long(size) && (got = ::read(fd, buf + total, size - 1 - total)) != 0;) {
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) break;
    total += got;
  }
  ::close(fd);
  buf[total] = '\0';
  return total;
}

// The state letter and parent of /proc/PID/stat ("pid (name) S ppid ...").
bool stat_of(const char* pid, char& state, long& parent)
{
  char buf[512];
  if (read_proc(pid, "stat", buf, sizeof buf) <= 0) return false;
  const char* close = std::strrchr(buf, ')');
  if (!close || close[1] != ' ' || !close[2]) return false;
  state = close[2];
  parent = 0;
  for (const char* c = close + 4; *c >= '0' && *c <= '9'; ++c) parent = parent * 10 + (*c - '0');
  return true;
}

// Whether the process's environment holds this run's mark (read in
// pieces: no buffer is large enough for every environment).
bool marked(const char* pid, const char* mark, std::size_t mark_size)
{
  char path[48] = "/proc/";
  std::size_t k = 6;
  for (const char* c = pid; *c && k < 30; ++c) path[k++] = *c;
  std::memcpy(path + k, "/environ", 9);
  int fd = ::open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  char buf[4096];
  std::size_t matched = 0;
  bool alive = true;   // the entry read so far is a prefix of the mark
  bool found = false;
  for (ssize_t n; !found && (n = ::read(fd, buf, sizeof buf)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    for (ssize_t i = 0; i < n && !found; ++i) {
      if (buf[i] == '\0') {
        found = alive && matched == mark_size;
        matched = 0;
        alive = true;
      } else if (alive && matched < mark_size && buf[i] == mark[matched]) {
        ++matched;
      } else {
        alive = false;
      }
    }
  }
  ::close(fd);
  return found;
}

// Kills and reaps this process's children that are a subject's leftovers:
// zombies and marked processes that are no live leader. How many it found.
int sweep_once()
{
  int fd = ::open("/proc", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return 0;
  char mark[48];
  std::size_t mark_size = mark_text(::getpid(), mark);
  long me = ::getpid();
  int found = 0;
  alignas(8) char buf[8192];
  for (long n; (n = ::syscall(SYS_getdents64, fd, buf, sizeof buf)) > 0;) {
    for (long at = 0; at < n;) {
      const char* name = buf + at + 19;   // linux_dirent64: ino 8, off 8, reclen 2, type 1, name
      unsigned short length;
      std::memcpy(&length, buf + at + 16, sizeof length);
      at += length;
      if (*name < '1' || *name > '9') continue;
      char state;
      long parent;
      if (!stat_of(name, state, parent) || parent != me) continue;
      pid_t pid = 0;
      for (const char* c = name; *c; ++c) pid = pid * 10 + (*c - '0');
      if (is_leader(pid)) continue;
      if (state != 'Z' && !marked(name, mark, mark_size)) continue;
      ++found;
      ::kill(-pid, SIGKILL);   // its group, when it made one (setsid)
      ::kill(pid, SIGKILL);
      reap(pid, nullptr);
    }
  }
  ::close(fd);
  return found;
}

// Sweeps until the group is empty and nothing more came back (at most about
// a second: a descendant re-parented here arrives once its parent is dead).
void sweep(pid_t group)
{
  for (int pass = 0; pass < 1000; ++pass) {
    bool group_left = group > 0 && ::kill(-group, 0) == 0;
    if (sweep_once() == 0 && !group_left) return;
    pause_ms(1);
  }
}

// SIGTERM, SIGINT, SIGHUP: every subject and what it started is killed,
// then the signal ends clash4d as it would have.
void on_signal(int sig)
{
  int saved = errno;
  ending = true;
  for (const auto& slot : leaders)
    if (pid_t p = slot.load()) ::kill(-p, SIGKILL);
  for (const auto& slot : leaders)
    if (pid_t p = slot.load()) ::waitpid(p, nullptr, 0);
  sweep(0);
  ::signal(sig, SIG_DFL);
  ::raise(sig);   // delivered once the handler returns
  errno = saved;
}

// Whether keep_descendants() made this process their keeper.
std::atomic<bool> keeper{false};

// Once: the subreaper and the signal handlers (only over the default
// action: an ignored signal stays ignored).
void guard()
{
  static std::once_flag once;
  std::call_once(once, [] {
    keeper = true;
    ::prctl(PR_SET_CHILD_SUBREAPER, 1);
    for (int sig : {SIGTERM, SIGINT, SIGHUP}) {
      struct sigaction old {}, sa {};
      if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL || (old.sa_flags & SA_SIGINFO)) continue;
      sa.sa_handler = on_signal;
      sigfillset(&sa.sa_mask);
      ::sigaction(sig, &sa, nullptr);
    }
  });
}
#else
void guard() {}
#endif

// In the child, before exec: only async-signal-safe calls.
[[noreturn]] void become_subject(const char* const* argv, char* const* envp, pid_t parent, int in, int out)
{
  ::setpgid(0, 0);
#ifdef __linux__
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(127);   // clash4d died before the line above
#endif
  struct sigaction sa {};
  sa.sa_handler = SIG_DFL;
  for (int sig : {SIGPIPE, SIGTERM, SIGINT, SIGHUP}) ::sigaction(sig, &sa, nullptr);
  sigset_t none;
  sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  ::dup2(in, 0);
  ::dup2(out, 1);
  ::execve("/bin/sh", const_cast<char* const*>(argv), envp);
  ::_exit(127);
}

} // namespace

void keep_descendants() { guard(); }

pid_t start(const std::string& command, int in, int out)
{
  // Everything the child needs, made before fork: it may not allocate.
  pid_t parent = ::getpid();
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "CLASH4D_SUBJECT_OF=", 19) != 0) env.emplace_back(*e);
  env.insert(env.begin(), "CLASH4D_SUBJECT_OF=" + std::to_string(parent));
  std::vector<char*> envp;
  for (auto& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  const char* argv[] = {"sh", "-c", command.c_str(), nullptr};

  std::lock_guard<std::mutex> lock(fork_mutex);
  if (ending) return errno = ECANCELED, -1;
  pid_t pid = ::fork();
  if (pid == 0) become_subject(argv, envp.data(), parent, in, out);
  if (pid > 0) {
    ::setpgid(pid, pid);   // also here: whichever runs first
    remember(pid);
  }
  return pid;
}

void end(pid_t leader, bool reaped, int& status)
{
  ::kill(-leader, SIGKILL);   // its process group: a shell's children, whatever it left running
  if (!reaped) reap(leader, &status);
  std::lock_guard<std::mutex> lock(fork_mutex);
  forget(leader);
#ifdef __linux__
  if (keeper) sweep(leader);   // a library in another program reaps none of its children
#endif
}

} // namespace clash4d::subject_processes
