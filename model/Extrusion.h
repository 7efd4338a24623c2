// The extrusion of objects into space-time (§2.1-§3), in one place: every
// plane of a primitive extruded by equation (4) in a chosen frame, and the
// CSG tree emitted as a formula over those planes in negation normal form.
// `check` searches a pair's extrusion on one constant-velocity sub-span
// (pair_table, pair_formula); the skeleton needs the whole extrusion of each
// object, every motion segment within its time slab (§3, whole); `extrude`
// prints the planes of each primitive (primitive_planes).
#ifndef CLASH4D_MODEL_EXTRUSION_H
#define CLASH4D_MODEL_EXTRUSION_H

#include "geometry/Box.h"
#include "geometry/Hyperplane4.h"
#include "model/Formula.h"
#include "model/Pair_formula.h"
#include "model/Motion_groups.h"
#include "model/Scene_model.h"
#include <vector>

namespace clash4d {

// One object on one constant-velocity sub-span: D(t) = v t + o there, with
// its S-bounds per CSG node (§4.3; an empty bound prunes the node).
template <class FT>
struct Moving_object {
  const Object_model<FT>* object = nullptr;
  Vector3<FT> v, o;
  std::vector<Box<FT, 3>> beta;
};

// Object i of the model on a sub-span, with the bounds beta.
template <class K>
Moving_object<typename K::FT> moving_on(const Scene_model<K>& model, int i, const Time_span<typename K::FT>& span,
                                        const std::vector<Box<typename K::FT, 3>>& beta)
{
  const auto& obj = model.objects[i];
  std::size_t seg = model.segment_on(i, span);
  return {&obj, obj.motion.velocity[seg], obj.motion.offset[seg], beta};
}

template <class K>
class Extrusion {
public:
  using FT = typename K::FT;
  using H = Hyperplane4<FT>;
  using Moving = Moving_object<FT>;

  // Equation (4) for every plane of a primitive moving with D(t) = v t + o.
  static std::vector<H> primitive_planes(const Primitive<FT>& p, const Vector3<FT>& v, const Vector3<FT>& o)
  {
    std::vector<H> planes;
    planes.reserve(p.planes.size());
    add_primitive_planes(p, v, o, planes);
    return planes;
  }
  // The same, appended to planes.
  static void add_primitive_planes(const Primitive<FT>& p, const Vector3<FT>& v, const Vector3<FT>& o,
                                   std::vector<H>& planes)
  {
    for (const auto& plane : p.planes) planes.push_back(extrude(plane, v, o));
  }

  // A's planes then B's (object_planes), groups 0 and 1, in the frame
  // x' = x - shear t; per axis, the frame is A's own (frame_of_a) or B's
  // when `own_frames`, otherwise neither's.
  static std::vector<H> pair_table(const Moving& A, const Moving& B, const Vector3<FT>& shear,
                                   const std::array<bool, 3>& frame_of_a, bool own_frames, Motion_groups<FT>& groups)
  {
    pair_groups(A, B, shear, frame_of_a, own_frames, groups);
    std::vector<H> table;
    table.reserve(groups.of.size() + 2);   // room for a closed slab (add_time_slab)
    object_planes(A, groups.velocity[0], table);
    object_planes(B, groups.velocity[1], table);
    return table;
  }

  // pair_table's groups alone (no plane made): each object's velocity in
  // the frame, and per entry its group and the corners it passes through.
  static void pair_groups(const Moving& A, const Moving& B, const Vector3<FT>& shear,
                          const std::array<bool, 3>& frame_of_a, bool own_frames, Motion_groups<FT>& groups)
  {
    std::array<bool, 3> own[2]{};
    for (int q = 0; q < 3 && own_frames; ++q) own[0][q] = frame_of_a[q], own[1][q] = !frame_of_a[q];
    for (int o = 0; o < 2; ++o) {
      const Moving& m = o == 0 ? A : B;
      groups.velocity.push_back(relative_velocity(m, shear, own[o]));
      object_corners(m, groups);
      groups.of.resize(groups.corners.size(), o);
    }
    groups.still = {own[0], own[1]};
  }

