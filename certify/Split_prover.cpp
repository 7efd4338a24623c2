#include "certify/Split_prover.h"

#include "certify/Apart_prover.h"
#include "model/Extrusion.h"
#include "search/Apart_pieces.h"
#include "search/Double_simplex.h"
#include "search/Motzkin_lp.h"
#include "run/Work_budget.h"
#include <algorithm>
#include <cmath>

namespace clash4d {
namespace {

using json = nlohmann::ordered_json;
using K = Rational_kernel;
using FT = K::FT;
using Point4d = std::array<double, 4>;

// The tree would pass a limit, or a pair of pieces meets in a leaf's cell:
// the caller proves the pair term by term instead.
struct Giving_up {};

// Every CSG node a union or a bounded primitive: the formula's DNF terms are
// the primitives.
bool union_of_bounded(const Csg_model<FT>& csg)
{
  for (const auto& n : csg.nodes)
    if (n.op != Csg_node::Op::Union && n.op != Csg_node::Op::Primitive) return false;
  for (const auto& p : csg.primitives)
    if (p.vertices.empty() || p.planes.empty()) return false;
  return !csg.primitives.empty();
}

// A plane w.p + c = 0 parting two sets of points, with margin delta.
struct Parting {
  Point4d w;
  double c = 0, delta = 0;
};

// The widest margin delta, in doubles, over the rows listed:
//   maximise delta  s.t.  w.p + c + delta <= 0 (A's points),
//   -(w.q + c) + delta <= 0 (B's), |w_k| <= 1, delta <= 1,
// asked of its dual in Double_simplex's form (six rows, b = e_6):
//   maximise -(sum alpha + sum beta + gamma)  s.t.
//   sum lambda_i (p_i, 1, 1) + sum mu_j (-q_j, -1, 1)
//     + (alpha - beta, 0, 0) + gamma e_6 = e_6,
// whose row multipliers are pi = -(w, c, delta) (pi . a_j >= cost_j is the
// primal's row j). Always feasible (gamma = 1) and bounded (costs <= 0).
std::optional<Parting> parting_on(const std::vector<Point4d> (&points)[2],
                                  const std::vector<std::pair<int, std::size_t>>& rows, double eps)
{
  Double_simplex lp(6, static_cast<int>(rows.size()) + 9, {0, 0, 0, 0, 0, 1}, eps);
  int j = 0;
  for (const auto& [side, i] : rows) {
    const Point4d& p = points[side][i];
    double sign = side == 0 ? 1 : -1;
    double a[6] = {sign * p[0], sign * p[1], sign * p[2], sign * p[3], sign, 1};
    lp.column(j++, a, 0);
  }
  for (int k = 0; k < 5; ++k)
    for (double sign : {1.0, -1.0}) {
      if (k == 4 && sign < 0) break;
      double a[6] = {0, 0, 0, 0, 0, 0};
      a[k == 4 ? 5 : k] = sign;
      lp.column(j++, a, -1);
    }
  std::optional<Double_simplex::Optimum> o = lp.solve();
  if (!o) return std::nullopt;
  Parting x;
  for (int k = 0; k < 4; ++k) x.w[static_cast<std::size_t>(k)] = -o->pi[k];
  x.c = -o->pi[4], x.delta = -o->pi[5];
  return x;
}

// The widest parting of A's points (in [-1, 1]^4) from B's: over a few
// points first, then those the answer violates added, until it holds for
// all (the program's cost grows with its rows). Nothing when the sets do
// not look apart.
std::optional<Parting> widest_parting(const std::vector<Point4d> (&points)[2])
{
  auto value = [](const Point4d& p, const Parting& x) {
    double v = x.c;
    for (int k = 0; k < 4; ++k) v += x.w[static_cast<std::size_t>(k)] * p[k];
    return v;
  };
  std::vector<std::pair<int, std::size_t>> rows;
  std::vector<char> listed[2];
  for (int side = 0; side < 2; ++side) {
    listed[side].assign(points[side].size(), 0);
    for (std::size_t i = 0; i < points[side].size(); i += std::max<std::size_t>(1, points[side].size() / 128))
      rows.emplace_back(side, i), listed[side][i] = 1;
  }
  for (int round = 0; round < 30; ++round) {
    std::optional<Parting> x;
    for (double eps : {1e-9, 1e-7})
      if ((x = parting_on(points, rows, eps))) break;
    if (!x || !(x->delta > 1e-9)) return std::nullopt;
    // The points not yet listed most violated, up to 256; within the
    // simplex's tolerance (a listed point's slack) the plane is taken.
    std::vector<std::pair<double, std::pair<int, std::size_t>>> worst;
    for (int side = 0; side < 2; ++side)
      for (std::size_t i = 0; i < points[side].size(); ++i) {
        double v = (side == 0 ? value(points[side][i], *x) : -value(points[side][i], *x)) + x->delta;
        if (v > 1e-8 && !listed[side][i]) worst.push_back({-v, {side, i}});
      }
    if (worst.empty()) return x;
    std::sort(worst.begin(), worst.end());
    for (std::size_t i = 0; i < worst.size() && i < 256; ++i)
      rows.push_back(worst[i].second), listed[worst[i].second.first][worst[i].second.second] = 1;
  }
  return std::nullopt;
}

// One piece of time [lo, hi] of the pair: its tree.
class Piece_tree {
public:
  Piece_tree(const Scene_model<K>& model, int a, int b, const Rational& lo, const Rational& hi, bool strict_end,
             bool closed, const Split_limits& limits)
      : lo_(lo), hi_(hi), strict_end_(strict_end), closed_(closed), limits_(limits)
  {
    const Time_span<FT> span{lo, hi};
    int objects[2] = {a, b};
    for (int side = 0; side < 2; ++side) {
      const Object_model<FT>& obj = model.objects[objects[side]];
      std::size_t seg = model.segment_on(objects[side], span);
      const Vector3<FT>& v = obj.motion.velocity[seg];
      const Vector3<FT>& o = obj.motion.offset[seg];
      for (const auto& p : obj.csg.primitives) {
        std::vector<int> lits;
        for (const auto& h : Extrusion<K>::primitive_planes(p, v, o))
          lits.push_back(table_.id({h.n[0], h.n[1], h.n[2], h.n[3], h.c}));
        lits_[side].push_back(std::move(lits));
        std::vector<std::array<double, 3>> corners;
        for (const auto& x : p.vertices)
          corners.push_back({round_to_nearest(x[0] + o[0]), round_to_nearest(x[1] + o[1]), round_to_nearest(x[2] + o[2])});
        corners_[side].push_back(std::move(corners));
      }
      for (int q = 0; q < 3; ++q) velocity_[side][q] = round_to_nearest(v[q]);
    }
    slab_ = {table_.id({FT(0), FT(0), FT(0), FT(-1), lo}), table_.id({FT(0), FT(0), FT(0), FT(1), -hi})};
  }

