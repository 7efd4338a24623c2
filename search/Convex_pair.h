// Convex pairs decided by linear programs (beyond the paper). When each
// object of a pair is one convex primitive (a block, convex, prism, hull or
// half-space, moved and rotated), its extrusion on a constant-velocity
// sub-span is one convex polyhedron, and so is the pair's:
// P = { h_j <= 0 for every plane of both, lo <= t <= hi }. Then:
//  - regularised: they collide on the sub-span iff the strict system
//    h_j < 0, lo < t < hi has a solution (regularised-semantics items 1-2);
//    a solution is the point inside the witness is made from. Otherwise
//    Motzkin's multipliers lambda >= 0, not all zero, with
//    sum lambda_j n_j = 0 and sum lambda_j c_j >= 0 prove it has none
//    (touching included: the sum is 0 there);
//  - closed: they meet iff P is not empty (each object is its closed
//    polyhedron, which has interior); a point of P is the witness, and
//    Farkas' multipliers with sum lambda_j c_j > 0 prove P empty;
//  - earliest: t* = min t over P (item 5: P is the closure of its interior
//    when that is not empty), attained at a vertex where four rows meet,
//    proven least by y >= 0 on those rows with e_t + sum y_j n_j = 0.
// The points that make the answer checkable follow from convexity: P's
// interior is one cell of the pair's arrangement, whose closure holds
// every point of P (the contact point too), and a point strictly inside an
// object at the contact's time sees it in its cell's closure likewise.
// A double simplex on the pair's guide (the same planes in doubles, made
// from the scene's own numbers, rounding to nearest: the same doubles in
// every kernel's run) guesses the point inside, the support of the
// multipliers and the vertex's four rows. Every verdict is then made from
// the guess with the kernel's signs, each sign one predicate whose
// arguments are guesses (Policy::convex_certain: a filter asks its exact
// kernel's stage on the same sub-span where its own kernel cannot tell), so
// every kernel takes the same decisions; a guess that proves nothing
// leaves the sub-span to the paper's cascade (undecided).
#ifndef CLASH4D_SEARCH_CONVEX_PAIR_H
#define CLASH4D_SEARCH_CONVEX_PAIR_H

#include "model/Extrusion.h"
#include "model/Model_builder.h"
#include "model/Primitive_planes.h"
#include "search/Convex_guide.h"
#include "search/Double_simplex.h"
#include "search/No_filter.h"
#include "search/Search_goal.h"
#include <CGAL/FPU.h>
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <type_traits>
#include <vector>

namespace clash4d {

// What a convex pair's stage recorded in the goal, for a filter making the
// answer in another kernel: the sub-span, the guess point (regularised:
// inside P; closed, when not at a vertex, the witness) and the vertex's
// four rows (the contact point, or the closed witness).
struct Convex_found {
  std::size_t index = 0;
  bool at_vertex = false;
  std::array<int, 4> basis{};
  Vector4<double> point{};
  bool at_centre = false;             // regularised: the point inside is the centre of these rows
  std::array<int, 5> centre_rows{};
};

template <class K, class Policy = No_filter>
class Convex_pair {
public:
  using FT = typename K::FT;
  using H = Hyperplane4<FT>;
  using R = typename K::RT;             // the kernel's ring for division-free elimination
  using Ring_row = Hyperplane4<R>;
  using V4 = Vector4<FT>;
  using Moving = Moving_object<FT>;
  using G = Hyperplane4<double>;
  using Point = Vector4<double>;      // a guess: the same doubles in every kernel's run
  using Basis = std::array<int, 4>;   // four rows meeting at a vertex
  using Centre = std::array<int, 5>;  // five rows whose margins are equal at the centre

  enum class Verdict { undecided, apart, collide };
  using Found = Convex_found;

  // Each object one primitive, one of them bounded (so the programs are
  // bounded), in a model that knows its scene (the guide's numbers).
  static bool applies(const Scene_model<K>& model, int a, int b)
  {
    auto single = [&](int i) {
      const Csg_model<FT>& csg = model.objects[i].csg;
      return csg.nodes.size() == 1 && csg.nodes[0].op == Csg_node::Op::Primitive;
    };
    auto bounded = [&](int i) { return !model.objects[i].csg.primitives[0].vertices.empty(); };
    return model.scene && single(a) && single(b) && (bounded(a) || bounded(b));
  }

