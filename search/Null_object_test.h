// Null-object detection by generate-and-test (§4.2, §7: "null object
// detection tests"): every line shared by three hyperplanes with
// independent normals, cut at every other hyperplane, and the midpoint of each
// resulting edge inside the region classified with the regularised
// neighbourhood test of Appendix A. Every open cell of the arrangement inside
// a bounded region is a polytope with an edge, and the midpoint of that edge
// sees the cell, so the search is complete.
// Closed semantics (search/Semantics.h) tests the ends and cuts of every
// segment instead, each for a cell inside A and a cell inside B around it
// (on_line_closed).
#ifndef CLASH4D_SEARCH_NULL_OBJECT_TEST_H
#define CLASH4D_SEARCH_NULL_OBJECT_TEST_H

#include "geometry/Box.h"
#include "search/Check_stats.h"
#include "model/Pair_formula.h"
#include "geometry/Hyperplane4.h"
#include "model/Motion_groups.h"
#include "search/Neighbourhood.h"
#include "search/No_filter.h"
#include "search/Search_goal.h"
#include "run/Work_budget.h"
#include <algorithm>
#include <array>
#include <optional>
#include <vector>

namespace clash4d {

// Which hyperplanes a conquer works with and how the formula's leaves and
// the region's faces map to them: the same in every kernel when the
// interning decisions are certified, so another kernel can rebuild the
// planes from its own table and decide a line the first could not.
struct Plane_layout {
  std::vector<long> entry;                               // per plane: its table entry, or -1 for a face
  std::vector<int> face;                                 // per plane made from a face: 2 * axis + upper, else -1
  std::vector<unsigned> moves_along;                     // per plane: bit g set when it contains group g's (r, 1)
  std::vector<std::pair<std::size_t, int>> leaf_plane;   // table index -> (plane, orientation)
  std::vector<std::pair<std::size_t, int>> face_plane;   // face 2 * axis + upper -> (plane, orientation)
  std::size_t first_face = 0;                            // planes from here on are faces only
  std::vector<std::vector<int>> corners;                 // per plane: the corners it passes through, sorted
};

template <class K, class Policy = No_filter>
class Null_object_test {
public:
  using FT = typename K::FT;
  using H = Hyperplane4<FT>;
  using V = Vector4<FT>;

  // Holds a reference into itself (its own policy when none is given).
  Null_object_test(const Null_object_test&) = delete;
  Null_object_test& operator=(const Null_object_test&) = delete;

  // groups: which table planes move together (model/Motion_groups.h), if
  // known. policy: search/No_filter.h.
  Null_object_test(const K& k, const std::vector<H>& table, Check_stats& stats,
                    const Motion_groups<FT>* groups = nullptr, Policy* policy = nullptr)
    : k_(k), table_(table), stats_(stats), groups_(groups), policy_(policy ? *policy : own_policy_.emplace()) {}

  // Records what it finds in the goal; in earliest mode it examines every
  // edge that could hold an earlier point (the least time over an edge is at
  // one of its ends, and every vertex of a cell's closure ends such an edge).
  void run(const Pair_formula& f, const Box<FT, 4>& region, Search_goal<FT>& goal)
  {
    collect_planes(f, region);
    goal.vertex.reset();   // another conquer's layout
    std::size_t n = planes_.size();
    if (const std::array<std::size_t, 3>* t = policy_.replay_line()) {
      if ((*t)[2] < n) test_line(f, (*t)[0], (*t)[1], (*t)[2], goal);
      policy_.replayed(goal.found);
      return;
    }
    for (std::size_t i = 0; i < n && !goal.done(); ++i)
      for (std::size_t j = i + 1; j < n && !goal.done(); ++j)
        for (std::size_t m = j + 1; m < n && !goal.done(); ++m) {
          Work_budget::check();
          policy_.test_line(*this, f, i, j, m, goal);
        }
  }

  // The line of planes i, j, m of this conquer: its edges' midpoints
  // classified, what they hold recorded in the goal.
  void test_line(const Pair_formula& f, std::size_t i, std::size_t j, std::size_t m, Search_goal<FT>& goal)
  {
    on_line(f, i, j, m, goal);
  }

  // Which planes this conquer works with, and the region (for a policy
  // deciding a line in another kernel); conquers() counts the conquers run.
  const Plane_layout& layout() const { return layout_; }
  const Box<FT, 4>& region() const { return *region_; }
  std::size_t conquers() const { return conquers_; }
  const H& plane(std::size_t p) const { return planes_[p]; }

  // Whether plane p is parallel to the line of planes i, j, m (along:
  // n_p . l = 0), or, being parallel, contains it (its value at a point of
  // the line is zero), in this kernel: for a policy deciding a zero its own
  // kernel left open.
  bool zero_on_line(const std::array<std::size_t, 3>& line, std::size_t p, bool along) const
  {
    V l, base;
    line_of(line, l, base);
    return k_.sign(along ? dot(planes_[p].n, l) : planes_[p].value(base)) == CGAL::ZERO;
  }

  // The order of the cuts of planes p and q (neither parallel to it) on the
  // line of planes i, j, m, oriented as on_line orients it (the generalised
  // cross product; a positive multiple of it in another kernel's planes
  // scaled by positive factors): for a policy deciding an order its own
  // kernel left open. The cut of h at base + s l is s = -h(base) / (n.l).
  CGAL::Sign cut_order(const std::array<std::size_t, 3>& line, std::size_t p, std::size_t q) const
  {
    V l, base;
    line_of(line, l, base);
    auto cut = [&](const H& h) {
      FT along = dot(h.n, l);
      CGAL::Sign sa = k_.sign(along);
      if (sa == CGAL::ZERO) throw std::logic_error("internal error: a cut of a plane parallel to the line");
      return k_.quotient(-h.value(base), along, sa);
    };
    return k_.compare(cut(planes_[p]), cut(planes_[q]));
  }

  // The direction of the line of three planes (the generalised cross
  // product of their normals) and a point of it: for a policy's questions
  // about a line, asked outside on_line.
  void line_of(const std::array<std::size_t, 3>& line, V& l, V& base) const
  {
    const Pair_minors<FT> ab(planes_[line[0]].n, planes_[line[1]].n);
    l = cross_with(ab, line[2], planes_[line[2]].n);
    std::optional<V> on = base_point(ab, line[0], line[1], line[2], l);
    if (!on) throw std::logic_error("internal error: a policy's line with no point in an exact kernel");
    base = *on;
  }

