#include "rotation/Rotating_extrusion.h"

#include "model/Csg_model.h"
#include "model/Far_bound.h"
#include "model/Model_builder.h"
#include "rotation/Moving_planes.h"

#include <algorithm>

namespace clash4d {

namespace {

using json = nlohmann::ordered_json;

using CGAL::is_zero;   // exact on Rational

int degree(const Time_poly& p)
{
  int d = p.size() - 1;
  while (d >= 0 && is_zero(p[d])) --d;
  return d;
}

json coefficients(const Time_poly& p)
{
  json out = json::array();
  for (int i = 0; i <= std::max(degree(p), 0); ++i) out.push_back(to_string(i < p.size() ? p[i] : Rational(0)));
  return out;
}

// A term "c*name" of a sum, its sign written by the caller: the polynomial
// coefficient in parentheses when it has more than one term.
std::string term(const Time_poly& p, const std::string& name, bool& negative)
{
  int d = degree(p), terms = 0;
  for (int i = 0; i <= d; ++i) terms += !is_zero(p[i]);
  negative = false;
  if (terms == 1 && d >= 0) {
    negative = p[d] < 0;
    Time_poly m = p;
    if (negative) m = -m;
    std::string c = time_poly_text(m);
    if (name.empty()) return c;
    return c == "1" ? name : c + "*" + name;
  }
  return "(" + time_poly_text(p) + ")" + (name.empty() ? "" : "*" + name);
}

// "(1 - t^2)*x + 2*t*y - t^2 - 1 <= 0" beside the coefficient polynomials.
json halfspace(const Moving_plane& h)
{
  static const char* names[4] = {"x", "y", "z", ""};
  std::string text;
  for (int i = 0; i < 4; ++i) {
    if (degree(h[i]) < 0) continue;
    bool negative = false;
    std::string t = term(h[i], names[i], negative);
    if (i == 3 && t.front() == '(') {   // the part without x, y, z: its terms, not a parenthesis
      t = time_poly_text(h[i]);
      negative = t.front() == '-';
      if (negative) t.erase(0, 1);
    }
    text += text.empty() ? (negative ? "-" : "") : (negative ? " - " : " + ");
    text += t;
  }
  if (text.empty()) text = "0";
  json c = json::array();
  for (const Time_poly& p : h) c.push_back(coefficients(p));
  return {{"text", text + " <= 0"}, {"coefficients", c}};
}

json tree(const Csg_model<Rational>& m, int node, const Pose_segment& s)
{
  const Csg_node& n = m.nodes[node];
  if (n.op == Csg_node::Op::Primitive) {
    const Primitive<Rational>& p = m.primitives[n.primitive];
    json hs = json::array();
    for (const Moving_plane& h : moving_planes(p.planes, s)) hs.push_back(halfspace(h));
    return {{"primitive", p.path}, {"halfspaces", hs}};
  }
  const char* op = n.op == Csg_node::Op::Union ? "union" : n.op == Csg_node::Op::Intersection ? "intersection" : "difference";
  json children = json::array();
  for (int c : n.children) children.push_back(tree(m, c, s));
  return {{op, children}};
}

// lo <= t <= hi as two half-spaces with n = 0.
json time_slab(const Rational& lo, const Rational& hi)
{
  Moving_plane below{Time_poly(Rational(0)), Time_poly(Rational(0)), Time_poly(Rational(0)), Time_poly(lo, Rational(-1))};
  Moving_plane above{Time_poly(Rational(0)), Time_poly(Rational(0)), Time_poly(Rational(0)), Time_poly(-hi, Rational(1))};
  return json::array({halfspace(below), halfspace(above)});
}

json pose(const Pose_segment& s)
{
  json q = json::array(), c = json::array();
  std::string text = "q(t) = (";
  for (int i = 0; i < 4; ++i) {
    q.push_back(coefficients(s.q[i]));
    text += (i ? ", " : "") + time_poly_text(s.q[i]);
  }
  text += "), c(t) = (";
  for (int i = 0; i < 3; ++i) {
    c.push_back(coefficients(s.c[i]));
    text += (i ? ", " : "") + time_poly_text(s.c[i]);
  }
  return {{"text", text + ")"}, {"rotate", q}, {"translate", c}};
}

// The span's ends and every object's pose times strictly inside it.
std::vector<Rational> span_ends(const std::vector<std::vector<Pose_segment>>& motions, const Scene& scene)
{
  std::vector<Rational> t = {scene.t_lo, scene.t_hi};
  for (const auto& segments : motions)
    for (const Pose_segment& s : segments)
      for (const Rational* x : {s.from_minus_infinity ? nullptr : &s.lo, s.to_plus_infinity ? nullptr : &s.hi})
        if (x && scene.t_lo < *x && *x < scene.t_hi) t.push_back(*x);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

} // namespace

std::string time_poly_text(const Time_poly& p)
{
  std::string text;
  for (int i = degree(p); i >= 0; --i) {
    if (is_zero(p[i])) continue;
    bool negative = p[i] < 0;
    Rational mag = negative ? Rational(-p[i]) : p[i];
    text += text.empty() ? (negative ? "-" : "") : (negative ? " - " : " + ");
    std::string power = i == 0 ? "" : i == 1 ? "t" : "t^" + std::to_string(i);
    if (i == 0) text += to_string(mag);
    else text += (mag == Rational(1) ? "" : to_string(mag) + "*") + power;
  }
  return text.empty() ? "0" : text;
}

json rotating_extrusion(const Scene& scene)
{
  far_bound_detail::Exact_reader reader;
  std::vector<Csg_model<Rational>> shapes;
  std::vector<std::vector<Pose_segment>> motions;
  for (const Scene_object& o : scene.objects) {
    shapes.push_back(Model_builder<far_bound_detail::Exact_reader>(reader).build(o.shape));
    motions.push_back(pose_segments(o.motion));
  }
  std::vector<Rational> ends = span_ends(motions, scene);
  json spans = json::array();
  for (std::size_t k = 0; k + 1 < ends.size(); ++k) {
    Rational mid = (ends[k] + ends[k + 1]) / 2;
    json objects = json::array();
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
      const Pose_segment& s = segment_at(motions[i], mid);
      json t = json::array({tree(shapes[i], 0, s), {{"time", time_slab(ends[k], ends[k + 1])}}});
      objects.push_back({{"name", scene.objects[i].name}, {"pose", pose(s)}, {"tree", {{"intersection", t}}}});
    }
    spans.push_back({{"t", {to_string(ends[k]), to_string(ends[k + 1])}}, {"objects", objects}});
  }
  return {{"number", "exact"}, {"rotation", true}, {"time", {to_string(scene.t_lo), to_string(scene.t_hi)}},
          {"spans", spans}};
}

} // namespace clash4d
