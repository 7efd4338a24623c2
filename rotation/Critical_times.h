// The critical times of a pair on an open time interval (regularised-
// semantics.md, fact 10): the real roots of the minors of the matrix whose
// rows are the pair's planes v_i(t) = (n_i(t), e_i(t)) and v_inf = (0, 0, 0,
// 1). Between two consecutive critical times every minor keeps its sign, so
// the pair's oriented matroid, hence every answer about the pair at time t,
// is constant there. Minors whose planes all come from one object keep
// their sign under a rigid motion and are left out. When neither object's
// normals span space (a slab against a half-space) the rank can be below
// four, and the 3 x 3 minors of each three columns are taken too.
#ifndef CLASH4D_ROTATION_CRITICAL_TIMES_H
#define CLASH4D_ROTATION_CRITICAL_TIMES_H

#include "numbers/Algebraic.h"
#include "rotation/Moving_planes.h"
#include <array>
#include <map>
#include <stdexcept>
#include <vector>

namespace clash4d {

// Four rows of the matrix; -1 stands for v_inf. A 3 x 3 minor of columns
// other than x, y, z (low rank only) is not kept: it names no contact.
using Minor_rows = std::array<int, 4>;

// More minors than a pair may have (exit 3 at the command): the minors of
// every plane of a pair grow as the fourth power of the planes.
constexpr std::size_t CLASH4D_MAX_PAIR_MINORS = 500000;

struct Minor_limit : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws Minor_limit when a pair of m planes, the first `split` of them
// the first object's, has more mixed minors than the limit.
void check_pair_minor_count(int m, int split);
// Throws Minor_limit when two convex pieces (m planes, the first split of
// them the first piece's) have more feature minors than the limit.
void check_feature_minor_count(std::size_t features, std::size_t m, std::size_t split);

// Two convex pieces' event minors (their vertex-face and edge-edge minors,
// Rotating_pair.cpp, feature_minors), with the side of its plane each piece
// is on, per row (the first piece's planes, then the second's): +1 where
// the row's value is <= 0, -1 the other (Shape_planes' orientations).
// Per minor, parts: the part of the first piece and of the second that is
// in the touch its root may mark (docs/rotation.md, Near features): a
// vertex v (Shape_planes::vertices), an edge e as (vertex count + e)
// (Shape_planes::edge_vertices), or -1 for none.
struct Pair_features {
  std::vector<Minor_rows> minors;
  std::vector<int> sides;
  std::vector<std::array<int, 2>> parts;
};

struct Critical_time {
  Algebraic t;
  std::vector<Minor_rows> vanishing;   // the minors with a root at t
};

class Critical_times {
public:
  // rows: the first object's planes, then the second's (first_count of
  // them); the interval (lo, hi), lo < hi. Throws Minor_limit past
  // CLASH4D_MAX_PAIR_MINORS; looks at the work budget (--max-seconds).
  Critical_times(const std::vector<Moving_plane>& rows, std::size_t first_count, const Rational& lo,
                 const Rational& hi, bool low_rank);
  // Only the roots of these minors (4 x 4, rows of both objects: two convex
  // pieces' vertex-face and edge-edge minors, Rotating_pair.cpp); when one
  // of them is identically zero on (lo, hi) (a vertex that stays on a plane
  // of the other piece), every mixed minor as above. Throws Minor_limit
  // past CLASH4D_MAX_PAIR_MINORS of them.
  Critical_times(const std::vector<Moving_plane>& rows, std::size_t first_count, const Rational& lo,
                 const Rational& hi, bool low_rank, const Pair_features& features);

  // Ascending, distinct, each strictly inside (lo, hi).
  const std::vector<Critical_time>& times() const { return times_; }
  // The minors solved (those the intervals did not settle).
  std::size_t minor_count() const { return minor_count_; }
  // Whether the times are the given features' only (not every mixed minor's).
  bool restricted() const { return restricted_; }

private:
  // The real roots in (lo, hi) of each distinct minor of these rows (the
  // first first_count of them the first object's), merged in order.
  void solve(const std::map<std::vector<mpz_class>, std::vector<Minor_rows>>& table,
             const std::vector<std::array<Integer_time_poly, 4>>& rows, std::size_t first_count, const Rational& lo,
             const Rational& hi);

  std::vector<mpz_class> without_known_roots(const std::vector<mpz_class>& p, const std::vector<Minor_rows>& minors);

  std::vector<Critical_time> times_;
  std::size_t minor_count_ = 0;
  bool restricted_ = false;
};

// det [n_i; n_j; n_k], the normals' minor, for rows of any polynomial type.
template <class Row>
auto normal_minor(const Row& a, const Row& b, const Row& c)
{
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

} // namespace clash4d

#endif