  // Another kernel's conquer, rebuilt in this one: the layout's planes made
  // from this kernel's table and region.
  void adopt(const Plane_layout& layout, const Box<FT, 4>& region)
  {
    layout_ = layout;
    planes_.clear();
    keys_ = nullptr;
    minors_.reset();
    key_minors_.reset();
    for (std::size_t p = 0; p < layout.entry.size(); ++p)
      planes_.push_back(layout.entry[p] >= 0 ? table_[layout.entry[p]] : face(region, layout.face[p]));
    resize_values();
  }

  // One line of an adopted conquer: whether it holds a point inside.
  // Only the verdict is wanted, so the policy may classify the
  // neighbourhoods of the line's points another way first (verdict_first).
  bool line_has_inside(const Pair_formula& f, std::size_t i, std::size_t j, std::size_t m,
                       Semantics semantics = Semantics::regularised)
  {
    Search_goal<FT> goal;
    goal.semantics = semantics;
    verdict_only_ = true;
    on_line(f, i, j, m, goal);
    verdict_only_ = false;
    return goal.found;
  }

  // Face 2 * a + upper of the region, inside <= 0: -x_a + lo <= 0 or x_a - hi <= 0.
  static H face(const Box<FT, 4>& region, int which)
  {
    int a = which / 2;
    V e{FT(0), FT(0), FT(0), FT(0)};
    e[a] = FT(which % 2 ? 1 : -1);
    return {e, which % 2 ? -region.hi[a] : region.lo[a]};
  }

  // Skeleton (§5): every edge of the boundary of the region the formula
  // describes, inside this closed region, as segments (p, q). Lines come from
  // formula planes only (the region's faces are artificial); an edge is kept
  // when the planes that separate inside from outside around it (the
  // essential ones) span the whole 3D neighbourhood, so it is a 1-face and not
  // a point of a 2- or 3-face.
  void skeleton(const Formula& f, const Box<FT, 4>& region, std::vector<std::array<V, 2>>& out)
  {
    collect_planes(f, region);
    for (std::size_t i = 0; i < layout_.first_face; ++i)
      for (std::size_t j = i + 1; j < layout_.first_face; ++j)
        for (std::size_t m = j + 1; m < layout_.first_face; ++m) skeleton_line(f, i, j, m, out);
  }

private:
  const K& k_;
  const std::vector<H>& table_;
  Check_stats& stats_;
  const Motion_groups<FT>* groups_;
  std::optional<Policy> own_policy_;   // made only when no policy is given
  Policy& policy_;
  std::vector<H> planes_;                 // distinct hyperplanes, region faces last
  Plane_layout layout_;                   // where they come from
  bool verdict_only_ = false;             // line_has_inside: no point will be made
  // A cut of the current line: its parameter and the plane cutting there
  // (a region face too; npos: not known), by which ties are recognised.
  struct Cut {
    FT s;
    std::size_t plane;
  };
  std::vector<Cut> cuts_;                 // on_line's cuts of the current line
  std::size_t lo_plane_ = 0, hi_plane_ = 0;   // range_in_region: the faces at the segment's ends (or npos)
  std::vector<FT> at_base_, along_;       // per plane: value at the base point, slope along l
  std::vector<int> sign_;                 // per plane at the current test point: -1, 0, +1
  std::array<std::size_t, 3> line_{};     // the planes that meet in the current line
  // The minors of the current line's first two planes (kernel_ft4.h), made
  // when that pair changes: run nests the third plane innermost, so they
  // serve every line of the pair.
  struct Minors_of_pair {
    Pair_minors<FT> minors;
    std::array<std::size_t, 2> of{npos, npos};
    const Pair_minors<FT>& at(std::size_t i, std::size_t j, const V& a, const V& b)
    {
      if (of[0] != i || of[1] != j) minors = Pair_minors<FT>(a, b), of = {i, j};
      return minors;
    }
    void reset() { of = {npos, npos}; }
  };
  Minors_of_pair minors_, key_minors_;    // of the planes' normals, and of their keys
  int line_group_ = -1;                   // their common motion group, or -1
  int line_corner_ = -1;                  // a corner all three pass through: the line is its path
  std::vector<int> line_meets_;           // corners two of them pass through: the line meets their paths
  // The policy's normal keys (normal_keys), per plane (a face's own normal),
  // and the current line's direction made from them: a zero certified on
  // those is a zero of the exact arithmetic, written so (planes parallel
  // after a rational rotation, which intervals would only enclose).
  const std::vector<V>* keys_ = nullptr;
  std::vector<V> plane_key_;
  std::vector<H> whole_key_;              // plane_keys, per plane (a face: itself)
  bool line_keyed_ = false;               // keys are known for this line
  std::optional<V> line_key_;             // the line's direction from them, once made
  // on_line_closed: the segment's points, per plane its cut's group (or -1)
  // and the sign of its slope along the line.
  struct Point_on_line {
    FT s;
    long plane;                           // the plane cut there, -1 for an end of the segment
    std::vector<std::size_t> more;        // planes cutting there through a corner's path
    std::size_t by;                       // the plane (a face for an end) cutting there, or npos
  };
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  // classify's cells around the current line, for the planes through the
  // point (Neighbourhood::Memo): the same at every point of the line
  // between cuts. Kept for one examination of one line, with the planes
  // through the point it was made for (none: not yet made on this line).
  typename Neighbourhood<K>::Memo memo_;
  std::optional<std::vector<std::size_t>> memo_through_;
  std::vector<Point_on_line> points_;
  std::vector<std::size_t> groups_at_;
  std::vector<long> group_of_;
  std::vector<int> cut_sign_;

  // Index of h among planes_ (appending it if new) and its orientation;
  // `along` (model/Motion_groups.h) is what h is known to contain, and is
  // added to the plane's (a plane shared by two entries contains both).
  // entry: h's index in the table, or -1 for the region face `face`.
  std::pair<std::size_t, int> intern(const H& h, unsigned along, long entry, int face = -1)
  {
    for (std::size_t p = 0; p < planes_.size(); ++p)
      if (int o = same_plane(h, p, entry, face)) {
        layout_.moves_along[p] |= along;
        add_corners(p, entry);
        return {p, o};
      }
    planes_.push_back(h);
    layout_.moves_along.push_back(along);
    layout_.entry.push_back(entry);
    layout_.face.push_back(face);
    layout_.corners.emplace_back();
    add_corners(planes_.size() - 1, entry);
    return {planes_.size() - 1, 1};
  }

