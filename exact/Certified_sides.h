// The sides of a solid's planes at a point, in the exact kernel EK's
// numbers, decided plane by plane in the approximate kernel AK where it can
// certify them: the witness checks of EK's runs (model/Point_classifier.h,
// Sides_at), which evaluate every plane of both objects at the witness
// and, closed, at the contact point and each cell point. Most planes are
// far from such a point; only the planes through it (or nearly) need EK.
// AK's model of a scene encloses EK's plane for plane (one builder on the
// same scene's numbers), and y's enclosure holds y, so a sign AK certifies
// is EK's own: the answer is Plane_sides(ek, exact, y), whatever AK says.
#ifndef CLASH4D_EXACT_CERTIFIED_SIDES_H
#define CLASH4D_EXACT_CERTIFIED_SIDES_H

#include "model/Point_classifier.h"
#include <CGAL/Uncertain.h>
#include <cstddef>

namespace clash4d {

// approx and exact: one solid's model in AK and in EK. decided_exactly,
// when given, counts the planes EK decided.
template <class AK, class EK>
Plane_sides<typename EK::FT> certified_sides(const AK& ak, const Csg_model<typename AK::FT>& approx, const EK& ek,
                                             const Csg_model<typename EK::FT>& exact,
                                             const Vector3<typename EK::FT>& y,
                                             std::size_t* decided_exactly = nullptr)
{
  using AFT = typename AK::FT;
  using EFT = typename EK::FT;
  bool same = approx.primitives.size() == exact.primitives.size();
  for (std::size_t p = 0; same && p < exact.primitives.size(); ++p)
    same = approx.primitives[p].planes.size() == exact.primitives[p].planes.size();
  if (!same) return Plane_sides<EFT>(ek, exact, y);   // not expected: one scene, one model
  typename AK::Protector protect;
  const Vector3<AFT> around{ak.from_rational(ek.to_rational(y[0])), ak.from_rational(ek.to_rational(y[1])),
                            ak.from_rational(ek.to_rational(y[2]))};
  return Plane_sides<EFT>(exact, [&](int p, std::size_t j) {
    const Plane3<AFT>& a = approx.primitives[static_cast<std::size_t>(p)].planes[j];
    CGAL::Uncertain<CGAL::Sign> s = ak.uncertain_side(Vector3<AFT>{a[0], a[1], a[2]}, a[3], around);
    if (CGAL::is_certain(s)) return CGAL::get_certain(s);
    if (decided_exactly) ++*decided_exactly;
    const Plane3<EFT>& e = exact.primitives[static_cast<std::size_t>(p)].planes[j];
    return ek.side(Vector3<EFT>{e[0], e[1], e[2]}, e[3], y);
  });
}

} // namespace clash4d

#endif
