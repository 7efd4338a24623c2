// Scene solid -> CSG model over the kernel's number type. One code path for
// every kernel: the scene's rationals are converted by the kernel (exactly, or
// rounded to nearest) and every construction is done in FT.
#ifndef CLASH4D_MODEL_MODEL_BUILDER_H
#define CLASH4D_MODEL_MODEL_BUILDER_H

#include "model/Csg_model.h"
#include "geometry/Kernel_concept.h"
#include "geometry/Polytope_ft.h"
#include "geometry/Rotation_matrix.h"
#include "scene/Scene.h"
#include <type_traits>

namespace clash4d {

// x -> R x + b. R is a product of rational rotations, so orthogonal exactly in
// the exact kernel, and R^T is its inverse.
template <class FT>
struct Affine3 {
  std::array<Vector3<FT>, 3> R;   // rows
  Vector3<FT> b;
  bool is_identity = false;       // no transform above: the primitive is used as read
  // R = I (translations only, the common case): products with R are skipped.
  // They would give the same numbers in every kernel (products with 0 and 1
  // are exact); in rationals they cost a normalised product each.
  bool linear_identity = false;

  // A copy of one made once: in rationals a copy shares its numbers, where
  // making them is an allocation each (every primitive starts from it).
  static Affine3 identity()
  {
    static const Affine3 one = [] {
      Affine3 a;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a.R[i][j] = FT(i == j ? 1 : 0);
      a.b = {FT(0), FT(0), FT(0)};
      a.is_identity = a.linear_identity = true;
      return a;
    }();
    return one;
  }
  Vector3<FT> linear(const Vector3<FT>& v) const
  {
    if (linear_identity) return v;
    return {dot(R[0], v), dot(R[1], v), dot(R[2], v)};
  }
  Vector3<FT> apply(const Vector3<FT>& v) const { return {apply(v, 0), apply(v, 1), apply(v, 2)}; }
  // Coordinate q of apply(v) alone.
  FT apply(const Vector3<FT>& v, int q) const { return linear_identity ? v[q] + b[q] : dot_plus(R[q], v, b[q]); }
  // The image of n.x + d <= 0: (R n).y + d - (R n).b <= 0, using R^-1 = R^T.
  Plane3<FT> apply(const Plane3<FT>& p) const
  {
    Vector3<FT> n = linear({p[0], p[1], p[2]});
    return {n[0], n[1], n[2], dot_from(p[3], n, b)};
  }
  // this o (x -> M x + t); M_identity: M = I (a translation).
  // Made from its parts, not assigned into a default one: in rationals
  // every default number is an allocation of its own.
  Affine3 then_local(const std::array<Vector3<FT>, 3>& M, const Vector3<FT>& t, bool M_identity = false) const
  {
    Affine3 r{M_identity ? R : linear_identity ? M : times(M), apply(t)};
    r.linear_identity = M_identity && linear_identity;
    return r;
  }
  // The product R M (rows), each entry made once.
  std::array<Vector3<FT>, 3> times(const std::array<Vector3<FT>, 3>& M) const
  {
    auto row = [&](int i) -> Vector3<FT> {
      return {R[i][0] * M[0][0] + R[i][1] * M[1][0] + R[i][2] * M[2][0],
              R[i][0] * M[0][1] + R[i][1] * M[1][1] + R[i][2] * M[2][1],
              R[i][0] * M[0][2] + R[i][1] * M[1][2] + R[i][2] * M[2][2]};
    };
    return {row(0), row(1), row(2)};
  }
};

template <class K>
class Model_builder {
public:
  using FT = typename K::FT;
  explicit Model_builder(const K& k) : k_(k) {}

  Csg_model<FT> build(const Solid& s) { return build_parts(s, Parts::all); }
  // The same placed by `outer` (x -> R x + b, R a rotation in FT), as if s
  // were written under a rotate and a translate of those numbers: a shape
  // posed at a time whose numbers are not the scene's rationals (the
  // number-field kernel's, exact/Closed_in_field.h).
  Csg_model<FT> build(const Solid& s, const Affine3<FT>& outer) { return build_parts(s, Parts::all, outer); }

