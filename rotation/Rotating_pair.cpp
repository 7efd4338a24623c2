#include "rotation/Rotating_pair.h"

#include "rotation/Apart_cover.h"
#include "rotation/Double_slices.h"
#include "rotation/Exact_slices.h"
#include "rotation/Moving_planes.h"
#include "scene/Scene_builder.h"

#include <algorithm>

namespace clash4d {

namespace {

using Point3 = std::array<Rational, 3>;

using CGAL::is_zero;   // exact on Rational

// w, made by the scene builder around s, with the path and approximations
// the reader would give it.
Solid wrapped(Solid w)
{
  w.path = w.children.front().path;
  w.numbers_approximated = approximations(w.numbers);
  w.constructed_approximated = approximations(w.constructed);
  return w;
}

// The shape where the pose puts it at time t: rotated about its origin,
// then translated (spec: Motion with rotation (poses)), as the scene's own
// rotate and translate solids, exactly as the reader makes them (the
// rotate's exact matrix too: a double run computing its own from the
// quaternion answered differently from the same scene read from its file,
// and once with a witness that was not a number). Only the two new solids'
// numbers are approximated here.
Solid posed_solid(const Solid& shape, const Pose_segment& s, const Rational& t)
{
  Solid out = shape;
  std::array<Rational, 4> q = {s.q[0].at(t), s.q[1].at(t), s.q[2].at(t), s.q[3].at(t)};
  if (!is_zero(q[1]) || !is_zero(q[2]) || !is_zero(q[3])) out = wrapped(rotate(q, std::move(out)));
  Point3 c = {s.c[0].at(t), s.c[1].at(t), s.c[2].at(t)};
  if (!is_zero(c[0]) || !is_zero(c[1]) || !is_zero(c[2])) out = wrapped(translate(c, std::move(out)));
  return out;   // the shape's own numbers keep the approximations the reader made
}

struct Static_hit {
  bool collide = false;
  Point3 x;
  bool verified = false;
};

template <class Slices>
Static_hit probe(const Rotating_object& a, const Rotating_object& b, const Rational& t, Semantics semantics,
                 const Slices& slices)
{
  Check_options o;
  o.semantics = semantics;
  Check_answer answer = slices.check(posed_pair(a, b, t), o);
  Static_hit hit;
  if (!answer.collide) return hit;
  hit.collide = true;
  const Pair_answer& p = answer.pairs.front();
  for (int i = 0; i < 3; ++i) hit.x[i] = slices.read_answer_number(p.witness[i]);
  hit.verified = p.witness_verified;
  return hit;
}

// The rows the minors name (v_inf left out).
std::vector<int> rows_of(const std::vector<Minor_rows>& minors)
{
  std::vector<int> out;
  for (const Minor_rows& m : minors)
    for (int r : m)
      if (r >= 0) out.push_back(r);
  return out;
}

std::array<Algebraic, 4> with_time(const Point3& x, const Rational& t)
{
  return {Algebraic(x[0]), Algebraic(x[1]), Algebraic(x[2]), Algebraic(t)};
}

} // namespace

// The events of two bounded, full-dimensional convex pieces (their rows: a's
// planes, then b's): the minors of a vertex's three planes (one independent
// triple through it) against each plane of the other piece, both ways, and
// of an edge's two planes against an edge's two of the other piece. None
// when either shape is not one such piece.
//
// Why these suffice. Whether two convex polytopes meet (closed), or meet
// with interior (regularised), changes at a time tau only where they touch:
// both conditions are closed or open in t, so at tau the closed sets meet
// and the interiors do not, and a plane H separates them. A = a(tau) and
// B = b(tau) meet H in faces F_A, F_B with a common point; let x be a
// vertex of the polygon F_A and F_B meet in, and G_A, G_B the faces of A
// and B with x in their relative interiors. Their affine hulls, both in H,
// meet in x alone (else a segment through x would lie in F_A and F_B), so
// G_A or G_B is a vertex, or both are edges on lines that cross at x. A
// vertex v of A on a facet of B: v's triple of planes and that facet's
// plane meet in v, and their minor vanishes (the triple's normals stay
// independent under a rigid motion and meet in v alone, so any independent
// triple through v, as at a vertex where four planes meet, gives a minor
// that vanishes exactly when v is on the plane: it is det of the triple's
// normals, never 0, times the plane's value at v). Two edges crossing at
// x: the four planes of the two edges meet at x and their minor vanishes.
// So the status can change only at a root of a feature minor; where such a
// minor is identically zero on the interval (a vertex that stays on a plane
// of the other piece), it is left out when it can never be the one a touch
// needs (Pair_minors.h, Eventless_features: parallel edges, a plane both
// pieces bound on the same side), and otherwise Critical_times takes every
// mixed minor instead. At a
// closed touch at an irrational time the point x is on the four planes of a
// vanishing feature minor, three of them independent (an edge's line is not
// parallel to both planes of a crossing edge), which is what
// Exact_slices.cpp's common_point_at tries. The contact point
// (Exact_slices::contact_point) needs the vertices of the witness's cell to
// keep their index triples on the slice: the cell is the meet of the two
// pieces, P(t) = a(t) and b(t), and a vertex triple of P enters or leaves
// only at a point of P on four of the planes (or three that become
// dependent there), which is, by the same faces argument, a vertex of one
// piece on a plane of the other or two edges' planes through one point: a
// root of a feature minor again.
std::optional<Pair_features> feature_minors(const Shape_planes& a, const Shape_planes& b)
{
  if (!a.convex_features || !b.convex_features) return std::nullopt;
  int n = static_cast<int>(a.planes.size()), m = static_cast<int>(b.planes.size());
  Pair_features f;
  std::vector<Minor_rows>& out = f.minors;
  out.reserve(a.vertex_triples.size() * m + b.vertex_triples.size() * n + a.edges.size() * b.edges.size());
  // Parts: each piece's vertices (vertex v on triple v), then its edges.
  int va = static_cast<int>(a.vertices.size()), vb = static_cast<int>(b.vertices.size());
  for (int v = 0; v < va; ++v) {
    const auto& t = a.vertex_triples[v];
    for (int q = 0; q < m; ++q) {
      out.push_back({t[0], t[1], t[2], n + q});
      f.parts.push_back({v, -1});
    }
  }
  for (int v = 0; v < vb; ++v) {
    const auto& t = b.vertex_triples[v];
    for (int p = 0; p < n; ++p) {
      out.push_back({p, n + t[0], n + t[1], n + t[2]});
      f.parts.push_back({-1, v});
    }
  }
  for (std::size_t e = 0; e < a.edges.size(); ++e)
    for (std::size_t g = 0; g < b.edges.size(); ++g) {
      auto [p1, p2] = a.edges[e];
      auto [q1, q2] = b.edges[g];
      out.push_back({p1, p2, n + q1, n + q2});
      f.parts.push_back({va + static_cast<int>(e), vb + static_cast<int>(g)});
    }
  // Each piece is its one primitive (convex_features): its planes' sides.
  f.sides.assign(n + m, 0);
  for (auto [plane, orientation] : a.primitives.front()) f.sides[plane] = orientation;
  for (auto [plane, orientation] : b.primitives.front()) f.sides[n + plane] = orientation;
  return f;
}

Rotating_object Rotating_object::make(const Scene_object& o)
{
  return {o.name, &o.shape, shape_planes(o.shape), pose_segments(o.motion)};
}

Rotating_object Rotating_object::piece(const Scene_object& o, const Solid& piece)
{
  return {o.name, &piece, shape_planes(piece), pose_segments(o.motion)};
}

std::vector<Rational> piece_ends(const Rotating_object& a, const Rotating_object& b, const Rational& lo,
                                 const Rational& hi)
{
  std::vector<Rational> t = {lo, hi};
  for (const auto* o : {&a, &b})
    for (const Pose_segment& s : o->segments) {
      if (!s.from_minus_infinity && lo < s.lo && s.lo < hi) t.push_back(s.lo);
      if (!s.to_plus_infinity && lo < s.hi && s.hi < hi) t.push_back(s.hi);
    }
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

std::vector<Moving_plane> pair_rows(const Rotating_object& a, const Rotating_object& b, const Rational& at)
{
  std::vector<Moving_plane> rows = moving_planes(a.shape.planes, segment_at(a.segments, at));
  std::vector<Moving_plane> more = moving_planes(b.shape.planes, segment_at(b.segments, at));
  rows.insert(rows.end(), more.begin(), more.end());
  return rows;
}

std::vector<Moving_plane> integer_pair_rows(const Rotating_object& a, const Rotating_object& b, const Rational& at)
{
  std::vector<Moving_plane> rows = integer_moving_planes(a.shape.planes, segment_at(a.segments, at));
  std::vector<Moving_plane> more = integer_moving_planes(b.shape.planes, segment_at(b.segments, at));
  rows.insert(rows.end(), more.begin(), more.end());
  return rows;
}

Scene posed_pair(const Rotating_object& a, const Rotating_object& b, const Rational& t)
{
  Scene s;
  s.name = "posed";
  s.t_lo = Rational(0);
  s.t_hi = Rational(1);
  for (const auto* o : {&a, &b}) {
    Scene_object so;
    so.name = o->name;
    so.shape = posed_solid(*o->solid, segment_at(o->segments, t), t);
    so.motion.velocities.push_back({Rational(0), Rational(0), Rational(0)});
    approximate_numbers(so.motion);
    s.objects.push_back(std::move(so));
  }
  return s;
}

} // namespace clash4d

namespace clash4d {

namespace {

// The time slices of one pair, in time order: each piece between the
// motions' breakpoints, its critical times, and the static question at
// each sample (and, closed, at each critical time); the first answer ends
// the search, so with --earliest it is the earliest.
template <class Slices>
class Slice_search {
public:
  Slice_search(const Rotating_object& a, const Rotating_object& b, const Check_options& o, const Slices& slices)
    : a_(a), b_(b), options_(o), slices_(slices), closed_(o.semantics == Semantics::closed)
  {
    if (o.feature_events) features_ = feature_minors(a.shape, b.shape);
  }

