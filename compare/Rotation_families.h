// Scene generators for `clash4d fuzz --rotation`: contact edge cases of
// parts that turn (issue 61), where the exact answer hinges on an instant
// and float code tends to err. Each family builds a configuration whose
// exact verdicts follow from its construction (the reasons are in
// Rotation_families.cpp and are checked by tests/test_rotation.cpp), in
// three variants: exactly touching, pushed into overlap by a small amount,
// or pulled apart by as much (10^-3, 10^-9 or 10^-15 of its size). The
// scene is then turned whole by a rational quaternion, moved, and its time
// unit changed, none of which changes a verdict.
#ifndef CLASH4D_COMPARE_ROTATION_FAMILIES_H
#define CLASH4D_COMPARE_ROTATION_FAMILIES_H

#include "compare/Contact_families.h"
#include <cstdint>
#include <optional>
#include <vector>

namespace clash4d {

// Every rotation family, in a stable order (case i is family i mod size).
const std::vector<Fuzz_family>& rotation_families();

// What the construction says the exact answer is (none: not derived).
struct Rotation_expectation {
  std::optional<bool> regularised, closed;
};

struct Rotation_case {
  Fuzz_case scene;
  Rotation_expectation expected;
};

// Case `index` of the rotation campaign `seed`: a function of (seed,
// index) only, the same on every platform.
Rotation_case make_rotation_case(std::uint64_t seed, std::uint64_t index);

} // namespace clash4d

#endif
