#include "compare/Ccd_comparer.h"

#include "compare/Comparer.h"
#include "compare/External_subject.h"
#include "exact/Ccd_instantiation.h"
#include "float/Ccd_double_instantiation.h"
#include "scene/Number_json.h"
#include "scene/Number_text.h"
#include "run/Work_budget.h"

#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

namespace clash4d {

namespace {

using Clock = std::chrono::steady_clock;

// One subject's answer to the query, before it is held against exact; its
// semantics is the closed one, the only question a query asks.
struct Ccd_run : Subject_run {
  Ccd_run() { semantics = "closed"; }
  bool collide = false;
  std::optional<Ccd_number> t;     // t*, when earliest was asked and it collides
};

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

template <class F>
Ccd_run timed(const std::string& subject, F f)
{
  Ccd_run r;
  r.subject = subject;
  auto start = Clock::now();
  try {
    Ccd_answer a = f();
    r.collide = a.collide;
    if (a.earliest) r.t = a.earliest->t;
  } catch (const std::exception& e) {
    r.ok = false;
    r.error = e.what();
  }
  r.seconds = since(start);
  return r;
}

// An external subject's answer as a run: its t read exactly from its text.
Ccd_run external_run(External_pool& pool, const Ccd_query& query, bool earliest)
{
  External_pool::Lease subject = pool.acquire();
  Ccd_run r;
  r.subject = pool.spec().name;
  auto start = Clock::now();
  Subject_answer a = subject->ask(query, earliest);
  r.seconds = since(start);
  r.tolerance = subject->tolerance();
  if (a.kind == Subject_answer::Kind::Unsupported) r.skipped = "unsupported: " + a.why;
  if (a.kind == Subject_answer::Kind::Fault) {
    r.ok = false;
    r.fault = a.fault;
    r.error = a.why;
  }
  if (a.kind != Subject_answer::Kind::Answer) return r;
  r.collide = a.collide;
  if (a.collide && a.t) r.t = Algebraic(parse_number_text(*a.t, true).value);
  return r;
}

std::vector<Ccd_run> builtin_runs(const Ccd_query& query, const Ccd_compare_options& o)
{
  Ccd_options plain;
  plain.earliest = o.earliest;
  std::vector<Ccd_run> runs;
  runs.push_back(timed("exact", [&] { return ccd_exact(query, plain); }));
  runs.push_back(timed("double", [&] { return ccd_double(query, plain); }));
  for (double tol : o.tolerances) {
    Ccd_options with = plain;
    with.tolerance = tol;
    runs.push_back(timed(tolerance_subject(tol), [&] { return ccd_double(query, with); }));
    runs.back().tolerance = tol;
  }
  if (o.rounded) runs.push_back(timed("exact-rounded", [&] { return ccd_exact(rounded_query(query), plain); }));
  return runs;
}

// A t as the exact number it is (a double's value for the double subjects).
Algebraic exact_of(const Ccd_number& t)
{
  if (const double* d = std::get_if<double>(&t)) return Algebraic(Rational(*d));
  return std::get<Algebraic>(t);
}

// A t as a row shows it: "p/q", a double's shortest decimal, or an
// irrational number's polynomial and interval.
std::string number_text(const Ccd_number& t)
{
  if (const double* d = std::get_if<double>(&t)) return shortest_decimal(*d);
  return std::get<Algebraic>(t).to_text();
}

// |a - b| to about four digits, for the row's t error (shown only).
Rational rounded_distance(const Algebraic& a, const Algebraic& b)
{
  Rational lo, hi;
  for (int i = 0; i < 200; ++i, a.refine(), b.refine()) {
    lo = a.lower() - b.upper();
    hi = a.upper() - b.lower();
    if (hi - lo <= CGAL::abs(lo + hi) / 20000) break;
  }
  return CGAL::abs((lo + hi) / 2);
}

// The exact answers a query's subjects are held against: the plain one, and
// on need the rounded query's (the exact-rounded run) and those with a
// minimum separation EPS, one per tolerance.
struct Ccd_reference {
  const Ccd_query& query;
  const Ccd_run& exact;
  const Ccd_run* rounded;
  double time_bound;               // its exact value is the bound
  std::map<double, bool> within;   // the verdict with separation EPS, by EPS

