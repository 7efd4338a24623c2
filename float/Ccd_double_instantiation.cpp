#include "float/Ccd_double_instantiation.h"

#include "ccd/Ccd_sweep.h"
#include "float/Ccd_double_kernel.h"
#include <cmath>
#include <stdexcept>

namespace clash4d {

Ccd_answer ccd_double(const Ccd_query& query, const Ccd_options& options)
{
  double separation = nearest_double(options.separation);
  if (!std::isfinite(separation)) throw std::range_error("the separation is beyond the range of double");
  Ccd_double_kernel k(query, options.tolerance, separation);
  auto r = ccd_sweep(k);
  Ccd_answer a;
  a.collide = r.collide;
  if (r.collide && options.earliest) {
    Ccd_uv_fraction<double> uv = uv_fraction(k.polynomials(), r.contact);
    double t = r.t.value;
    a.earliest = Ccd_earliest{t, uv.u_num.at(t) / uv.u_den.at(t), uv.v_num.at(t) / uv.v_den.at(t), r.contact,
                              std::nullopt};
  }
  return a;
}

} // namespace clash4d
