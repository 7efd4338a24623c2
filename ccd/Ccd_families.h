// Generated CCD queries (docs/ccd-queries.md): families aimed at the
// contact edge cases float CCD gets wrong, each built exactly so that its
// answer hinges on a tie (a touch exactly at t = 1, a vertex through an
// edge, coplanar sliding, parallel edges, a degenerate triangle, near
// misses of 1e-9 and 1e-15, inputs that are doubles as the benchmark's
// are), and a simulation-like mix for benchmarks. Used by `clash4d fuzz
// --ccd`, the tests and the benchmark; every draw is a function of the
// seed (scene/Random_draw.h).
#ifndef CLASH4D_CCD_CCD_FAMILIES_H
#define CLASH4D_CCD_CCD_FAMILIES_H

#include "ccd/Ccd_query.h"
#include <cstdint>
#include <string>
#include <vector>

namespace clash4d {

class Random_draw;

struct Ccd_family {
  const char* name;
  Ccd_type type;
  const char* description;
};

// Every family, in a stable order (case i of a campaign is family i mod size).
const std::vector<Ccd_family>& ccd_families();

struct Ccd_case {
  std::string family;
  Ccd_query query;
};

// Case `index` of the campaign `seed`.
Ccd_case make_ccd_case(std::uint64_t seed, std::uint64_t index);
// One query of family `f` from the draw.
Ccd_query make_ccd_query(const Ccd_family& f, Random_draw& draw);

// The benchmark's simulation-like mix: 95% clear misses (primitives of a
// mesh far apart, as a broad phase passes on), the rest near contact, a
// tenth of those degenerate. `degenerate` says which kind a query is.
Ccd_query make_simulation_query(Ccd_type type, Random_draw& draw, bool& near, bool& degenerate);

} // namespace clash4d

#endif
