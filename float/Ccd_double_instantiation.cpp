#include "float/Ccd_double_instantiation.h"

#include "ccd/Ccd_sweep.h"
#include "float/Ccd_double_kernel.h"

namespace clash4d {

Ccd_answer ccd_double(const Ccd_query& query, const Ccd_options& options)
{
  Ccd_double_kernel k(query, options.tolerance);
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
