// Compact apart proofs for pairs of unions of convex pieces (meshes: issue
// 58 item 5), in the certificate format as it is (docs/certificate-format.md
// version 1: split trees and leaf conflicts). Per time piece, a tree of
// splits on separating space-time planes (else on planes just beyond a
// face of one side's box or at a median, else on times), whose every leaf
// closes off each piece of A, or each piece of B, on its own: "this piece
// is not in the leaf's cell" is one conflict over the piece's literals and
// the path. The proof grows with the pieces times the leaves (a handful),
// not with the pieces of A times the pieces of B. docs/meshes.md,
// "Certificates for meshes".
//
// Why every term of F_A AND F_B is closed off at a leaf (both semantics).
// A and B are unions of convex pieces (the CSG holds only unions of bounded
// primitives), so every DNF term of F_A holds every literal of some piece P
// of A (the checker's term is the AND of P's hull facets, the same planes
// as the pipeline's primitive), and likewise for B. At a leaf with path Pi
// and slab S, a term T = TA AND TB, TA holding piece P, TB piece Q:
//  * if the leaf lists a conflict over P's literals, Pi and S, it is valid
//    over T, Pi and S (its literals are among them), so T is closed off;
//  * otherwise P is "present" there, and the leaf lists, for Q, a conflict
//    over Q's literals, Pi and S, or one over P's, Q's, Pi and S (a pair
//    conflict); either is valid over T, Pi and S.
// The writer lists a conflict for every piece of A that is not present; when
// some piece of A is present, one for every piece of B not present and one
// for each present pair. So every term is closed off. In closed semantics
// the conflicts are "of": "both", over non-strict literals (t - hi strict at
// an open end), exactly as Motzkin's theorem is asked for them; in
// regularised semantics all literals are strict. Every conflict's
// multipliers come from the exact LP (search/Motzkin_lp.h, checked
// exactly); the planes of the splits are guesses in doubles (a double
// simplex), rounded to small integers: a wrong guess only leaves a piece
// present, never an unproved leaf. And the certificate writer has the
// checker of verify/ check the whole certificate before it is written.
#ifndef CLASH4D_CERTIFY_SPLIT_PROVER_H
#define CLASH4D_CERTIFY_SPLIT_PROVER_H

#include "exact/Rational_kernel.h"
#include "model/Scene_model.h"
#include "search/Semantics.h"
#include <nlohmann/json.hpp>
#include <optional>

namespace clash4d {

struct Split_limits {
  std::size_t min_pairs = 2;     // pieces of A times pieces of B: fewer, the term-by-term proof
  std::size_t max_leaves = 16;   // per time piece (and 4 nodes per leaf)
  int max_depth = 12;
  std::size_t max_pair_conflicts = 4096;   // per leaf: present pieces of A times of B
  std::size_t compare_pairs = 4096;        // up to this, the proof term by term too: the smaller is kept
};

struct Split_stats {
  std::size_t conflicts = 0, leaves = 0, splits = 0;
};

// The APART's "pieces" for objects a and b until `until`, or nothing when
// the pair is not two unions of bounded convex pieces, has too few piece
// pairs, or its tree would pass the limits (the caller then proves it term
// by term: search/Apart_pieces.h). strict_end: closed semantics leaves
// t = until out.
std::optional<nlohmann::ordered_json> split_apart_pieces(const Scene_model<Rational_kernel>& model, int a, int b,
                                                          const Rational& until, bool strict_end, Semantics semantics,
                                                          const Split_limits& limits = Split_limits(),
                                                          Split_stats* stats = nullptr);

} // namespace clash4d

#endif