  Rotating_answer run(const Rational& t_lo, const Rational& t_hi)
  {
    std::vector<Rational> ends = piece_ends(a_, b_, t_lo, t_hi);
    t_lo_ = t_lo;
    answer_.counts.piece_pairs = 1;
    for (std::size_t p = 0; p + 1 < ends.size(); ++p)
      if (piece(ends[p], ends[p + 1])) return answer_;
    if (closed_ && !end_apart_ && at_rational(t_hi)) return answer_;   // the span's end, closed only
    // No contact anywhere else: whether they touch at the undecided time
    // decides the verdict, so it is not made.
    if (!undecided_.empty()) throw Rotation_unsupported(undecided_);
    return answer_;
  }

private:
  // True once the piece [lo, hi] has answered.
  bool piece(const Rational& lo, const Rational& hi)
  {
    Rational mid = (lo + hi) / 2;
    // A verdict alone: one sample first, for the common case where the
    // pair collides there, before any minor is made.
    if (!options_.earliest && in_interval({}, Algebraic(lo), Algebraic(hi))) return true;
    end_apart_ = false;
    if (!features_) return slice(slices_.rows(a_, b_, mid), {lo, hi, false}, nullptr);
    // Two convex pieces: the slices only where they are not surely apart,
    // each run with the features that can touch there (near_features). The
    // exact rows are made once a run is left (a miss makes none).
    Apart_cover cover(a_, b_, mid);
    cover_ = &cover;
    std::vector<Moving_plane> rows;
    Rational sliced_to = lo;
    bool answered = cover.for_each_unsure(lo, hi, [&](const Time_piece& p) {
      sliced_to = p.hi;
      if (rows.empty()) rows = slices_.rows(a_, b_, mid);
      Pair_features near = cover.near_features(*features_, p.lo, p.hi);
      return slice(rows, p, &near);
    });
    cover_ = nullptr;
    answer_.counts.apart_intervals += cover.proved_apart();
    end_apart_ = sliced_to < hi;
    return answered;
  }

