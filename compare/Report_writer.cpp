#include "compare/Report_writer.h"

#include "compare/Decimal_text.h"
#include "compare/Display_mesh.h"
#include "compare/Scene_view.h"

#include "geometry/Rotation_matrix.h"
#include "model/Model_builder.h"
#include "model/Motion_path.h"
#include "scene/Pose_motion.h"
#include "float/Double_kernel.h"
#include "scene/Files.h"
#include "scene/Number_text.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace clash4d {

// Escapes for HTML text and attributes and for XML; control characters that
// XML 1.0 forbids become U+FFFD.
std::string escape_markup(const std::string& s)
{
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') out += "\xEF\xBF\xBD";
        else out += c;
    }
  }
  return out;
}

namespace {

using json = nlohmann::ordered_json;
namespace fs = std::filesystem;

// Disagreements (scenes and CCD queries), then faults of external subjects.
const char* const all_causes[] = {"contact",         "input rounding", "tolerance", "arithmetic", "time",
                                  "invalid witness", "crash",          "timeout",   "protocol"};
constexpr std::size_t max_drawn_objects = 24;

// ---------------------------------------------------------------- text

std::string escape(const std::string& s) { return escape_markup(s); }

std::string format(const char* spec, double x)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, spec, x);
  return buffer;
}

std::string seconds_text(double s)
{
  return s < 1 ? format("%.3g ms", s * 1000) : format("%.3g s", s);
}

// ---------------------------------------------------------------- comparison fields

const char* const dash = "\xE2\x80\x94";

// The detail of a subject's disagreement, from the comparison's list.
std::string detail_of(const Comparison& c, const Subject_row& s)
{
  for (const Disagreement& d : c.disagreements)
    if (d.subject == s.subject) return d.detail;
  return s.subject + " disagrees with exact (" + s.cause.value_or("") + ")";
}

bool case_disagrees(const Comparison& c)
{
  for (const Subject_row& s : c.subjects)
    if (s.disagrees()) return true;
  return false;
}

std::string verdict_text(const Subject_row* s)
{
  if (!s || !s->collide) return dash;
  return *s->collide ? "collision" : "no collision";
}

std::string yes_no(const std::optional<bool>& f, const char* unknown = dash) { return !f ? unknown : (*f ? "yes" : "no"); }

template <class Strings>
std::string joined(const Strings& a)
{
  std::string out;
  for (const auto& e : a) out += (out.empty() ? "" : ", ") + e;
  return out;
}

// A number kept on one line unless long (a break in "31/4" would read "3 1/4"),
// with its decimal beside it (display only).
std::string number_html(const std::string& s)
{
  std::string approx = decimal_text(s);
  return std::string(s.size() <= 24 ? "<code class=\"whole\">" : "<code>") + escape(s) + "</code>" +
         (approx.empty() ? "" : " <span class=\"approx\">(" + approx + ")</span>");
}

// located_text as HTML, each coordinate with its decimal.
std::string located_html(const std::optional<Located>& w)
{
  if (!w) return dash;
  std::string out = escape(joined(w->objects));
  if (!w->point) return out;
  out += " at (";
  for (std::size_t i = 0; i < 4; ++i) out += (i ? ", " : "") + number_html((*w->point)[i]);
  return out + ")";
}

// "a, b at (x, y, z, t)" for a witness or earliest contact; "a, b" when the
// subject gives no point (fcl).
std::string located_text(const std::optional<Located>& w)
{
  if (!w) return dash;
  if (!w->point) return joined(w->objects);
  return joined(w->objects) + " at (" + joined(*w->point) + ")";
}

// ---------------------------------------------------------------- summary

struct Tally {
  int answers = 0, agreements = 0, disagreements = 0, errors = 0, skips = 0;
  json by_cause = json::object();
  json by_family = json::object();  // disagreements and faults per fuzz family
  std::string semantics;            // as the subject declared it (the last one seen)
  double seconds = 0;
  int timed = 0;

  Tally() { for (const char* c : all_causes) by_cause[c] = 0; }
  void add(const Subject_row& s, const std::string& family)
  {
    semantics = s.semantics;
    if (s.seconds) { seconds += *s.seconds; ++timed; }
    if (s.skipped) { ++skips; return; }   // no answer to count
    ++answers;
    if (s.cause) by_cause[*s.cause] = by_cause.value(*s.cause, 0) + 1;   // faults (crash, timeout) too
    if (s.cause && !family.empty()) by_family[family] = by_family.value(family, 0) + 1;
    if (s.failed()) ++errors;
    else if (s.disagrees()) ++disagreements;
    else ++agreements;
  }
  json to_json() const
  {
    return {{"answers", answers}, {"agreements", agreements}, {"disagreements", disagreements},
            {"errors", errors}, {"skipped", skips}, {"by_cause", by_cause}};
  }
  // A subject's own line: its semantics and mean time per query beside the rest.
  json subject_json() const
  {
    json j = to_json();
    j["semantics"] = semantics;
    j["seconds_per_query"] = timed ? json(seconds / timed) : json();
    j["by_family"] = by_family;
    return j;
  }
};

// Case counts (scenes and CCD queries apart; agreeing, disagreeing and with
// errors over both); answer counts over the non-reference subjects, in total
// and per subject; failures of the reference counted apart.
json summary_of(const std::vector<Report_case>& cases)
{
  int queries = 0, agreeing = 0, disagreeing = 0, with_errors = 0, reference_errors = 0;
  Tally total, reference;
  json by_subject = json::object();
  std::vector<std::string> order;
  std::vector<Tally> tallies;
  for (const Report_case& c : cases) {
    bool d = case_disagrees(c.comparison), e = c.comparison.has_failure();
    queries += c.ccd.has_value();
    agreeing += !d && !e;
    disagreeing += d;
    with_errors += e;
    for (const Subject_row& s : c.comparison.subjects) {
      if (s.reference) {
        reference_errors += s.failed();
        reference.add(s, c.family);
        continue;
      }
      auto it = std::find(order.begin(), order.end(), s.subject);
      if (it == order.end()) { order.push_back(s.subject); tallies.emplace_back(); it = order.end() - 1; }
      tallies[it - order.begin()].add(s, c.family);
      total.add(s, c.family);
    }
  }
  for (std::size_t i = 0; i < order.size(); ++i) by_subject[order[i]] = tallies[i].subject_json();
  json t = total.to_json();
  return {{"scenes", cases.size() - static_cast<std::size_t>(queries)}, {"queries", queries},
          {"scenes_agreeing", agreeing}, {"scenes_disagreeing", disagreeing}, {"scenes_with_errors", with_errors}, {"answers", t["answers"]}, {"agreements", t["agreements"]},
          {"disagreements", t["disagreements"]}, {"errors", t["errors"]}, {"skipped", t["skipped"]}, {"reference_errors", reference_errors},
          {"by_cause", t["by_cause"]}, {"by_subject", by_subject},
          {"reference_seconds_per_query", reference.subject_json()["seconds_per_query"]}};
}

