// The answer of `check` in text form, independent of the number type.
#ifndef CLASH4D_CHECK_CHECK_ANSWER_H
#define CLASH4D_CHECK_CHECK_ANSWER_H

#include "search/Check_stats.h"
#include "search/Semantics.h"
#include <array>
#include <string>
#include <vector>

namespace clash4d {

struct Check_options {
  bool all_pairs = false;     // examine every pair instead of stopping at the first collision
  bool earliest = false;      // find each pair's earliest collision time t* (§5)
  // false: the paper's "original" bounding (the objects' boxes at the
  // velocity changes, intersected; §4.1) instead of S-bounds. Reproduction only.
  bool sbounds = true;
  // false: the exact kernel never hands a long search over to a proof by
  // conflicts (exact/Interval_filter.h, decides_here): generate-and-test
  // decides every pair, as in the paper (tests of that search).
  bool apart_proofs = true;
  // false: convex pairs too go through the paper's cascade instead of
  // being decided by linear programs first (search/Convex_pair.h;
  // --no-convex-lp: reproduction, and tests of the cascade).
  bool convex_lp = true;
  // Measure each stage's seconds (Check_stats::seconds_*, printed by
  // --stats, which sets this). Off by default: the clock reads are about
  // 5% of a convex pair's query (search/Stage_clock.h).
  bool stage_seconds = false;
  // Candidate pairs checked at a time (check/Check_runner.h, run_pairs): the
  // memory kept per pair is the chunk's. Any size gives the same answer;
  // tests make it small to cross chunk boundaries.
  std::size_t pair_chunk = 4096;
  // false: a turning pair of two bounded convex pieces takes its critical
  // times from every mixed minor of their planes, not only from their
  // vertex-face and edge-edge minors (rotation/Rotating_pair.cpp): tests
  // of the restriction against the full enumeration.
  bool feature_events = true;
  // false: --earliest on objects that are unions of convex pieces (meshes)
  // searches the whole union formula, as the paper does, instead of the
  // piece pairs (check/Piece_pairs.h): tests compare the two.
  bool piece_pairs = true;
  bool json = false;          // output form (used by the command line only)
  Semantics semantics = Semantics::regularised;
};

struct Pair_answer {
  std::string a, b;                      // object names
  std::array<std::string, 4> witness;    // x, y, z, t
  bool witness_verified = false;
  bool earliest = false;                 // the three below are set
  std::string t_star;                    // exact t* (or the double's)
  std::array<std::string, 4> contact;    // (x*, t*) in the closure of the collision region
  bool at_start = false;                 // t* = tL: already overlapping when the span starts
  // The generic points that make the answer checkable (issue 14 item 3;
  // certificates). A generic point lies on no hyperplane of the pair's
  // extrusion (regularised-semantics.md item 1), so its cell is decided by
  // strict signs, and "p in the closure of g's cell" means: every atom h of
  // both objects has h(p) = 0 or the sign of h(g).
  //  - closed semantics: witness_cells[0] strictly inside the first object,
  //    witness_cells[1] strictly inside the second, each with the witness
  //    point in the closure of its cell (empty strings in regularised mode,
  //    where the witness is itself generic and inside both);
  //  - with earliest: contact_cells likewise for the contact point (x*, t*);
  //    in regularised mode both entries are one generic point strictly
  //    inside both objects, in the same constant-velocity sub-span as t*.
  std::array<std::array<std::string, 4>, 2> witness_cells;
  std::array<std::array<std::string, 4>, 2> contact_cells;
  // Regularised, exact, --json: the half-width of the largest axis-aligned
  // cube inside both objects' witness cells at the witness's time
  // (exact/Witness_depth.h); empty when not asked or unbounded.
  std::string depth;
};

struct Check_answer {
  std::string number;                    // "exact", "rational" or "double"
  Semantics semantics = Semantics::regularised;   // the question answered
  bool collide = false;
  std::vector<Pair_answer> pairs;        // colliding pairs, in pair order
  int earliest_pair = -1;                // index in pairs of the smallest t* (--earliest)

  // The pair whose witness is reported: the earliest one with --earliest,
  // else the first; null when nothing collides.
  const Pair_answer* reported() const
  {
    if (pairs.empty()) return nullptr;
    return &pairs[earliest_pair >= 0 ? earliest_pair : 0];
  }
  Check_stats stats;
};

// `skeleton`: the edges of each colliding pair's collision region.
struct Skeleton_answer {
  std::string number;
  struct Pair {
    std::string a, b;
    std::vector<std::array<std::array<std::string, 4>, 2>> edges;   // (x, y, z, t) ends
  };
  std::vector<Pair> pairs;                // pairs with a non-empty region, in pair order
  Check_stats stats;
};

} // namespace clash4d

#endif