  json prove(Split_stats& stats)
  {
    Cell whole{round_to_nearest(lo_), round_to_nearest(hi_), lo_, hi_, {}};
    for (int side = 0; side < 2; ++side) whole.absent[side].assign(lits_[side].size(), -1);
    std::vector<int> path;
    json root = node(path, whole, 0);
    stats.conflicts += conflicts_written_, stats.leaves += leaves_, stats.splits += splits_;
    return root;
  }

private:
  Rational lo_, hi_;
  bool strict_end_, closed_;
  const Split_limits& limits_;
  Literal_table table_;
  std::vector<std::vector<int>> lits_[2];                            // per side and piece: literal ids
  std::vector<std::vector<std::array<double, 3>>> corners_[2];       // at t = 0, offset added (guesses)
  double velocity_[2][3] = {};
  std::vector<int> slab_;
  std::vector<Conflict> pool_;
  std::size_t leaves_ = 0, splits_ = 0, conflicts_written_ = 0, nodes_ = 0;

  // A conflict over the literals (all strict in regularised semantics;
  // non-strict but for t - hi at an open end in closed semantics), or -1
  // when they have a common point: one exact LP.
  int conflict(std::vector<int> ids, const std::vector<int>& path)
  {
    ids.insert(ids.end(), path.begin(), path.end());
    ids.insert(ids.end(), slab_.begin(), slab_.end());
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::vector<Motzkin_row> rows;
    for (int id : ids) rows.push_back({&table_.form(id), !closed_ || (strict_end_ && id == slab_[1])});
    auto lambda = motzkin_multipliers(rows);
    if (!lambda) return -1;
    Conflict c;
    for (std::size_t i = 0; i < ids.size(); ++i)
      if (CGAL::sign((*lambda)[i]) == CGAL::POSITIVE) c.literals.push_back(ids[i]), c.lambda.push_back((*lambda)[i]);
    pool_.push_back(std::move(c));
    return static_cast<int>(pool_.size()) - 1;
  }