  // Entry e of pair_table (A, B and groups as it made them), made alone:
  // the same plane, for a run that reads a few entries (exact/Exact_span.h).
  static H pair_entry(const Moving& A, const Moving& B, const Motion_groups<FT>& groups, std::size_t e)
  {
    int o = groups.of.at(e);
    const Moving& m = o == 0 ? A : B;
    std::size_t j = e;
    if (o == 1)
      for (const auto& p : A.object->csg.primitives) j -= 2 * p.planes.size();
    for (const auto& p : m.object->csg.primitives) {
      if (j < 2 * p.planes.size()) {
        H h = extrude(p.planes[j / 2], groups.velocity[static_cast<std::size_t>(o)], m.o);
        return j % 2 ? h.complement() : h;
      }
      j -= 2 * p.planes.size();
    }
    throw std::logic_error("internal error: a table entry past its object's planes");
  }

  // The frame's shear (x' = x - shear t): per axis A's velocity or B's
  // (frame_of_a); unfitted, the world frame.
  static Vector3<FT> shear_of(const Moving& A, const Moving& B, const std::array<bool, 3>& frame_of_a, bool fitted)
  {
    Vector3<FT> shear;
    for (int q = 0; q < 3; ++q) shear[q] = !fitted ? FT(0) : frame_of_a[q] ? A.v[q] : B.v[q];
    return shear;
  }

  // Closed semantics: the sub-span's slab lo <= t <= hi appended to the
  // table (two entries, no complements), for pair_formula's `slab`. Each
  // object on the sub-span is its extrusion restricted to the closed slab
  // (§2.2: regular because the time domain is closed), so a cell found
  // around a point at the slab's end lies within the sub-span, where the
  // velocities are the table's. Returns the first entry's index.
  static std::size_t add_time_slab(std::vector<H>& table, const FT& lo, const FT& hi)
  {
    table.push_back(time_at_least(lo));
    table.push_back(time_at_most(hi));
    return table.size() - 2;
  }

  // A's formula and B's over pair_table's entries, kept apart
  // (model/Pair_formula.h); with `slab` (add_time_slab's index), each also
  // within the sub-span's time slab.
  static Pair_formula pair_formula(const Moving& A, const Moving& B, const std::size_t* slab = nullptr)
  {
    std::size_t next = 0;
    Formula a = object_formula(A, next, slab);
    for (const auto& p : A.object->csg.primitives) next += 2 * p.planes.size();   // B's first plane
    Formula b = object_formula(B, next, slab);
    return Pair_formula(std::move(a), std::move(b));
  }

  // Object i over all time within [tL, tH]: the union over its motion
  // segments of the segment's tree within the segment's time slab (§3), its
  // planes appended to `table`, its formula to `b`.
  static void whole(const K& k, const Scene_model<K>& model, int i, const std::vector<Box<FT, 3>>& beta, const Vector3<FT>& shear,
                    std::vector<H>& table, Formula::Builder& b)
  {
    const Object_model<FT>& obj = model.objects[i];
    const Motion_path<FT>& m = obj.motion;
    std::size_t mark = b.open();
    for (std::size_t s = 0; s < m.velocity.size(); ++s) {
      if (s > 0 && !k.less(m.times[s - 1], model.t_hi)) continue;
      if (s < m.times.size() && !k.less(model.t_lo, m.times[s])) continue;
      Moving seg{&obj, m.velocity[s], m.offset[s], beta};
      std::size_t seg_mark = b.open();
      if (s > 0) slab_leaf(time_at_least(m.times[s - 1]), table, b);
      if (s < m.times.size()) slab_leaf(time_at_most(m.times[s]), table, b);
      std::size_t next = table.size();
      object_planes(seg, relative_velocity(seg, shear, {}), table);
      emit(seg, 0, false, b, next);
      b.close(Formula::Op::And, seg_mark);
    }
    b.close(Formula::Op::Or, mark);
  }