std::string report_json(const std::vector<Report_case>& cases, const json& summary)
{
  json out = {{"format", "clash4d-report/1"}, {"summary", summary}, {"cases", json::array()}};
  for (const Report_case& c : cases) out["cases"].push_back(c.ccd ? c.ccd->to_json() : c.comparison.to_json());
  return out.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

// ---------------------------------------------------------------- JUnit

// A case's name: its file, and for a CCD query which one.
std::string case_title(const Report_case& c) { return c.ccd ? c.file + ": " + c.comparison.name : c.file; }

std::string junit_case(const Report_case& c, const Subject_row& s)
{
  std::ostringstream out;
  out << "  <testcase classname=\"" << escape(case_title(c)) << "\" name=\"" << escape(s.subject) << "\"";
  if (s.seconds) out << " time=\"" << format("%.6f", *s.seconds) << "\"";
  if (s.failed()) {
    std::string type = s.cause.value_or("error");
    out << ">\n    <error message=\"" << escape(s.error) << "\" type=\"" << escape(type) << "\">" << escape(s.error)
        << "</error>\n  </testcase>\n";
  } else if (s.skipped) {
    out << ">\n    <skipped message=\"" << escape(*s.skipped) << "\"/>\n  </testcase>\n";
  } else if (s.disagrees()) {
    out << ">\n    <failure message=\"" << escape(*s.cause) << "\" type=\"disagreement\">"
        << escape(detail_of(c.comparison, s)) << "</failure>\n  </testcase>\n";
  } else out << "/>\n";
  return out.str();
}

std::string junit_xml(const std::vector<Report_case>& cases)
{
  int tests = 0, failures = 0, errors = 0, skips = 0;
  double seconds = 0;
  std::string body;
  for (const Report_case& c : cases)
    for (const Subject_row& s : c.comparison.subjects) {
      ++tests;
      failures += s.disagrees();
      errors += s.failed();
      skips += s.skipped.has_value();
      seconds += s.seconds.value_or(0);
      body += junit_case(c, s);
    }
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuite name=\"clash4d\" tests=\"" << tests
      << "\" failures=\"" << failures << "\" errors=\"" << errors << "\" skipped=\"" << skips << "\" time=\"" << format("%.6f", seconds)
      << "\">\n" << body << "</testsuite>\n";
  return out.str();
}

// ---------------------------------------------------------------- drawing data

struct Marker {
  enum class Kind { Witness, Earliest, Other };
  Kind kind;
  std::array<double, 4> point;      // x, y, z, t
  std::string title;
};

// A pose in doubles (display only): R(q) p + c.
struct Drawn_pose {
  double t;
  std::array<double, 3> c;
  std::array<double, 4> q;   // w x y z, not normalised (R divides by |q|^2)
};

struct Drawn_object {
  std::string name, colour;
  std::size_t index;                // in the scene
  Box<double, 3> box;               // of the shape (a turning object's as written)
  Motion_path<double> motion;       // a translation's
  std::vector<Drawn_pose> poses;    // a turning object's (its motion then at rest)
  std::vector<std::array<double, 3>> vertices;   // a turning object's cells' vertices
  bool turns() const { return !poses.empty(); }
};

struct Drawing {
  double t_lo = 0, t_hi = 1;
  std::vector<Drawn_object> objects;
  std::size_t object_count = 0;
  std::vector<Marker> markers;
  std::string error;                // why nothing can be drawn
};

void add_marker(std::vector<Marker>& out, Marker::Kind kind, const std::optional<Located>& located, const std::string& title)
{
  if (!located || !located->point) return;
  Marker m{kind, {}, title + ": " + located_text(located)};
  for (std::size_t i = 0; i < 4; ++i) {
    std::optional<double> d = decimal_value((*located->point)[i]);
    if (!d) return;
    m.point[i] = *d;
  }
  out.push_back(m);
}

std::vector<Marker> markers_of(const Comparison& comparison)
{
  std::vector<Marker> out;
  if (const Subject_row* ref = comparison.reference()) {
    add_marker(out, Marker::Kind::Witness, ref->witness, ref->subject + " witness");
    add_marker(out, Marker::Kind::Earliest, ref->earliest,
               ref->subject + " earliest contact, t* = " + (ref->earliest ? ref->earliest->t : ""));
  }
  for (const Subject_row& s : comparison.subjects)
    if (!s.reference) add_marker(out, Marker::Kind::Other, s.witness, s.subject + " witness");
  return out;
}

// Every object when there are few; otherwise those named by some answer.
std::vector<std::size_t> objects_to_draw(const Report_case& c)
{
  std::vector<std::size_t> all;
  for (std::size_t i = 0; i < c.scene.objects.size(); ++i) all.push_back(i);
  if (all.size() <= max_drawn_objects) return all;
  std::vector<std::string> named;
  for (const Subject_row& s : c.comparison.subjects)
    for (const auto* l : {&s.witness, &s.earliest})
      if (*l) named.insert(named.end(), (*l)->objects.begin(), (*l)->objects.end());
  std::vector<std::size_t> chosen;
  for (std::size_t i : all)
    if (std::find(named.begin(), named.end(), c.scene.objects[i].name) != named.end()) chosen.push_back(i);
  if (chosen.empty()) chosen.assign(all.begin(), all.begin() + max_drawn_objects);
  return chosen;
}

std::array<double, 3> doubles(const std::array<Rational, 3>& v)
{
  return {round_to_nearest(v[0]), round_to_nearest(v[1]), round_to_nearest(v[2])};
}

std::vector<Drawn_pose> drawn_poses(const Motion& m)
{
  std::vector<Drawn_pose> out;
  for (const Pose& p : m.poses)
    out.push_back({round_to_nearest(p.t), doubles(p.translate),
                   {round_to_nearest(p.rotate[0]), round_to_nearest(p.rotate[1]), round_to_nearest(p.rotate[2]),
                    round_to_nearest(p.rotate[3])}});
  return out;
}

// The size of the drawn scene (boxes and pose centres), at least 1: an
// unbounded turning object's cells are cut a thousand times further out.
double drawing_scale(const Drawing& d)
{
  double s = 1;
  auto take = [&](double v) { if (std::isfinite(v)) s = std::max(s, std::abs(v)); };
  for (const Drawn_object& o : d.objects) {
    for (int a = 0; a < 3; ++a) {
      if (o.box.has_lo[a]) take(o.box.lo[a]);
      if (o.box.has_hi[a]) take(o.box.hi[a]);
    }
    for (const Drawn_pose& p : o.poses) for (double v : p.c) take(v);
  }
  return s;
}

// The vertices of a turning object's convex cells (the shape as written):
// the poses place them, and their extremes are its extent.
std::vector<std::array<double, 3>> shape_vertices(const Csg_model<double>& csg, const Box<double, 3>& b, double far)
{
  std::array<double, 3> lo, hi;
  for (int a = 0; a < 3; ++a) {
    lo[a] = b.has_lo[a] ? b.lo[a] - 1 : -far;
    hi[a] = b.has_hi[a] ? b.hi[a] + 1 : far;
  }
  return display_mesh(csg, lo, hi).vertices;
}

// Each drawn object in doubles; a turning object's shape as written, which
// its poses place (a translation's shape is where its D(t) moves it from).
Drawing drawing_of(const Report_case& c)
{
  Drawing d;
  d.object_count = c.scene.objects.size();
  d.markers = markers_of(c.comparison);
  try {
    Double_kernel k;
    Model_builder<Double_kernel> builder(k);
    d.t_lo = round_to_nearest(c.scene.t_lo);
    d.t_hi = round_to_nearest(c.scene.t_hi);
    std::vector<Csg_model<double>> shapes;
    for (std::size_t i : objects_to_draw(c)) {
      const Scene_object& o = c.scene.objects[i];
      bool turns = o.motion.rotates();
      shapes.push_back(builder.build(turns ? written_shape(o) : o.shape));
      d.objects.push_back({o.name, object_colour(d.objects.size()), i, node_box(shapes.back(), 0),
                           Motion_path<double>::build(k, o.motion), turns ? drawn_poses(o.motion) : std::vector<Drawn_pose>(), {}});
    }
    double far = 1000 * drawing_scale(d);
    for (std::size_t n = 0; n < shapes.size(); ++n)
      if (d.objects[n].turns()) d.objects[n].vertices = shape_vertices(shapes[n], d.objects[n].box, far);
  } catch (const std::exception& e) {
    d.error = e.what();
    d.objects.clear();
  }
  return d;
}

// ---------------------------------------------------------------- extents

// The pose law (spec): c and q linear between poses, held outside them.
Drawn_pose pose_at(const std::vector<Drawn_pose>& poses, double t)
{
  if (t <= poses.front().t) return poses.front();
  if (t >= poses.back().t) return poses.back();
  auto b = std::upper_bound(poses.begin(), poses.end(), t, [](double u, const Drawn_pose& p) { return u < p.t; });
  auto a = b - 1;
  double s = (t - a->t) / (b->t - a->t);
  Drawn_pose p{t, {}, {}};
  for (int i = 0; i < 3; ++i) p.c[i] = (1 - s) * a->c[i] + s * b->c[i];
  for (int i = 0; i < 4; ++i) p.q[i] = (1 - s) * a->q[i] + s * b->q[i];
  return p;
}

// An object's extent along the axis at time t: infinite on a translated
// box's unbounded side; a turning object's over its placed vertices, which
// sets the frame only when the object is bounded (else its cells were cut
// far out and the diagram clips them).
struct Extent {
  double lo, hi;
  bool framed;
};

Extent extent_at(const Drawn_object& o, int axis, double t)
{
  if (!o.turns()) {
    double shift = o.motion.displacement(t)[axis];
    return {o.box.has_lo[axis] ? o.box.lo[axis] + shift : -INFINITY,
            o.box.has_hi[axis] ? o.box.hi[axis] + shift : INFINITY, true};
  }
  Drawn_pose p = pose_at(o.poses, t);
  auto r = rotation_matrix(p.q[0], p.q[1], p.q[2], p.q[3]);   // display only: doubles
  Extent e{INFINITY, -INFINITY, o.box.bounded()};
  for (const auto& v : o.vertices) {
    double q = r[axis][0] * v[0] + r[axis][1] * v[1] + r[axis][2] * v[2] + p.c[axis];
    e.lo = std::min(e.lo, q);
    e.hi = std::max(e.hi, q);
  }
  return e;
}

// A turning object's extent is sampled this many times per piece between
// pose times: fewer when there are many poses, so a page stays small.
int samples_per_piece(std::size_t poses)
{
  return static_cast<int>(std::clamp<std::size_t>(8192 / std::max<std::size_t>(poses, 1), 8, 128));
}

// tL, the motion's breakpoints (or pose times) inside (tL, tH), tH; for a
// turning object each piece sampled too (its extent is not linear there).
std::vector<double> band_times(const Drawn_object& o, double t_lo, double t_hi)
{
  std::vector<double> ts{t_lo};
  for (double t : o.motion.times)
    if (t_lo < t && t < t_hi) ts.push_back(t);
  for (const Drawn_pose& p : o.poses)
    if (t_lo < p.t && p.t < t_hi) ts.push_back(p.t);
  ts.push_back(t_hi);
  if (!o.turns()) return ts;
  int n = samples_per_piece(o.poses.size());
  std::vector<double> dense;
  for (std::size_t i = 0; i + 1 < ts.size(); ++i)
    for (int k = 0; k < n; ++k) dense.push_back(ts[i] + (ts[i + 1] - ts[i]) * k / n);
  dense.push_back(t_hi);
  return dense;
}

bool drawable(const Drawn_object& o, int axis)
{
  if (o.turns()) return !o.vertices.empty();
  const Box<double, 3>& b = o.box;
  return !b.empty && !(b.has_lo[axis] && b.has_hi[axis] && b.hi[axis] < b.lo[axis]);
}

// ---------------------------------------------------------------- q-t diagrams

// The plot: q horizontal, t vertical upwards (as in the paper's figures).
struct Frame {
  double q_lo, q_hi, t_lo, t_hi;
  static constexpr double width = 360, height = 330, left = 56, right = 14, top = 24, bottom = 42;
  double x(double q) const { return left + (q - q_lo) / (q_hi - q_lo) * (width - left - right); }
  double y(double t) const { return top + (t_hi - t) / (t_hi - t_lo) * (height - top - bottom); }
};

// The range of q over every bounded band edge and marker, padded.
Frame frame_of(const Drawing& d, int axis)
{
  double lo = INFINITY, hi = -INFINITY;
  auto take = [&](double q) { if (std::isfinite(q)) { lo = std::min(lo, q); hi = std::max(hi, q); } };
  for (const Drawn_object& o : d.objects) {
    if (!drawable(o, axis)) continue;
    for (double t : band_times(o, d.t_lo, d.t_hi)) {
      Extent e = extent_at(o, axis, t);
      if (e.framed) { take(e.lo); take(e.hi); }
    }
  }
  for (const Marker& m : d.markers) take(m.point[axis]);
  if (lo > hi) { lo = -1; hi = 1; }
  double pad = hi - lo > 0 ? 0.06 * (hi - lo) : std::max(1.0, std::abs(lo));
  double t_pad = 0.05 * (d.t_hi - d.t_lo);
  return {lo - pad, hi + pad, d.t_lo - t_pad, d.t_hi + t_pad};
}

std::string coordinate(double v) { return format("%.2f", v); }

// An object's space-time extent along the axis: a polygon through tL, every
// breakpoint (a turning object's samples) and tH, lower edge upwards then
// upper edge downwards; an unbounded side at the frame's edge.
std::string band_polygon(const Drawn_object& o, int axis, const Frame& f, double t_lo, double t_hi)
{
  std::vector<double> ts = band_times(o, t_lo, t_hi);
  std::vector<Extent> es;
  for (double t : ts) es.push_back(extent_at(o, axis, t));
  std::string points;
  auto edge = [&](std::size_t i, bool upper) {
    double q = upper ? es[i].hi : es[i].lo;
    if (!std::isfinite(q)) q = upper ? f.q_hi : f.q_lo;
    points += coordinate(f.x(q)) + "," + coordinate(f.y(ts[i])) + " ";
  };
  for (std::size_t i = 0; i < ts.size(); ++i) edge(i, false);
  for (std::size_t i = ts.size(); i-- > 0;) edge(i, true);
  std::string note = std::string(o.box.bounded() ? "" : " (unbounded, clipped)") +
                     (o.turns() ? " (turns: extent of its vertices under the poses, sampled)" : "");
  return "<polygon points=\"" + points + "\" fill=\"" + o.colour + "\" fill-opacity=\"0.35\" stroke=\"" +
         o.colour + "\" stroke-width=\"1.5\"" + (o.turns() ? " class=\"turning\"" : "") + "><title>" +
         escape(o.name + note) + "</title></polygon>\n";
}

double nice_step(double span, int wanted)
{
  double raw = span / wanted, p = std::pow(10.0, std::floor(std::log10(raw))), m = raw / p;
  return p * (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10);
}

// A tick's label in decimal, with as many decimals as the step needs (never
// an exponent: coordinates read as numbers, however large).
std::string tick_text(double v, double step)
{
  int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 12);
  char buffer[400];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return std::string(buffer) == "-0" ? "0" : buffer;
}