  // The corners table entry `entry` passes through, added to plane p's.
  void add_corners(std::size_t p, long entry)
  {
    if (!groups_ || entry < 0) return;
    const std::vector<int>& more = groups_->corners_of(static_cast<std::size_t>(entry));
    if (more.empty()) return;
    std::vector<int>& mine = layout_.corners[p];
    std::vector<int> both;
    std::set_union(mine.begin(), mine.end(), more.begin(), more.end(), std::back_inserter(both));
    mine = std::move(both);
  }

  bool through_corner(std::size_t p, int corner) const
  {
    const std::vector<int>& c = layout_.corners[p];
    return std::binary_search(c.begin(), c.end(), corner);
  }

  // line_corner_ and line_meets_ for the line of planes i, j, m: merges of
  // their sorted corner lists (most are empty).
  void find_line_corners(std::size_t i, std::size_t j, std::size_t m)
  {
    line_corner_ = -1;
    line_meets_.clear();
    const std::vector<int> &ci = layout_.corners[i], &cj = layout_.corners[j], &cm = layout_.corners[m];
    if ((ci.empty() ? 1 : 0) + (cj.empty() ? 1 : 0) + (cm.empty() ? 1 : 0) >= 2) return;
    auto shared = [&](const std::vector<int>& a, const std::vector<int>& b, const std::vector<int>& third) {
      for (auto x = a.begin(), y = b.begin(); x != a.end() && y != b.end();) {
        if (*x < *y) ++x;
        else if (*y < *x) ++y;
        else {
          if (std::binary_search(third.begin(), third.end(), *x)) line_corner_ = *x;
          else if (std::find(line_meets_.begin(), line_meets_.end(), *x) == line_meets_.end()) line_meets_.push_back(*x);
          ++x, ++y;
        }
      }
    };
    shared(ci, cj, cm);
    shared(ci, cm, cj);
    shared(cj, cm, ci);
  }

  // The line where planes i, j and m meet (zero when they do not). Three
  // planes that contain a group's motion (r, 1) meet along it: the
  // generalised cross product is then its last coordinate times (r, 1),
  // written so.
  V line_direction(std::size_t i, std::size_t j, std::size_t m)
  {
    unsigned common = layout_.moves_along[i] & layout_.moves_along[j] & layout_.moves_along[m];
    line_group_ = -1;
    for (int g = 0; common && line_group_ < 0; ++g)
      if (common & (1u << g)) line_group_ = g;
    line_ = {i, j, m};
    memo_through_.reset();   // each examination of a line anew
    find_line_corners(i, j, m);
    line_keyed_ = false;
    line_key_.reset();
    if (const std::vector<V>* keys = policy_.template normal_keys<FT>()) {
      if (keys != keys_) {
        keys_ = keys;
        key_minors_.reset();
        plane_key_.clear();
        whole_key_.clear();
        const std::vector<H>* whole = policy_.template plane_keys<FT>();
        for (std::size_t p = 0; p < planes_.size(); ++p) {
          long e = layout_.entry[p];
          plane_key_.push_back(e >= 0 ? (*keys)[static_cast<std::size_t>(e)] : planes_[p].n);
          if (whole) whole_key_.push_back(e >= 0 ? (*whole)[static_cast<std::size_t>(e)] : planes_[p]);
        }
      }
      line_keyed_ = true;
    }
    V l;
    if (line_group_ < 0) {
      l = cross_with(pair_minors(i, j), m, planes_[m].n);
    } else {
      const Vector3<FT>& r = groups_->velocity[line_group_];
      FT d = cross_with(pair_minors(i, j), m, planes_[m].n)[3];
      l = {d * r[0], d * r[1], d * r[2], d};
    }
    // The keys' line is a nonzero multiple of this one: its zero
    // coordinates are this one's (made only when some coordinate may be zero).
    if (line_keyed_ && (possibly_zero(l[0]) || possibly_zero(l[1]) || possibly_zero(l[2]) || possibly_zero(l[3]))) {
      const V& lk = line_key();
      for (int q = 0; q < 4; ++q)
        if (certainly_zero(lk[q])) l[q] = FT(0);
    }
    return l;
  }

  // The generalised cross product of a pair's minors with c, plane m's
  // normal (or its key): without products when m is a region face, whose
  // normal and key are +-e_a (Pair_minors::cross_axis).
  V cross_with(const Pair_minors<FT>& ab, std::size_t m, const V& c) const
  {
    int which = layout_.face[m];
    return which >= 0 ? ab.cross_axis(which / 2, which % 2 == 1) : ab.cross(c);
  }

  const Pair_minors<FT>& pair_minors(std::size_t i, std::size_t j)
  {
    return minors_.at(i, j, planes_[i].n, planes_[j].n);
  }

  // The current line's direction from the keys, made once per line.
  const V& line_key()
  {
    if (!line_key_) {
      const auto& ab = key_minors_.at(line_[0], line_[1], plane_key_[line_[0]], plane_key_[line_[1]]);
      line_key_ = cross_with(ab, line_[2], plane_key_[line_[2]]);
    }
    return *line_key_;
  }

  // Whether plane p, parallel to the current line, contains it, beyond
  // doubt on the whole keys: the line's three planes are independent, so
  // p contains the line when its key is a combination of theirs, that is
  // when every 4x4 minor with the offset column is zero (the one without
  // it is, p being parallel).
  bool contains_line(std::size_t p) const
  {
    if (whole_key_.empty()) return false;
    const H* rows[4] = {&whole_key_[line_[0]], &whole_key_[line_[1]], &whole_key_[line_[2]], &whole_key_[p]};
    for (int drop = 0; drop < 4; ++drop) {
      V m[4];
      for (int r = 0; r < 4; ++r) {
        for (int q = 0, col = 0; q < 4; ++q)
          if (q != drop) m[r][col++] = rows[r]->n[q];
        m[r][3] = rows[r]->c;
      }
      if (!certainly_zero(determinant4(m[0], m[1], m[2], m[3]))) return false;
    }
    return true;
  }

  // Whether x is zero beyond doubt (no sign is asked: it may be unknown).
  bool certainly_zero(const FT& x) const { return !k_.possibly_positive(x) && !k_.possibly_positive(-x); }
  bool possibly_zero(const FT& x) const { return k_.possibly_nonnegative(x) && k_.possibly_nonnegative(-x); }

  // The groups whose motion a face x_a = c contains (still along axis a).
  unsigned face_along(int a) const
  {
    unsigned along = 0;
    for (std::size_t g = 0; groups_ && a < 3 && g < groups_->still.size(); ++g)
      if (groups_->still[g][a]) along |= 1u << g;
    return along;
  }

  const Box<FT, 4>* region_ = nullptr;    // the conquer's region
  std::size_t conquers_ = 0;