  // The pieces of a side still present are tested against the cell: each one
  // found absent gets its conflict.
  void sweep_out(int side, std::vector<int>& absent, const std::vector<int>& path)
  {
    for (std::size_t i = 0; i < absent.size(); ++i)
      if (absent[i] < 0) absent[i] = conflict(lits_[side][i], path);
  }

  static std::vector<int> present(const std::vector<int>& absent)
  {
    std::vector<int> out;
    for (std::size_t i = 0; i < absent.size(); ++i)
      if (absent[i] < 0) out.push_back(static_cast<int>(i));
    return out;
  }

  // A node's cell beyond its path: its time and the pieces shown absent
  // there (per side and piece: a conflict of pool_, or -1).
  struct Cell {
    double t0, t1;
    Rational r0, r1;
    std::vector<int> absent[2];
  };

  json node(std::vector<int>& path, const Cell& cell, int depth)
  {
    Work_budget::check();
    if (++nodes_ > 4 * limits_.max_leaves) throw Giving_up();
    std::vector<int> pa = present(cell.absent[0]), pb = present(cell.absent[1]);
    std::size_t pairs = pa.size() * pb.size();
    // Few pairs left near each other: a conflict for each. A split would
    // cost another leaf, which lists a conflict for about every piece, and
    // a pair's conflict holds about two pieces' literals.
    if (pairs <= std::max<std::size_t>(4, (lits_[0].size() + lits_[1].size()) / 2)) return leaf(path, cell, pa, pb);
    if (depth >= limits_.max_depth) {
      if (pairs > limits_.max_pair_conflicts) throw Giving_up();
      return leaf(path, cell, pa, pb);
    }
    if (auto s = separating_plane(pa, pb, cell.t0, cell.t1)) {
      Cell side[2] = {cell, cell};
      int below = table_.id(*s);
      path.push_back(below);
      sweep_out(1, side[0].absent[1], path);
      path.back() = table_.negation(below);
      sweep_out(0, side[1].absent[0], path);
      path.pop_back();
      if (present(side[0].absent[1]).size() < pb.size() || present(side[1].absent[0]).size() < pa.size())
        return split(path, below, side, depth);
    }
    // No plane parts what is still present: cut space at a face of one
    // side's box, or at the median of the present pieces' centres along
    // their widest axis (a kd-tree step), when that leaves some piece
    // wholly on one side, each side's pieces then tested against its half.
    std::optional<Literal_coefficients> cut = box_cut(pa, pb, cell.t0, cell.t1);
    if (!cut) cut = median_cut(pa, pb, cell.t0, cell.t1);
    if (cut) {
      Cell side[2] = {cell, cell};
      int below = table_.id(*cut);
      for (int h = 0; h < 2; ++h) {
        path.push_back(h == 0 ? below : table_.negation(below));
        for (int o = 0; o < 2; ++o) sweep_out(o, side[h].absent[o], path);
        path.pop_back();
      }
      return split(path, below, side, depth);
    }
    // Nor a cut in space: a leaf while its pairs cost no more than a few
    // leaves (halving the time towards a contact at t* makes a leaf per
    // halving), else halve the time, where the pieces sweep less (the
    // literal t - tm: below t < tm).
    if (pairs <= 2 * (lits_[0].size() + lits_[1].size())) return leaf(path, cell, pa, pb);
    Rational rm = (cell.r0 + cell.r1) / 2;
    double tm = round_to_nearest(rm);
    Cell side[2] = {cell, cell};
    side[0].t1 = side[1].t0 = tm, side[0].r1 = side[1].r0 = rm;
    return split(path, table_.id({FT(0), FT(0), FT(0), FT(1), -rm}), side, depth);
  }