struct Ticks {
  std::vector<double> values;
  double step;
};

// The ticks of [lo, hi] (the near-zero one at 0): as many as fit along
// `pixels` with labels `across` (their text width) or not (a line each).
Ticks ticks(double lo, double hi, double pixels, bool across)
{
  Ticks t{{}, 1};
  for (int wanted = 6; wanted >= 1; --wanted) {
    t = {{}, nice_step(hi - lo, wanted)};
    for (double k = std::ceil(lo / t.step); k * t.step <= hi && t.values.size() < 20; ++k)
      t.values.push_back(std::abs(k) < 0.5 ? 0.0 : k * t.step);
    std::size_t widest = 0;
    for (double v : t.values) widest = std::max(widest, tick_text(v, t.step).size());
    double each = across ? 6.2 * widest + 10 : 16;   // 11px text: about 6.2px a character
    if (t.values.size() * each <= pixels) return t;
  }
  return t;
}

std::string svg_text(double x, double y, const std::string& anchor, const std::string& s, const char* cls = "")
{
  return "<text x=\"" + coordinate(x) + "\" y=\"" + coordinate(y) + "\" text-anchor=\"" + anchor +
         "\" class=\"" + cls + "\">" + escape(s) + "</text>\n";
}

std::string svg_line(double x1, double y1, double x2, double y2, const char* cls)
{
  return "<line x1=\"" + coordinate(x1) + "\" y1=\"" + coordinate(y1) + "\" x2=\"" + coordinate(x2) +
         "\" y2=\"" + coordinate(y2) + "\" class=\"" + cls + "\"/>\n";
}