  // Whether h (table entry `entry`, or region face `face`) is plane p.
  int same_plane(const H& h, std::size_t p, long entry, int face) const
  {
    return policy_.same_plane(k_, h, planes_[p], entry, face, layout_.entry[p], layout_.face[p], *region_);
  }

  void collect_planes(const Pair_formula& f, const Box<FT, 4>& region)
  {
    ++conquers_;
    region_ = &region;
    planes_.clear();
    keys_ = nullptr;
    minors_.reset();
    key_minors_.reset();
    layout_ = Plane_layout();
    layout_.leaf_plane.assign(table_.size(), {0, 0});
    f.for_each_leaf([&](std::uint32_t h) {
      if (layout_.leaf_plane[h].second == 0)
        layout_.leaf_plane[h] =
            intern(table_[h], groups_ && groups_->group(h) >= 0 ? 1u << groups_->group(h) : 0u, static_cast<long>(h));
    });
    // Region faces, inside <= 0; they may coincide with leaves, so intern too.
    layout_.first_face = planes_.size();
    for (int which = 0; which < 8; ++which)
      layout_.face_plane.push_back(intern(face(region, which), face_along(which / 2), -1, which));
    resize_values();
  }

  void resize_values()
  {
    at_base_.resize(planes_.size());
    along_.resize(planes_.size());
    sign_.resize(planes_.size());
  }

  Truth leaf_truth(std::uint32_t h) const
  {
    int s = sign_[layout_.leaf_plane[h].first] * layout_.leaf_plane[h].second;
    return s < 0 ? Truth::True : s > 0 ? Truth::False : Truth::Unknown;
  }
  bool inside_region() const
  {
    for (const auto& fp : layout_.face_plane)
      if (sign_[fp.first] * fp.second >= 0) return false;
    return true;
  }

  void on_line(const Pair_formula& f, std::size_t i, std::size_t j, std::size_t m, Search_goal<FT>& goal)
  {
    if (goal.closed()) {
      on_line_closed(f, i, j, m, goal);
      return;
    }
    V l = line_direction(i, j, m);
    if (k_.is_zero(l)) return;
    ++stats_.lines;
    std::optional<V> on = base_point(pair_minors(i, j), i, j, m, l);
    FT s_lo(0), s_hi(0);
    if (!on || !range_in_region(*on, l, s_lo, s_hi)) return;
    const V& base = *on;
    // The segment's earliest end (time is linear along it), where the
    // face end_plane cuts it.
    auto earliest_end = [&] { return end_plane(k_.sign(l[3]) != CGAL::NEGATIVE); };
    // At the recorded contact point: a tie with t*, which cannot improve
    // (Search_goal::vertex).
    if (goal.vertex && at_contact(goal, i, j, m, earliest_end())) return;
    if (!improves(goal, Number_ops<FT>::lower(base[3] + s_lo * l[3], base[3] + s_hi * l[3]), earliest_end)) return;
    evaluate_planes(base, l, layout_.first_face);
    std::vector<Cut>& cuts = cuts_;         // reused: a line's cuts, no allocation per line
    cuts.assign({{s_lo, lo_plane_}, {s_hi, hi_plane_}});
    FT centre = (s_lo + s_hi) / FT(2);
    // Per corner whose path the line meets: whether that point is on the
    // segment (every plane of the corner cuts the line there).
    std::vector<std::pair<int, bool>> meets;
    for (std::size_t p = 0; p < planes_.size(); ++p) {
      sign_[p] = 0;   // Unknown on the segment unless constant there
      CGAL::Sign sa = k_.sign(along_[p]);
      if (sa == CGAL::ZERO) {
        sign_[p] = static_cast<int>(k_.sign(at_base_[p]));
        continue;
      }
      // A face the line crosses bounds the segment: strictly inside between.
      if (p >= layout_.first_face) { sign_[p] = -1; continue; }
      int corner = meeting_corner(p);
      auto seen = std::find_if(meets.begin(), meets.end(), [&](const auto& e) { return e.first == corner; });
      bool inside;
      if (corner >= 0 && seen != meets.end()) {
        inside = seen->second;                 // the same point as the corner's first plane
      } else {
        FT cut = k_.quotient(-at_base_[p], along_[p], sa);
        inside = compare_cuts(s_lo, lo_plane_, cut, p) == CGAL::NEGATIVE &&
                 compare_cuts(cut, p, s_hi, hi_plane_) == CGAL::NEGATIVE;
        if (inside) cuts.push_back({cut, p});
        if (corner >= 0) meets.emplace_back(corner, inside);
      }
      if (!inside) sign_[p] = static_cast<int>(k_.sign(at_base_[p] + centre * along_[p]));
    }
    // Cheap rejection of the whole segment: false whatever the planes that
    // cut it (or contain it) do, hence false at every midpoint on it.
    if (f.evaluate([&](std::uint32_t h) { return leaf_truth(h); }) == Truth::False) return;
    // Sorted by the kernel's order of the numbers, which is an order for
    // every kernel (a tolerance is not); cuts the kernel calls equal are
    // skipped.
    std::sort(cuts.begin(), cuts.end(),
              [&](const Cut& a, const Cut& b) { return compare_cuts(a.s, a.plane, b.s, b.plane) == CGAL::NEGATIVE; });
    bool up = k_.sign(l[3]) != CGAL::NEGATIVE;   // time grows along the line
    for (std::size_t q = 0; q + 1 < cuts.size() && !goal.done(); ++q) {
      if (compare_cuts(cuts[q + 1].s, cuts[q + 1].plane, cuts[q].s, cuts[q].plane) == CGAL::ZERO) continue;
      // The edge's earlier end (time is linear along it).
      const Cut& end = up ? cuts[q] : cuts[q + 1];
      // The plane cutting there (a face at a segment's end: asked only at
      // a possible tie and at a record, earliest mode).
      bool segment_end = up ? q == 0 : q + 2 == cuts.size();
      auto by = [&] { return end.plane == npos && segment_end ? end_plane(up) : end.plane; };
      if (goal.vertex && at_contact(goal, i, j, m, by())) continue;
      V early = point_along(base, end.s, l);
      if (!improves(goal, early[3], by)) continue;
      FT mid = (cuts[q].s + cuts[q + 1].s) / FT(2);
      if (auto in = classify(f, base, l, mid))
        if (goal.record(k_, *in, early) && goal.earliest) remember_contact(goal, i, j, m, by());
    }
  }

