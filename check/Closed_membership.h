// Whether a given point lies in an object's closed set (scene-format.md,
// "Closed semantics": the closure of the object's interior), for points that
// come from elsewhere, such as an engine's witness of a contact. The point is
// taken back to the solid by D(t); if the planes through it leave the CSG
// tree undecided, some open cell of those planes around it must be inside
// (regularised-semantics item 1 on each cell), found with Appendix A's
// enumeration (search/Neighbourhood.h) in 3D, embedded in space-time along
// the time axis, which every embedded plane contains.
#ifndef CLASH4D_CHECK_CLOSED_MEMBERSHIP_H
#define CLASH4D_CHECK_CLOSED_MEMBERSHIP_H

#include "model/Point_classifier.h"
#include "search/Neighbourhood.h"
#include <utility>
#include <vector>

namespace clash4d {

template <class K>
bool in_closed_object(const K& k, const Scene_model<K>& model, int i, const Vector4<typename K::FT>& p)
{
  using FT = typename K::FT;
  const Object_model<FT>& o = model.objects[i];
  Vector3<FT> y = solid_point(k, o, p);
  Truth plain = classify_point(k, o.csg, y);
  if (plain != Truth::Unknown) return plain == Truth::True;
  // The planes through y, and their normals (n, 0).
  std::vector<std::pair<int, std::size_t>> through;
  std::vector<Vector4<FT>> normals;
  for (std::size_t p3 = 0; p3 < o.csg.primitives.size(); ++p3)
    for (std::size_t j = 0; j < o.csg.primitives[p3].planes.size(); ++j) {
      const Plane3<FT>& pl = o.csg.primitives[p3].planes[j];
      if (k.side(Vector3<FT>{pl[0], pl[1], pl[2]}, pl[3], y) != CGAL::ZERO) continue;
      through.emplace_back(static_cast<int>(p3), j);
      normals.push_back({pl[0], pl[1], pl[2], FT(0)});
    }
  auto inside = [&](const std::vector<int>& signs) {
    auto side = [&](int prim, std::size_t j) {
      for (std::size_t t = 0; t < through.size(); ++t)
        if (through[t].first == prim && through[t].second == j) return signs[t] < 0 ? CGAL::NEGATIVE : CGAL::POSITIVE;
      const Plane3<FT>& pl = o.csg.primitives[prim].planes[j];
      return k.side(Vector3<FT>{pl[0], pl[1], pl[2]}, pl[3], y);
    };
    return classify_with(o.csg, side) == Truth::True;
  };
  Neighbourhood<K> hood(k);
  return hood.find_inside(Vector4<FT>{FT(0), FT(0), FT(0), FT(1)}, normals, inside).has_value();
}

// p is a common point of the closed objects a and b within [tL, tH].
template <class K>
bool is_valid_contact(const K& k, const Scene_model<K>& model, int a, int b, const Vector4<typename K::FT>& p)
{
  if (k.less(p[3], model.t_lo) || k.less(model.t_hi, p[3])) return false;
  return in_closed_object(k, model, a, p) && in_closed_object(k, model, b, p);
}

} // namespace clash4d

#endif
