#include "compare/External_subject.h"
#include "compare/Ccd_query_files.h"
#include "compare/Subject_processes.h"
#include "scene/Input_error.h"
#include "scene/Json_reader.h"
#include "scene/Number_text.h"
#include "scene/Scene_writer.h"
#include "run/Work_budget.h"

#include <chrono>
#include <cstdio>
#include <csignal>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace clash4d {
namespace {

using Clock = std::chrono::steady_clock;
using Json_kind = Json_value::Kind;

constexpr std::size_t max_line_bytes = 64u << 20;
constexpr double grace_seconds = 2;   // for a subject to exit once its input is closed
// Waits are cut in slices this long, to look at the run's budget and at
// whether the subject has exited between them.
constexpr int slice_ms = 50;

// A write to a subject that died must be an error we report, not a SIGPIPE
// that ends clash4d: ignored once for the process (children get it back).
void ignore_sigpipe()
{
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction sa {};
    sa.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &sa, nullptr);
  });
}

int remaining_ms(Clock::time_point deadline)
{
  auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return ms < 0 ? 0 : static_cast<int>(std::min<long long>(ms, 1 << 30));
}

Clock::time_point after(double seconds)
{
  return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

int slice(Clock::time_point deadline) { return std::min(remaining_ms(deadline), slice_ms); }

bool within_budget()
{
  try {
    Work_budget::check();
    return true;
  } catch (const Budget_exceeded&) {
    return false;
  }
}

std::string seconds_text(double seconds)
{
  char text[32];
  std::snprintf(text, sizeof text, "%g", seconds);
  return text;
}

// The keys of an object must be among `allowed`.
std::string unknown_key(const Json_value& v, std::initializer_list<const char*> allowed)
{
  for (const auto& m : v.members) {
    bool known = false;
    for (const char* a : allowed) known = known || m.first == a;
    if (!known) return m.first;
  }
  return "";
}

// A number of the answer, read exactly from its text (JSON number or string).
std::optional<std::string> exact_text(const Json_value& v)
{
  if (v.kind != Json_kind::Number && v.kind != Json_kind::String) return std::nullopt;
  Number_parse p = parse_number_text(v.text, v.kind == Json_kind::String);
  if (!p.ok) return std::nullopt;
  return to_string(p.value);
}

// Parses an answer line; on a protocol violation returns why in `problem`.
// A CCD answer has no witness (there is no scene point to check).
Subject_answer parse_answer(const std::string& line, long id, bool earliest, bool ccd, std::string& problem)
{
  Subject_answer a;
  Json_value v;
  try {
    v = read_json_text(line);
  } catch (const Input_error& e) {
    problem = std::string("the answer is not JSON (") + e.format("line") + ")";
    return a;
  }
  if (v.kind != Json_kind::Object) return problem = "the answer is not a JSON object", a;
  std::string extra = ccd ? unknown_key(v, {"id", "collide", "t", "unsupported"})
                          : unknown_key(v, {"id", "collide", "t", "witness", "unsupported"});
  if (!extra.empty()) return problem = "unknown key \"" + extra + "\" in the answer", a;
  const Json_value* got = v.find("id");
  if (!got || got->kind != Json_kind::Number || got->text != std::to_string(id))
    return problem = "the answer's id is not " + std::to_string(id), a;
  if (const Json_value* u = v.find("unsupported")) {
    if (u->kind != Json_kind::String || v.find("collide")) return problem = "\"unsupported\" must be a string, alone", a;
    a.kind = Subject_answer::Kind::Unsupported;
    a.why = u->text;
    return a;
  }
  const Json_value* c = v.find("collide");
  if (!c || c->kind != Json_kind::Boolean) return problem = "\"collide\" (true or false) is missing", a;
  a.collide = c->boolean;
  if (const Json_value* t = v.find("t")) {
    if (!(a.t = exact_text(*t))) return problem = "\"t\" is not a number", a;
  } else if (earliest && a.collide) {
    return problem = "\"t\" is missing (the request asked for the earliest time)", a;
  }
  if (const Json_value* w = v.find("witness")) {
    if (w->kind != Json_kind::Array || w->items.size() != 4) return problem = "\"witness\" must be 4 numbers", a;
    std::array<std::string, 4> p;
    for (int i = 0; i < 4; ++i) {
      std::optional<std::string> x = exact_text(w->items[i]);
      if (!x) return problem = "\"witness\" must be 4 numbers", a;
      p[i] = *x;
    }
    a.witness = p;
  }
  return a;
}

} // namespace