  // The face at the segment's lower (lo) or upper end, when one face's cut
  // is certainly beyond every other's there (range_in_region records it
  // only on keyed lines); npos otherwise. Asked only at ties and records.
  std::size_t end_plane(bool lo) const
  {
    std::size_t best = lo ? lo_plane_ : hi_plane_;
    if (best != npos) return best;
    auto cut_of = [&](std::size_t p, CGAL::Sign sa) { return k_.quotient(-at_base_[p], along_[p], sa); };
    // The faces bounding this end: cuts of faces with e < 0 bound it below
    // (the greatest is the end), e > 0 above (the least), as in
    // range_in_region.
    std::optional<FT> top;
    for (int pass = 0; pass < 2; ++pass)
      for (const auto& fp : layout_.face_plane) {
        std::size_t p = fp.first;
        CGAL::Sign sa = k_.sign(along_[p]);
        int e = sa * fp.second;
        if (e == 0 || (e < 0) != lo || p == best) continue;
        FT cut = cut_of(p, sa);
        if (!top) {
          best = p;
          top = cut;
          continue;
        }
        FT d = lo ? cut - *top : *top - cut;   // > 0: beyond the best
        if (pass == 0 && !k_.possibly_nonnegative(-d)) {
          best = p;
          top = cut;
        } else if (pass == 1 && k_.possibly_nonnegative(d)) {
          return npos;   // not certainly short of the best
        }
      }
    return best;
  }

  // Whether a point of the current line at time t, where plane fourth()
  // cuts it (npos: not known; asked only by a filter at a tie it cannot
  // decide), could improve the goal: Search_goal::can_improve, through the
  // policy (improves).
  template <class Fourth>
  bool improves(const Search_goal<FT>& goal, const FT& t, Fourth fourth)
  {
    return policy_.improves(k_, *this, goal, t, line_, fourth);
  }

  // Whether the point where plane p cuts line i, j, m is the goal's
  // recorded contact point (earliest mode, this conquer): its time is t*.
  static bool at_contact(const Search_goal<FT>& goal, std::size_t i, std::size_t j, std::size_t m, std::size_t p)
  {
    return goal.earliest && goal.vertex && p != npos && vertex_of(i, j, m, p) == *goal.vertex;
  }

  // The contact point just recorded is where plane p cuts line i, j, m.
  static void remember_contact(Search_goal<FT>& goal, std::size_t i, std::size_t j, std::size_t m, std::size_t p)
  {
    if (p == npos) return;
    goal.vertex = vertex_of(i, j, m, p);
  }

  // The line's three planes and the plane cutting it, sorted: the four
  // planes (independent: the line is a point's, and p cuts it) meeting at
  // one point, the same point for every line of three of them.
  static std::array<std::size_t, 4> vertex_of(std::size_t i, std::size_t j, std::size_t m, std::size_t p)
  {
    std::array<std::size_t, 4> v{i, j, m, p};
    std::sort(v.begin(), v.end());
    return v;
  }

  // Closed semantics: the touching set of A and B within the closed region
  // is a union of polytopes (the closure of a cell inside A meeting the
  // closure of a cell inside B), and each, if non-empty, has a vertex on
  // the arrangement of the objects' planes and the region's faces: an end
  // or a cut of the segment of some line of three of them. So every end
  // and cut is tested; the least time of the touching set is attained at
  // one (regularised-semantics item 5).
  void on_line_closed(const Pair_formula& f, std::size_t i, std::size_t j, std::size_t m, Search_goal<FT>& goal)
  {
    V l = line_direction(i, j, m);
    if (k_.is_zero(l)) return;
    ++stats_.lines;
    std::optional<V> on = base_point(pair_minors(i, j), i, j, m, l);
    FT s_lo(0), s_hi(0);
    if (!on || !range_in_region(*on, l, s_lo, s_hi)) return;
    const V& base = *on;
    auto earliest_end = [&] { return end_plane(k_.sign(l[3]) != CGAL::NEGATIVE); };
    // A tie with t* (Search_goal::vertex).
    if (goal.vertex && at_contact(goal, i, j, m, earliest_end())) return;
    if (!improves(goal, Number_ops<FT>::lower(base[3] + s_lo * l[3], base[3] + s_hi * l[3]), earliest_end)) return;
    evaluate_planes(base, l, layout_.first_face);
    collect_points(s_lo, s_hi);
    // Cheap rejection: A (or B) false whatever the planes meeting the closed
    // segment do, hence at every point of it and in every cell around one.
    auto truth = [&](std::uint32_t h) { return leaf_truth(h); };
    if (f.a().evaluate(truth) == Truth::False || f.b().evaluate(truth) == Truth::False) return;
    group_points();
    for (std::size_t g = 0; g < groups_at_.size() && !goal.done(); ++g) {
      const Point_on_line& at = points_[groups_at_[g]];
      auto by = [&] { return at.by == npos && at.plane < 0 ? end_plane(g == 0) : at.by; };
      if (goal.vertex && at_contact(goal, i, j, m, by())) continue;
      if (!improves(goal, base[3] + at.s * l[3], by)) continue;
      for (std::size_t p = 0; p < layout_.first_face; ++p)
        if (group_of_[p] >= 0) sign_[p] = cut_sign_[p] * (g > std::size_t(group_of_[p]) ? 1 : g < std::size_t(group_of_[p]) ? -1 : 0);
      std::size_t before = goal.records;
      test_touch(f, point_along(base, at.s, l), goal);
      if (goal.earliest && goal.records != before) remember_contact(goal, i, j, m, by());
    }
  }

  // The segment's points for on_line_closed: its ends (plane -1) and the
  // cut of every object plane crossing it, inclusive of the ends. A plane
  // that meets the line at a corner's path shares the corner's first
  // plane's cut, written so. Sets sign_ on the segment: the constant sign
  // of planes not crossing it, 0 for those that do (and for those holding
  // it); group_of_ is -1 until group_points.
  void collect_points(const FT& s_lo, const FT& s_hi)
  {
    points_.clear();
    points_.push_back({s_lo, -1, {}, lo_plane_});
    points_.push_back({s_hi, -1, {}, hi_plane_});
    group_of_.assign(layout_.first_face, -1);
    cut_sign_.assign(layout_.first_face, 0);
    FT centre = (s_lo + s_hi) / FT(2);
    std::vector<std::pair<int, std::size_t>> corner_point;   // corner -> index in points_
    for (std::size_t p = 0; p < layout_.first_face; ++p) {
      CGAL::Sign sa = k_.sign(along_[p]);
      sign_[p] = 0;
      if (sa == CGAL::ZERO) { sign_[p] = static_cast<int>(k_.sign(at_base_[p])); continue; }
      cut_sign_[p] = static_cast<int>(sa);
      int corner = meeting_corner(p);
      auto seen = std::find_if(corner_point.begin(), corner_point.end(), [&](const auto& e) { return e.first == corner; });
      if (corner >= 0 && seen != corner_point.end()) {
        if (seen->second != npos) points_[seen->second].more.push_back(p);
        else sign_[p] = static_cast<int>(k_.sign(at_base_[p] + centre * along_[p]));
        continue;
      }
      FT cut = k_.quotient(-at_base_[p], along_[p], sa);
      bool on = compare_cuts(cut, p, s_lo, lo_plane_) != CGAL::NEGATIVE &&
                compare_cuts(s_hi, hi_plane_, cut, p) != CGAL::NEGATIVE;
      if (corner >= 0) corner_point.emplace_back(corner, on ? points_.size() : npos);
      if (on) points_.push_back({cut, static_cast<long>(p), {}, p});
      else sign_[p] = static_cast<int>(k_.sign(at_base_[p] + centre * along_[p]));
    }
  }

