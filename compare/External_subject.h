// An external subject (spec: "External subjects"): a collision engine run as
// `/bin/sh -c COMMAND`, speaking newline-delimited JSON on its standard input
// and output (docs/subject-protocol.md). One long-lived process answers many
// requests (scenes and CCD queries); a crash, a request past the time limit
// or an answer out of protocol is a Subject_fault (cause "crash", "timeout"
// or "protocol"), the process is killed and the next request starts a fresh
// one.
//
// Processes run in their own process group, so a shell's children are killed
// with it; every child is reaped (no zombie survives the object), and what
// it started dies with it or with clash4d (compare/Subject_processes.h).
// Every wait looks at the run's budget (--max-seconds): past it the subject
// is killed and Budget_exceeded goes on up.
#ifndef CLASH4D_COMPARE_EXTERNAL_SUBJECT_H
#define CLASH4D_COMPARE_EXTERNAL_SUBJECT_H

#include "ccd/Ccd_query.h"
#include "scene/Scene.h"
#include <nlohmann/json.hpp>
#include <sys/types.h>
#include <array>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace clash4d {

// What `--subject NAME=COMMAND` names.
struct Subject_spec {
  std::string name, command;
  double timeout_seconds = 10;
};

// Parses "NAME=COMMAND"; throws std::invalid_argument saying what is wrong.
Subject_spec parse_subject_spec(const std::string& text, double timeout_seconds);

// One answer. Numbers are the subject's text read exactly and written back
// as rationals (never through a double); an answer to a CCD query has no
// witness.
struct Subject_answer {
  enum class Kind { Answer, Unsupported, Fault };
  Kind kind = Kind::Answer;
  bool collide = false;
  std::optional<std::string> t;                    // earliest collision time
  std::optional<std::array<std::string, 4>> witness;
  std::string why;                                 // unsupported: the subject's reason; fault: what happened
  std::string fault;                               // "crash", "timeout" or "protocol"
};

class External_subject {
public:
  explicit External_subject(Subject_spec spec);
  ~External_subject();
  External_subject(const External_subject&) = delete;
  External_subject& operator=(const External_subject&) = delete;

  // Sends the scene (started on first use or after a fault) and waits for
  // the answer, at most the time limit.
  Subject_answer ask(const Scene& scene, bool earliest);
  // The same for a CCD query ({"id", "ccd": {"type", "t0", "t1"}, "earliest"});
  // its answer has no witness.
  Subject_answer ask(const Ccd_query& query, bool earliest);

  const Subject_spec& spec() const { return spec_; }
  // From the hello line; "regularised" until a process has said otherwise.
  const std::string& semantics() const { return semantics_; }
  std::optional<double> tolerance() const { return tolerance_; }
  // Closes its standard input: the subject should end (spec); the
  // destructor waits for it, then kills what is left.
  void close_input();

private:
  // One request {"id": N, key: body, "earliest": ...} and its answer.
  Subject_answer exchange(const char* key, const nlohmann::ordered_json& body, bool earliest);
  Subject_answer converse(const char* key, const nlohmann::ordered_json& body, bool earliest);
  Subject_answer start();
  Subject_answer read_hello();
  void stop(bool kill_now);
  Subject_answer fault(const std::string& cause, const std::string& what);
  // A whole line within the deadline (`hello`: the first one); a fault
  // otherwise, with its cause.
  Subject_answer read_line(std::string& line, double seconds, bool hello);
  std::string ended_text(bool hello);
  bool write_all(const std::string& text);
  std::string exit_text();

  Subject_spec spec_;
  std::string semantics_ = "regularised";
  std::optional<double> tolerance_;
  pid_t pid_ = -1;
  int to_child_ = -1, from_child_ = -1;
  std::string buffer_;                 // read but not yet consumed
  long next_id_ = 1;
  int exit_status_ = -1;               // waitpid status once reaped
};

// The processes of one subject: one per worker thread at a time, created on
// demand and kept for the next case (spec: one long-lived process per run).
class External_pool {
public:
  explicit External_pool(Subject_spec spec) : spec_(std::move(spec)) {}
  ~External_pool();
  External_pool(const External_pool&) = delete;
  External_pool& operator=(const External_pool&) = delete;
  const Subject_spec& spec() const { return spec_; }

  class Lease {
  public:
    Lease(External_pool& pool, std::unique_ptr<External_subject> s) : pool_(pool), subject_(std::move(s)) {}
    ~Lease() { pool_.give_back(std::move(subject_)); }
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    External_subject& operator*() { return *subject_; }
    External_subject* operator->() { return subject_.get(); }

  private:
    External_pool& pool_;
    std::unique_ptr<External_subject> subject_;
  };
  Lease acquire();

private:
  void give_back(std::unique_ptr<External_subject> s);
  Subject_spec spec_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<External_subject>> idle_;
};

} // namespace clash4d

#endif