  // Holds a reference into itself (its own policy when none is given).
  Convex_pair(const Convex_pair&) = delete;
  Convex_pair& operator=(const Convex_pair&) = delete;

  // guides: the objects' (search/Convex_guide.h), shared with another
  // kernel's stage or kept for many pairs; each made here when none.
  Convex_pair(const K& k, const Scene_model<K>& model, int a, int b, Policy* policy = nullptr,
              Convex_guides guides = {})
    : k_(k), model_(model), a_(a), b_(b), policy_(policy ? *policy : own_policy_.emplace()),
      guides_(std::move(guides))
  {
    for (int o = 0; o < 2; ++o)
      if (!guides_[o]) guides_[o] = Convex_guide::make(model.scene->objects[static_cast<std::size_t>(o == 0 ? a : b)]);
  }

  const Convex_guides& guides() const { return guides_; }

  // Each object's planes from these instead of the model's objects (which
  // then need only their motions): planes made as the stage reads them.
  void use_planes(Primitive_planes<K>& a, Primitive_planes<K>& b) { planes_[0] = &a, planes_[1] = &b; }

  int a() const { return a_; }
  int b() const { return b_; }
  std::size_t span_index() const { return index_; }
  const Found& found() const { return found_; }

  // The sub-span's rows, in order: A's planes, B's, t >= lo, t <= hi: the
  // world planes Witness::world_planes makes of a pair of single
  // primitives, by the same extrusions (most made by decide already).
  const std::vector<H>& world_rows()
  {
    world_rows_.clear();
    world_rows_.reserve(rows_.size());
    for (std::size_t j = 0; j < rows_.size(); ++j) world_rows_.push_back(row(j));
    return world_rows_;
  }

  // The rows' values at the point inside the goal holds, when decide took
  // it from the guess (in(), strict, evaluated every row there, in this
  // kernel): the witness starts from them (Witness::make_on). None else.
  const std::vector<FT>* values_inside() const
  {
    return guess_in_ && !found_.at_centre ? &guess_values_ : nullptr;
  }

  // Sub-span `index` (time order), where A and B move as given: apart, or
  // collide with the goal holding what the cascade would record (the
  // point inside; closed, the point with a point inside each object at its
  // time; earliest, the least time and its vertex), or undecided (nothing
  // recorded).
  Verdict decide(std::size_t index, const Moving& A, const Moving& B, const Time_span<FT>& span,
                 Search_goal<FT>& goal)
  {
    if (!span.exact_lo || !span.exact_hi) return Verdict::undecided;
    start_span(index, A, B, span);
    std::optional<Double_simplex::Optimum> margin = guide_finite() ? widest_margin() : std::nullopt;
    if (!margin) return Verdict::undecided;
    Point g = guess_point(margin->pi);
    if (!finite(g)) return Verdict::undecided;
    std::vector<std::size_t> tight = support(*margin);
    if (!goal.closed()) {
      // A guess inside by less than its own zero (a touch, or an overlap
      // as thin as its rounding) is not tried: the multipliers or the centre
      // decide those.
      if (margin->value < -guess_eps && in(g, true, tight)) return earliest_or_point(goal, exact_point(g), g, nullptr);
      if (certain([&](auto& s) { return s.proves_empty(tight, false); })) return Verdict::apart;
      // A thin overlap the guess misses (its rounding of the scene moved a
      // face by more than the overlap): the programs' optimum itself, made
      // exactly from the guess's five rows.
      std::optional<Centre> rows = centre_rows(*margin);
      if (rows && strictly_inside_centre(*rows)) return earliest_or_point(goal, centre(*rows), g, &*rows);
      return Verdict::undecided;
    }
    // Closed, any point: the guess itself when it lies in P (a float
    // kernel's tolerance takes a thin overlap for a touch).
    if (!goal.earliest && in(g, false, tight) && deep_inside()) return touch(goal, g, nullptr);
    if (margin->value >= 0 && certain([&](auto& s) { return s.proves_empty(tight, true); })) return Verdict::apart;
    std::optional<Basis> rows = least_vertex(goal.earliest);
    return rows && deep_inside() ? touch(goal, g, &*rows) : Verdict::undecided;
  }

