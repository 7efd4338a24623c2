// The result of comparing one scene across subjects (compare/Comparer.h), as
// a typed value; JSON only at the edges (`compare --json`, report.json, the
// `meta` of fuzz findings). The JSON form is documented in compare/README.md.
#ifndef CLASH4D_COMPARE_COMPARISON_H
#define CLASH4D_COMPARE_COMPARISON_H

#include <nlohmann/json.hpp>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace clash4d {

// A witness or an earliest contact: the pair, and the point when the subject
// gives one (fcl and most external engines give none); `t` for earliest only.
struct Located {
  std::array<std::string, 2> objects;
  std::optional<std::array<std::string, 4>> point;
  std::string t;
};

// One subject's answer held against exact. A subject that did not run has
// `skipped` (the reason) and no answer, agreement or cause.
struct Subject_row {
  std::string subject;
  std::string semantics = "regularised";   // the question it answers (spec: closed or regularised)
  std::optional<double> tolerance;         // as it declares it
  bool reference = false;                  // the exact subject
  bool ok = true;                          // it answered (false: error, or a crash/timeout/protocol fault)
  std::string error;
  std::optional<std::string> skipped;
  std::optional<bool> collide;
  std::optional<Located> witness;
  std::optional<bool> witness_valid;       // checked exactly; none without a point
  std::optional<Located> earliest;
  std::optional<std::string> t_error;      // |t* - exact t*|, 3 significant digits
  std::optional<double> seconds;           // none in saved findings (not reproducible)
  std::optional<bool> agrees;
  std::optional<std::string> cause;        // why it disagrees, or what went wrong with it

  bool failed() const { return !ok; }
  // A disagreement with exact (a failure with a cause is a fault, not this).
  bool disagrees() const { return ok && cause.has_value(); }
};

// How a subject's run went, whatever it was asked (a scene or a CCD query):
// the part of its row every comparer fills alike.
struct Subject_run {
  std::string subject;
  std::string semantics = "regularised";
  std::optional<double> tolerance;
  bool ok = true;
  std::string error;
  std::string fault;              // external subject: crash, timeout or protocol
  std::string skipped;            // why the subject did not run (fcl: scene not expressible; unsupported)
  double seconds = 0;

  // Its row with these fields (and `skipped` when it did not run); the
  // answer, agreement and cause are the comparer's to fill.
  Subject_row row(bool reference) const;
};

struct Disagreement {
  std::string subject, cause, detail;
  std::string semantics = "regularised";   // the question the subject was judged in
};

// A row as Comparison::to_json writes it (compare/README.md); the CCD
// comparison writes its rows from it too (compare/Ccd_comparison.h).
nlohmann::ordered_json row_json(const Subject_row& s);

struct Comparison {
  std::string file, name;
  // Where exact (regularised) says no collision: whether the closed objects
  // meet all the same (exact closed); none where exact says collision.
  std::optional<bool> closed_touch;
  std::vector<Subject_row> subjects;
  std::vector<Disagreement> disagreements;

  // The exact answer (regularised), and the exact answer in a semantics.
  const Subject_row* reference() const;
  const Subject_row* reference_in(const std::string& semantics) const;
  const Subject_row* find(const std::string& subject) const;
  // "subject: cause" of each disagreement or fault, in order.
  std::vector<std::string> disagreement_keys() const;
  bool has_disagreement() const { return !disagreements.empty(); }
  bool has_failure() const;
  // Drops the timings, which differ from run to run.
  Comparison reproducible() const;

  nlohmann::ordered_json to_json() const;
  // Reads what to_json wrote (fuzz folders read back by report); missing
  // keys are absent values. Throws std::runtime_error naming the key on a
  // value of the wrong type.
  static Comparison from_json(const nlohmann::ordered_json& j);
};

} // namespace clash4d

#endif