  // A split on the literal `below` (its negation above), each side's cell.
  json split(std::vector<int>& path, int below, const Cell (&side)[2], int depth)
  {
    ++splits_;
    json out{{"split", literal_json(table_.form(below))}};
    const char* name[2] = {"below", "above"};
    for (int h = 0; h < 2; ++h) {
      path.push_back(h == 0 ? below : table_.negation(below));
      out[name[h]] = node(path, side[h], depth + 1);
      path.pop_back();
    }
    return out;
  }

  // The leaf: every absent piece of A; with a piece of A present, every
  // absent piece of B and a conflict for each present pair (the proof in
  // Split_prover.h).
  json leaf(const std::vector<int>& path, const Cell& cell, const std::vector<int>& pa, const std::vector<int>& pb)
  {
    const auto& absent = cell.absent;
    if (++leaves_ > limits_.max_leaves) throw Giving_up();
    std::vector<int> listed;
    for (int c : absent[0])
      if (c >= 0) listed.push_back(c);
    if (!pa.empty()) {
      for (int c : absent[1])
        if (c >= 0) listed.push_back(c);
      for (int i : pa)
        for (int j : pb) {
          std::vector<int> both = lits_[0][static_cast<std::size_t>(i)];
          const auto& q = lits_[1][static_cast<std::size_t>(j)];
          both.insert(both.end(), q.begin(), q.end());
          int c = conflict(both, path);
          if (c < 0) throw Giving_up();   // the pieces meet here: the term-by-term proof says so
          listed.push_back(c);
        }
    }
    json conflicts = json::array();
    for (int c : listed) conflicts.push_back(conflict_json(pool_[static_cast<std::size_t>(c)], table_, closed_));
    conflicts_written_ += listed.size();
    return json{{"conflicts", conflicts}};
  }