  // The same tree with each primitive's box alone (no planes, no
  // vertices): all the S-bounds read (search/S_bounds.h), at a fraction of
  // the model's cost where only they are needed (a region stage made in
  // rationals, exact/Exact_span.h). Each box is the one build gives.
  Csg_model<FT> build_boxes(const Solid& s) { return build_parts(s, Parts::boxes); }

  // The same tree with each primitive's planes alone (no vertices, no
  // box): all plane tables, witnesses and their checks read
  // (model/Extrusion.h, search/Witness.h, model/Point_classifier.h), made
  // by local_plane and moved as build moves them, so they are build's.
  Csg_model<FT> build_planes(const Solid& s) { return build_parts(s, Parts::planes); }

  // The same tree with each primitive's vertices and box alone (no
  // planes): what build_planes leaves out, to complete its model into
  // build's (exact/Filtered_runner.h).
  Csg_model<FT> build_vertices(const Solid& s) { return build_parts(s, Parts::vertices); }

private:
  enum class Parts { all, boxes, planes, vertices };
  const K& k_;
  Csg_model<FT> model_;
  Parts parts_ = Parts::all;

  Csg_model<FT> build_parts(const Solid& s, Parts parts, const Affine3<FT>& outer = Affine3<FT>::identity())
  {
    model_ = Csg_model<FT>();
    parts_ = parts;
    add(s, outer, -1);
    return std::move(model_);
  }

  FT num(const Solid& s, std::size_t i) const { return converted(s.numbers, s.numbers_approximated, i); }
  // A scene number in FT: from the reader's approximation of it where the
  // kernel reads those (read_number: the same number as from_rational
  // makes, without converting again), else converted.
  FT converted(const std::vector<Rational>& numbers, const std::vector<Approximation>& a, std::size_t i) const
  {
    return read_number(k_, numbers[i], a, i);
  }

  // -1, 0 or 1 (v): in rationals copies of numbers made once (a number
  // made per plane is an allocation), otherwise made in place.
  static FT unit(int v)
  {
    if constexpr (std::is_trivially_copyable_v<FT>) {
      return FT(v);
    } else {
      static const FT units[3] = {FT(-1), FT(0), FT(1)};
      return units[v + 1];
    }
  }

  // Whether to read the reader's exact constructions (Solid::constructed)
  // instead of computing them in FT: the interval kernel then encloses each
  // exact coefficient as tightly as a number of the file, and keeps its
  // exact zeros.
  bool exact_read(const Solid& s) const { return K::reads_exact_constructions && !s.constructed.empty(); }
  // The same for a rotate's matrix (reads_exact_rotations_v: a kernel that
  // computes its other constructions may still read it).
  bool exact_rotation(const Solid& s) const { return reads_exact_rotations_v<K> && !s.constructed.empty(); }
  FT made(const Solid& s, std::size_t i) const { return converted(s.constructed, s.constructed_approximated, i); }
  Vector3<FT> constructed3(const Solid& s, std::size_t i) const { return {made(s, i), made(s, i + 1), made(s, i + 2)}; }
  Plane3<FT> constructed4(const Solid& s, std::size_t i) const
  {
    return {made(s, i), made(s, i + 1), made(s, i + 2), made(s, i + 3)};
  }
  Vector3<FT> vec3(const Solid& s, std::size_t i) const { return {num(s, i), num(s, i + 1), num(s, i + 2)}; }