  // The sub-span's rows, from its motions (another kernel's stage is set
  // on the same sub-span to take the decisions its own leaves open).
  void start_span(std::size_t index, const Moving& A, const Moving& B, const Time_span<FT>& span)
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    index_ = index;
    moving_[0] = &A, moving_[1] = &B;
    lo_ = span.lo, hi_ = span.hi;
    guide_rows_.clear();
    guide_rows_.reserve(guides_[0]->planes.size() + guides_[1]->planes.size() + 2);
    for (int o = 0; o < 2; ++o) {
      const Motion_path<double>& m = guides_[o]->motion;
      std::size_t seg = model_.segment_on(o == 0 ? a_ : b_, span);   // the kernel's, the same in every run
      for (const auto& plane : guides_[o]->planes) guide_rows_.push_back(extrude(plane, m.velocity[seg], m.offset[seg]));
    }
    count_a_ = plane_count(0);
    count_b_ = plane_count(1);
    guide_rows_.push_back(time_at_least(nearest_double(*span.exact_lo)));
    guide_rows_.push_back(time_at_most(nearest_double(*span.exact_hi)));
    rows_.assign(guide_rows_.size(), std::nullopt);
    ring_rows_.assign(guide_rows_.size(), std::nullopt);
    guess_in_ = false;
    vertex_basis_.reset();
    centre_rows_.reset();
    cofactors_.reset();
  }

  // --- Predicates: arguments and results the same in every kernel. ---

  // The predicates' signs are indeterminate where the kernel cannot
  // certify them (kernel uncertain_sign), so that the policy decides them
  // without a throw (convex_certain): zeros where the objects touch. (A
  // construction an interval kernel cannot make, the vertex or the centre,
  // still throws: the policy catches that too.)

  // The sign of row j at p.
  CGAL::Uncertain<CGAL::Sign> row_sign(std::size_t j, const Point& p)
  {
    return k_.uncertain_sign(row(j).value(exact_point(p)));
  }

  // Whether lambda >= 0 with sum lambda_i n_i = 0 over the rows `which`
  // (their one line of dependencies) has sum lambda_i c_i >= 0 (strict:
  // > 0): the strict system (strict: P) is empty. Indeterminate where the
  // sum's sign is (a touch), or a multiplier's or a pivot's.
  CGAL::Uncertain<bool> proves_empty(const std::vector<std::size_t>& which, bool strict)
  {
    std::vector<Ring_row> scaled;
    bool unsure = false;
    std::optional<std::vector<R>> lambda = null_vector(which, scaled, unsure);
    if (unsure) return CGAL::Uncertain<bool>::indeterminate();
    if (!lambda) return false;
    R sum(0);
    for (std::size_t i = 0; i < which.size(); ++i) {
      CGAL::Uncertain<CGAL::Sign> s = k_.uncertain_sign((*lambda)[i]);
      if (!CGAL::is_certain(s)) return CGAL::Uncertain<bool>::indeterminate();
      if (CGAL::get_certain(s) == CGAL::NEGATIVE) return false;
      sum += (*lambda)[i] * scaled[i].c;
    }
    CGAL::Uncertain<CGAL::Sign> s = k_.uncertain_sign(sum);
    if (!CGAL::is_certain(s)) return CGAL::Uncertain<bool>::indeterminate();
    return strict ? CGAL::get_certain(s) == CGAL::POSITIVE : CGAL::get_certain(s) != CGAL::NEGATIVE;
  }

  // Whether the four rows meet in one point (their normals independent).
  CGAL::Uncertain<bool> vertex_exists(const Basis& B) { return k_.uncertain_sign(time_cofactors(B).det) != CGAL::ZERO; }

  // The sign of row j at the vertex of B (a touch: zero).
  CGAL::Uncertain<CGAL::Sign> vertex_sign(const Basis& B, std::size_t j)
  {
    return k_.uncertain_sign(row(j).value(vertex(B)));
  }

  // The sign of y_i in sum_B y_i n_i = -e_t: by Cramer, y_i =
  // -det(N with row i replaced by e_t) / det N, whose numerator is C_i,
  // the cofactor of n_i's time coordinate (time_cofactors).
  CGAL::Uncertain<CGAL::Sign> dual_sign(const Basis& B, int i)
  {
    const Time_cofactors& tc = time_cofactors(B);
    CGAL::Uncertain<CGAL::Sign> num = k_.uncertain_sign(tc.c[static_cast<std::size_t>(i)]),
                                den = k_.uncertain_sign(tc.det);
    if (!CGAL::is_certain(num) || !CGAL::is_certain(den)) return CGAL::Uncertain<CGAL::Sign>::indeterminate();
    return CGAL::Sign(-static_cast<int>(CGAL::get_certain(num)) * static_cast<int>(CGAL::get_certain(den)));
  }

