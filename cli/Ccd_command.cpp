#include "cli/Ccd_command.h"

#include "ccd/Ccd_answer_json.h"
#include "ccd/Ccd_reader.h"
#include "exact/Ccd_instantiation.h"
#include "float/Ccd_double_instantiation.h"
#include "scene/Input_error.h"
#include "scene/Number_text.h"
#include "run/Work_budget.h"

#include <CLI/CLI.hpp>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <memory>
#include <ostream>
#include <unistd.h>

namespace clash4d {

namespace {

using json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;
using Decide = Ccd_answer (*)(const Ccd_query&, const Ccd_options&);

// Queries read and decided at a time: enough to keep every core busy, few
// enough that a file of millions streams.
constexpr std::size_t batch_size = 1 << 14;

struct Ccd_args {
  std::vector<std::string> files;
  std::string type, number = "exact", separation;
  Ccd_options options;
  bool json = false, labels = false;
};

Decide decider(const std::string& number)
{
  if (number == "rational") return ccd_rational;
  if (number == "double") return ccd_double;
  return ccd_exact;
}

// Progress on standard error for long files: a line rewritten in place on
// a terminal, a line every ten seconds in a log.
class Progress {
public:
  Progress(std::ostream& err, bool terminal, std::size_t total) : err_(err), terminal_(terminal), total_(total) {}
  void update(std::size_t done)
  {
    auto now = Clock::now();
    if (now - last_ < (terminal_ ? std::chrono::milliseconds(500) : std::chrono::milliseconds(10000))) return;
    last_ = now;
    err_ << (terminal_ ? "\rclash4d ccd: " : "clash4d ccd: ") << done << " of " << total_ << " queries decided"
         << (terminal_ ? "" : "\n") << std::flush;
    shown_ = true;
  }
  ~Progress()
  {
    if (shown_ && terminal_) err_ << "\r" << std::string(60, ' ') << "\r" << std::flush;
  }

private:
  std::ostream& err_;
  bool terminal_;
  std::size_t total_;
  Clock::time_point last_ = Clock::now();
  bool shown_ = false;
};

// What pass 1 knows of a file: its query count, and, for input that cannot
// be read twice (a pipe), the queries themselves.
struct Checked_file {
  std::string path;
  std::size_t queries = 0;
  std::optional<std::vector<Ccd_query>> kept;
};

std::optional<Ccd_type> type_option(const std::string& type)
{
  return type.empty() ? std::nullopt : ccd_type_from_name(type);
}

// Pass 1: every query of every file is read before any answer is printed,
// so bad input is exit 2 (or 3) naming the file and place, and never a
// partial answer. The double instantiation also needs every number within
// the double range.
int check_files(const Ccd_args& a, std::vector<Checked_file>& out, std::ostream& err)
{
  for (const std::string& path : a.files) {
    Checked_file f{path, 0, std::nullopt};
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec) && !std::filesystem::is_directory(path, ec)) f.kept.emplace();
    try {
      Ccd_reader reader(path, type_option(a.type));
      std::vector<Ccd_query> qs;
      while (reader.read(batch_size, qs) > 0) {
        Work_budget::check();
        f.queries += qs.size();
        if (a.number == "double")
          for (const Ccd_query& q : qs)
            for (std::size_t i = 0; i < 8; ++i)
              for (std::size_t k = 0; k < 3; ++k)
                if (!std::isfinite(q.nearest()[i][k]))
                  throw Input_error("line " + std::to_string(q.line),
                                    "the number " + to_string(q.rows()[i][k]) +
                                        " is beyond the range of double (the double instantiation cannot read this "
                                        "query)");
        if (f.kept) f.kept->insert(f.kept->end(), qs.begin(), qs.end());
        qs.clear();
      }
    } catch (const Input_error& e) {
      err << "clash4d ccd: " << e.format(path) << "\n";
      return e.exit_code();
    }
    out.push_back(std::move(f));
  }
  return 0;
}

struct Tally {
  std::size_t queries = 0, collide = 0, agree = 0, disagree = 0;
  double seconds = 0;
};

// Decides a batch on all cores; the answers are in input order.
std::vector<Ccd_answer> decide_batch(const std::vector<Ccd_query>& qs, Decide decide, const Ccd_options& o)
{
  std::vector<Ccd_answer> answers(qs.size());
  tbb::parallel_for(std::size_t(0), qs.size(), [&](std::size_t i) { answers[i] = decide(qs[i], o); });
  return answers;
}

void report_batch(const Ccd_args& a, const std::vector<Ccd_query>& qs, const std::vector<Ccd_answer>& answers,
                  Tally& t, std::ostream& out)
{
  for (std::size_t i = 0; i < qs.size(); ++i, ++t.queries) {
    const Ccd_answer& answer = answers[i];
    if (answer.collide) ++t.collide;
    bool labelled = a.labels && qs[i].label.has_value();
    bool agree = labelled && *qs[i].label == answer.collide;
    if (labelled) ++(agree ? t.agree : t.disagree);
    if (a.json) {
      json j = ccd_answer_json(t.queries, answer, a.options.earliest);
      if (labelled) j["label"] = *qs[i].label, j["agree"] = agree;
      out << j.dump() << "\n";
    } else if (labelled && !agree) {
      out << "  query " << t.queries << " (line " << qs[i].line << "): " << (answer.collide ? "collides" : "does not collide")
          << ", labelled " << (*qs[i].label ? 1 : 0) << "\n";
    }
  }
}

