// Two static blocks under rotations that share their z axis exactly
// (fixtures/found/double_rotations_share_faces.json is one): the stop under
// q, the door under q times a turn about z, scaled by a rational so that its
// numbers are not exact in doubles. Their z faces are then the same two
// planes in exact numbers, and were a plane and its rounded twin in doubles.
// The stop is placed 1/1000 beyond the door's least x in the stop's frame,
// so they are apart, far beyond rounding. Only the engine's raw output is
// used (as tests/support/Random_scene.h), so a seed names one scene.
#ifndef CLASH4D_TESTS_SUPPORT_ROTATED_BLOCKS_H
#define CLASH4D_TESTS_SUPPORT_ROTATED_BLOCKS_H

#include "geometry/Rotation_matrix.h"
#include "numbers/Rational.h"
#include <array>
#include <cstdint>
#include <random>
#include <string>

namespace clash4d {

inline std::string rotated_blocks_apart(std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  auto pick = [&](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo + 1)); };
  using Q = std::array<Rational, 4>;
  Q qs;
  do
    for (auto& c : qs) c = Rational(pick(-9, 9));
  while (CGAL::is_zero(qs[0]) && CGAL::is_zero(qs[1]) && CGAL::is_zero(qs[2]) && CGAL::is_zero(qs[3]));
  Rational a(pick(1, 60)), b(pick(-60, 60)), scale = Rational(pick(1, 1000000)) / Rational(pick(1, 1000000));
  // qs (a, 0, 0, b): a turn about z first, so the z axis goes where qs takes it.
  Q qd{(qs[0] * a - qs[3] * b) * scale, (qs[1] * a + qs[2] * b) * scale, (qs[2] * a - qs[1] * b) * scale,
       (qs[3] * a + qs[0] * b) * scale};
  auto rs = rotation_matrix(qs[0], qs[1], qs[2], qs[3]), rd = rotation_matrix(qd[0], qd[1], qd[2], qd[3]);
  Rational length(pick(1, 8)), height = Rational(pick(1, 4)) / Rational(2), least;
  // The door's corners' x in the stop's frame: (rs^T rd p)_0.
  for (int c = 0; c < 4; ++c) {
    Rational px = c & 1 ? length : Rational(0), py = c & 2 ? height : Rational(0), x(0);
    for (int k = 0; k < 3; ++k) x += rs[k][0] * (rd[k][0] * px + rd[k][1] * py);
    if (c == 0 || x < least) least = x;
  }
  Rational hi = least - Rational(1) / Rational(1000), lo = hi - Rational(1), y(pick(-4, 4));
  auto text = [](const Rational& q) { return "\"" + to_string(q) + "\""; };
  auto quaternion = [&](const Q& q) { return text(q[0]) + "," + text(q[1]) + "," + text(q[2]) + "," + text(q[3]); };
  return R"({"format":"clash4d-scene/1","name":"rotated blocks apart","time":[0,1],"objects":[)"
         R"({"name":"door","shape":{"rotate":[)" + quaternion(qd) + R"(],"solid":{"block":{"min":[0,0,0],"max":[)" +
         text(length) + "," + text(height) + R"(,2]}}}},)"
         R"({"name":"stop","shape":{"rotate":[)" + quaternion(qs) + R"(],"solid":{"block":{"min":[)" + text(lo) + "," +
         text(y) + R"(,0],"max":[)" + text(hi) + "," + text(y + Rational(2)) + R"(,2]}}}}]})";
}

} // namespace clash4d

#endif