Subject_spec parse_subject_spec(const std::string& text, double timeout_seconds)
{
  auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw std::invalid_argument("--subject expects NAME=COMMAND, found '" + text + "'");
  std::string name = text.substr(0, eq);
  for (const char* taken : {"exact", "double", "exact-rounded", "fcl", "bullet"})
    if (name == taken) throw std::invalid_argument("--subject: the name '" + name + "' is a built-in subject's");
  if (name.rfind("double tol=", 0) == 0) throw std::invalid_argument("--subject: the name '" + name + "' is a built-in subject's");
  return {name, text.substr(eq + 1), timeout_seconds};
}

External_subject::External_subject(Subject_spec spec) : spec_(std::move(spec)) {}

// Past the run's budget there is no time to let it exit by itself.
External_subject::~External_subject() { stop(!within_budget()); }

Subject_answer External_subject::fault(const std::string& cause, const std::string& what)
{
  stop(true);
  Subject_answer a;
  a.kind = Subject_answer::Kind::Fault;
  a.fault = cause;
  a.why = what;
  return a;
}

std::string External_subject::exit_text()
{
  if (exit_status_ < 0) return "it closed its output";
  if (WIFSIGNALED(exit_status_)) return std::string("killed by signal ") + std::to_string(WTERMSIG(exit_status_)) + " (" + strsignal(WTERMSIG(exit_status_)) + ")";
  return "exited with status " + std::to_string(WEXITSTATUS(exit_status_));
}

void External_subject::close_input()
{
  if (to_child_ >= 0) ::close(to_child_);
  to_child_ = -1;
}

// Closes its input (spec: stdin closed when done); waits for it to exit,
// at most the grace time unless `kill_now`; then kills its process group
// and whatever it started (compare/Subject_processes.h).
void External_subject::stop(bool kill_now)
{
  close_input();
  if (pid_ > 0) {
    bool reaped = exit_status_ >= 0;
    for (auto deadline = after(kill_now ? 0 : grace_seconds); !reaped && Clock::now() < deadline; ::usleep(2000))
      reaped = ::waitpid(pid_, &exit_status_, WNOHANG) == pid_;
    subject_processes::end(pid_, reaped, exit_status_);
  }
  pid_ = -1;
  if (from_child_ >= 0) ::close(from_child_);
  from_child_ = -1;
  buffer_.clear();
}

Subject_answer External_subject::start()
{
  ignore_sigpipe();
  int in[2], out[2];
  if (::pipe2(in, O_CLOEXEC) != 0) return fault("crash", std::string("cannot make a pipe: ") + std::strerror(errno));
  if (::pipe2(out, O_CLOEXEC) != 0) {
    ::close(in[0]);
    ::close(in[1]);
    return fault("crash", std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  pid_t pid = subject_processes::start(spec_.command, in[0], out[1]);
  int started = errno;
  ::close(in[0]);
  ::close(out[1]);
  if (pid < 0) {
    ::close(in[1]);
    ::close(out[0]);
    return fault("crash", std::string("cannot start it: ") + std::strerror(started));
  }
  pid_ = pid;
  exit_status_ = -1;
  to_child_ = in[1];
  from_child_ = out[0];
  ::fcntl(to_child_, F_SETFL, ::fcntl(to_child_, F_GETFL) | O_NONBLOCK);
  return read_hello();
}

// The first line: {"subject": NAME, "semantics": "closed"|"regularised"[, "tolerance": EPS]}.
Subject_answer External_subject::read_hello()
{
  std::string line;
  Subject_answer got = read_line(line, spec_.timeout_seconds, true);
  if (got.kind == Subject_answer::Kind::Fault) return got;
  Json_value hello;
  try {
    hello = read_json_text(line);
  } catch (const Input_error& e) {
    return fault("protocol", "the hello line is not JSON (" + e.format("hello") + ")");
  }
  const Json_value* semantics = hello.kind == Json_kind::Object ? hello.find("semantics") : nullptr;
  const Json_value* name = hello.kind == Json_kind::Object ? hello.find("subject") : nullptr;
  if (!semantics || semantics->kind != Json_kind::String || (semantics->text != "closed" && semantics->text != "regularised") ||
      !name || name->kind != Json_kind::String || !unknown_key(hello, {"subject", "semantics", "tolerance"}).empty())
    return fault("protocol", "the hello line must be {\"subject\": NAME, \"semantics\": \"closed\" or \"regularised\"[, "
                             "\"tolerance\": EPS]}, found: " + line.substr(0, 200));
  semantics_ = semantics->text;
  tolerance_.reset();
  if (const Json_value* tol = hello.find("tolerance")) {
    if (tol->kind != Json_kind::Number) return fault("protocol", "the hello line's tolerance is not a number");
    tolerance_ = std::strtod(tol->text.c_str(), nullptr);   // shown only, never computed with
  }
  return Subject_answer();
}

// Why it ended: its exit status or signal when reaped, else that its
// output ended; "before its hello line" when it never said hello.
std::string External_subject::ended_text(bool hello)
{
  return exit_text() + (hello ? " before its hello line" : "");
}

// Cut in slices: past the run's budget it throws Budget_exceeded; once the
// subject has exited, or its output has ended, it says so at once, not at
// the time limit (a descendant may hold its output open after it died).
Subject_answer External_subject::read_line(std::string& line, double seconds, bool hello)
{
  auto deadline = after(seconds);
  for (;;) {
    auto nl = buffer_.find('\n');
    if (nl != std::string::npos) {
      line = buffer_.substr(0, nl);
      buffer_.erase(0, nl + 1);
      return Subject_answer();
    }
    if (buffer_.size() > max_line_bytes) return fault("protocol", "a line longer than 64 MB");
    Work_budget::check();
    bool exited = exit_status_ >= 0 || ::waitpid(pid_, &exit_status_, WNOHANG) == pid_;
    struct pollfd p {from_child_, POLLIN, 0};
    int r = ::poll(&p, 1, exited ? 0 : slice(deadline));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0 && exited) return fault("crash", ended_text(hello));   // all it wrote is read
    if (r <= 0 && Clock::now() >= deadline)
      return fault("timeout", (hello ? "did not say hello within " : "no answer within ") + seconds_text(seconds) +
                                  " s (--subject-timeout)");
    if (r <= 0) continue;
    char chunk[65536];
    ssize_t n = ::read(from_child_, chunk, sizeof chunk);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) {   // end of its output: it is gone or going; its status if it comes soon
      for (auto d = after(0.05); ::waitpid(pid_, &exit_status_, WNOHANG) != pid_ && Clock::now() < d;) ::usleep(1000);
      return fault("crash", ended_text(hello));
    }
    buffer_.append(chunk, static_cast<std::size_t>(n));
  }
}