Tally run_file(const Ccd_args& a, const Checked_file& f, std::ostream& out, Progress& progress, std::size_t& done)
{
  Tally t;
  Decide decide = decider(a.number);
  auto start = Clock::now();
  auto run = [&](const std::vector<Ccd_query>& qs) {
    report_batch(a, qs, decide_batch(qs, decide, a.options), t, out);
    done += qs.size();
    progress.update(done);
    Work_budget::check();
  };
  if (f.kept) {
    for (std::size_t i = 0; i < f.kept->size(); i += batch_size) {
      auto end = f.kept->begin() + static_cast<std::ptrdiff_t>(std::min(i + batch_size, f.kept->size()));
      run(std::vector<Ccd_query>(f.kept->begin() + static_cast<std::ptrdiff_t>(i), end));
    }
  } else {
    Ccd_reader reader(f.path, type_option(a.type));
    std::vector<Ccd_query> qs;
    while (reader.read(batch_size, qs) > 0) {
      run(qs);
      qs.clear();
    }
  }
  t.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return t;
}

void print_summary(const Ccd_args& a, const std::string& path, const Tally& t, std::ostream& s)
{
  double us = t.queries ? 1e6 * t.seconds / static_cast<double>(t.queries) : 0;
  s << path << ": " << t.queries << " queries, " << t.collide << " collide (" << a.number << ", closed"
    << (a.separation.empty() ? "" : ", separation " + a.separation) << (a.options.earliest ? ", earliest" : "") << "); " << std::fixed << std::setprecision(3) << us
    << " us per query (" << tbb::this_task_arena::max_concurrency() << " threads, reading included)\n"
    << std::defaultfloat;
  if (a.labels) s << "  labels: " << t.agree << " agree, " << t.disagree << " disagree, "
                  << t.queries - t.agree - t.disagree << " unlabelled\n";
}

int run_ccd(Ccd_args& a, std::ostream& out, std::ostream& err)
{
  if (a.options.tolerance != 0 && a.number != "double") {
    err << "clash4d ccd: --tolerance applies to --number double only\n";
    return CLASH4D_EXIT_INVALID;
  }
  if (!a.separation.empty()) {
    Number_parse d = parse_number_text(a.separation, true);
    if (!d.ok || CGAL::is_negative(d.value)) {
      err << "clash4d ccd: --separation expects a number D >= 0 (decimal or p/q, read exactly), found '"
          << a.separation << "'" << (d.ok ? "" : ": " + d.error) << "\n";
      return d.limit ? CLASH4D_EXIT_LIMIT : CLASH4D_EXIT_INVALID;
    }
    a.options.separation = d.value;
  }
  std::vector<Checked_file> files;
  if (int s = check_files(a, files, err)) return s;
  std::size_t total = 0, done = 0;
  for (const auto& f : files) total += f.queries;
  Progress progress(err, isatty(fileno(stderr)) != 0, total);
  bool any_collide = false, any_disagree = false;
  for (const auto& f : files) {
    Tally t = run_file(a, f, out, progress, done);
    print_summary(a, f.path, t, a.json ? err : out);
    any_collide = any_collide || t.collide > 0;
    any_disagree = any_disagree || t.disagree > 0;
  }
  return a.labels ? (any_disagree ? 1 : 0) : (any_collide ? 1 : 0);
}

} // namespace

std::function<int()> add_ccd(CLI::App& app, std::ostream& out, std::ostream& err)
{
  auto a = std::make_shared<Ccd_args>();
  CLI::App* cmd = app.add_subcommand(
      "ccd", "Answer CCD queries exactly: does a moving vertex meet a moving triangle, or a moving edge another "
             "(vertex-face, edge-edge; linear motion over t in [0, 1]; touching counts). Files are the CCD "
             "benchmark's CSV or JSON lines (docs/ccd-queries.md). Exit 0 when no query collides, 1 when one does "
             "(--labels: when an answer disagrees with its label), 2 invalid input, 3 a limit.");
  cmd->add_option("FILE", a->files, "query files: .csv (8 rows of 7 integers per query) or JSON lines")->required();
  cmd->add_option("--type", a->type,
                  "vf (vertex-face) or ee (edge-edge); default: from a vertex-face or edge-edge file or folder name, or "
                  "each JSON line's \"type\"")
      ->check(CLI::IsMember({"vf", "ee", "vertex-face", "edge-edge"}));
  cmd->add_option("--number", a->number,
                  "exact (default; intervals, rationals where a sign is in doubt), rational (the reference) or double")
      ->check(CLI::IsMember({"exact", "rational", "double"}));
  cmd->add_flag("--earliest", a->options.earliest, "also give t*, the first time of contact, and the contact's (u, v)");
  cmd->add_flag("--json", a->json, "one JSON line per query on standard output; the summary goes to standard error");
  cmd->add_flag("--labels", a->labels,
                "compare each answer with the file's label (CSV column 7, JSON \"label\"); exit 1 when one disagrees");
  cmd->add_option("--tolerance", a->options.tolerance, "double only: treat |value| <= EPS as zero (default 0)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--separation", a->separation,
                  "D >= 0: a query collides when the primitives come within distance D (exact: squared distances "
                  "against D^2; read exactly, e.g. 1e-6 or 1/1000); t* is the first such time");
  return [cmd, a, &out, &err] {
    if (!cmd->parsed()) return -1;
    return run_ccd(*a, out, err);
  };
}

} // namespace clash4d
