#include "exact/Ccd_instantiation.h"

#include "ccd/Ccd_sweep.h"
#include "exact/Ccd_filtered_kernel.h"
#include "exact/Ccd_rational_kernel.h"
#include "exact/Interval_kernel.h"

namespace clash4d {

namespace {

Polynomial<Rational> rational_poly(const Polynomial<mpz_class>& p)
{
  std::vector<Rational> c;
  for (int i = 0; i < p.size(); ++i) c.emplace_back(p[i].get_mpz_t());
  return Polynomial<Rational>(c);
}

// t*, and (u, v) as the quotients the contact names, evaluated at t* in
// Q(t*) (numbers/Algebraic.h, quotient_at).
Ccd_earliest exact_earliest(Ccd_rational_kernel& k, const Algebraic& t, const Ccd_contact& contact)
{
  Ccd_uv_fraction<mpz_class> f = uv_fraction(k.polynomials(), contact);
  Algebraic u = Algebraic::quotient_at(t, f.u_num.coefficients(), f.u_den.coefficients());
  Algebraic v = Algebraic::quotient_at(t, f.v_num.coefficients(), f.v_den.coefficients());
  Ccd_uv_fraction<Rational> uv{rational_poly(f.u_num), rational_poly(f.u_den), rational_poly(f.v_num),
                               rational_poly(f.v_den)};
  return Ccd_earliest{t, u, v, contact, uv};
}

} // namespace

Ccd_answer ccd_rational(const Ccd_query& query, const Ccd_options& options)
{
  Ccd_rational_kernel k(query, options.separation);
  auto r = ccd_sweep(k);
  Ccd_answer a;
  a.collide = r.collide;
  if (r.collide && options.earliest) a.earliest = exact_earliest(k, r.t, r.contact);
  return a;
}

Ccd_answer ccd_exact(const Ccd_query& query, const Ccd_options& options)
{
  // Where the machine does not round as the intervals ask (valgrind), the
  // answer is the rational kernel's alone.
  if (!Interval_kernel::encloses_here()) return ccd_rational(query, options);
  if (Ccd_filtered_kernel::boxes_surely_apart(query, options.separation)) return {};   // most queries of a simulation
  Ccd_filtered_kernel::Protector protect;   // the intervals' upward rounding; rationals run in nearest
  Ccd_filtered_kernel k(query, options.separation);
  auto r = ccd_sweep(k);
  Ccd_answer a;
  a.collide = r.collide;
  if (r.collide && options.earliest) {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    a.earliest = exact_earliest(k.rational(), k.exact(r.t), r.contact);
  }
  return a;
}

} // namespace clash4d
