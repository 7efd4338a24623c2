// Scene generators for `clash4d fuzz`: families of cases aimed at contact,
// where the exact verdict hinges on regularisation ("touching is not a
// collision", spec) and float code tends to err.
//
// Most families build a contact configuration and then draw one of three
// variants: touching exactly (no collision), its twin pushed into overlap by
// a small amount (collision) or pulled apart by as much (no collision). The
// scene is then varied in ways that keep the exact verdict: axes permuted and
// mirrored, which object moves, a velocity common to all objects, scale,
// translation, time unit, object order, and sometimes an ignored copy of an
// object. Every number is built exactly (rationals); the only double-specific
// choices are decimal values picked because their double sums miss.
#ifndef CLASH4D_COMPARE_CONTACT_FAMILIES_H
#define CLASH4D_COMPARE_CONTACT_FAMILIES_H

#include <cstdint>
#include <string>
#include <vector>

namespace clash4d {

struct Fuzz_family {
  const char* name;
  const char* description;
};

// Every family, in a stable order (case i of a campaign is family i mod size).
const std::vector<Fuzz_family>& fuzz_families();

struct Fuzz_case {
  std::string family;
  std::string json;     // a valid scene file (clash4d-scene/1), numbers as exact strings
};

// Case `index` of the campaign `seed`: a function of (seed, index) only, the
// same on every platform and standard library.
Fuzz_case make_fuzz_case(std::uint64_t seed, std::uint64_t index);

} // namespace clash4d

#endif