  // The sign of object o's plane i (its solid's own frame) at its deep point.
  CGAL::Uncertain<CGAL::Sign> deep_sign(int o, std::size_t i)
  {
    const Plane3<FT>& pl = plane(o, i);
    const Vector3<double>& d = guides_[o]->deep;
    Vector3<FT> m{FT(d[0]), FT(d[1]), FT(d[2])};
    return k_.uncertain_side(Vector3<FT>{pl[0], pl[1], pl[2]}, pl[3], m);
  }

  // Whether the five rows' equal-margin system (n_j . p + s big_j = -c_j,
  // big_j the guide's scale of row j) has one solution: its determinant,
  // by Laplace along the s column, is sum_j (-1)^(j+4) big_j det(the other
  // four normals).
  CGAL::Uncertain<bool> centre_exists(const Centre& C) { return k_.uncertain_sign(centre_det(C)) != CGAL::ZERO; }

  // The sign of row j at the centre of C.
  CGAL::Uncertain<CGAL::Sign> centre_sign(const Centre& C, std::size_t j)
  {
    return k_.uncertain_sign(row(j).value(centre(C)));
  }

  // --- Constructions. ---

  // The point p of the solution (p, s) of C's equal-margin system; kept for C.
  const V4& centre(const Centre& C)
  {
    if (centre_rows_ && *centre_rows_ == C) return centre_;
    std::array<std::array<FT, 6>, 5> M;
    for (int i = 0; i < 5; ++i) {
      const H& h = row(static_cast<std::size_t>(C[i]));
      M[i] = {h.n[0], h.n[1], h.n[2], h.n[3], FT(scale_of(guide_rows_[static_cast<std::size_t>(C[i])])), -h.c};
    }
    std::array<FT, 5> x = k_.solve_regular(M);
    centre_ = {x[0], x[1], x[2], x[3]};
    centre_rows_ = C;
    return centre_;
  }

  // The vertex of B (B's rows meeting), by elimination; kept for B.
  const V4& vertex(const Basis& B)
  {
    if (vertex_basis_ && *vertex_basis_ == B) return vertex_;
    std::array<std::array<FT, 5>, 4> M;
    for (int i = 0; i < 4; ++i) {
      const H& h = row(static_cast<std::size_t>(B[i]));
      M[i] = {h.n[0], h.n[1], h.n[2], h.n[3], -h.c};
    }
    vertex_ = k_.solve_regular(M);
    vertex_basis_ = B;
    return vertex_;
  }

  // Object o's deep point moved to time t, at time t: strictly inside it
  // (deep_sign), so every point of the object at t is in its cell's closure.
  V4 cell(int o, const FT& t) const
  {
    const Moving& m = *moving_[o];
    const Vector3<double>& d = guides_[o]->deep;
    // (d + v t) + o per coordinate, as one dot product (in rationals, one
    // reduction; in floats the same operations, the products by 1 exact).
    const Vector3<FT> weights{FT(1), t, FT(1)};
    auto at = [&](int q) { return dot(Vector3<FT>{FT(d[q]), m.v[q], m.o[q]}, weights); };
    return {at(0), at(1), at(2), t};
  }

private:
  const K& k_;
  const Scene_model<K>& model_;
  int a_, b_;
  std::optional<Policy> own_policy_;   // made only when no policy is given
  Policy& policy_;
  Convex_guides guides_;
  std::size_t index_ = 0;
  std::vector<G> guide_rows_;              // the sub-span's rows in doubles, in the order of rows_
  // A's planes, B's, t >= lo, t <= hi: extruded on first use (none made
  // up front: a rational stage asked one sign reads a few rows of many).
  std::vector<std::optional<H>> rows_;
  std::vector<H> world_rows_;              // all of them, as world_rows() hands them out
  std::vector<FT> guess_values_;           // rows at the guess, as in() found them
  bool guess_in_ = false;                  // in() found the guess strictly inside, every row valued
  std::vector<std::optional<Ring_row>> ring_rows_;   // the same in the kernel's ring (ring_row)
  const Moving* moving_[2] = {nullptr, nullptr};
  Primitive_planes<K>* planes_[2] = {nullptr, nullptr};
  std::size_t count_a_ = 0, count_b_ = 0;
  FT lo_{}, hi_{};
  std::optional<Basis> vertex_basis_;
  V4 vertex_{};
  std::optional<Centre> centre_rows_;
  V4 centre_{};
  struct Time_cofactors {
    Basis basis;
    std::array<R, 4> c;   // C_i, the cofactor of row i's time coordinate
    R det;                // det N
  };
  std::optional<Time_cofactors> cofactors_;   // B's, time_cofactors
  Found found_;