std::string svg_axes(const Frame& f, const std::string& q_name, bool zoom)
{
  std::string out;
  double x0 = Frame::left, x1 = Frame::width - Frame::right, y0 = Frame::top, y1 = Frame::height - Frame::bottom;
  Ticks q_ticks = ticks(f.q_lo, f.q_hi, x1 - x0, true), t_ticks = ticks(f.t_lo, f.t_hi, y1 - y0, false);
  for (double q : q_ticks.values) {
    out += svg_line(f.x(q), y0, f.x(q), y1, "grid");
    out += svg_text(f.x(q), y1 + 14, "middle", tick_text(q, q_ticks.step));
  }
  for (double t : t_ticks.values) {
    out += svg_line(x0, f.y(t), x1, f.y(t), "grid");
    out += svg_text(x0 - 5, f.y(t) + 4, "end", tick_text(t, t_ticks.step));
  }
  out += "<rect x=\"" + coordinate(x0) + "\" y=\"" + coordinate(y0) + "\" width=\"" + coordinate(x1 - x0) +
         "\" height=\"" + coordinate(y1 - y0) + "\" class=\"frame\"/>\n";
  out += svg_text((x0 + x1) / 2, Frame::height - 6, "middle", q_name, "axis");
  out += svg_text(14, (y0 + y1) / 2, "middle", "t", "axis");
  out += svg_text(x0, 15, "start", q_name + "\xE2\x80\x93t: extent along " + q_name + " over time" + (zoom ? ", near the contact" : ""),
                  "heading");
  return out;
}

// The searched span [tL, tH] as dashed lines.
std::string svg_span(const Frame& f, double t_lo, double t_hi)
{
  double x0 = Frame::left, x1 = Frame::width - Frame::right;
  return svg_line(x0, f.y(t_lo), x1, f.y(t_lo), "span") + svg_line(x0, f.y(t_hi), x1, f.y(t_hi), "span") +
         svg_text(x1 - 3, f.y(t_lo) + 12, "end", "tL = " + format("%g", t_lo), "span-label") +
         svg_text(x1 - 3, f.y(t_hi) - 4, "end", "tH = " + format("%g", t_hi), "span-label");
}

std::string svg_marker(const Marker& m, int axis, const Frame& f)
{
  std::string x = coordinate(f.x(m.point[axis])), y = coordinate(f.y(m.point[3]));
  double cx = f.x(m.point[axis]), cy = f.y(m.point[3]);
  std::string title = "<title>" + escape(m.title) + "</title>";
  switch (m.kind) {
    case Marker::Kind::Witness:
      return "<circle cx=\"" + x + "\" cy=\"" + y + "\" r=\"4\" class=\"witness\">" + title + "</circle>\n";
    case Marker::Kind::Earliest:
      return svg_line(Frame::left, cy, Frame::width - Frame::right, cy, "earliest-line") +
             "<polygon points=\"" + coordinate(cx) + "," + coordinate(cy - 8) + " " + coordinate(cx + 8) + "," + y +
             " " + coordinate(cx) + "," + coordinate(cy + 8) + " " + coordinate(cx - 8) + "," + y +
             "\" class=\"earliest\">" + title + "</polygon>\n";
    default:
      return "<path d=\"M" + coordinate(cx - 5) + " " + coordinate(cy - 5) + "L" + coordinate(cx + 5) + " " +
             coordinate(cy + 5) + "M" + coordinate(cx - 5) + " " + coordinate(cy + 5) + "L" + coordinate(cx + 5) +
             " " + coordinate(cy - 5) + "\" class=\"other\">" + title + "</path>\n";
  }
}

// The diagram of one axis; zoom: in that frame (about the contact), the
// markers clipped to it too.
std::string svg_diagram(const Drawing& d, int axis, const std::string& id, const std::optional<Frame>& zoom = std::nullopt)
{
  const std::string q_name(1, "xyz"[axis]);
  std::ostringstream out;
  out << "<svg class=\"qt\" width=\"" << Frame::width << "\" height=\"" << Frame::height << "\" viewBox=\"0 0 "
      << Frame::width << " " << Frame::height << "\" role=\"img\" aria-label=\"" << q_name << "-t diagram\">\n";
  if (!d.error.empty()) {
    out << svg_text(Frame::width / 2, Frame::height / 2, "middle", "cannot draw: " + d.error) << "</svg>\n";
    return out.str();
  }
  Frame f = zoom ? *zoom : frame_of(d, axis);
  double x0 = Frame::left, y0 = Frame::top;
  out << "<clipPath id=\"" << id << "\"><rect x=\"" << x0 << "\" y=\"" << y0 << "\" width=\""
      << Frame::width - Frame::left - Frame::right << "\" height=\"" << Frame::height - Frame::top - Frame::bottom
      << "\"/></clipPath>\n" << svg_axes(f, q_name, zoom.has_value()) << "<g clip-path=\"url(#" << id << ")\">\n";
  // A zoom's bands over its window and as much again each side (clipped):
  // a turning object's samples then fall where they show.
  double wt = f.t_hi - f.t_lo;
  double t_lo = zoom ? std::max(d.t_lo, f.t_lo - wt) : d.t_lo, t_hi = zoom ? std::min(d.t_hi, f.t_hi + wt) : d.t_hi;
  for (const Drawn_object& o : d.objects)
    if (drawable(o, axis) && t_lo <= t_hi) out << band_polygon(o, axis, f, t_lo, t_hi);
  out << "</g>\n";
  if (!zoom) out << svg_span(f, d.t_lo, d.t_hi);
  // Markers unclipped (clipped in a zoom), the exact witness last so nothing hides it.
  out << (zoom ? "<g clip-path=\"url(#" + id + ")\">\n" : "");
  for (Marker::Kind kind : {Marker::Kind::Other, Marker::Kind::Earliest, Marker::Kind::Witness})
    for (const Marker& m : d.markers)
      if (m.kind == kind) out << svg_marker(m, axis, f);
  out << (zoom ? "</g>\n" : "") << "</svg>\n";
  return out.str();
}

