// Exact rationals as points of CGAL's lazy exact kernel (Epeck), whose
// predicates are decided on intervals and, only where those cannot tell, on
// the very rationals the points are made from: the same signs as
// CGAL::Cartesian<Rational>, sooner. Used where scene/ runs a CGAL algorithm
// on input points (the mesh check's self-intersection test, hulls).
#ifndef CLASH4D_SCENE_LAZY_POINT_H
#define CLASH4D_SCENE_LAZY_POINT_H

#include "numbers/Rational.h"

#include <array>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

namespace clash4d {

// x as the lazy kernel's number: its exact part is x itself.
inline CGAL::Epeck::FT lazy_number(const Rational& x)
{
  using ET = CGAL::Epeck::FT::ET;   // mpq_class or Gmpq: each is made from an mpq_t
  return CGAL::Epeck::FT(ET(x.mpq()));
}

inline CGAL::Epeck::Point_3 lazy_point(const std::array<Rational, 3>& p)
{
  return CGAL::Epeck::Point_3(lazy_number(p[0]), lazy_number(p[1]), lazy_number(p[2]));
}

inline mpq_srcptr mpq_of(const mpq_class& q) { return q.get_mpq_t(); }
inline mpq_srcptr mpq_of(const CGAL::Gmpq& q) { return q.mpq(); }

// The exact rational a lazy number stands for (its exact part, computed if
// it was not yet): what a construction on the lazy kernel hands back.
inline Rational rational_of(const CGAL::Epeck::FT& x)
{
  Rational r;
  mpq_set(r.mpq(), mpq_of(CGAL::exact(x)));
  return r;
}

} // namespace clash4d

#endif
