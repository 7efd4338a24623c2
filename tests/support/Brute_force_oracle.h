// An independent, brute-force collision oracle for tests only
// (regularised-semantics.md, item 2). It shares nothing with the pipeline but
// the Scene struct: it turns each solid into its own negation-normal formula
// over rest-frame planes (its own transforms, its own prism planes, its own
// hull facets by brute force), extrudes with its own displacement D(t), and
// decides every DNF term of "A and B" on every constant-velocity time slab
// with an exact linear program: the open polyhedron {h_i < 0, lo < t < hi} is
// non-empty iff max s subject to h_i + s <= 0 (and the slab rows) is > 0.
//
// The DNF is enumerated lazily (a term's prefix that is already infeasible
// cuts off every term that extends it), which decides exactly the same thing
// as the full expansion, only faster. The full term count is still computed
// and capped: past the cap the oracle throws rather than answer.
#ifndef CLASH4D_TESTS_SUPPORT_BRUTE_FORCE_ORACLE_H
#define CLASH4D_TESTS_SUPPORT_BRUTE_FORCE_ORACLE_H

#include "numbers/Rational.h"
#include "scene/Scene.h"

#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace clash4d {
namespace oracle {

using Q = Rational;
using Vec3 = std::array<Q, 3>;
using Mat3 = std::array<Vec3, 3>;      // rows
using Plane = std::array<Q, 4>;        // a x + b y + c z + d, "inside" is < 0

constexpr std::size_t max_dnf_terms = 200000;

inline Q dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 sub3(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 cross3(const Vec3& a, const Vec3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Plane negate(const Plane& p) { return {-p[0], -p[1], -p[2], -p[3]}; }

// The spec's quaternion matrix, divided by the norm (orthogonal, exactly).
inline Mat3 quaternion_matrix(const Q& w, const Q& x, const Q& y, const Q& z)
{
  Q n = w * w + x * x + y * y + z * z;
  Mat3 m = {{{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
             {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
             {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}}};
  for (auto& row : m)
    for (auto& e : row) e /= n;
  return m;
}

// world = R local + b
struct Frame {
  Mat3 R{{{Q(1), Q(0), Q(0)}, {Q(0), Q(1), Q(0)}, {Q(0), Q(0), Q(1)}}};
  Vec3 b{Q(0), Q(0), Q(0)};

  Vec3 linear(const Vec3& v) const { return {dot3(R[0], v), dot3(R[1], v), dot3(R[2], v)}; }
  // local n.q + d with q = R^T (p - b): (R n).p + d - (R n).b
  Plane to_world(const Plane& p) const
  {
    Vec3 n = linear({p[0], p[1], p[2]});
    return {n[0], n[1], n[2], p[3] - dot3(n, b)};
  }
  Frame rotated(const Mat3& M) const
  {
    Frame f;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) f.R[i][j] = R[i][0] * M[0][j] + R[i][1] * M[1][j] + R[i][2] * M[2][j];
    f.b = b;
    return f;
  }
  Frame translated(const Vec3& t) const
  {
    Frame f = *this;
    Vec3 rt = linear(t);
    for (int i = 0; i < 3; ++i) f.b[i] = b[i] + rt[i];
    return f;
  }
};

// The closed half-spaces (plane <= 0) whose intersection is a primitive, in
// its own frame.
inline std::vector<Plane> local_planes(const Solid& s)
{
  using K = Solid::Kind;
  const auto& v = s.numbers;
  std::vector<Plane> out;
  switch (s.kind) {
    case K::Halfspace: out.push_back({v[0], v[1], v[2], v[3]}); break;
    case K::Block:
      for (int a = 0; a < 3; ++a) {
        Plane lo{Q(0), Q(0), Q(0), v[a]}, hi{Q(0), Q(0), Q(0), -v[3 + a]};
        lo[a] = Q(-1);   // lo - x <= 0
        hi[a] = Q(1);    // x - hi <= 0
        out.push_back(lo);
        out.push_back(hi);
      }
      break;
    case K::Convex:
      for (std::size_t i = 0; i + 3 < v.size(); i += 4) out.push_back({v[i], v[i + 1], v[i + 2], v[i + 3]});
      break;
    case K::Prism: {
      std::size_t n = (v.size() - 2) / 2;
      for (std::size_t i = 0; i < n; ++i) {
        std::size_t j = (i + 1) % n;
        Q x0 = v[2 * i], y0 = v[2 * i + 1], x1 = v[2 * j], y1 = v[2 * j + 1];
        // Counter-clockwise: inside is to the left of (x0,y0)->(x1,y1), i.e.
        // cross((x1-x0, y1-y0), (x-x0, y-y0)) > 0; the plane is minus that.
        Q ex = x1 - x0, ey = y1 - y0;
        out.push_back({ey, -ex, Q(0), -(ey * x0 - ex * y0)});
      }
      out.push_back({Q(0), Q(0), Q(-1), v[2 * n]});
      out.push_back({Q(0), Q(0), Q(1), -v[2 * n + 1]});
      break;
    }
    case K::Hull: {
      // Brute force: every plane through three non-collinear points with all
      // points on one side is a facet plane. Ignores the validated triples.
      std::vector<Vec3> pts;
      for (std::size_t i = 0; i + 2 < v.size(); i += 3) pts.push_back({v[i], v[i + 1], v[i + 2]});
      std::vector<Plane> seen;
      auto same_plane = [](const Plane& a, const Plane& b) {
        // a = lambda b with lambda > 0
        int k = 0;
        while (CGAL::is_zero(a[k])) ++k;
        if (CGAL::is_zero(b[k]) || CGAL::sign(a[k]) != CGAL::sign(b[k])) return false;
        for (int i = 0; i < 4; ++i)
          if (a[i] * b[k] != b[i] * a[k]) return false;
        return true;
      };
      for (std::size_t i = 0; i < pts.size(); ++i)
        for (std::size_t j = i + 1; j < pts.size(); ++j)
          for (std::size_t k = j + 1; k < pts.size(); ++k) {
            Vec3 n = cross3(sub3(pts[j], pts[i]), sub3(pts[k], pts[i]));
            if (CGAL::is_zero(n[0]) && CGAL::is_zero(n[1]) && CGAL::is_zero(n[2])) continue;
            bool neg = false, pos = false;
            for (const auto& p : pts) {
              CGAL::Sign sg = CGAL::sign(dot3(n, sub3(p, pts[i])));
              neg = neg || sg == CGAL::NEGATIVE;
              pos = pos || sg == CGAL::POSITIVE;
            }
            if (neg && pos) continue;
            Plane pl{n[0], n[1], n[2], -dot3(n, pts[i])};
            if (pos) pl = negate(pl);
            bool dup = false;
            for (const auto& q : seen) dup = dup || same_plane(q, pl);
            if (!dup) seen.push_back(pl);
          }
      out = seen;
      break;
    }
    default: throw std::logic_error("oracle: not a primitive");
  }
  return out;
}

// A formula in negation normal form over rest-frame planes: Atom means
// plane(p) < 0 (a complement is stored as the negated plane).
struct Nnf {
  enum class Op { Atom, And, Or };
  Op op = Op::Atom;
  Plane plane{};
  std::vector<Nnf> kids;
};

inline Nnf nnf_of(const Solid& s, const Frame& f, bool negated)
{
  using K = Solid::Kind;
  Nnf n;
  switch (s.kind) {
    case K::Translate: return nnf_of(s.children[0], f.translated({s.numbers[0], s.numbers[1], s.numbers[2]}), negated);
    case K::Rotate:
      return nnf_of(s.children[0], f.rotated(quaternion_matrix(s.numbers[0], s.numbers[1], s.numbers[2], s.numbers[3])), negated);
    case K::Union:
    case K::Intersection:
      n.op = ((s.kind == K::Intersection) != negated) ? Nnf::Op::And : Nnf::Op::Or;
      for (const Solid& c : s.children) n.kids.push_back(nnf_of(c, f, negated));
      return n;
    case K::Difference:
      // S - T1 - T2 = S and not T1 and not T2; not that = not S or T1 or T2.
      n.op = negated ? Nnf::Op::Or : Nnf::Op::And;
      for (std::size_t i = 0; i < s.children.size(); ++i) n.kids.push_back(nnf_of(s.children[i], f, i == 0 ? negated : !negated));
      return n;
    default: {
      n.op = negated ? Nnf::Op::Or : Nnf::Op::And;
      for (const Plane& p : local_planes(s)) {
        Nnf a;
        a.plane = negated ? negate(f.to_world(p)) : f.to_world(p);
        n.kids.push_back(a);
      }
      return n;
    }
  }
}

inline std::size_t term_count(const Nnf& n)
{
  auto sat_mul = [](std::size_t a, std::size_t b) { return (a != 0 && b > max_dnf_terms * 8 / a) ? max_dnf_terms * 8 : a * b; };
  switch (n.op) {
    case Nnf::Op::Atom: return 1;
    case Nnf::Op::And: {
      std::size_t r = 1;
      for (const auto& k : n.kids) r = std::min(sat_mul(r, term_count(k)), max_dnf_terms * 8);
      return r;
    }
    case Nnf::Op::Or: {
      std::size_t r = 0;
      for (const auto& k : n.kids) r = std::min(r + term_count(k), max_dnf_terms * 8);
      return r;
    }
  }
  return 0;
}

// D(t) = integral from 0 to t of the piecewise-constant velocity.
inline Vec3 displacement(const Motion& m, const Q& t)
{
  Vec3 d{Q(0), Q(0), Q(0)};
  Q a = t < Q(0) ? t : Q(0), b = t < Q(0) ? Q(0) : t;   // integrate over [a, b]
  Q sign = t < Q(0) ? Q(-1) : Q(1);
  for (std::size_t i = 0; i < m.velocities.size(); ++i) {
    // segment i covers (times[i-1], times[i]) with open ends at infinity
    Q lo = a, hi = b;
    if (i > 0 && lo < m.times[i - 1]) lo = m.times[i - 1];
    if (i < m.times.size() && m.times[i] < hi) hi = m.times[i];
    if (!(lo < hi)) continue;
    for (int k = 0; k < 3; ++k) d[k] += sign * m.velocities[i][k] * (hi - lo);
  }
  return d;
}

// Velocity at a time that is not a breakpoint.
inline Vec3 velocity_at(const Motion& m, const Q& t)
{
  std::size_t i = 0;
  while (i < m.times.size() && m.times[i] < t) ++i;
  return m.velocities[i];
}

// One constant-velocity linear motion on a slab: D(t) = v t + o.
struct Linear_motion {
  Vec3 v, o;
};

inline Linear_motion linear_on(const Motion& m, const Q& lo, const Q& hi)
{
  Q mid = (lo + hi) / 2;
  Linear_motion l;
  l.v = velocity_at(m, mid);
  Vec3 d = displacement(m, mid);
  for (int k = 0; k < 3; ++k) l.o[k] = d[k] - l.v[k] * mid;
  return l;
}

// a.(x, y, z, t) + c, "inside" is < 0.
struct Row {
  std::array<Q, 4> a;
  Q c;
};

// h(x, t) = n.(x - v t - o) + d
inline Row extrude(const Plane& p, const Linear_motion& m)
{
  Vec3 n{p[0], p[1], p[2]};
  return {{p[0], p[1], p[2], -dot3(n, m.v)}, p[3] - dot3(n, m.o)};
}

struct Lp_answer {
  Q slack;                    // max s, capped at 1
  std::array<Q, 4> point;     // an optimal (x, y, z, t)
};

// max s subject to row + s <= 0 for every row and lo + s <= t <= hi - s, s <= 1.
inline Lp_answer max_slack(const std::vector<Row>& rows, const Q& lo, const Q& hi, std::size_t& lp_count)
{
  ++lp_count;
  CGAL::Quadratic_program<Q> lp(CGAL::SMALLER, false, 0, false, 0);
  int r = 0;
  for (const Row& row : rows) {
    for (int k = 0; k < 4; ++k)
      if (!CGAL::is_zero(row.a[k])) lp.set_a(k, r, row.a[k]);
    lp.set_a(4, r, Q(1));
    lp.set_b(r, -row.c);
    ++r;
  }
  lp.set_a(3, r, Q(-1)); lp.set_a(4, r, Q(1)); lp.set_b(r, -lo); ++r;   // -t + lo + s <= 0
  lp.set_a(3, r, Q(1));  lp.set_a(4, r, Q(1)); lp.set_b(r, hi); ++r;    //  t - hi + s <= 0
  lp.set_u(4, true, Q(1));
  lp.set_c(4, Q(-1));
  CGAL::Quadratic_program_solution<Q> sol = CGAL::solve_linear_program(lp, Q());
  if (!sol.is_optimal()) throw std::logic_error("oracle: slack LP not optimal (it is always feasible and bounded)");
  Lp_answer ans;
  auto ov = sol.objective_value();
  ans.slack = -(Q(ov.numerator()) / Q(ov.denominator()));
  int k = 0;
  for (auto it = sol.variable_values_begin(); it != sol.variable_values_end() && k < 4; ++it, ++k)
    ans.point[k] = Q(it->numerator()) / Q(it->denominator());
  return ans;
}

struct Object_formula {
  Nnf formula;
  const Motion* motion;
};

inline Object_formula object_formula(const Scene& scene, int i)
{
  Object_formula f{nnf_of(scene.objects[i].shape, Frame(), false), &scene.objects[i].motion};
  std::size_t terms = term_count(f.formula);
  if (terms > max_dnf_terms)
    throw std::runtime_error("oracle: object '" + scene.objects[i].name + "' expands to more than " +
                             std::to_string(max_dnf_terms) + " DNF terms; keep test scenes smaller");
  return f;
}

// The time slabs of constant velocity of both motions inside [tL, tH].
inline std::vector<std::pair<Q, Q>> slabs(const Scene& scene, const Motion& a, const Motion& b)
{
  std::vector<Q> cuts{scene.t_lo, scene.t_hi};
  for (const Motion* m : {&a, &b})
    for (const Q& t : m->times)
      if (scene.t_lo < t && t < scene.t_hi) cuts.push_back(t);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<std::pair<Q, Q>> out;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) out.push_back({cuts[i], cuts[i + 1]});
  return out;
}

// Lazy DNF: rows collected so far, formulas still to expand. Visits every
// term whose every prefix is feasible; `on_term` returns true to stop.
class Term_search {
public:
  struct Item {
    const Nnf* node;
    const Linear_motion* motion;
  };

  Term_search(const Q& lo, const Q& hi, bool closed, std::size_t& lp_count)
    : lo_(lo), hi_(hi), closed_(closed), lp_count_(lp_count) {}

  template <class F>
  bool run(std::vector<Row> rows, std::vector<Item> pending, F&& on_term)
  {
    std::vector<Item> ors;
    while (!pending.empty()) {
      Item it = pending.back();
      pending.pop_back();
      switch (it.node->op) {
        case Nnf::Op::Atom: rows.push_back(extrude(it.node->plane, *it.motion)); break;
        case Nnf::Op::And:
          for (const auto& k : it.node->kids) pending.push_back({&k, it.motion});
          break;
        case Nnf::Op::Or:
          if (it.node->kids.size() == 1) pending.push_back({&it.node->kids[0], it.motion});
          else ors.push_back(it);
          break;
      }
    }
    Lp_answer lp = max_slack(rows, lo_, hi_, lp_count_);
    bool feasible = closed_ ? !CGAL::is_negative(lp.slack) : CGAL::is_positive(lp.slack);
    if (!feasible) return false;
    if (ors.empty()) return on_term(rows, lp);
    Item choice = ors.back();
    ors.pop_back();
    for (const auto& k : choice.node->kids) {
      std::vector<Item> next = ors;
      next.push_back({&k, choice.motion});
      if (run(rows, next, on_term)) return true;
    }
    return false;
  }

private:
  Q lo_, hi_;
  bool closed_;
  std::size_t& lp_count_;
};

// The least t over the closure of [tL, tH] x rows (an LP; rows feasible).
inline Q min_time(const std::vector<Row>& rows, const Q& lo, const Q& hi, std::size_t& lp_count)
{
  ++lp_count;
  CGAL::Quadratic_program<Q> lp(CGAL::SMALLER, false, 0, false, 0);
  int r = 0;
  for (const Row& row : rows) {
    for (int k = 0; k < 4; ++k) lp.set_a(k, r, row.a[k]);
    lp.set_b(r, -row.c);
    ++r;
  }
  lp.set_l(3, true, lo);
  lp.set_u(3, true, hi);
  lp.set_c(3, Q(1));
  CGAL::Quadratic_program_solution<Q> sol = CGAL::solve_linear_program(lp, Q());
  if (!sol.is_optimal()) throw std::logic_error("oracle: earliest-time LP not optimal");
  auto ov = sol.objective_value();
  return Q(ov.numerator()) / Q(ov.denominator());
}

// §5 earliest time t*, independently: the minimum of t over the closure of
// every non-empty open DNF term of a and b (regularised-semantics item 5).
// Returns false when they do not collide.
inline bool oracle_earliest(const Scene& scene, int a, int b, Q& t_star)
{
  std::size_t lps = 0;
  bool found = false;
  Object_formula A = object_formula(scene, a), B = object_formula(scene, b);
  for (const auto& span : slabs(scene, *A.motion, *B.motion)) {
    Linear_motion ma = linear_on(*A.motion, span.first, span.second);
    Linear_motion mb = linear_on(*B.motion, span.first, span.second);
    Term_search search(span.first, span.second, false, lps);
    search.run({}, {{&A.formula, &ma}, {&B.formula, &mb}}, [&](const std::vector<Row>& rows, const Lp_answer&) {
      Q t = min_time(rows, span.first, span.second, lps);
      if (!found || t < t_star) t_star = t;
      found = true;
      return false;
    });
  }
  return found;
}

// Closed semantics (scene-format.md, "Closed semantics"), independently: each
// closed object is the union of the closures of its non-empty open DNF
// terms (never the formula with <=, which would keep a difference's
// dangling faces); within [tL, tH] the objects meet when the closures of
// some pair of terms do, and the first contact time is the least t over
// those meetings (attained: an LP over closed sets).
struct Closed_verdict {
  bool meet = false;
  Q first;                    // the first contact time, when they meet
  std::size_t lps = 0;
};

inline Closed_verdict oracle_closed(const Scene& scene, int a, int b)
{
  Closed_verdict out;
  Object_formula A = object_formula(scene, a), B = object_formula(scene, b);
  for (const auto& span : slabs(scene, *A.motion, *B.motion)) {
    Linear_motion ma = linear_on(*A.motion, span.first, span.second);
    Linear_motion mb = linear_on(*B.motion, span.first, span.second);
    std::vector<std::vector<Row>> terms[2];
    int side = 0;
    for (const Object_formula* f : {&A, &B}) {
      Term_search search(span.first, span.second, false, out.lps);
      search.run({}, {{&f->formula, side == 0 ? &ma : &mb}}, [&](const std::vector<Row>& rows, const Lp_answer&) {
        terms[side].push_back(rows);
        return false;
      });
      ++side;
    }
    for (const auto& ta : terms[0])
      for (const auto& tb : terms[1]) {
        std::vector<Row> rows = ta;
        rows.insert(rows.end(), tb.begin(), tb.end());
        if (CGAL::is_negative(max_slack(rows, span.first, span.second, out.lps).slack)) continue;
        Q t = min_time(rows, span.first, span.second, out.lps);
        if (!out.meet || t < out.first) out.first = t;
        out.meet = true;
      }
  }
  return out;
}

struct Pair_verdict {
  bool collide = false;
  std::array<Q, 4> witness;   // (x, y, z, t), strictly inside both when collide
  bool touch = false;         // closed objects meet though they do not collide (only if asked)
  std::size_t lps = 0;        // linear programs solved
};

// The regularised verdict for objects a and b over the scene's span; with
// want_touch, also whether their closures meet within [tL, tH] when they do
// not collide (closure of a regularised set = union of the closures of its
// non-empty open DNF terms).
inline Pair_verdict oracle_pair(const Scene& scene, int a, int b, bool want_touch = false)
{
  Pair_verdict out;
  Object_formula A = object_formula(scene, a), B = object_formula(scene, b);
  auto spans = slabs(scene, *A.motion, *B.motion);
  for (const auto& span : spans) {
    Linear_motion ma = linear_on(*A.motion, span.first, span.second);
    Linear_motion mb = linear_on(*B.motion, span.first, span.second);
    Term_search search(span.first, span.second, false, out.lps);
    bool found = search.run({}, {{&A.formula, &ma}, {&B.formula, &mb}}, [&](const std::vector<Row>&, const Lp_answer& lp) {
      out.witness = lp.point;
      return true;
    });
    if (found) { out.collide = true; return out; }
  }
  if (!want_touch) return out;
  Closed_verdict closed = oracle_closed(scene, a, b);
  out.touch = closed.meet;
  out.lps += closed.lps;
  return out;
}

inline bool oracle_collide(const Scene& scene, int a, int b) { return oracle_pair(scene, a, b).collide; }

// Every pair not ignored, in order; the first colliding pair (or -1, -1).
inline std::pair<int, int> oracle_first_collision(const Scene& scene)
{
  int n = static_cast<int>(scene.objects.size());
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      if (!scene.ignored(a, b) && oracle_collide(scene, a, b)) return {a, b};
  return {-1, -1};
}

inline bool oracle_scene_collide(const Scene& scene) { return oracle_first_collision(scene).first >= 0; }

} // namespace oracle

using oracle::oracle_collide;
using oracle::oracle_scene_collide;

} // namespace clash4d

#endif