  int add(const Solid& under, const Affine3<FT>& outer, int parent)
  {
    using K_ = Solid::Kind;
    Affine3<FT> T = outer;
    const Solid& s = peel(under, T);
    int id = static_cast<int>(model_.nodes.size());
    model_.nodes.emplace_back();
    model_.nodes[id].parent = parent;
    if (s.kind == K_::Union || s.kind == K_::Intersection || s.kind == K_::Difference) {
      model_.nodes[id].op = s.kind == K_::Union ? Csg_node::Op::Union
                          : s.kind == K_::Intersection ? Csg_node::Op::Intersection : Csg_node::Op::Difference;
      for (const Solid& c : s.children) {
        int child = add(c, T, id);
        model_.nodes[id].children.push_back(child);
      }
      return id;
    }
    model_.nodes[id].op = Csg_node::Op::Primitive;
    model_.nodes[id].primitive = static_cast<int>(model_.primitives.size());
    switch (parts_) {
      case Parts::boxes: model_.primitives.push_back(boxed(s, T)); break;
      case Parts::planes: model_.primitives.push_back(planed(s, T)); break;
      case Parts::vertices: model_.primitives.push_back(vertexed(s, T)); break;
      default: model_.primitives.push_back(primitive(s, T)); break;
    }
    return id;
  }

public:
  // s without its transforms (translate, rotate): the solid under them,
  // with T composed with them.
  const Solid& peel(const Solid& s, Affine3<FT>& T) const
  {
    if (s.kind == Solid::Kind::Translate) {
      T = T.then_local(Affine3<FT>::identity().R, vec3(s, 0), true);
      return peel(s.children[0], T);
    }
    if (s.kind == Solid::Kind::Rotate) {
      T = T.then_local(exact_rotation(s) ? std::array<Vector3<FT>, 3>{constructed3(s, 0), constructed3(s, 3), constructed3(s, 6)}
                                     : rotation_matrix(num(s, 0), num(s, 1), num(s, 2), num(s, 3)),
                       {FT(0), FT(0), FT(0)});
      return peel(s.children[0], T);
    }
    return s;
  }

  // A one-primitive shape's planes and vertices in the world, as build
  // makes them (the same numbers), without its box, path or corners: what
  // an object's convex-pair guide reads (search/Convex_guide.h), made once
  // per object by a check's runner.
  Primitive<FT> placed_geometry(const Solid& shape) const
  {
    Affine3<FT> T = Affine3<FT>::identity();
    const Solid& s = peel(shape, T);
    Primitive<FT> p;
    local_geometry(s, p);
    move_by(p, T);
    return p;
  }

  // A primitive solid in its own frame (planes and vertices, as read).
  Primitive<FT> local(const Solid& s) const
  {
    Primitive<FT> p;
    p.path = s.path;
    p.corners = s.corners;
    local_geometry(s, p);
    return p;
  }

  // The box build gives a one-primitive solid (its Primitive::box), made
  // without the primitive's planes where its vertices are read rather than
  // made from them (block, hull, prism): what a sweep's tie asks of an
  // object (exact/Filtered_runner.h), at a fraction of a model's cost.
  Box<FT, 3> primitive_box(const Solid& shape) const
  {
    Affine3<FT> T = Affine3<FT>::identity();
    const Solid& s = peel(shape, T);
    return boxed(s, T).box;
  }

  // How many planes a primitive solid has (local_geometry's).
  std::size_t local_plane_count(const Solid& s) const
  {
    using K_ = Solid::Kind;
    switch (s.kind) {
      case K_::Halfspace: return 1;
      case K_::Block: return 6;
      case K_::Convex: return s.numbers.size() / 4;
      case K_::Prism: return (s.numbers.size() - 2) / 2 + 2;
      case K_::Hull: return s.triples.size();
      default: return 0;
    }
  }

  // Plane i of a primitive solid in its own frame, in local_geometry's
  // order and by its formulas, made alone: what a convex pair's rational
  // stage reads (model/Primitive_planes.h), a few planes of each object.
  Plane3<FT> local_plane(const Solid& s, std::size_t i) const
  {
    using K_ = Solid::Kind;
    const FT zero = unit(0), one = unit(1), minus_one = unit(-1);
    switch (s.kind) {
      case K_::Block: return block_plane(i, num(s, i % 2 ? 3 + i / 2 : i / 2));
      case K_::Prism: {
        std::size_t n = (s.numbers.size() - 2) / 2;
        if (i == n) return {zero, zero, minus_one, num(s, 2 * n)};
        if (i == n + 1) return {zero, zero, one, -num(s, 2 * n + 1)};
        std::size_t j = (i + 1) % n;
        Vector2<FT> at{num(s, 2 * i), num(s, 2 * i + 1)};
        FT dx = num(s, 2 * j) - at[0], dy = num(s, 2 * j + 1) - at[1];
        // Counter-clockwise base: the outward normal of edge i is (dy, -dx),
        // and the edge's start is on the plane.
        Vector2<FT> normal{dy, -dx};
        return {normal[0], normal[1], zero, negated_dot(normal, at)};
      }
      case K_::Hull: {
        if (exact_read(s)) return constructed4(s, 4 * i);
        const auto& t = s.triples.at(i);
        return facet_plane(vec3(s, 3 * t[0]), vec3(s, 3 * t[1]), vec3(s, 3 * t[2]));
      }
      default:   // a half-space's or a convex solid's plane, as read
        return {num(s, 4 * i), num(s, 4 * i + 1), num(s, 4 * i + 2), num(s, 4 * i + 3)};
    }
  }

