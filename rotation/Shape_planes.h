// What the rotation stage reads of a shape, in the shape's own coordinates
// (before its motion): its distinct planes, whether it is a union of bounded
// convex pieces (closed semantics at an irrational time, Rotating_pair.h),
// and a bound on its reach from its origin (the swept boxes of many objects).
#ifndef CLASH4D_ROTATION_SHAPE_PLANES_H
#define CLASH4D_ROTATION_SHAPE_PLANES_H

#include "geometry/kernel_ft4.h"
#include "model/Csg_model.h"
#include "scene/Scene.h"
#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace clash4d {

struct Shape_planes {
  // Each plane of the shape once: a plane and its complement (a difference)
  // are one row of fact 10's matrix.
  std::vector<Plane3<Rational>> planes;
  // The convex pieces when the shape is a union of bounded convex
  // primitives (their closed union is the closed regular set), each as
  // indices into planes with the orientation of the piece (+1: plane <= 0
  // inside, -1: its complement); empty otherwise.
  std::vector<std::vector<std::pair<int, int>>> convex_pieces;
  // The whole CSG tree (any shape): its nodes, and each primitive's planes
  // as (index into planes, orientation) as above.
  std::vector<Csg_node> nodes;
  std::vector<std::vector<std::pair<int, int>>> primitives;
  // A bound on |p|_2 over the shape's vertices, which a rotation about the
  // origin keeps (a dyadic just above the root of the largest |p|^2); none
  // when some primitive is unbounded.
  std::optional<Rational> reach;
  bool spans_space = false;   // the normals span R^3 (rank four with v_inf)
  // When the shape is one bounded, full-dimensional convex polytope: its
  // features, found once at rest (a rigid motion keeps them), as indices
  // into planes. For each vertex, one triple of the planes through it whose
  // normals are independent (any such triple meets in the vertex alone);
  // each pair of planes that share two distinct vertices (their line holds
  // an edge). Rotating_pair.cpp restricts the events of a pair of such
  // shapes to these features' minors (docs/rotation.md, Convex pieces'
  // events). convex_features is false otherwise.
  bool convex_features = false;
  std::vector<std::array<int, 3>> vertex_triples;
  std::vector<Vector3<Rational>> vertices;   // each vertex once, at rest, on its triple
  std::vector<std::pair<int, int>> edges;
  std::vector<std::vector<int>> edge_vertices;   // per edge, the vertices on its line (its ends)
};

Shape_planes shape_planes(const Solid& shape);

// Whether a point strictly on the sides `side` of the planes (each -1 or
// +1, indexed as planes) is inside the shape: the CSG formula with strict
// signs, which decides membership at a generic point (fact 1).
bool inside_at_generic(const Shape_planes& shape, const std::vector<int>& side);

} // namespace clash4d

#endif