  // Each present piece's box over [t0, t1] (doubles: guesses).
  std::array<double, 6> box(int side, int i, double t0, double t1) const
  {
    std::array<double, 6> b{HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (const auto& x : corners_[side][static_cast<std::size_t>(i)])
      for (double t : {t0, t1})
        for (int k = 0; k < 3; ++k) {
          double v = x[static_cast<std::size_t>(k)] + velocity_[side][k] * t;
          b[static_cast<std::size_t>(k)] = std::min(b[static_cast<std::size_t>(k)], v);
          b[static_cast<std::size_t>(k + 3)] = std::max(b[static_cast<std::size_t>(k + 3)], v);
        }
    return b;
  }

  // The present pieces' boxes over [t0, t1], A's then B's.
  std::vector<std::array<double, 6>> boxes(const std::vector<int>& pa, const std::vector<int>& pb, double t0,
                                           double t1) const
  {
    std::vector<std::array<double, 6>> out;
    for (int i : pa) out.push_back(box(0, i, t0, t1));
    for (int j : pb) out.push_back(box(1, j, t0, t1));
    return out;
  }

  // The plane x_k = m just beyond a face of the box of one side's present
  // pieces (m a step of 20 bits below the extent outside it), the face that
  // leaves the most present pieces of the other side wholly beyond it:
  // beyond it the side's pieces are all absent (a leaf), and before it
  // those of the other side. Where the pieces of A and B interleave (a
  // wrist entering the base's hollow), the pieces away from the other side
  // go out a face at a time.
  std::optional<Literal_coefficients> box_cut(const std::vector<int>& pa, const std::vector<int>& pb, double t0,
                                              double t1) const
  {
    std::vector<std::array<double, 6>> all = boxes(pa, pb, t0, t1);
    std::size_t split_at = pa.size();
    std::size_t best = 0;
    Literal_coefficients cut;
    for (int side = 0; side < 2; ++side) {
      std::size_t from = side == 0 ? 0 : split_at, to = side == 0 ? split_at : all.size();
      std::size_t other_from = side == 0 ? split_at : 0, other_to = side == 0 ? all.size() : split_at;
      for (int k = 0; k < 3; ++k) {
        double lo = HUGE_VAL, hi = -HUGE_VAL, all_lo = HUGE_VAL, all_hi = -HUGE_VAL;
        for (std::size_t i = 0; i < all.size(); ++i) {
          all_lo = std::min(all_lo, all[i][static_cast<std::size_t>(k)]);
          all_hi = std::max(all_hi, all[i][static_cast<std::size_t>(k + 3)]);
          if (i >= from && i < to)
            lo = std::min(lo, all[i][static_cast<std::size_t>(k)]), hi = std::max(hi, all[i][static_cast<std::size_t>(k + 3)]);
        }
        if (!(all_hi > all_lo) || !std::isfinite(all_hi - all_lo)) continue;
        int e;
        std::frexp(all_hi - all_lo, &e);
        double unit = std::ldexp(1.0, e - 20);
        double face[2] = {(std::floor(lo / unit) - 1) * unit, (std::ceil(hi / unit) + 1) * unit};
        for (int f = 0; f < 2; ++f) {
          std::size_t beyond = 0;
          for (std::size_t i = other_from; i < other_to; ++i)
            beyond += f == 0 ? all[i][static_cast<std::size_t>(k + 3)] < face[0] : all[i][static_cast<std::size_t>(k)] > face[1];
          if (beyond <= best) continue;
          best = beyond;
          cut = {FT(0), FT(0), FT(0), FT(0), -exact_rational(face[f])};
          cut[static_cast<std::size_t>(k)] = FT(1);
        }
      }
    }
    if (best == 0) return std::nullopt;
    return cut;
  }

  // The plane x_k = m (as x_k - m, m rounded to 20 bits below the extent)
  // at the median of the present pieces' box centres along the axis where
  // they spread most, when some present piece lies wholly on each side.
  std::optional<Literal_coefficients> median_cut(const std::vector<int>& pa, const std::vector<int>& pb, double t0,
                                                 double t1) const
  {
    std::vector<std::array<double, 6>> boxes = this->boxes(pa, pb, t0, t1);
    int axis = -1;
    double spread = 0;
    for (int k = 0; k < 3; ++k) {
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for (const auto& b : boxes) {
        double c = (b[static_cast<std::size_t>(k)] + b[static_cast<std::size_t>(k + 3)]) / 2;
        lo = std::min(lo, c), hi = std::max(hi, c);
      }
      if (hi - lo > spread) spread = hi - lo, axis = k;
    }
    if (axis < 0 || !(spread > 0) || !std::isfinite(spread)) return std::nullopt;
    std::vector<double> centres;
    for (const auto& b : boxes) centres.push_back((b[static_cast<std::size_t>(axis)] + b[static_cast<std::size_t>(axis + 3)]) / 2);
    std::nth_element(centres.begin(), centres.begin() + static_cast<long>(centres.size() / 2), centres.end());
    int e;
    std::frexp(spread, &e);
    double unit = std::ldexp(1.0, e - 20);
    double m = std::nearbyint(centres[centres.size() / 2] / unit) * unit;
    bool left = false, right = false;
    for (const auto& b : boxes)
      left = left || b[static_cast<std::size_t>(axis + 3)] < m, right = right || b[static_cast<std::size_t>(axis)] > m;
    if (!left || !right) return std::nullopt;
    Literal_coefficients cut{FT(0), FT(0), FT(0), FT(0), -exact_rational(m)};
    cut[static_cast<std::size_t>(axis)] = FT(1);
    return cut;
  }

  // A space-time plane with the present pieces of A on its negative side and
  // those of B on its positive side over [t0, t1], as small integers: the
  // largest margin over the pieces' corners at t0 and t1 (a piece moving with
  // a constant velocity sweeps the hull of those), in the box of those
  // corners scaled to [-1, 1]^4. A guess: the exact LPs of the conflicts
  // decide what it parts.
  std::optional<Literal_coefficients> separating_plane(const std::vector<int>& pa, const std::vector<int>& pb,
                                                       double t0, double t1) const
  {
    std::vector<Point4d> points[2];
    for (int side = 0; side < 2; ++side)
      for (int i : side == 0 ? pa : pb)
        for (const auto& x : corners_[side][static_cast<std::size_t>(i)])
          for (double t : {t0, t1})
            points[side].push_back({x[0] + velocity_[side][0] * t, x[1] + velocity_[side][1] * t,
                                    x[2] + velocity_[side][2] * t, t});
    Point4d low, high;
    low.fill(HUGE_VAL), high.fill(-HUGE_VAL);
    for (const auto& list : points)
      for (const auto& p : list)
        for (int k = 0; k < 4; ++k) low[k] = std::min(low[k], p[k]), high[k] = std::max(high[k], p[k]);
    Point4d centre, half;
    for (int k = 0; k < 4; ++k) {
      centre[k] = (low[k] + high[k]) / 2;
      half[k] = std::max((high[k] - low[k]) / 2, 1e-9 * std::max(1.0, std::fabs(centre[k])));
    }
    for (auto& list : points)
      for (auto& p : list)
        for (int k = 0; k < 4; ++k) p[k] = (p[k] - centre[k]) / half[k];
    std::optional<Parting> x = widest_parting(points);
    if (!x) return std::nullopt;
    // s(p) = sum w_k (p_k - centre_k) / half_k + c, in world coordinates,
    // rounded to integers of about 24 bits.
    double coef[5];
    double top = 0;
    for (int k = 0; k < 4; ++k) coef[k] = x->w[static_cast<std::size_t>(k)] / half[k], top = std::max(top, std::fabs(coef[k]));
    coef[4] = x->c;
    for (int k = 0; k < 4; ++k) coef[4] -= coef[k] * centre[k];
    if (!(top > 0) || !std::isfinite(top)) return std::nullopt;
    double scale = std::ldexp(1.0, 24) / top;
    Literal_coefficients s;
    bool moves = false;
    for (int k = 0; k < 5; ++k) {
      double v = std::nearbyint(coef[k] * scale);
      if (!std::isfinite(v)) return std::nullopt;
      s[static_cast<std::size_t>(k)] = exact_rational(v);
      moves = moves || (k < 4 && v != 0);
    }
    if (!moves) return std::nullopt;
    return s;
  }
};

} // namespace

std::optional<json> split_apart_pieces(const Scene_model<K>& model, int a, int b, const Rational& until,
                                       bool strict_end, Semantics semantics, const Split_limits& limits,
                                       Split_stats* stats)
{
  const Csg_model<FT>& A = model.objects[static_cast<std::size_t>(a)].csg;
  const Csg_model<FT>& B = model.objects[static_cast<std::size_t>(b)].csg;
  if (!union_of_bounded(A) || !union_of_bounded(B)) return std::nullopt;
  if (A.primitives.size() * B.primitives.size() < limits.min_pairs) return std::nullopt;
  std::vector<Rational> cuts = apart_cuts(model, a, b, until);
  Split_stats mine;
  json list = json::array();
  try {
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      Piece_tree tree(model, a, b, cuts[i], cuts[i + 1], strict_end && i + 2 == cuts.size(),
                      semantics == Semantics::closed, limits);
      list.push_back(json{{"t", json::array({to_string(cuts[i]), to_string(cuts[i + 1])})}, {"proof", tree.prove(mine)}});
    }
  } catch (const Giving_up&) {
    return std::nullopt;
  }
  if (stats) stats->conflicts += mine.conflicts, stats->leaves += mine.leaves, stats->splits += mine.splits;
  return list;
}

} // namespace clash4d