  // Sorts the points along the segment and groups those the kernel calls
  // equal (several planes through one point); group_of_[p] is the group of
  // plane p's cut, groups_at_[g] a point of group g.
  void group_points()
  {
    auto order = [&](const Point_on_line& a, const Point_on_line& b) { return compare_cuts(a.s, a.by, b.s, b.by); };
    std::sort(points_.begin(), points_.end(),
              [&](const Point_on_line& a, const Point_on_line& b) { return order(a, b) == CGAL::NEGATIVE; });
    groups_at_.clear();
    for (std::size_t q = 0; q < points_.size(); ++q) {
      if (q == 0 || order(points_[q], points_[q - 1]) != CGAL::ZERO) groups_at_.push_back(q);
      long g = static_cast<long>(groups_at_.size()) - 1;
      if (points_[q].plane >= 0) group_of_[points_[q].plane] = g;
      for (std::size_t p : points_[q].more) group_of_[p] = g;
    }
  }

  // Point x (signs of the object planes there in sign_): in the closure of
  // a cell inside A and of a cell inside B? Recorded in the goal if so.
  void test_touch(const Pair_formula& f, const V& x, Search_goal<FT>& goal)
  {
    ++stats_.points_classified;
    std::vector<std::size_t> through;
    for (std::size_t p = 0; p < layout_.first_face; ++p)
      if (sign_[p] == 0) through.push_back(p);
    auto truth = [&](std::uint32_t h) { return leaf_truth(h); };
    if (f.a().evaluate(truth) == Truth::False || f.b().evaluate(truth) == Truth::False) return;
    std::vector<V> normals;
    for (std::size_t p : through) normals.push_back(planes_[p].n);
    auto cell_of = [&](const Formula& g) {
      return [&, g_ptr = &g](const std::vector<int>& signs) {
        for (std::size_t t = 0; t < through.size(); ++t) sign_[through[t]] = signs[t];
        return g_ptr->evaluate(truth) == Truth::True;
      };
    };
    // As classify: the policy may decide the verdicts another way first (on
    // the keys of a keyed line); no cell inside one object, no touch. Only
    // a verdict wanted and both known: the touch, without its directions.
    bool keyed = line_keyed_ && !through.empty();
    if (verdict_only_ || keyed) {
      std::vector<V> keys;
      for (std::size_t p : through)
        if (keyed) keys.push_back(plane_key_[p]);
      bool both = true;
      for (const Formula* g : {&f.a(), &f.b()}) {
        std::optional<bool> in = policy_.verdict_around(keyed ? keys : normals, cell_of(*g), stats_.cells_tested);
        both = both && in && *in;
        if (in && !*in) {
          for (std::size_t p : through) sign_[p] = 0;
          return;
        }
      }
      if (verdict_only_ && both) {
        for (std::size_t p : through) sign_[p] = 0;
        V none{FT(0), FT(0), FT(0), FT(0)};
        goal.record_touch(k_, x, none, none);
        return;
      }
    }
    Neighbourhood<K> hood(k_);
    std::optional<V> da = hood.find_inside_around(normals, cell_of(f.a()));
    std::optional<V> db = da ? hood.find_inside_around(normals, cell_of(f.b())) : std::nullopt;
    stats_.cells_tested += hood.cells_tested();
    for (std::size_t p : through) sign_[p] = 0;
    if (da && db) goal.record_touch(k_, x, *da, *db);
  }

  // The line's parameter range inside the closed region, from the faces
  // only: most lines of a conquer miss the region, and then no other plane
  // need be evaluated.
  bool range_in_region(const V& base, const V& l, FT& s_lo, FT& s_hi)
  {
    bool has_lo = false, has_hi = false;
    lo_plane_ = hi_plane_ = npos;
    for (const auto& fp : layout_.face_plane) {
      std::size_t p = fp.first;
      evaluate_plane(p, base, l);
      CGAL::Sign sa = k_.sign(along_[p]);
      int e = sa * fp.second;
      if (e == 0) {
        if (k_.sign(at_base_[p]) * fp.second > 0) return false;
        continue;
      }
      FT cut = k_.quotient(-at_base_[p], along_[p], sa);
      if (e > 0) {
        hi_plane_ = has_hi ? attaining(s_hi, hi_plane_, cut, p, false) : p;
        s_hi = has_hi ? Number_ops<FT>::lower(s_hi, cut) : cut;
        has_hi = true;
      } else {
        lo_plane_ = has_lo ? attaining(s_lo, lo_plane_, cut, p, true) : p;
        s_lo = has_lo ? Number_ops<FT>::upper(s_lo, cut) : cut;
        has_lo = true;
      }
    }
    return has_lo && has_hi && compare_cuts(s_hi, hi_plane_, s_lo, lo_plane_) == CGAL::POSITIVE;
  }

  // The order of two cuts of the current line, a by plane pa and b by
  // plane pb. On the keys, a tie is recognised beyond doubt (concurrent):
  // a vertex where five planes meet, as under rational rotations, which
  // intervals would only enclose. Otherwise the kernel's comparison,
  // through the policy (compare_cuts), which may decide an order the kernel
  // leaves open on the planes.
  CGAL::Sign compare_cuts(const FT& a, std::size_t pa, const FT& b, std::size_t pb) const
  {
    if (line_keyed_ && pa != npos && pb != npos && possibly_zero(a - b) && concurrent(pa, pb)) return CGAL::ZERO;
    return policy_.compare_cuts(k_, *this, a, pa, b, pb, line_);
  }