  // A block's plane i, below then above per axis: -x_a + lo_a <= 0, then
  // x_a - hi_a <= 0; bound is lo_a or hi_a.
  static Plane3<FT> block_plane(std::size_t i, const FT& bound)
  {
    std::size_t a = i / 2;
    Plane3<FT> h{unit(0), unit(0), unit(0), i % 2 ? FT(-bound) : bound};
    h[a] = unit(i % 2 ? 1 : -1);
    return h;
  }

  // Vertex k of a block, hull, prism or convex solid in its own frame, in
  // local_geometry's order, made alone: what a sweep's tie asks of the
  // vertex the intervals cannot rule out of a box's side
  // (exact/Sweep_tie.h), without the primitive's other vertices.
  Vector3<FT> local_vertex(const Solid& s, std::size_t k) const
  {
    using K_ = Solid::Kind;
    switch (s.kind) {
      case K_::Block: return {num(s, k & 1 ? 3 : 0), num(s, k & 2 ? 4 : 1), num(s, k & 4 ? 5 : 2)};
      case K_::Hull: return vec3(s, 3 * k);
      case K_::Prism: {
        std::size_t n = (s.numbers.size() - 2) / 2, i = k / 2;
        return {num(s, 2 * i), num(s, 2 * i + 1), num(s, 2 * n + k % 2)};
      }
      case K_::Convex:
        if (exact_read(s)) return constructed3(s, 3 * k);
        break;
      default:
        break;
    }
    Primitive<FT> p;
    local_geometry(s, p, false);
    return p.vertices.at(k);
  }

private:
  Primitive<FT> primitive(const Solid& s, const Affine3<FT>& T) const
  {
    Primitive<FT> p = local(s);
    if (s.kind != Solid::Kind::Block || !T.linear_identity) {
      place(p, T);
      return p;
    }
    // A block under a translation: its box is its corners 0 and 7, (min)
    // and (max) moved, as boxed makes it (min < max, the reader; rounding
    // is monotone, so in every kernel they are vertex_box's numbers too).
    move_by(p, T);
    for (int a = 0; a < 3; ++a) p.box.set(a, p.vertices[0][a], p.vertices[7][a]);
    return p;
  }

  // A primitive with its box only (primitive_box, build_boxes): its
  // vertices' box moved by T (a translation moves the box itself: min and
  // max commute with adding b), or a half-space's moved plane's. A block's
  // corners are its box's: block_box, or under a translation its min and
  // max moved.
  Primitive<FT> boxed(const Solid& s, const Affine3<FT>& T) const
  {
    Primitive<FT> p;
    p.path = s.path;
    if (s.kind == Solid::Kind::Block) {
      Vector3<FT> lo = vec3(s, 0), hi = vec3(s, 3);
      if (!T.linear_identity) p.box = block_box(lo, hi, T);
      else   // min < max (the reader): the corners' box is [min, max], moved
        for (int a = 0; a < 3; ++a)
          T.is_identity ? p.box.set(a, lo[a], hi[a]) : p.box.set(a, lo[a] + T.b[a], hi[a] + T.b[a]);
      return p;
    }
    if constexpr (std::is_same_v<FT, Rational>)
      if (s.kind == Solid::Kind::Prism && !T.linear_identity) {
        p.box = prism_box(s, T);
        return p;
      }
    local_geometry(s, p, false);
    if (p.vertices.empty()) {
      place(p, T);
    } else if (T.linear_identity) {
      p.box = vertex_box(p.vertices);
      for (int a = 0; a < 3 && !T.is_identity; ++a) p.box.set(a, p.box.lo[a] + T.b[a], p.box.hi[a] + T.b[a]);
    } else {
      for (auto& v : p.vertices) v = T.apply(v);
      p.box = vertex_box(p.vertices);
    }
    p.planes.clear();
    p.vertices.clear();
    return p;
  }