// The diagrams again about the exact earliest contact (t*, its coordinate):
// a window a tenth of the full frame's on each axis. None without a t*.
std::string zoom_html(const Drawing& d, std::size_t index)
{
  if (!d.error.empty()) return "";
  auto m = std::find_if(d.markers.begin(), d.markers.end(), [](const Marker& k) { return k.kind == Marker::Kind::Earliest; });
  if (m == d.markers.end()) return "";
  std::string out = "<div class=\"diagrams zoom\">\n";
  for (int axis = 0; axis < 3; ++axis) {
    Frame full = frame_of(d, axis);
    double wq = 0.05 * (full.q_hi - full.q_lo), wt = 0.05 * (full.t_hi - full.t_lo);
    Frame z{m->point[axis] - wq, m->point[axis] + wq, m->point[3] - wt, m->point[3] + wt};
    out += svg_diagram(d, axis, "zoom-" + std::to_string(index) + "-" + "xyz"[axis], z);
  }
  return out + "</div>\n";
}

std::string legend(const Drawing& d)
{
  std::string out = "<div class=\"legend\">";
  for (const Drawn_object& o : d.objects)
    out += "<span class=\"item\"><span class=\"swatch\" style=\"background:" + o.colour + "\"></span>" +
           escape(o.name) + (o.box.bounded() ? "" : " (unbounded, clipped)") + (o.turns() ? " (turns)" : "") + "</span>";
  bool kinds[3] = {false, false, false};
  for (const Marker& m : d.markers) kinds[static_cast<int>(m.kind)] = true;
  if (kinds[0]) out += "<span class=\"item\"><span class=\"mark-witness\">\xE2\x97\x8F</span>exact witness</span>";
  if (kinds[1]) out += "<span class=\"item\"><span class=\"mark-earliest\">\xE2\x97\x86</span>exact earliest contact (t* dotted)</span>";
  if (kinds[2]) out += "<span class=\"item\"><span class=\"mark-other\">\xE2\x9C\x95</span>another subject's witness</span>";
  out += "<span class=\"item\"><span class=\"mark-span\">- -</span>searched span [tL, tH]</span>";
  if (d.objects.size() < d.object_count)
    out += "<span class=\"item\">" + std::to_string(d.objects.size()) + " of " + std::to_string(d.object_count) +
           " objects drawn (those named by an answer)</span>";
  return out + "</div>\n";
}

// ---------------------------------------------------------------- HTML