  // True once the slices of the closed interval p have answered; features:
  // the events to take there (two convex pieces), or none for every mixed
  // minor.
  bool slice(const std::vector<Moving_plane>& rows, const Time_piece& p, const Pair_features* features)
  {
    bool low_rank = !a_.shape.spans_space && !b_.shape.spans_space;
    std::vector<Critical_time> c =
        slices_.critical_times(rows, a_.shape.planes.size(), p.lo, p.hi, low_rank, features);
    ++answer_.counts.sliced_intervals;
    answer_.counts.critical_times += c.size();
    if (closed_ && !p.after_apart && at_rational(p.lo)) return true;
    for (std::size_t k = 0; k <= c.size(); ++k) {
      Algebraic left = k == 0 ? Algebraic(p.lo) : c[k - 1].t;
      Algebraic right = k == c.size() ? Algebraic(p.hi) : c[k].t;
      if (closed_ && k > 0 && at_critical(rows, c[k - 1])) return true;
      if (in_interval(rows, left, right, k == 0 ? nullptr : &c[k - 1])) return true;
    }
    return false;
  }

  // critical_left: left when it is a critical time, whose vanishing
  // minors' planes are where a contact at left is (the contact point's
  // vertex is sought there first).
  bool in_interval(const std::vector<Moving_plane>& rows, const Algebraic& left, const Algebraic& right,
                   const Critical_time* critical_left = nullptr)
  {
    std::optional<Rational> sample = slices_.sample(left, right);
    if (!sample) return false;   // doubles: no double strictly between
    const Rational& s = *sample;
    if (apart_at(s)) return false;
    ++answer_.counts.static_questions;
    Static_hit hit = probe(a_, b_, s, options_.semantics, slices_);
    if (!hit.collide) return false;
    if (closed_ && options_.earliest && Slices::is_exact)
      // The closed contact set is closed: had it met this interval first,
      // it would have met its left end, which was asked before. An
      // irrational left end whose contact point the minors did not give is
      // named, never answered with a later time.
      throw Rotation_unsupported("the first contact is at a critical time where no contact point was found "
                                 "(a degenerate contact this release does not resolve)");
    answer_.collide = true;
    answer_.witness = with_time(hit.x, s);
    answer_.witness_verified = hit.verified;
    if (options_.earliest) {
      answer_.earliest = true;
      answer_.t_star = left;
      answer_.at_start = left == Algebraic(t_lo_);
      answer_.contact =
          slices_.contact_point(rows, hit.x, s, left, critical_left ? rows_of(critical_left->vanishing) : std::vector<int>{});
    }
    return true;
  }