  // A primitive with its planes only (build_planes): local_plane's, which
  // are local_geometry's, moved by T as place moves them.
  Primitive<FT> planed(const Solid& s, const Affine3<FT>& T) const
  {
    Primitive<FT> p;
    p.path = s.path;
    p.corners = s.corners;
    std::size_t n = local_plane_count(s);
    p.planes.reserve(n);
    for (std::size_t i = 0; i < n; ++i) p.planes.push_back(local_plane(s, i));
    move_by(p, T);
    return p;
  }

  // A primitive with its vertices and box only (build_vertices): place's
  // (a convex solid's and a half-space's planes are made all the same, for
  // its vertices or its box, then dropped).
  Primitive<FT> vertexed(const Solid& s, const Affine3<FT>& T) const
  {
    Primitive<FT> p;
    p.path = s.path;
    p.corners = s.corners;
    local_geometry(s, p, false);
    place(p, T);
    p.planes.clear();
    return p;
  }

  // p's planes and vertices moved by T.
  static void move_by(Primitive<FT>& p, const Affine3<FT>& T)
  {
    if (T.is_identity) return;
    for (auto& h : p.planes) h = T.apply(h);
    for (auto& v : p.vertices) v = T.apply(v);
  }

  // p moved by T, and its box.
  void place(Primitive<FT>& p, const Affine3<FT>& T) const
  {
    move_by(p, T);
    p.box = p.vertices.empty() ? halfspace_box(p.planes[0]) : vertex_box(p.vertices);
  }

  // with_planes false: a block's, hull's or prism's vertices only (a convex
  // solid's and a half-space's planes are made anyway: their vertices and
  // box come from them).
  void local_geometry(const Solid& s, Primitive<FT>& p, bool with_planes = true) const
  {
    using K_ = Solid::Kind;
    switch (s.kind) {
      case K_::Halfspace:
        p.planes.push_back(local_plane(s, 0));
        break;
      case K_::Block: {
        Vector3<FT> lo = vec3(s, 0), hi = vec3(s, 3);
        if (with_planes) p.planes.reserve(6);
        p.vertices.reserve(8);
        for (std::size_t i = 0; i < 6 && with_planes; ++i) p.planes.push_back(block_plane(i, i % 2 ? hi[i / 2] : lo[i / 2]));
        for (int c = 0; c < 8; ++c)
          p.vertices.push_back({(c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1], (c & 4) ? hi[2] : lo[2]});
        break;
      }
      case K_::Convex: {
        p.planes.reserve(s.numbers.size() / 4);
        p.vertices.reserve(s.triples.size());
        for (std::size_t i = 0; i < s.numbers.size() / 4; ++i) p.planes.push_back(local_plane(s, i));
        for (std::size_t i = 0; i < s.triples.size(); ++i) {
          const auto& t = s.triples[i];
          p.vertices.push_back(exact_read(s) ? constructed3(s, 3 * i)
                                             : vertex_of(p.planes[t[0]], p.planes[t[1]], p.planes[t[2]]));
        }
        break;
      }
      case K_::Prism: {
        std::size_t n = (s.numbers.size() - 2) / 2;
        FT z0 = num(s, 2 * n), z1 = num(s, 2 * n + 1);
        p.vertices.reserve(2 * n);
        if (with_planes) p.planes.reserve(n + 2);
        for (std::size_t i = 0; i < n; ++i) {
          FT x = num(s, 2 * i), y = num(s, 2 * i + 1);
          p.vertices.push_back({x, y, z0});
          p.vertices.push_back({x, y, z1});
        }
        for (std::size_t i = 0; i < n + 2 && with_planes; ++i) p.planes.push_back(local_plane(s, i));
        break;
      }
      case K_::Hull: {
        p.vertices.reserve(s.numbers.size() / 3);
        if (with_planes) p.planes.reserve(s.triples.size());
        for (std::size_t i = 0; i < s.numbers.size(); i += 3) p.vertices.push_back(vec3(s, i));
        for (std::size_t i = 0; i < s.triples.size() && with_planes; ++i) {
          const auto& t = s.triples[i];
          p.planes.push_back(exact_read(s) ? constructed4(s, 4 * i)
                                           : facet_plane(p.vertices[t[0]], p.vertices[t[1]], p.vertices[t[2]]));
        }
        break;
      }
      default:
        break;
    }
  }

