// The exact kernel: CGAL's rational over GMP, signs decided exactly.
#ifndef CLASH4D_EXACT_EXACT_KERNEL_H
#define CLASH4D_EXACT_EXACT_KERNEL_H

#include "core/Kernel_base.h"
#include "exact/Rational.h"
#include <string>

namespace clash4d {

class Exact_kernel : public Kernel_base<Exact_kernel, Rational> {
public:
  static constexpr const char* name() { return "exact"; }
  static constexpr bool is_exact = true;
  CGAL::Sign sign(const FT& x) const { return CGAL::sign(x); }
  FT from_rational(const Rational& q) const { return q; }
  Rational to_rational(const FT& x) const { return x; }
  std::string to_text(const FT& x) const { return to_string(x); }
};

} // namespace clash4d

#endif