  // Which plane's cut bounds the segment after cut b (plane pb) is taken
  // with cut a (plane pa): the greater for the lower end, the lesser for
  // the upper; npos when no sign says so without asking one the kernel may
  // not certify (only keyed lines need the answer).
  std::size_t attaining(const FT& a, std::size_t pa, const FT& b, std::size_t pb, bool greater) const
  {
    if (!line_keyed_) return npos;
    FT d = b - a;
    if (!k_.possibly_nonnegative(d)) return greater ? pa : pb;       // b < a
    if (!k_.possibly_nonnegative(-d)) return greater ? pb : pa;      // b > a
    return pa != npos && concurrent(pa, pb) ? pa : npos;             // equal
  }

  // Whether planes p and q cut the current line at one point, beyond doubt
  // on the whole keys. The line's three planes and p (not parallel to the
  // line) meet in one point v; q holds v exactly when the five rows
  // (n, c) are dependent: det5 = sum_r (-1)^r c_r det4(normals but r) = 0.
  bool concurrent(std::size_t p, std::size_t q) const
  {
    if (whole_key_.empty()) return false;
    const H* rows[5] = {&whole_key_[line_[0]], &whole_key_[line_[1]], &whole_key_[line_[2]], &whole_key_[p],
                        &whole_key_[q]};
    FT det(0);
    for (int r = 0; r < 5; ++r) {
      V m[4];
      for (int t = 0, u = 0; t < 5; ++t)
        if (t != r) m[u++] = rows[t]->n;
      FT term = rows[r]->c * determinant4(m[0], m[1], m[2], m[3]);
      det = r % 2 ? det - term : det + term;
    }
    return certainly_zero(det);
  }

  void evaluate_planes(const V& base, const V& l, std::size_t count)
  {
    for (std::size_t p = 0; p < count; ++p) evaluate_plane(p, base, l);
  }

  // The corner of plane p whose path the line meets (line_meets_), or -1.
  int meeting_corner(std::size_t p) const
  {
    for (int c : line_meets_)
      if (through_corner(p, c)) return c;
    return -1;
  }

  // The line lies in its own three planes (and, when it is a corner's path,
  // in every plane of the corner), and runs parallel to every plane of its
  // motion group: those zeros hold by construction and are written so (an
  // interval would only enclose them).
  void evaluate_plane(std::size_t p, const V& base, const V& l)
  {
    bool holds = p == line_[0] || p == line_[1] || p == line_[2] || (line_corner_ >= 0 && through_corner(p, line_corner_));
    bool parallel = holds || (line_group_ >= 0 && (layout_.moves_along[p] >> line_group_ & 1u));
    // A region face, +-x_a + c: two terms, not the eight of a product.
    int which = layout_.face[p];
    FT along = parallel ? FT(0) : which >= 0 ? (which % 2 ? l[which / 2] : -l[which / 2]) : dot(planes_[p].n, l);
    // The keys are asked only about values the intervals leave open, then
    // the policy (zero_on_line: the other kernel's planes).
    if (line_keyed_ && !parallel) parallel = possibly_zero(along) && certainly_zero(dot(plane_key_[p], line_key()));
    if (!parallel)
      parallel = possibly_zero(along) && !certainly_zero(along) && policy_.zero_on_line(k_, *this, line_, p, true);
    FT value = holds ? FT(0) : which >= 0 ? (which % 2 ? base[which / 2] : -base[which / 2]) + planes_[p].c
                                          : planes_[p].value(base);
    if (parallel && !holds)
      holds = possibly_zero(value) && ((line_keyed_ && contains_line(p)) ||
                                       (!certainly_zero(value) && policy_.zero_on_line(k_, *this, line_, p, false)));
    at_base_[p] = holds ? FT(0) : value;
    along_[p] = parallel ? FT(0) : along;
  }

  // The segment of the line through planes i, j, m inside the closed region,
  // and every cut by a formula plane in it, sorted; empty when it misses.
  std::vector<FT> cuts_in_region(std::size_t i, std::size_t j, std::size_t m, V& base, V& l)
  {
    l = line_direction(i, j, m);
    if (k_.is_zero(l)) return {};
    std::optional<V> on = base_point(pair_minors(i, j), i, j, m, l);
    if (!on) return {};
    base = *on;
    FT s_lo(0), s_hi(0);
    if (!range_in_region(base, l, s_lo, s_hi)) return {};
    evaluate_planes(base, l, layout_.first_face);
    std::vector<FT> cuts{s_lo, s_hi};
    for (std::size_t p = 0; p < layout_.first_face; ++p) {
      if (k_.sign(along_[p]) == CGAL::ZERO) continue;
      FT cut = -at_base_[p] / along_[p];
      if (k_.less(s_lo, cut) && k_.less(cut, s_hi)) cuts.push_back(cut);
    }
    std::sort(cuts.begin(), cuts.end());
    return cuts;
  }

  void skeleton_line(const Formula& f, std::size_t i, std::size_t j, std::size_t m, std::vector<std::array<V, 2>>& out)
  {
    V base, l;
    std::vector<FT> cuts = cuts_in_region(i, j, m, base, l);
    if (!cuts.empty()) ++stats_.lines;
    for (std::size_t q = 0; q + 1 < cuts.size(); ++q) {
      if (k_.compare(cuts[q + 1], cuts[q]) == CGAL::ZERO) continue;
      FT mid = (cuts[q] + cuts[q + 1]) / FT(2);
      if (is_edge(f, l, mid)) out.push_back({point_along(base, cuts[q], l), point_along(base, cuts[q + 1], l)});
    }
  }