  bool at_rational(const Rational& t)
  {
    if (apart_at(t)) return false;
    ++answer_.counts.static_questions;
    Static_hit hit = probe(a_, b_, t, Semantics::closed, slices_);
    if (!hit.collide) return false;
    std::array<Algebraic, 4> w = with_time(hit.x, t);
    found_closed(w, hit.verified);
    return true;
  }

  // A filter before a static question at the one time t (two convex
  // pieces): the cover's separating plane at t alone, in intervals as tight
  // as t is exact. Where it holds, the closed pieces are apart at t, which
  // is the static answer "no" in both semantics, and nothing is posed.
  bool apart_at(const Rational& t)
  {
    if (!cover_ || !cover_->apart_on(t, t)) return false;
    ++answer_.counts.apart_samples;
    return true;
  }

  // An irrational time whose closed question is not decided ends an
  // --earliest search (the first contact may be there); a verdict goes on,
  // since a contact found later decides it all the same.
  bool at_critical(const std::vector<Moving_plane>& rows, const Critical_time& c)
  {
    if (c.t.is_rational()) return at_rational(c.t.rational());
    Contact_at_critical x = slices_.closed_at_irrational(rows, a_, b_, c);
    if (!x.decided()) {
      if (options_.earliest) throw Rotation_unsupported(x.undecided);
      if (undecided_.empty()) undecided_ = x.undecided;
      return false;
    }
    if (!x.point) return false;
    found_closed({(*x.point)[0], (*x.point)[1], (*x.point)[2], c.t}, true);
    return true;
  }

  void found_closed(const std::array<Algebraic, 4>& w, bool verified)
  {
    answer_.collide = true;
    answer_.witness = w;
    answer_.witness_verified = verified;
    if (!options_.earliest) return;
    answer_.earliest = true;
    answer_.t_star = w[3];
    answer_.contact = {w[0], w[1], w[2]};
    answer_.at_start = w[3] == Algebraic(t_lo_);
  }

  const Rotating_object &a_, &b_;
  const Check_options& options_;
  const Slices& slices_;
  bool closed_;
  Rational t_lo_;
  bool end_apart_ = false;   // the last piece's end lies in an interval proved apart
  std::string undecided_;    // the first critical time's closed question not decided, why
  Rotating_answer answer_;
  std::optional<Pair_features> features_;   // two convex pieces' event minors
  const Apart_cover* cover_ = nullptr;       // the piece's, while its runs are sliced
};

} // namespace

template <class Slices>
Rotating_answer decide_rotating_pair(const Rotating_object& a, const Rotating_object& b, const Rational& t_lo,
                                     const Rational& t_hi, const Check_options& options, const Slices& slices)
{
  return Slice_search<Slices>(a, b, options, slices).run(t_lo, t_hi);
}

template Rotating_answer decide_rotating_pair<Exact_slices>(const Rotating_object&, const Rotating_object&,
                                                            const Rational&, const Rational&, const Check_options&,
                                                            const Exact_slices&);
template Rotating_answer decide_rotating_pair<Double_slices>(const Rotating_object&, const Rotating_object&,
                                                             const Rational&, const Rational&, const Check_options&,
                                                             const Double_slices&);

} // namespace clash4d