bool External_subject::write_all(const std::string& text)
{
  auto deadline = after(spec_.timeout_seconds);
  std::size_t done = 0;
  while (done < text.size()) {
    ssize_t n = ::write(to_child_, text.data() + done, text.size() - done);
    if (n > 0) { done += static_cast<std::size_t>(n); continue; }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno != EAGAIN) return false;   // EPIPE: it closed its input or died
    Work_budget::check();
    if (Clock::now() >= deadline || (exit_status_ < 0 && ::waitpid(pid_, &exit_status_, WNOHANG) == pid_)) return false;
    struct pollfd p {to_child_, POLLOUT, 0};
    ::poll(&p, 1, slice(deadline));
  }
  return true;
}

Subject_answer External_subject::ask(const Scene& scene, bool earliest)
{
  return exchange("scene", scene_json(scene), earliest);
}

Subject_answer External_subject::ask(const Ccd_query& query, bool earliest)
{
  return exchange("ccd", ccd_query_json(query), earliest);
}

// Past the run's budget the subject is killed at once and the budget's end
// goes on up: the run answers nothing (--max-seconds).
Subject_answer External_subject::exchange(const char* key, const nlohmann::ordered_json& body, bool earliest)
{
  try {
    return converse(key, body, earliest);
  } catch (const Budget_exceeded&) {
    stop(true);
    throw;
  }
}

Subject_answer External_subject::converse(const char* key, const nlohmann::ordered_json& body, bool earliest)
{
  if (pid_ < 0) {
    Subject_answer started = start();
    if (started.kind == Subject_answer::Kind::Fault) return started;
  }
  long id = next_id_++;
  nlohmann::ordered_json request = {{"id", id}, {key, body}, {"earliest", earliest}};
  if (!write_all(request.dump() + "\n")) {
    // It stopped reading: it is gone (its output has ended), or stuck.
    std::string ignored;
    Subject_answer gone = read_line(ignored, 0.05, false);
    if (gone.kind == Subject_answer::Kind::Fault && gone.fault == "crash") return gone;
    return fault("timeout", "it did not read the request within the time limit (--subject-timeout)");
  }
  std::string line;
  Subject_answer got = read_line(line, spec_.timeout_seconds, false);
  if (got.kind == Subject_answer::Kind::Fault) return got;
  std::string problem;
  Subject_answer a = parse_answer(line, id, earliest, std::string(key) == "ccd", problem);
  if (!problem.empty()) return fault("protocol", problem + ": " + line.substr(0, 200));
  return a;
}

External_pool::Lease External_pool::acquire()
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (idle_.empty()) return Lease(*this, std::make_unique<External_subject>(spec_));
  std::unique_ptr<External_subject> s = std::move(idle_.back());
  idle_.pop_back();
  return Lease(*this, std::move(s));
}

// Every idle process is told to end first, so they exit side by side
// within one grace time, not one after another.
External_pool::~External_pool()
{
  for (auto& s : idle_) s->close_input();
  idle_.clear();
}

void External_pool::give_back(std::unique_ptr<External_subject> s)
{
  std::lock_guard<std::mutex> lock(mutex_);
  idle_.push_back(std::move(s));
}

} // namespace clash4d