  bool is_edge(const Formula& f, const V& l, const FT& s)
  {
    ++stats_.points_classified;
    std::vector<std::size_t> through;
    for (std::size_t p = 0; p < layout_.first_face; ++p) {
      sign_[p] = static_cast<int>(k_.sign(at_base_[p] + s * along_[p]));
      if (sign_[p] == 0) through.push_back(p);
    }
    if (f.evaluate([&](std::uint32_t h) { return leaf_truth(h); }) != Truth::Unknown) return false;
    std::vector<V> normals;
    for (std::size_t p : through) normals.push_back(planes_[p].n);
    // Every cell around the point, by its sign vector, inside or not.
    std::vector<std::pair<std::vector<int>, bool>> cells;
    Neighbourhood<K> hood(k_);
    hood.find_inside(l, normals, [&](const std::vector<int>& signs) {
      for (std::size_t t = 0; t < through.size(); ++t) sign_[through[t]] = signs[t];
      bool in = f.evaluate([&](std::uint32_t h) { return leaf_truth(h); }) == Truth::True;
      bool seen = false;
      for (const auto& c : cells) seen = seen || c.first == signs;
      if (!seen) cells.emplace_back(signs, in);
      return false;
    });
    stats_.cells_tested += hood.cells_tested();
    // Essential planes: some pair of cells adjacent across it differ.
    std::vector<V> essential;
    for (std::size_t t = 0; t < through.size(); ++t) {
      bool found = false;
      for (std::size_t a = 0; a < cells.size() && !found; ++a)
        for (std::size_t b = a + 1; b < cells.size() && !found; ++b) {
          if (cells[a].second == cells[b].second || cells[a].first[t] == cells[b].first[t]) continue;
          bool one_apart = true;
          for (std::size_t u = 0; u < through.size() && one_apart; ++u) one_apart = u == t || cells[a].first[u] == cells[b].first[u];
          found = one_apart;
        }
      if (found) essential.push_back(normals[t]);
    }
    for (std::size_t a = 0; a < essential.size(); ++a)
      for (std::size_t b = a + 1; b < essential.size(); ++b)
        for (std::size_t c = b + 1; c < essential.size(); ++c)
          if (k_.orientation4(l, essential[a], essential[b], essential[c]) != CGAL::ZERO) return true;
    return false;
  }

  // A point on planes a, b and c: the one whose coordinate k is zero, for
  // the k where the direction l is largest (l_k is, up to sign, the
  // determinant of the system). Any k with l_k != 0 gives a point of the
  // line, and every decision along the line is about its points, not this
  // one, so kernels need not agree on k. The other three coordinates by
  // Cramer's rule, as cross products of the rows.
  // ab: planes i's and j's minors (line_direction's), whose x01 is
  // cross(r0, r1) term for term (a_i b_j - a_j b_i, negated for columns c2, c0).
  // None when the kernel's sign of the system's determinant is zero: never
  // in an exact kernel (it is +-l_k, not 0), but a float kernel's rounding
  // of it can be 0 where its l_k is not; it then sees no point on the line,
  // as it sees no line where l rounds to zero (a point made by dividing by
  // 0 was a witness of NaNs, rotation-fuzz #38).
  std::optional<V> base_point(const Pair_minors<FT>& ab, std::size_t i, std::size_t j, std::size_t m, const V& l) const
  {
    const H &a = planes_[i], &b = planes_[j], &c = planes_[m];
    int k = k_.largest_component(l);
    int cols[3], n = 0;
    for (int q = 0; q < 4; ++q)
      if (q != k) cols[n++] = q;
    const H* hs[3] = {&a, &b, &c};
    Vector3<FT> r[3];
    for (int t = 0; t < 3; ++t) r[t] = {hs[t]->n[cols[0]], hs[t]->n[cols[1]], hs[t]->n[cols[2]]};
    Vector3<FT> x12 = cross(r[1], r[2]), x20 = cross(r[2], r[0]);
    Vector3<FT> x01{ab.minor(cols[1], cols[2]), -ab.minor(cols[0], cols[2]), ab.minor(cols[0], cols[1])};
    FT det = dot(r[0], x12);
    CGAL::Sign sd = k_.sign(det);
    if (sd == CGAL::ZERO) return std::nullopt;
    V p;
    p[k] = FT(0);
    for (int t = 0; t < 3; ++t) p[cols[t]] = k_.quotient(-(a.c * x12[t] + b.c * x20[t] + c.c * x01[t]), det, sd);
    return p;
  }

  std::optional<V> classify(const Pair_formula& f, const V& base, const V& l, const FT& s)
  {
    ++stats_.points_classified;
    std::vector<std::size_t> through;
    for (std::size_t p = 0; p < planes_.size(); ++p) {
      sign_[p] = static_cast<int>(k_.sign(at_base_[p] + s * along_[p]));
      if (sign_[p] == 0) through.push_back(p);
    }
    // Cheap rejection: false whatever the planes through the point do.
    if (f.evaluate([&](std::uint32_t h) { return leaf_truth(h); }) == Truth::False) return std::nullopt;
    std::vector<V> normals;
    for (std::size_t p : through) normals.push_back(planes_[p].n);
    Neighbourhood<K> hood(k_);
    auto inside = [&](const std::vector<int>& signs) {
      for (std::size_t i = 0; i < through.size(); ++i) sign_[through[i]] = signs[i];
      return inside_region() && f.evaluate([&](std::uint32_t h) { return leaf_truth(h); }) == Truth::True;
    };
    // On a keyed line the policy may first classify on the keys (positive
    // multiples of the normals: the same cells), where the zeros of planes
    // made parallel by a rational rotation are certain; the point itself is
    // then made on the planes, as every run makes it.
    bool keyed = line_keyed_ && !through.empty();
    if (verdict_only_ || keyed) {
      std::vector<V> keys;
      for (std::size_t p : through)
        if (keyed) keys.push_back(plane_key_[p]);
      if (std::optional<bool> found = policy_.verdict_first(keyed ? line_key() : l, keyed ? keys : normals, inside,
                                                            stats_.cells_tested)) {
        if (!*found) return std::nullopt;
        if (verdict_only_) return point_along(base, s, l);   // inside: a verdict, the point is not used
      }
    }
    if (!memo_through_ || *memo_through_ != through) {
      memo_.cells.clear();
      memo_.complete = false;
      memo_through_ = through;
    }
    std::optional<V> d = hood.find_inside(l, normals, inside, &memo_);
    stats_.cells_tested += hood.cells_tested();
    if (!d) return std::nullopt;
    V p = point_along(base, s, l);
    if (through.empty()) return p;
    return point_along(p, step_into_cell(through, *d, s), *d);
  }

  // regularised-semantics item 3: how far to go along d, from the point at s
  // on the line, into the open cell found inside. The planes through the
  // point are those d was chosen against; every other plane not parallel to
  // d is met at |h| / |n.d|, and half the least of those crosses none.
  FT step_into_cell(const std::vector<std::size_t>& through, const V& d, const FT& s) const
  {
    bool any = false;
    FT best(1);
    for (std::size_t p = 0, t = 0; p < planes_.size(); ++p) {
      if (t < through.size() && through[t] == p) { ++t; continue; }
      FT nd = dot(planes_[p].n, d);
      if (k_.sign(nd) == CGAL::ZERO) continue;
      FT q = Number_ops<FT>::magnitude(at_base_[p] + s * along_[p]) / Number_ops<FT>::magnitude(nd);
      best = any ? Number_ops<FT>::lower(best, q) : q;
      any = true;
    }
    return best / FT(2);
  }
};

} // namespace clash4d

#endif