  // The box of [lo, hi] under x -> R x + b, without its eight corners:
  // coordinate i is linear over the box, least at the corner taking lo_j
  // where R_ij > 0 and hi_j where R_ij < 0 (greatest the other way), so
  // its range is [sum_j R_ij (lo_j or hi_j) + b_i, ...], exactly.
  Box<FT, 3> block_box(const Vector3<FT>& lo, const Vector3<FT>& hi, const Affine3<FT>& T) const
  {
    Box<FT, 3> b;
    for (int i = 0; i < 3; ++i) {
      Vector3<FT> least, most;
      for (int j = 0; j < 3; ++j) {
        bool positive = k_.sign(T.R[i][j]) == CGAL::POSITIVE;
        least[j] = positive ? lo[j] : hi[j];
        most[j] = positive ? hi[j] : lo[j];
      }
      b.set(i, dot(T.R[i], least) + T.b[i], dot(T.R[i], most) + T.b[i]);
    }
    return b;
  }

  // A prism's box under x -> R x + b, in rationals: coordinate i of its
  // vertex (x_k, y_k, z) is (R_i0 x_k + R_i1 y_k) + R_i2 z + b_i, whose
  // least over every k and both z is the least of the first term plus the
  // least of the second, so the vertices' box (vertex_box) exactly, with a
  // third of the products. Other kernels round the vertices' sums, so they
  // keep vertex_box's numbers.
  Box<FT, 3> prism_box(const Solid& s, const Affine3<FT>& T) const
  {
    std::size_t n = (s.numbers.size() - 2) / 2;
    std::vector<Vector2<FT>> base;
    base.reserve(n);
    for (std::size_t k = 0; k < n; ++k) base.push_back({num(s, 2 * k), num(s, 2 * k + 1)});
    const FT z0 = num(s, 2 * n), z1 = num(s, 2 * n + 1);
    Box<FT, 3> b;
    for (int i = 0; i < 3; ++i) {
      const Vector3<FT>& r = T.R[i];
      FT lo = r[0] * base[0][0] + r[1] * base[0][1], hi = lo;
      for (std::size_t k = 1; k < n; ++k) {
        FT v = r[0] * base[k][0] + r[1] * base[k][1];
        lo = Number_ops<FT>::lower(lo, v);
        hi = Number_ops<FT>::upper(hi, v);
      }
      FT a = r[2] * z0, c = r[2] * z1;
      b.set(i, lo + Number_ops<FT>::lower(a, c) + T.b[i], hi + Number_ops<FT>::upper(a, c) + T.b[i]);
    }
    return b;
  }

  Box<FT, 3> vertex_box(const std::vector<Vector3<FT>>& vs) const
  {
    Box<FT, 3> b;
    for (int a = 0; a < 3; ++a) {
      FT lo = vs[0][a], hi = vs[0][a];
      for (const auto& v : vs) {
        lo = Number_ops<FT>::lower(lo, v[a]);
        hi = Number_ops<FT>::upper(hi, v[a]);
      }
      b.set(a, lo, hi);
    }
    return b;
  }

  // A half-space is bounded on one side of one axis when its normal is that axis.
  Box<FT, 3> halfspace_box(const Plane3<FT>& h) const
  {
    Box<FT, 3> b;
    int nonzero = 0, axis = -1;
    for (int a = 0; a < 3; ++a)
      if (k_.sign(h[a]) != CGAL::ZERO) { ++nonzero; axis = a; }
    if (nonzero != 1) return b;
    FT bound = -h[3] / h[axis];
    if (k_.sign(h[axis]) == CGAL::POSITIVE) { b.hi[axis] = bound; b.has_hi[axis] = true; }
    else { b.lo[axis] = bound; b.has_lo[axis] = true; }
    return b;
  }
};

} // namespace clash4d

#endif