  // A predicate, through the policy (a filter may ask another kernel).
  template <class Predicate>
  auto certain(Predicate p)
  {
    return policy_.convex_certain(*this, p);
  }

  static V4 exact_point(const Point& p) { return {FT(p[0]), FT(p[1]), FT(p[2]), FT(p[3])}; }

  // Object o's plane i in the world, not moving.
  const Plane3<FT>& plane(int o, std::size_t i)
  {
    return planes_[o] ? (*planes_[o])[i] : moving_[o]->object->csg.primitives[0].planes[i];
  }
  std::size_t plane_count(int o) const
  {
    return planes_[o] ? planes_[o]->size() : moving_[o]->object->csg.primitives[0].planes.size();
  }

  // Row j in the kernel's numbers (equation (4) on the sub-span's motion).
  const H& row(std::size_t j)
  {
    std::optional<H>& r = rows_[j];
    if (!r) {
      if (j < count_a_ + count_b_) {
        const Moving& m = *moving_[j < count_a_ ? 0 : 1];
        std::size_t i = j < count_a_ ? j : j - count_a_;
        r = extrude(plane(j < count_a_ ? 0 : 1, i), m.v, m.o);
      } else {
        r = j == count_a_ + count_b_ ? time_at_least(lo_) : time_at_most(hi_);
      }
    }
    return *r;
  }
  // Row j in the kernel's ring (Kernel_base::in_ring: a positive multiple),
  // made once per sub-span: the determinants' and null vectors' rows.
  const Ring_row& ring_row(std::size_t j)
  {
    if (!ring_rows_[j]) ring_rows_[j] = k_.in_ring(row(j));
    return *ring_rows_[j];
  }

  // The guesses' zero: a row missed by the guess by more than this (in its
  // largest normal coordinate's units) makes the exact check fail; contact
  // scenes' overlaps go down to 1e-15 of their coordinates.
  static constexpr double guess_eps = 1e-13;
  // A pivot tolerance that fine can leave the doubles pivoting on rounding
  // where the rows' normals span many orders (a mesh piece's, 1e-12 to
  // 1e-4 before scaling: the run does not settle, and the pair went to the
  // cascade); a program that does not settle is solved again with the
  // next of these. Only the guess changes: what is taken from it is
  // checked as before.
  static constexpr std::array<double, 3> pivot_eps{guess_eps, 1e-9, 1e-7};

  // Each row scaled by its largest normal coordinate, so that the margin
  // below is the same in every row's units.
  static double scale_of(const G& g)
  {
    double big = 0;
    for (double x : g.n) big = std::max(big, std::abs(x));
    return big;
  }