  bool within_tolerance(double eps)
  {
    auto it = within.find(eps);
    if (it != within.end()) return it->second;
    Ccd_options o;
    o.separation = Rational(eps);
    return within[eps] = ccd_exact(query, o).collide;
  }
};

const char* verdict(bool collide) { return collide ? "collision" : "no collision"; }

// The cause of a verdict that differs from exact's, as defined in the header.
std::string verdict_cause(const Ccd_run& r, Ccd_reference& ref, std::string& detail)
{
  detail = r.subject + " says " + verdict(r.collide) + ", exact says " + verdict(ref.exact.collide);
  if (&r == ref.rounded || (ref.rounded && ref.rounded->ok && ref.rounded->collide == r.collide)) return "input rounding";
  if (r.tolerance && ref.within_tolerance(*r.tolerance) == r.collide) {
    // Only a collision can be so: the primitives come within any separation where they meet.
    detail += ", but they come within its tolerance " + shortest_decimal(*r.tolerance);
    return "tolerance";
  }
  return "arithmetic";
}

// The cause of r's disagreement with exact (empty: none), with the detail.
std::string classify(const Ccd_run& r, Ccd_reference& ref, std::string& detail)
{
  if (&r == &ref.exact) return "";
  if (!r.fault.empty()) {
    detail = r.subject + ": " + r.fault + ": " + r.error;
    return r.fault;
  }
  if (!r.ok) return "";
  if (r.collide != ref.exact.collide) return verdict_cause(r, ref, detail);
  if (r.t && ref.exact.t && farther_than(exact_of(*r.t), exact_of(*ref.exact.t), Rational(ref.time_bound))) {
    detail = r.subject + "'s t* = " + number_text(*r.t) + " is off exact t* = " + number_text(*ref.exact.t) +
             " by more than " + shortest_decimal(ref.time_bound);
    return "time";
  }
  return "";
}

Subject_row row_of(const Ccd_run& r, Ccd_reference& ref, std::vector<Disagreement>& list)
{
  Subject_row s = r.row(&r == &ref.exact);
  if (s.skipped) return s;
  if (r.ok) s.collide = r.collide;
  if (r.t) s.earliest = Located{{"", ""}, std::nullopt, number_text(*r.t)};
  if (r.t && ref.exact.t) s.t_error = t_error_text(rounded_distance(exact_of(*r.t), exact_of(*ref.exact.t)));
  std::string detail, cause = classify(r, ref, detail);
  s.agrees = r.ok && cause.empty();
  if (!cause.empty()) {
    s.cause = cause;
    list.push_back({r.subject, cause, detail, "closed"});
  }
  return s;
}

} // namespace

Ccd_query rounded_query(const Ccd_query& query)
{
  Ccd_query::Rows rows;
  for (std::size_t i = 0; i < 8; ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      double d = query.nearest()[i][k];
      if (!std::isfinite(d)) throw std::range_error("the number " + to_string(query.rows()[i][k]) + " has no double");
      rows[i][k] = Rational(d);
    }
  Ccd_query r(query.type(), rows);
  r.line = query.line;
  return r;
}

Ccd_comparison compare_query(const Ccd_query& query, const std::string& file, std::size_t index,
                             const Ccd_compare_options& options)
{
  Work_budget::check();
  std::vector<Ccd_run> runs = builtin_runs(query, options);
  if (!runs[0].ok) throw std::runtime_error("the exact subject failed: " + runs[0].error);
  for (const auto& pool : options.externals) runs.push_back(external_run(*pool, query, options.earliest));
  const Ccd_run* rounded = nullptr;
  for (const Ccd_run& r : runs)
    if (r.subject == "exact-rounded") rounded = &r;
  Ccd_reference ref{query, runs[0], rounded, options.time_bound, {}};

  Ccd_comparison out;
  out.index = index;
  out.line = query.line;
  out.query = query;
  out.comparison.file = file;
  out.comparison.name = ccd_query_name(index, query.line);
  for (const Ccd_run& r : runs) out.comparison.subjects.push_back(row_of(r, ref, out.comparison.disagreements));
  Work_budget::check();   // a comparison finished past the budget is not shown (--max-seconds)
  return out;
}

} // namespace clash4d
