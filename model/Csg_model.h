// A solid as a CSG tree over convex primitives in world coordinates (the
// transforms of the scene are applied to the primitives, §3 item 1).
#ifndef CLASH4D_MODEL_CSG_MODEL_H
#define CLASH4D_MODEL_CSG_MODEL_H

#include "geometry/Box.h"
#include "geometry/kernel_ft4.h"
#include "scene/Scene.h"
#include <memory>
#include <string>
#include <vector>

namespace clash4d {

// A convex primitive: the intersection of its half-spaces, with the exact box
// of its vertices (Omega for an unbounded half-space, §4.3.1 leaf bound).
template <class FT>
struct Primitive {
  std::string path;                  // scene path, for reports
  std::vector<Plane3<FT>> planes;
  std::vector<Vector3<FT>> vertices; // empty for a half-space
  Box<FT, 3> box;
  // Points where four or more of the planes meet, each as the indices of
  // those planes (Solid::corners, shared; transforms keep them); none, null.
  std::shared_ptr<const Corners> corners;
};

struct Csg_node {
  enum class Op { Primitive, Union, Intersection, Difference };
  Op op = Op::Primitive;
  int primitive = -1;                // for Op::Primitive
  std::vector<int> children;         // difference: first minus the others
  int parent = -1;
};

template <class FT>
struct Csg_model {
  std::vector<Csg_node> nodes;       // parents before children; root is 0
  std::vector<Primitive<FT>> primitives;

  std::size_t plane_count() const
  {
    std::size_t n = 0;
    for (const auto& p : primitives) n += p.planes.size();
    return n;
  }
};

} // namespace clash4d

#endif