  // The guide's  max s  s.t.  h_j + s big_j <= 0  as its dual, Motzkin's LP:
  // max sum y_j c_j / big_j  s.t.  sum y_j n_j / big_j = 0, sum y_j = 1,
  // y >= 0. Its optimum is -s*; its row multipliers pi give the point,
  // p = -(pi_x, pi_y, pi_z, pi_t), with h_j(p) <= value big_j; its basis
  // the rows of a proof of emptiness when the value is not negative.
  std::optional<Double_simplex::Optimum> widest_margin() const
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    for (double eps : pivot_eps)
      if (std::optional<Double_simplex::Optimum> o = guide_program(5, {0, 0, 0, 0, 1}, eps).solve()) return o;
    return std::nullopt;
  }

  // The guide's  min t  over P as its dual: max sum y_j c_j / big_j  s.t.
  // sum y_j n_j / big_j = -e_t, y >= 0; its basis is the vertex's rows.
  std::optional<Basis> least_time_rows() const
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    for (double eps : pivot_eps) {
      std::optional<Double_simplex::Optimum> o = guide_program(4, {0, 0, 0, -1, 0}, eps).solve();
      if (o && o->basis.size() == 4) return Basis{o->basis[0], o->basis[1], o->basis[2], o->basis[3]};
    }
    return std::nullopt;
  }

  // A program whose columns are the guide's rows, each scaled by
  // scale_of: y_j's column (n_j / big_j, then 1 in a fifth row) and cost
  // c_j / big_j, with `rows` equality rows of right-hand side b.
  Double_simplex guide_program(int rows, const Double_simplex::Row_vector& b, double eps) const
  {
    Double_simplex lp(rows, static_cast<int>(guide_rows_.size()), b, eps);
    for (std::size_t j = 0; j < guide_rows_.size(); ++j) {
      const G& g = guide_rows_[j];
      double big = scale_of(g), a[5] = {g.n[0] / big, g.n[1] / big, g.n[2] / big, g.n[3] / big, 1.0};
      lp.column(static_cast<int>(j), a, g.c / big);
    }
    return lp;
  }

  static Point guess_point(const Double_simplex::Row_vector& pi) { return {-pi[0], -pi[1], -pi[2], -pi[3]}; }

  template <std::size_t N>
  static bool finite(const std::array<double, N>& x)
  {
    double zero = 0;   // v * 0 is NaN exactly when v is not finite; no branch per number
    for (double v : x) zero += v * 0.0;
    return zero == 0;
  }

  // A scene number beyond the doubles (1e400) leaves no guess to make.
  bool guide_finite() const
  {
    for (const G& g : guide_rows_)
      if (!finite(std::array<double, 5>{g.n[0], g.n[1], g.n[2], g.n[3], g.c})) return false;
    for (const auto& g : guides_)
      if (!finite(g->deep)) return false;
    return true;
  }

  // The basic rows that carry weight: where the multipliers are.
  static std::vector<std::size_t> support(const Double_simplex::Optimum& o)
  {
    std::vector<std::size_t> out;
    out.reserve(o.basis.size());
    double most = 0;
    for (double y : o.y) most = std::max(most, y);
    for (std::size_t i = 0; i < o.basis.size(); ++i)
      if (o.y[i] > 1e-9 * most) out.push_back(static_cast<std::size_t>(o.basis[i]));
    return out;
  }

  // Whether p is inside every row (strict: strictly), rows `first` first
  // (those the guess holds tight: a miss shows there soonest). Each row's
  // value is this kernel's row_sign's, kept (values_inside); a sign it
  // cannot tell is asked of the policy's other stage as row_sign.
  bool in(const Point& p, bool strict, const std::vector<std::size_t>& first)
  {
    guess_in_ = false;
    guess_values_.resize(rows_.size());
    const V4 at = exact_point(p);
    auto holds = [&](std::size_t j) {
      guess_values_[j] = row(j).value(at);
      CGAL::Sign s = certain([&](auto& st) {
        if constexpr (std::is_same_v<std::decay_t<decltype(st)>, Convex_pair>)
          if (&st == this) return k_.uncertain_sign(guess_values_[j]);   // row_sign(j, p), made above
        return st.row_sign(j, p);
      });
      return strict ? s == CGAL::NEGATIVE : s != CGAL::POSITIVE;
    };
    for (std::size_t j : first)
      if (!holds(j)) return false;
    for (std::size_t j = 0; j < rows_.size(); ++j)
      if (std::find(first.begin(), first.end(), j) == first.end() && !holds(j)) return false;
    guess_in_ = strict;
    return true;
  }

  // Whether each object's deep point is strictly inside it.
  bool deep_inside()
  {
    for (int o = 0; o < 2; ++o)
      for (std::size_t i = 0; i < plane_count(o); ++i)
        if (certain([&](auto& s) { return s.deep_sign(o, i); }) != CGAL::NEGATIVE) return false;
    return true;
  }

  // The vertex of the guide's least-time rows when it lies in P and
  // (proven: multipliers y >= 0 on its rows) has the least time of P.
  std::optional<Basis> least_vertex(bool proven)
  {
    std::optional<Basis> B = least_time_rows();
    if (!B || !certain([&](auto& s) { return s.vertex_exists(*B); })) return std::nullopt;
    for (std::size_t j = 0; j < rows_.size(); ++j)
      if (std::find(B->begin(), B->end(), static_cast<int>(j)) == B->end() &&
          certain([&](auto& s) { return s.vertex_sign(*B, j); }) == CGAL::POSITIVE)
        return std::nullopt;
    for (int i = 0; i < 4 && proven; ++i)
      if (certain([&](auto& s) { return s.dual_sign(*B, i); }) == CGAL::NEGATIVE) return std::nullopt;
    return B;
  }

  // Regularised: the point inside (the guess g, or the centre of C);
  // earliest, with the least time of P (the closure of its interior,
  // where the point lies), at a vertex proven least.
  Verdict earliest_or_point(Search_goal<FT>& goal, const V4& in, const Point& g, const Centre* C)
  {
    std::optional<Basis> B;
    if (goal.earliest && !(B = least_vertex(true))) return Verdict::undecided;
    V4 lowest = B ? vertex(*B) : in;
    if (!policy_.convex_improves(k_, *this, goal, B ? &*B : nullptr, lowest[3]))
      return Verdict::apart;   // past the ceiling: nothing to record
    goal.record(k_, in, lowest);
    goal.convex.emplace();
    found_ = {index_, B.has_value(), B ? *B : Basis{}, g, C != nullptr, C ? *C : Centre{}};
    policy_.convex_found(*this);
    return Verdict::collide;
  }

  // Closed: the point g, or B's vertex, with each object's deep point at
  // its time.
  Verdict touch(Search_goal<FT>& goal, const Point& g, const Basis* B)
  {
    V4 p = B ? vertex(*B) : exact_point(g);
    if (!policy_.convex_improves(k_, *this, goal, B, p[3])) return Verdict::apart;
    goal.record_touch(k_, p, V4{FT(0), FT(0), FT(0), FT(0)}, V4{FT(0), FT(0), FT(0), FT(0)});
    goal.convex = typename Search_goal<FT>::Convex_record{cell(0, p[3]), cell(1, p[3])};
    found_ = {index_, B != nullptr, B ? *B : Basis{}, g, false, Centre{}};
    policy_.convex_found(*this);
    return Verdict::collide;
  }

  // B's normals N (rows n_i, on the rows in the ring: positive multiples,
  // so every determinant below keeps its sign) by the cofactors of their
  // time column: C_i = (-1)^(i+3) det3(the other three normals' x, y, z).
  // Expanding along that column, det N = sum_i n_i[t] C_i; expanding along
  // row i, det(N with row i replaced by e_t) = C_i. Four 3x3 determinants
  // give all five of vertex_exists and dual_sign; kept for B.
  const Time_cofactors& time_cofactors(const Basis& B)
  {
    if (cofactors_ && cofactors_->basis == B) return *cofactors_;
    std::array<Vector3<R>, 4> space;
    for (std::size_t i = 0; i < 4; ++i) {
      const Vector4<R>& n = ring_row(static_cast<std::size_t>(B[i])).n;
      space[i] = {n[0], n[1], n[2]};
    }
    Time_cofactors tc{B, {}, R(0)};
    for (std::size_t i = 0; i < 4; ++i) {
      std::array<const Vector3<R>*, 3> other;
      for (std::size_t j = 0, k = 0; j < 4; ++j)
        if (j != i) other[k++] = &space[j];
      R minor = determinant3(*other[0], *other[1], *other[2]);
      tc.c[i] = i % 2 == 1 ? minor : R(-minor);   // (-1)^(i+3)
      tc.det += ring_row(static_cast<std::size_t>(B[i])).n[3] * tc.c[i];
    }
    return cofactors_.emplace(std::move(tc));
  }

  // det of C's equal-margin system (centre_exists).
  FT centre_det(const Centre& C)
  {
    FT sum(0);
    for (int j = 0; j < 5; ++j) {
      std::array<V4, 4> N;
      for (int i = 0, k = 0; i < 5; ++i)
        if (i != j) N[static_cast<std::size_t>(k++)] = row(static_cast<std::size_t>(C[i])).n;
      FT term = FT(scale_of(guide_rows_[static_cast<std::size_t>(C[j])])) * determinant4(N[0], N[1], N[2], N[3]);
      sum += j % 2 == 0 ? term : -term;   // (-1)^(j+4)
    }
    return sum;
  }

  // The guess's five basic rows, when it has five.
  static std::optional<Centre> centre_rows(const Double_simplex::Optimum& o)
  {
    if (o.basis.size() != 5) return std::nullopt;
    return Centre{o.basis[0], o.basis[1], o.basis[2], o.basis[3], o.basis[4]};
  }

  // Whether C's centre exists and is strictly inside every row.
  bool strictly_inside_centre(const Centre& C)
  {
    if (!certain([&](auto& s) { return s.centre_exists(C); })) return false;
    for (std::size_t j = 0; j < rows_.size(); ++j)
      if (certain([&](auto& s) { return s.centre_sign(C, j); }) != CGAL::NEGATIVE) return false;
    return true;
  }

  // A positive multiple of lambda with sum lambda_i n_i = 0 over the rows
  // `which`, the free column's lambda positive, when the normals'
  // dependencies are one line (Gaussian elimination with the kernel's signs
  // choosing pivots). Each row is scaled by a positive factor first (the
  // kernel's ring: coprime GMP integers in rationals), which scales
  // lambda_i by its inverse, so every sign asked of lambda and of
  // sum lambda_i c_i is unchanged. All in the kernel's ring, without
  // division: the elimination takes row r <- p r - r_c pivot row (p the
  // pivot: the same null space), and the back substitution, solving
  // p lambda_c = -s, scales the lambdas found so far by |p| instead of
  // dividing by p (one positive factor for all: the same signs). A pivot's
  // sign the kernel cannot certify sets `unsure` (nothing returned): the
  // predicate is then indeterminate, without a throw (uncertain_sign).
  std::optional<std::vector<R>> null_vector(const std::vector<std::size_t>& which, std::vector<Ring_row>& scaled,
                                            bool& unsure)
  {
    auto sign = [&](const R& x) {
      CGAL::Uncertain<CGAL::Sign> s = k_.uncertain_sign(x);
      unsure = unsure || !CGAL::is_certain(s);
      return unsure ? CGAL::ZERO : CGAL::get_certain(s);
    };
    std::size_t n = which.size();
    if (n < 2) return std::nullopt;
    scaled.clear();
    for (std::size_t i : which) scaled.push_back(ring_row(i));
    std::vector<std::array<R, 5>> M(4);   // M[q][i] = n_i[q]
    for (std::size_t i = 0; i < n; ++i)
      for (int q = 0; q < 4; ++q) M[q][i] = scaled[i].n[q];
    std::vector<std::size_t> pivot_col;
    std::size_t rank = 0, free = n;
    for (std::size_t c = 0; c < n; ++c) {
      std::size_t r = rank;
      while (r < 4 && sign(M[r][c]) == CGAL::ZERO && !unsure) ++r;
      if (unsure) return std::nullopt;
      if (r == 4) {
        if (free != n) return std::nullopt;   // two free columns: more than one line
        free = c;
        continue;
      }
      std::swap(M[r], M[rank]);
      for (std::size_t below = rank + 1; below < 4; ++below) {
        for (std::size_t cc = c + 1; cc < n; ++cc) M[below][cc] = M[rank][c] * M[below][cc] - M[below][c] * M[rank][cc];
        M[below][c] = R(0);
      }
      pivot_col.push_back(c);
      ++rank;
    }
    if (free == n) return std::nullopt;   // independent normals
    // Pivot columns after the free one have lambda 0 (their rows' sums hold
    // only later columns); the others follow from the bottom up.
    std::vector<R> lambda(n, R(0));
    lambda[free] = R(1);
    for (std::size_t r = rank; r-- > 0;) {
      std::size_t c = pivot_col[r];
      if (c > free) continue;
      R s(0);
      for (std::size_t cc = c + 1; cc < n; ++cc) s += M[r][cc] * lambda[cc];
      const R& p = M[r][c];
      bool positive = sign(p) == CGAL::POSITIVE;
      if (unsure) return std::nullopt;
      for (std::size_t cc = c + 1; cc < n; ++cc) lambda[cc] = positive ? R(lambda[cc] * p) : R(-(lambda[cc] * p));
      lambda[c] = positive ? R(-s) : s;
    }
    return lambda;
  }
};

} // namespace clash4d

#endif