  // A leaf h (and its complement after it) appended to the table.
  static void slab_leaf(const H& h, std::vector<H>& table, Formula::Builder& b)
  {
    b.leaf(static_cast<std::uint32_t>(table.size()));
    table.push_back(h);
    table.push_back(h.complement());
  }

private:
  // One object's tree from table entry `next` on, within the slab when given.
  static Formula object_formula(const Moving& m, std::size_t next, const std::size_t* slab)
  {
    Formula::Builder builder;
    std::size_t mark = builder.open();
    emit(m, 0, false, builder, next);
    if (slab) {
      builder.leaf(static_cast<std::uint32_t>(*slab));
      builder.leaf(static_cast<std::uint32_t>(*slab + 1));
    }
    builder.close(Formula::Op::And, mark);
    return builder.finish();
  }

  // In the frame x' = x - w t the object moves with v - w (eq. 4 with that
  // velocity). On an axis measured in the object's own frame (own[q]) that
  // is a written zero, not v - v: an interval run then gets a point zero
  // where the exact run has one, instead of an uncertain sign.
  static Vector3<FT> relative_velocity(const Moving& m, const Vector3<FT>& shear, const std::array<bool, 3>& own)
  {
    Vector3<FT> relative;
    for (int q = 0; q < 3; ++q) relative[q] = own[q] ? FT(0) : m.v[q] - shear[q];
    return relative;
  }

  // Every plane of every primitive, extruded (eq. 4) with the velocity
  // `relative` (relative_velocity), followed by its complement: table[2i]
  // is plane i, table[2i + 1] its complement.
  static void object_planes(const Moving& m, const Vector3<FT>& relative, std::vector<H>& table)
  {
    for (const auto& p : m.object->csg.primitives)
      for (const auto& plane : p.planes) {
        table.push_back(extrude(plane, relative, m.o));
        table.push_back(table.back().complement());
      }
  }

  // Per entry object_planes makes (two per plane), the corners its plane
  // passes through (model/Motion_groups.h), appended to groups.corners.
  static void object_corners(const Moving& m, Motion_groups<FT>& groups)
  {
    for (const auto& p : m.object->csg.primitives) {
      std::vector<std::vector<int>> through(p.planes.size());
      if (p.corners)
        for (const auto& corner : *p.corners) {
          for (int plane : corner) through[plane].push_back(groups.corner_count);
          ++groups.corner_count;
        }
      for (std::size_t i = 0; i < p.planes.size(); ++i) groups.corners.insert(groups.corners.end(), 2, through[i]);
    }
  }

  // The object's tree in negation normal form; pruned nodes (empty S-bound)
  // are the null set. `next` walks the table in primitive order.
  static void emit(const Moving& m, int node, bool negated, Formula::Builder& b, std::size_t& next)
  {
    const Csg_model<FT>& csg = m.object->csg;
    const Csg_node& n = csg.nodes[node];
    if (m.beta[node].empty) {
      skip_planes(csg, node, next);
      b.constant(negated);
      return;
    }
    std::size_t mark = b.open();
    switch (n.op) {
      case Csg_node::Op::Primitive:
        for (std::size_t i = 0; i < csg.primitives[n.primitive].planes.size(); ++i, next += 2)
          b.leaf(static_cast<std::uint32_t>(negated ? next + 1 : next));
        b.close(negated ? Formula::Op::Or : Formula::Op::And, mark);
        return;
      case Csg_node::Op::Union:
      case Csg_node::Op::Intersection: {
        for (int c : n.children) emit(m, c, negated, b, next);
        bool conj = (n.op == Csg_node::Op::Intersection) != negated;
        b.close(conj ? Formula::Op::And : Formula::Op::Or, mark);
        return;
      }
      case Csg_node::Op::Difference:
        // L - R1 - ... = L and not R1 and ...; its negation is not L or R1 or ...
        for (std::size_t i = 0; i < n.children.size(); ++i) emit(m, n.children[i], i == 0 ? negated : !negated, b, next);
        b.close(negated ? Formula::Op::Or : Formula::Op::And, mark);
        return;
    }
  }

  static void skip_planes(const Csg_model<FT>& csg, int node, std::size_t& next)
  {
    const Csg_node& n = csg.nodes[node];
    if (n.op == Csg_node::Op::Primitive) { next += 2 * csg.primitives[n.primitive].planes.size(); return; }
    for (int c : n.children) skip_planes(csg, c, next);
  }
};

} // namespace clash4d

#endif
