#include "compare/Shrinker.h"
#include "scene/Pose_motion.h"
#include "numbers/Rational.h"
#include "scene/Json_reader.h"
#include "scene/Scene_reader.h"
#include "scene/Scene_writer.h"

#include <algorithm>
#include <optional>
#include <set>

namespace clash4d {
namespace {

using Kind = Solid::Kind;
using Integer = CGAL::Gmpz;
using Steps = std::vector<Scene> (*)(const Scene&);

// ------------------------------------------------------------------ addressing

void collect(Solid& s, std::vector<Solid*>& out)
{
  out.push_back(&s);
  for (auto& c : s.children) collect(c, out);
}

// Every solid node of the scene, objects in order, each shape in preorder.
std::vector<Solid*> solids(Scene& s)
{
  std::vector<Solid*> out;
  for (auto& o : s.objects) collect(o.shape, out);
  return out;
}

// Every number of the scene, in a fixed order.
std::vector<Rational*> numbers(Scene& s)
{
  std::vector<Rational*> out{&s.t_lo, &s.t_hi};
  for (Solid* n : solids(s))
    for (auto& q : n->numbers) out.push_back(&q);
  for (auto& o : s.objects) {
    for (auto& t : o.motion.times) out.push_back(&t);
    for (auto& v : o.motion.velocities)
      for (auto& q : v) out.push_back(&q);
  }
  return out;
}

// A turning object's numbers: its poses' (t, translate, rotate), in order.
std::vector<Rational*> pose_numbers(Motion& m)
{
  std::vector<Rational*> out;
  for (Pose& p : m.poses) {
    out.push_back(&p.t);
    for (auto& c : p.translate) out.push_back(&c);
    for (auto& c : p.rotate) out.push_back(&c);
  }
  return out;
}

// Adds the scene with object k moving by m: through set_motion, which
// keeps the shape as the pose motion needs it (at c(0) when m no longer
// turns, scene/Pose_motion.h); poses it refuses (equal times, a zero
// quaternion) are no candidate.
void add_with_motion(std::vector<Scene>& out, const Scene& s, std::size_t k, Motion m)
{
  Scene c = s;
  try {
    set_motion(c.objects[k], std::move(m));
  } catch (const std::exception&) {
    return;
  }
  out.push_back(std::move(c));
}

// A copy of s with node m (in the order of solids()) changed by `edit`.
template <class Edit>
void add_node_edit(std::vector<Scene>& out, const Scene& s, std::size_t m, Edit edit)
{
  Scene c = s;
  edit(*solids(c)[m]);
  out.push_back(std::move(c));
}

// ------------------------------------------------------------------ steps

std::vector<Scene> drop_objects(const Scene& s)
{
  std::vector<Scene> out;
  if (s.objects.size() <= 2) return out;
  for (int k = 0; k < static_cast<int>(s.objects.size()); ++k) {
    Scene c = s;
    c.objects.erase(c.objects.begin() + k);
    c.ignore.clear();
    for (const auto& p : s.ignore)
      if (p.first != k && p.second != k) c.ignore.emplace_back(p.first - (p.first > k), p.second - (p.second > k));
    out.push_back(std::move(c));
  }
  return out;
}

bool is_operation(Kind k)
{
  return k == Kind::Union || k == Kind::Intersection || k == Kind::Difference || k == Kind::Translate || k == Kind::Rotate;
}

std::vector<Scene> replace_by_child(const Scene& s)
{
  std::vector<Scene> out;
  Scene probe = s;
  std::vector<Solid*> nodes = solids(probe);
  for (std::size_t m = 0; m < nodes.size(); ++m) {
    if (!is_operation(nodes[m]->kind)) continue;
    for (std::size_t i = 0; i < nodes[m]->children.size(); ++i)
      add_node_edit(out, s, m, [i](Solid& x) {
        Solid child = std::move(x.children[i]);
        x = std::move(child);
      });
  }
  return out;
}

std::vector<Scene> drop_children(const Scene& s)
{
  std::vector<Scene> out;
  Scene probe = s;
  std::vector<Solid*> nodes = solids(probe);
  for (std::size_t m = 0; m < nodes.size(); ++m) {
    const Solid& n = *nodes[m];
    std::size_t first = 0;
    if (n.kind == Kind::Difference && n.children.size() > 2) first = 1;   // the minuend stays
    else if ((n.kind != Kind::Union && n.kind != Kind::Intersection) || n.children.size() < 2) continue;
    for (std::size_t i = first; i < n.children.size(); ++i)
      add_node_edit(out, s, m, [i](Solid& x) { x.children.erase(x.children.begin() + static_cast<long>(i)); });
  }
  return out;
}

std::vector<Scene> shorten_motions(const Scene& s)
{
  std::vector<Scene> out;
  for (std::size_t k = 0; k < s.objects.size(); ++k) {
    const Motion& m = s.objects[k].motion;
    auto with = [&](Motion changed) {
      Scene c = s;
      c.objects[k].motion = std::move(changed);
      out.push_back(std::move(c));
    };
    Motion rest;
    rest.velocities.push_back({Rational(0), Rational(0), Rational(0)});
    with(rest);
    for (std::size_t i = 0; i < m.times.size(); ++i)
      for (std::size_t keep : {i, i + 1}) {   // the merged segment keeps the left or the right velocity
        Motion c = m;
        c.times.erase(c.times.begin() + static_cast<long>(i));
        c.velocities.erase(c.velocities.begin() + static_cast<long>(keep == i ? i + 1 : i));
        with(c);
      }
    if (m.velocities.size() > 1)
      for (std::size_t i = 0; i < m.velocities.size(); ++i) {
        Motion c = m;
        c.velocities[i] = rest.velocities[0];
        with(c);
      }
    if (m.rotates() && m.poses.size() > 1)   // a turning motion with one pose fewer
      for (std::size_t i = 0; i < m.poses.size(); ++i) {
        Motion c = m;
        c.poses.erase(c.poses.begin() + static_cast<long>(i));
        add_with_motion(out, s, k, std::move(c));
      }
  }
  return out;
}

// A half-space of a convex solid, a point of a hull, a vertex of a prism.
std::vector<Scene> drop_parts(const Scene& s)
{
  std::vector<Scene> out;
  Scene probe = s;
  std::vector<Solid*> nodes = solids(probe);
  for (std::size_t m = 0; m < nodes.size(); ++m) {
    const Solid& n = *nodes[m];
    std::size_t width = 0, least = 0, count = 0;
    if (n.kind == Kind::Convex) width = 4, least = 4, count = n.numbers.size() / 4;
    else if (n.kind == Kind::Hull) width = 3, least = 4, count = n.numbers.size() / 3;
    else if (n.kind == Kind::Prism) width = 2, least = 3, count = (n.numbers.size() - 2) / 2;
    if (count <= least) continue;
    for (std::size_t j = 0; j < count; ++j)
      add_node_edit(out, s, m, [j, width](Solid& x) {
        auto at = x.numbers.begin() + static_cast<long>(j * width);
        x.numbers.erase(at, at + static_cast<long>(width));
      });
  }
  return out;
}

// ------------------------------------------------------------------ simpler numbers

Integer magnitude(const Integer& z) { return z < 0 ? Integer(-z) : z; }

// a is simpler than b: a smaller denominator, or the same and a smaller |numerator|.
bool simpler(const Rational& a, const Rational& b)
{
  if (a.denominator() != b.denominator()) return a.denominator() < b.denominator();
  return magnitude(a.numerator()) < magnitude(b.numerator());
}

Rational floor_of(const Rational& q)
{
  Integer f;
  mpz_fdiv_q(f.mpz(), q.numerator().mpz(), q.denominator().mpz());
  return Rational(f);
}

Rational truncated(const Rational& q) { return q < 0 ? Rational(-floor_of(-q)) : floor_of(q); }

// q rounded to `digits` decimal digits (halves away from zero).
Rational rounded(const Rational& q, int digits)
{
  Rational scale(1);
  for (int i = 0; i < digits; ++i) scale *= 10;
  Rational x = q * scale + (q < 0 ? Rational(-1, 2) : Rational(1, 2));
  return truncated(x) / scale;
}

// Values simpler than q, simplest first (at most `limit`).
std::vector<Rational> simpler_values(const Rational& q, std::size_t limit = 8)
{
  std::vector<Rational> v{Rational(0), floor_of(q), floor_of(q) + 1};
  if (q.denominator() == 1) {   // integers: toward small ones
    v.push_back(q < 0 ? Rational(-1) : Rational(1));
    v.push_back(truncated(q / 10));
    v.push_back(truncated(q / 2));
  }
  for (int d = 1; d <= 30; ++d) {
    Rational r = rounded(q, d);
    if (r == q) break;
    v.push_back(r);
  }
  // Convergents of the continued fraction of q.
  Rational x = q, p0(0), p1(1), q0(1), q1(0);
  for (int k = 0; k < 40; ++k) {
    Rational a = floor_of(x);
    Rational p2 = a * p1 + p0, q2 = a * q1 + q0;
    v.push_back(p2 / q2);
    if (x == a) break;
    x = 1 / (x - a);
    p0 = p1;
    p1 = p2;
    q0 = q1;
    q1 = q2;
  }
  std::vector<Rational> out;
  for (const auto& r : v)
    if (simpler(r, q) && std::find(out.begin(), out.end(), r) == out.end()) out.push_back(r);
  std::stable_sort(out.begin(), out.end(), simpler);
  if (out.size() > limit) out.resize(limit);
  return out;
}

std::vector<Scene> simplify_numbers(const Scene& s)
{
  std::vector<Scene> out;
  Scene probe = s;
  std::vector<Rational*> slots = numbers(probe);
  for (std::size_t j = 0; j < slots.size(); ++j)
    for (const Rational& r : simpler_values(*slots[j])) {
      Scene c = s;
      *numbers(c)[j] = r;
      out.push_back(std::move(c));
    }
  for (std::size_t k = 0; k < s.objects.size(); ++k) {
    if (!s.objects[k].motion.rotates()) continue;
    Motion m = s.objects[k].motion;
    std::vector<Rational*> pose_slots = pose_numbers(m);
    for (std::size_t j = 0; j < pose_slots.size(); ++j)
      for (const Rational& r : simpler_values(*pose_slots[j])) {
        Motion c = s.objects[k].motion;
        *pose_numbers(c)[j] = r;
        add_with_motion(out, s, k, std::move(c));
      }
  }
  return out;
}

// ------------------------------------------------------------------ queries

using Query_steps = std::vector<Ccd_query> (*)(const Ccd_query&);

// The query moved by -p: every vertex at both times (its answer and t* stay).
Ccd_query translated(const Ccd_query& q, const Ccd_query::Point& p)
{
  Ccd_query c = q;
  for (int i = 0; i < 8; ++i) c.set_row(i, {q.row(i)[0] - p[0], q.row(i)[1] - p[1], q.row(i)[2] - p[2]});
  return c;
}

// Each row moved to the origin, then the integer part of row 0 removed.
std::vector<Ccd_query> remove_translations(const Ccd_query& q)
{
  std::vector<Ccd_query> out;
  for (int i = 0; i < 8; ++i) out.push_back(translated(q, q.row(i)));
  const Ccd_query::Point& first = q.row(0);
  out.push_back(translated(q, {truncated(first[0]), truncated(first[1]), truncated(first[2])}));
  return out;
}

// A vertex at rest: its position at t = 1 that of t = 0, or the reverse.
std::vector<Ccd_query> stop_vertices(const Ccd_query& q)
{
  std::vector<Ccd_query> out;
  for (int i = 0; i < 4; ++i)
    for (int from : {i, i + 4}) {
      Ccd_query c = q;
      c.set_row(from == i ? i + 4 : i, q.row(from));
      out.push_back(std::move(c));
    }
  return out;
}

std::vector<Ccd_query> simplify_coordinates(const Ccd_query& q)
{
  std::vector<Ccd_query> out;
  for (int i = 0; i < 8; ++i)
    for (std::size_t k = 0; k < 3; ++k)
      for (const Rational& r : simpler_values(q.row(i)[k])) {
        Ccd_query c = q;
        Ccd_query::Point p = q.row(i);
        p[k] = r;
        c.set_row(i, p);
        out.push_back(std::move(c));
      }
  return out;
}

std::string query_text(const Ccd_query& q)
{
  std::string out;
  for (const auto& p : q.rows())
    for (const Rational& x : p) out += to_string(x) + ",";
  return out;
}

// ------------------------------------------------------------------ the loop

// Greedy shrinking of `start` by the passes (each lists candidates, largest
// step first) while `still_fails` holds; none when no candidate was kept.
// `prepare` makes a candidate what the predicate is asked on (false: an
// invalid candidate, skipped); `text` names a candidate, so none is tried
// twice.
template <class T, class Steps_of, class Prepare, class Text>
std::optional<T> greedy_shrink(const T& start, const std::vector<Steps_of>& passes, Prepare prepare, Text text,
                               const std::function<bool(const T&)>& still_fails, std::size_t max_checks)
{
  std::optional<T> kept;
  T best = start;
  std::set<std::string> seen{text(best)};   // the input and every candidate tried (the predicate is a function)
  std::size_t checks = 0;
  auto accept = [&](const T& candidate) {
    if (!seen.insert(text(candidate)).second) return false;
    T valid;
    if (!prepare(candidate, valid) || checks >= max_checks) return false;
    ++checks;
    bool fails = false;
    try {
      fails = still_fails(valid);
    } catch (const std::exception&) {
      fails = false;
    }
    if (!fails) return false;
    best = std::move(valid);
    kept = best;
    return true;
  };
  for (bool progress = true; progress && checks < max_checks;) {
    progress = false;
    for (Steps_of steps : passes) {
      std::vector<T> candidates = steps(best);
      for (std::size_t i = 0; i < candidates.size() && checks < max_checks;) {
        if (!accept(candidates[i])) {
          ++i;
          continue;
        }
        progress = true;
        candidates = steps(best);   // go on from the same place in the new list
      }
    }
  }
  return kept;
}

} // namespace

Scene shrink_scene(const Scene& scene, const std::function<bool(const Scene&)>& still_fails, std::size_t max_checks)
{
  // Every candidate is written and read back: validated, its combinatorics redone.
  auto read_back = [](const Scene& candidate, Scene& valid) {
    try {
      // The steps change shapes and times / velocities: a rotation-free pose
      // motion is written as that translation (its shape at c(0) included,
      // scene/Pose_motion.h), so the change is kept.
      Scene edited = candidate;
      for (Scene_object& o : edited.objects)
        if (!o.motion.rotates()) o.motion.poses.clear();
      valid = read_scene(read_json_text(write_scene(edited)));
      return true;
    } catch (const std::exception&) {
      return false;
    }
  };
  std::optional<Scene> best =
      greedy_shrink<Scene>(scene,
                           std::vector<Steps>{drop_objects, replace_by_child, drop_children, shorten_motions, drop_parts,
                                              simplify_numbers},
                           read_back, [](const Scene& s) { return write_scene(s); }, still_fails, max_checks);
  if (!best) return scene;
  best->name = scene.name.empty() ? "shrunk" : "shrunk from: " + scene.name;
  return *best;
}

Ccd_query shrink_query(const Ccd_query& query, const std::function<bool(const Ccd_query&)>& still_fails,
                       std::size_t max_checks)
{
  auto as_is = [](const Ccd_query& candidate, Ccd_query& valid) {   // every query is valid
    valid = candidate;
    return true;
  };
  Ccd_query best = greedy_shrink<Ccd_query>(query, std::vector<Query_steps>{remove_translations, stop_vertices,
                                                                            simplify_coordinates},
                                            as_is, query_text, still_fails, max_checks)
                       .value_or(query);
  best.label = query.label;
  best.line = query.line;
  return best;
}

} // namespace clash4d