const char* const page_style = R"(
body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,"DejaVu Sans",sans-serif;font-size:14px;color:#222;max-width:1220px;margin:16px auto;padding:0 12px}
h1{font-size:22px;margin:8px 0}h2{font-size:17px;margin:0 0 4px;word-break:break-all}
table{border-collapse:collapse;margin:8px 0}th,td{border:1px solid #ccc;padding:3px 7px;text-align:left;vertical-align:top}
th{background:#f2f2f2}td.n{text-align:right;font-variant-numeric:tabular-nums}
code,.mono{font-family:"DejaVu Sans Mono",Menlo,Consolas,monospace;font-size:12px;word-break:break-all}
.case{border:1px solid #ddd;border-radius:6px;padding:10px 14px;margin:18px 0}
.case.bad{border-left:6px solid #d9534f}.case.good{border-left:6px solid #5cb85c}.case.err{border-left:6px solid #f0ad4e}
.bad-cell{background:#fde2e1}.good-cell{background:#e6f4e4}.err-cell{background:#fff1c2}
.name{color:#555;margin:0 0 8px}dl{display:grid;grid-template-columns:max-content auto;gap:2px 12px;margin:6px 0}dt{color:#666}dd{margin:0}
.diagrams{display:flex;flex-wrap:wrap;gap:8px}svg.qt{background:#fff;font-family:inherit;font-size:11px}
svg .grid{stroke:#eee;stroke-width:1}svg .frame{fill:none;stroke:#888}svg .axis{font-size:13px;font-style:italic;fill:#333}
svg .heading{font-size:12px;fill:#333}svg .span{stroke:#333;stroke-dasharray:6 4;stroke-width:1.2}svg .span-label{fill:#333;font-size:10px}
svg .witness{fill:#111;stroke:#fff;stroke-width:1.5}svg .earliest{fill:#ffd400;stroke:#111;stroke-width:1.5}
svg .earliest-line{stroke:#111;stroke-dasharray:1 3;stroke-width:1.2}svg .other{stroke:#d62728;stroke-width:2.2;fill:none}
.legend{display:flex;flex-wrap:wrap;gap:4px 16px;margin:4px 0 0}.item{white-space:nowrap}
.swatch{display:inline-block;width:14px;height:10px;margin-right:5px;border:1px solid #888;opacity:.7;vertical-align:middle}
.mark-witness{color:#111;margin-right:4px}.mark-earliest{color:#d4a800;margin-right:4px}.mark-other{color:#d62728;margin-right:4px;font-weight:bold}.mark-span{margin-right:4px}
ul.details{margin:4px 0;padding-left:20px}
code.whole,.whole{white-space:nowrap;word-break:normal}
.approx{color:#666;white-space:nowrap}.original{font-size:13px;font-weight:normal;color:#555}
.view3d{margin:8px 0}.view-row{display:flex;flex-wrap:wrap;gap:12px;align-items:flex-start}
canvas.view-canvas{border:1px solid #ccc;cursor:grab;width:560px;height:420px}.view-side{max-width:600px}
.view-controls{margin:8px 0}.view-controls input{width:320px;vertical-align:middle}.view-controls button{margin:4px 4px 0 0}
.dot{display:inline-block;width:10px;height:10px;border-radius:50%;margin-right:5px;vertical-align:middle}
svg.time-axis{background:#fff;font-family:inherit;font-size:11px;display:block}svg .t-star-label{font-size:11px;fill:#333}
.view-note{color:#555;font-size:12px}.view-msg{color:#a94442}.diagrams.zoom svg.qt{background:#fcfcf4}
)";

std::string cell(const std::string& content, const char* cls = "")
{
  return std::string("<td") + (*cls ? std::string(" class=\"") + cls + "\"" : "") + ">" + content + "</td>";
}

std::string number_cell(long n) { return cell(std::to_string(n), "n"); }

// ---------------------------------------------------------------- time axis

// The exact t* the page marks, with its name: regularised, else the closed
// first contact (as the 3D view's "exact t*"); none without one.
std::optional<std::pair<std::string, std::string>> t_star_of(const Comparison& c)
{
  const Subject_row* ref = c.reference();
  const Subject_row* closed = c.reference_in("closed");
  if (ref && ref->earliest) return std::make_pair(std::string("t*"), ref->earliest->t);
  if (closed && closed->earliest) return std::make_pair(std::string("t* (closed)"), closed->earliest->t);
  return std::nullopt;
}

struct Time_frame {
  double t_lo, t_hi;
  static constexpr double width = 1092, height = 56, left = 56, right = 28, y = 30;
  double x(double t) const { return left + (t - t_lo) / (t_hi - t_lo) * (width - left - right); }
};

// A turning object's pose times on the axis, in its colour.
std::string svg_pose_ticks(const Report_case& rc, const Drawing& d, const Time_frame& f)
{
  std::string out;
  for (const Drawn_object& o : d.objects)
    for (const Pose& p : rc.scene.objects[o.index].motion.poses) {
      if (!o.turns()) break;
      double t = round_to_nearest(p.t), x = f.x(t), y = Time_frame::y;
      if (t < d.t_lo || t > d.t_hi) continue;
      out += "<polygon points=\"" + coordinate(x - 5) + "," + coordinate(y - 9) + " " + coordinate(x + 5) + "," +
             coordinate(y - 9) + " " + coordinate(x) + "," + coordinate(y - 1) + "\" fill=\"" + o.colour +
             "\" class=\"pose-time\"><title>" + escape(o.name + ": pose at t = " + to_string(p.t)) + "</title></polygon>\n";
    }
  return out;
}

// t* at its double (drawing only); its exact text in the title and data-exact.
std::string svg_t_star(const std::string& name, const std::string& text, const Time_frame& f)
{
  std::optional<double> t = decimal_value(text);
  if (!t) return "";
  double x = f.x(*t), y = Time_frame::y;
  const char* anchor = x > Time_frame::width - 110 ? "end" : x < Time_frame::left + 50 ? "start" : "middle";
  return "<g class=\"t-star\" data-t=\"" + format("%.17g", *t) + "\" data-exact=\"" + escape(text) + "\"><title>" +
         escape("exact " + name + " = " + text) + "</title>" + svg_line(x, 4, x, y + 8, "earliest-line") +
         "<polygon points=\"" + coordinate(x) + "," + coordinate(y - 6) + " " + coordinate(x + 6) + "," + coordinate(y) +
         " " + coordinate(x) + "," + coordinate(y + 6) + " " + coordinate(x - 6) + "," + coordinate(y) +
         "\" class=\"earliest\"/>" + svg_text(x, 12, anchor, name + " \xE2\x89\x88 " + format("%.6g", *t), "t-star-label") +
         "</g>\n";
}

// The scene's time axis [tL, tH]: ticks, each turning object's pose times
// and the exact t*, with a line giving t*'s exact text.
std::string time_axis_html(const Report_case& rc, const Drawing& d)
{
  if (!(d.t_lo < d.t_hi)) return "";
  Time_frame f{d.t_lo, d.t_hi};
  double x0 = Time_frame::left, x1 = Time_frame::width - Time_frame::right, y = Time_frame::y;
  std::ostringstream out;
  out << "<svg class=\"time-axis\" width=\"" << Time_frame::width << "\" height=\"" << Time_frame::height
      << "\" viewBox=\"0 0 " << Time_frame::width << " " << Time_frame::height << "\" role=\"img\" aria-label=\"time axis\">\n"
      << svg_line(x0, y, x1, y, "frame") << svg_text(x0 - 10, y + 4, "end", "t", "axis");
  Ticks tk = ticks(d.t_lo, d.t_hi, x1 - x0, true);
  for (double t : tk.values) out << svg_line(f.x(t), y, f.x(t), y + 5, "frame") << svg_text(f.x(t), y + 18, "middle", tick_text(t, tk.step));
  out << svg_pose_ticks(rc, d, f);
  auto t_star = t_star_of(rc.comparison);
  if (t_star) out << svg_t_star(t_star->first, t_star->second, f);
  out << "</svg>\n<p class=\"view-note\">Time axis over [tL, tH]";
  if (t_star) out << "; \xE2\x97\x86 exact " << escape(t_star->first) << " = " << number_html(t_star->second);
  if (std::any_of(d.objects.begin(), d.objects.end(), [](const Drawn_object& o) { return o.turns(); }))
    out << "; \xE2\x96\xBE a turning object's pose times";
  out << ".</p>\n";
  return out.str();
}

// ---------------------------------------------------------------- what turns where

// The turn from pose a to pose b as q goes linearly between them: q_b q_a*
// is (cos h, sin h u) up to scale, so the world axis is u and the angle 2h,
// past 180 degrees when q_a . q_b < 0 (the longer way round).
std::pair<std::array<double, 3>, double> turn_between(const std::array<double, 4>& a, const std::array<double, 4>& b)
{
  double w = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  std::array<double, 3> v{a[0] * b[1] - b[0] * a[1] - (b[2] * a[3] - b[3] * a[2]),
                          a[0] * b[2] - b[0] * a[2] - (b[3] * a[1] - b[1] * a[3]),
                          a[0] * b[3] - b[0] * a[3] - (b[1] * a[2] - b[2] * a[1])};
  double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (n > 0) for (double& e : v) e /= n;
  return {v, 2 * std::atan2(n, w) * 180 / M_PI};
}

std::string short_number(double x)
{
  std::string s = format("%.4g", x);
  return s == "-0" ? "0" : s;
}

std::string exact_point(const std::array<Rational, 3>& c)
{
  return "(" + to_string(c[0]) + ", " + to_string(c[1]) + ", " + to_string(c[2]) + ")";
}

// A row: the object, when, the angle turned, its axis, the centre c(t).
std::string turn_row(const std::string& name, const std::string& when, const std::array<double, 4>& a,
                     const std::array<double, 4>& b, const std::string& centre)
{
  auto [axis, degrees] = turn_between(a, b);
  bool turns = degrees > 0;
  std::string axis_text = turns ? "(" + short_number(axis[0]) + ", " + short_number(axis[1]) + ", " + short_number(axis[2]) + ")" : dash;
  return "<tr>" + cell(escape(name)) + cell(when) + cell(short_number(degrees) + "\xC2\xB0", "n whole") +
         cell(axis_text, "whole") + cell("<span class=\"mono\">" + escape(centre) + "</span>") + "</tr>\n";
}

// One turning object's rows: its orientation at the first pose (from the
// shape as written), then each pose segment (at most 40 shown).
std::string turn_rows(const Drawn_object& o, const std::vector<Pose>& poses)
{
  const std::vector<Drawn_pose>& p = o.poses;
  std::string out = turn_row(o.name, "at t = " + number_html(to_string(poses[0].t)) + " (first pose)", {1, 0, 0, 0},
                             p[0].q, "c = " + exact_point(poses[0].translate));
  std::size_t shown = std::min<std::size_t>(poses.size() - 1, 40);
  for (std::size_t i = 0; i < shown; ++i) {
    const Pose &a = poses[i], &b = poses[i + 1];
    std::string centre = a.translate == b.translate ? exact_point(a.translate) + ", fixed"
                                                    : exact_point(a.translate) + " \xE2\x86\x92 " + exact_point(b.translate);
    out += turn_row(o.name, "[" + number_html(to_string(a.t)) + ", " + number_html(to_string(b.t)) + "]", p[i].q, p[i + 1].q, centre);
  }
  if (shown + 1 < poses.size())
    out += "<tr><td colspan=\"5\">" + escape(o.name) + ": " + std::to_string(poses.size() - 1 - shown) + " more pose segments</td></tr>\n";
  return out;
}

// "What turns where": per turning object and pose segment, the angle turned
// (q linear between poses), the world axis and the path of the centre.
std::string turns_html(const Report_case& rc, const Drawing& d)
{
  std::string rows;
  for (const Drawn_object& o : d.objects)
    if (o.turns()) rows += turn_rows(o, rc.scene.objects[o.index].motion.poses);
  if (rows.empty()) return "";
  return "<p class=\"view-note\">What turns where: the turn over each pose segment (degrees, about the world axis "
         "through the centre c(t); doubles, display only).</p>\n<table class=\"turns\">\n<tr><th>object</th><th>time</th>"
         "<th>turn</th><th>axis</th><th>centre c(t)</th></tr>\n" + rows + "</table>\n";
}

// The mesh files the scene read and what was done to them (scene/Mesh_record.h):
// an answer about a repaired, scaled or hull solid says so (issue 58 item 1).
std::string meshes_html(const Report_case& rc)
{
  std::string rows;
  for (const Mesh_record& m : rc.scene.meshes) {
    std::string repairs;
    for (const std::string& r : m.repairs) repairs += (repairs.empty() ? "" : "<br>") + escape(r);
    rows += "<tr>" + cell(escape(m.file)) + number_cell(m.facets) + number_cell(m.pieces) + cell(escape(m.scale)) +
            cell(escape(m.solid_rule)) + cell(repairs.empty() ? "none" : repairs) + "</tr>\n";
  }
  if (rows.empty()) return "";
  return "<p class=\"view-note\">Mesh files: the answers are about these solids, scaled and repaired as the scene "
         "asks (docs/meshes.md).</p>\n<table class=\"meshes\">\n<tr><th>file</th><th>facets</th><th>convex pieces</th>"
         "<th>scale</th><th>solid</th><th>repairs</th></tr>\n" + rows + "</table>\n";
}

// Fuzz findings: per subject, its disagreements and faults by family.
std::string family_html(const json& s)
{
  std::ostringstream out;
  for (const auto& t : s["by_subject"].items()) {
    const json& families = t.value()["by_family"];
    if (families.empty()) continue;
    out << "<p>" << escape(t.key()) << ", findings by family:";
    for (const auto& f : families.items()) out << " " << escape(f.key()) << " " << f.value().get<long>() << ";";
    out << "</p>\n";
  }
  return out.str();
}

std::string summary_html(const json& s)
{
  std::ostringstream out;
  out << "<h2>Summary</h2>\n<table>\n<tr><th>cases</th><th>all agree</th><th>some disagreement</th><th>some error</th>"
      << "<th>answers compared</th><th>agreements</th><th>disagreements</th><th>errors</th><th>skipped</th></tr>\n<tr>"
      << number_cell(s.value("scenes", 0L) + s.value("queries", 0L));
  for (const char* k : {"scenes_agreeing", "scenes_disagreeing", "scenes_with_errors", "answers", "agreements",
                        "disagreements", "errors", "skipped"})
    out << number_cell(s.value(k, 0L));
  out << "</tr>\n</table>\n";
  if (s.value("queries", 0L) > 0)
    out << "<p>" << s.value("scenes", 0L) << " scenes, " << s.value("queries", 0L) << " CCD queries.</p>\n";
  out << "<table>\n<tr><th>subject</th><th>semantics</th><th>time per query</th><th>answers</th><th>agreements</th>";
  for (const auto& c : s["by_cause"].items()) out << "<th>" << escape(c.key()) << "</th>";
  out << "<th>errors</th><th>skipped</th></tr>\n";
  auto time_cell = [&](const json& t) {
    const json& v = t.contains("seconds_per_query") ? t["seconds_per_query"] : json();
    return cell(v.is_number() ? seconds_text(v.get<double>()) : dash, "n whole");
  };
  auto row = [&](const std::string& name, const json& t) {
    out << "<tr><td>" << name << "</td>" << cell(escape(t.value("semantics", ""))) << time_cell(t)
        << number_cell(t["answers"].get<long>()) << number_cell(t["agreements"].get<long>());
    for (const auto& c : s["by_cause"].items()) out << number_cell(t["by_cause"].value(c.key(), 0L));
    out << number_cell(t["errors"].get<long>()) << number_cell(t.value("skipped", 0L)) << "</tr>\n";
  };
  for (const auto& t : s["by_subject"].items()) row(escape(t.key()), t.value());
  row("<b>all</b>", s);
  out << "</table>\n" << family_html(s);
  const json& exact_time = s["reference_seconds_per_query"];
  if (exact_time.is_number()) out << "<p>exact (the reference): " << seconds_text(exact_time.get<double>()) << " per query.</p>\n";
  return out.str();
}

std::string status_text(const Comparison& comparison)
{
  std::string out;
  for (const Subject_row& s : comparison.subjects) {
    if (s.disagrees()) out += (out.empty() ? "" : "; ") + s.subject + ": " + *s.cause;
    else if (s.failed()) out += (out.empty() ? "" : "; ") + s.subject + ": " + s.cause.value_or("error");
  }
  return out.empty() ? "all agree" : out;
}

const char* case_class(const Comparison& comparison)
{
  return case_disagrees(comparison) ? "bad" : comparison.has_failure() ? "err" : "good";
}

std::string index_html(const std::vector<Report_case>& cases, const std::vector<std::size_t>& order)
{
  std::ostringstream out;
  out << "<h2>Cases</h2>\n<table>\n<tr><th>file</th><th>name</th><th>exact</th><th>result</th></tr>\n";
  for (std::size_t i : order) {
    const Comparison& c = cases[i].comparison;
    std::string cls = std::string(case_class(c)) + "-cell";
    out << "<tr><td><a href=\"#case-" << i << "\"><code>" << escape(cases[i].file) << "</code></a></td>"
        << cell(escape(c.name)) << cell(verdict_text(c.reference()))
        << cell(escape(status_text(c)), cls.c_str()) << "</tr>\n";
  }
  return out.str() + "</table>\n";
}

std::string result_cell(const Subject_row& s)
{
  if (s.failed()) return cell((s.cause ? *s.cause + ": " : "error: ") + escape(s.error), "err-cell");
  if (s.skipped) return cell("skipped: " + escape(*s.skipped));
  if (s.disagrees()) return cell("disagrees: " + escape(*s.cause), "bad-cell");
  if (s.reference) return cell("reference");
  return cell(s.agrees == false ? "disagrees" : "agrees", s.agrees == false ? "bad-cell" : "good-cell");
}


// A subject's row: a scene's has its semantics and witness, a CCD query's not
// (one semantics, no witness).
std::string subject_row(const Subject_row& s, bool scene)
{
  std::string t_star = s.earliest ? number_html(s.earliest->t) : dash;
  std::string row = "<tr>" + cell(escape(s.subject));
  if (scene) row += cell(escape(s.semantics));
  row += cell(verdict_text(&s));
  if (scene)
    row += cell("<span class=\"mono\">" + located_html(s.witness) + "</span>") + cell(yes_no(s.witness_valid));
  return row + cell(t_star) + cell(s.t_error ? number_html(*s.t_error) : dash) +
         cell(s.seconds ? seconds_text(*s.seconds) : dash, "n whole") + result_cell(s) + "</tr>\n";
}

std::string details_html(const Comparison& comparison)
{
  std::string out;
  for (const Disagreement& d : comparison.disagreements)
    out += "<li><b>" + escape(d.subject) + "</b> (" + escape(d.cause) + "): " + escape(d.detail) + "</li>\n";
  for (const Subject_row& s : comparison.subjects)
    if (s.failed() && !s.cause) out += "<li><b>" + escape(s.subject) + "</b> failed: " + escape(s.error) + "</li>\n";
  return out.empty() ? "" : "<ul class=\"details\">\n" + out + "</ul>\n";
}

std::string facts_html(const Report_case& rc)
{
  const Comparison& c = rc.comparison;
  const Subject_row* ref = c.reference();
  std::optional<Located> none;
  const std::optional<Located>& earliest = ref ? ref->earliest : none;
  const Subject_row* closed = c.reference_in("closed");
  std::string out = "<dl>\n<dt>exact verdict (regularised)</dt><dd><b>" + verdict_text(ref) + "</b></dd>\n";
  out += "<dt>exact verdict (closed: touching counts)</dt><dd><b>" + verdict_text(closed) + "</b>" +
         (c.closed_touch == true ? " (touching only: the interiors do not meet)" : "") + "</dd>\n";
  out += "<dt>exact witness</dt><dd class=\"mono\">" + located_html(ref ? ref->witness : none) + "</dd>\n";
  out += "<dt>exact earliest</dt><dd class=\"mono\">" +
         (earliest ? "t* = " + number_html(earliest->t) + ", " + located_html(earliest) : std::string(dash)) + "</dd>\n";
  out += "<dt>time span</dt><dd class=\"mono\">[" + number_html(to_string(rc.scene.t_lo)) + ", " +
         number_html(to_string(rc.scene.t_hi)) + "]</dd>\n";
  if (closed && closed->earliest)
    out += "<dt>exact first contact (closed)</dt><dd class=\"mono\">t* = " + number_html(closed->earliest->t) + ", " +
           located_html(closed->earliest) + "</dd>\n";
  return out + "</dl>\n";
}

// A relative link from the report folder would break when the folder moves;
// the file as given is what the user ran the report with.
std::string original_link(const Report_case& rc)
{
  if (rc.original.empty()) return "";
  return " <span class=\"original\">minimised from <a href=\"" + escape(rc.original) + "\"><code>" +
         escape(rc.original) + "</code></a></span>";
}

std::string section_head(const Report_case& rc, std::size_t index)
{
  return std::string("<section class=\"case ") + case_class(rc.comparison) + "\" id=\"case-" + std::to_string(index) +
         "\">\n<h2><code>" + escape(rc.file) + "</code>" + original_link(rc) + "</h2>\n<p class=\"name\">" +
         escape(rc.comparison.name) + "</p>\n";
}

// A CCD query's vertices, exact, at t = 0 and t = 1 (in place of diagrams).
std::string query_html(const Ccd_query& q)
{
  static const char* const vertex_face[] = {"v", "f0", "f1", "f2"};
  static const char* const edge_edge[] = {"ea0", "ea1", "eb0", "eb1"};
  const char* const* names = q.type() == Ccd_type::vertex_face ? vertex_face : edge_edge;
  auto point = [](const Ccd_query::Point& p) {
    return "<span class=\"mono\">(" + number_html(to_string(p[0])) + ", " + number_html(to_string(p[1])) + ", " +
           number_html(to_string(p[2])) + ")</span>";
  };
  std::string out = "<table>\n<tr><th>vertex</th><th>at t = 0</th><th>at t = 1</th></tr>\n";
  for (int i = 0; i < 4; ++i) out += "<tr>" + cell(names[i]) + cell(point(q.row(i))) + cell(point(q.row(i + 4))) + "</tr>\n";
  return out + "</table>\n";
}

std::string ccd_case_html(const Report_case& rc, std::size_t index)
{
  const Comparison& c = rc.comparison;
  const Subject_row* exact = c.reference();
  std::ostringstream out;
  out << section_head(rc, index) << "<dl>\n<dt>query</dt><dd>" << ccd_type_name(rc.ccd->query.type()) << "</dd>\n";
  if (!rc.family.empty()) out << "<dt>family</dt><dd>" << escape(rc.family) << "</dd>\n";
  out << "<dt>exact verdict (closed: touching counts)</dt><dd><b>" << verdict_text(exact) << "</b></dd>\n"
      << "<dt>exact t*</dt><dd class=\"mono\">" << (exact && exact->earliest ? number_html(exact->earliest->t) : dash)
      << "</dd>\n</dl>\n<table>\n<tr><th>subject</th><th>verdict</th><th>t*</th><th>t error</th><th>time</th>"
      << "<th>result</th></tr>\n";
  for (const Subject_row& s : c.subjects) out << subject_row(s, false);
  out << "</table>\n" << details_html(c) << query_html(rc.ccd->query) << "</section>\n";
  return out.str();
}

std::string case_html(const Report_case& rc, std::size_t index)
{
  if (rc.ccd) return ccd_case_html(rc, index);
  const Comparison& c = rc.comparison;
  std::ostringstream out;
  out << section_head(rc, index) << facts_html(rc)
      << "<table>\n<tr><th>subject</th><th>semantics</th><th>verdict</th><th>witness</th><th>witness valid</th><th>t*</th>"
      << "<th>t error</th><th>time</th><th>result</th></tr>\n";
  for (const Subject_row& s : c.subjects) out << subject_row(s, true);
  out << "</table>\n" << details_html(c) << meshes_html(rc);
  if (!rc.scene.objects.empty()) out << scene_view_html(rc, index, objects_to_draw(rc));
  Drawing d = drawing_of(rc);
  // Nothing to draw: one line, not three empty diagrams.
  if (!d.error.empty()) {
    out << "<p class=\"view-note\">No q-t diagrams: " << escape(d.error) << ".</p>\n</section>\n";
    return out.str();
  }
  out << time_axis_html(rc, d) << "<div class=\"diagrams\">\n";
  for (int axis = 0; axis < 3; ++axis) out << svg_diagram(d, axis, "clip-" + std::to_string(index) + "-" + "xyz"[axis]);
  out << "</div>\n" << zoom_html(d, index) << legend(d) << turns_html(rc, d) << "</section>\n";
  return out.str();
}

std::string page_html(const std::vector<Report_case>& cases, const json& summary, bool three)
{
  std::vector<std::size_t> order(cases.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    auto rank = [&](std::size_t i) { return case_disagrees(cases[i].comparison) ? 0 : cases[i].comparison.has_failure() ? 1 : 2; };
    return rank(a) < rank(b);
  });
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>clash4d verification report</title>\n"
      << "<style>" << page_style << "</style>\n</head>\n<body>\n<h1>clash4d verification report</h1>\n"
      << "<p>Every subject's answer held against the exact one in the subject's own semantics (regularised: touching "
      << "is not a collision; closed: touching counts; a CCD query is always closed). "
      << "Diagrams: each object's extent along one axis over time (a turning object's over its vertices as its "
      << "poses place them, sampled), above them the time axis with the exact t*. 3D views: each object as the union of the "
      << "convex cells of its CSG formula, placed by its motion at the chosen time. Both in doubles, for "
      << "presentation only: no answer is read from them.</p>\n";
  if (!three) out << "<p class=\"view-msg\">The 3D views need three.js (three.min.js beside this page), which was not found when "
                  << "the report was written.</p>\n";
  out << summary_html(summary) << index_html(cases, order);
  for (std::size_t i : order) out << case_html(cases[i], i);
  out << "<script src=\"three.min.js\"></script>\n<script>" << scene_view_script() << "</script>\n</body>\n</html>\n";
  return out.str();
}

// ---------------------------------------------------------------- files

// three.js as CMake found it (CLASH4D_THREE_JS), copied beside the page so
// the report opens offline; none when absent (the page says so).
std::string three_js_path()
{
#ifdef CLASH4D_THREE_JS
  return CLASH4D_THREE_JS;
#else
  return "not configured";
#endif
}

std::optional<std::string> three_js()
{
#ifdef CLASH4D_THREE_JS
  std::ifstream in(CLASH4D_THREE_JS, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (in.is_open() && !text.str().empty()) return text.str();
#endif
  return std::nullopt;
}

} // namespace

Report_case ccd_report_case(const std::string& file, const Ccd_comparison& c, const std::string& family)
{
  return {file, Scene(), c.comparison, family, c};
}

void write_report(const std::vector<Report_case>& cases, const std::string& dir)
{
  json summary = summary_of(cases);
  std::optional<std::string> three = three_js();
  if (!three)
    std::cerr << "clash4d report: warning: three.js not found (" << three_js_path()
              << "): the report's 3D views will not draw (install libjs-three)\n";
  std::string report = report_json(cases, summary), junit = junit_xml(cases), page = page_html(cases, summary, three.has_value());
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw std::runtime_error(dir + ": cannot create the report directory" + (ec ? ": " + ec.message() : ""));
  write_file_atomically((fs::path(dir) / "report.json").string(), report);
  write_file_atomically((fs::path(dir) / "junit.xml").string(), junit);
  if (three) write_file_atomically((fs::path(dir) / "three.min.js").string(), *three);
  write_file_atomically((fs::path(dir) / "index.html").string(), page);
}

} // namespace clash4d
