// The space-time half-space trees of every object per time sub-span (§2-3),
// as JSON with exact number strings, so a person can check them by hand.
#ifndef CLASH4D_MODEL_EXTRUSION_REPORT_H
#define CLASH4D_MODEL_EXTRUSION_REPORT_H

#include "model/Extrusion.h"
#include <nlohmann/json.hpp>

namespace clash4d {

template <class K>
class Extrusion_report {
public:
  using FT = typename K::FT;
  using json = nlohmann::ordered_json;

  explicit Extrusion_report(const K& k) : k_(k) {}

  json make(const Scene& scene) const
  {
    Scene_model<K> model = Scene_model<K>::build(k_, scene);
    std::vector<int> all;
    for (std::size_t i = 0; i < model.objects.size(); ++i) all.push_back(static_cast<int>(i));
    json spans = json::array();
    for (const auto& span : model.sub_spans(all)) {
      json objects = json::array();
      for (int i : all) {
        const Object_model<FT>& o = model.objects[i];
        std::size_t seg = model.segment_on(i, span);
        const auto &v = o.motion.velocity[seg], &off = o.motion.offset[seg];
        json slab = json::array({halfspace(time_at_least(span.lo)), halfspace(time_at_most(span.hi))});
        objects.push_back({{"name", o.name},
                           {"velocity", {k_.to_text(v[0]), k_.to_text(v[1]), k_.to_text(v[2])}},
                           {"offset", {k_.to_text(off[0]), k_.to_text(off[1]), k_.to_text(off[2])}},
                           {"tree", {{"intersection", json::array({tree(o.csg, 0, v, off), {{"time", slab}}})}}}});
      }
      spans.push_back({{"t", {k_.to_text(span.lo), k_.to_text(span.hi)}}, {"objects", objects}});
    }
    return {{"number", K::name()}, {"time", {k_.to_text(model.t_lo), k_.to_text(model.t_hi)}}, {"spans", spans}};
  }

private:
  const K& k_;

  json tree(const Csg_model<FT>& m, int node, const Vector3<FT>& v, const Vector3<FT>& o) const
  {
    const Csg_node& n = m.nodes[node];
    if (n.op == Csg_node::Op::Primitive) {
      const Primitive<FT>& p = m.primitives[n.primitive];
      json hs = json::array();
      for (const auto& h : Extrusion<K>::primitive_planes(p, v, o)) hs.push_back(halfspace(h));
      return {{"primitive", p.path}, {"halfspaces", hs}};
    }
    const char* op = n.op == Csg_node::Op::Union ? "union" : n.op == Csg_node::Op::Intersection ? "intersection" : "difference";
    json children = json::array();
    for (int c : n.children) children.push_back(tree(m, c, v, o));
    return {{op, children}};
  }

  // "x - t - 1 <= 0" beside the coefficients [a, b, c, e, f].
  json halfspace(const Hyperplane4<FT>& h) const
  {
    static const char* names[4] = {"x", "y", "z", "t"};
    std::string text;
    for (int i = 0; i < 5; ++i) {
      const FT& c = i < 4 ? h.n[i] : h.c;
      CGAL::Sign s = k_.sign(c);
      if (s == CGAL::ZERO) continue;
      FT mag = s == CGAL::NEGATIVE ? FT(-c) : c;
      text += text.empty() ? (s == CGAL::NEGATIVE ? "-" : "") : (s == CGAL::NEGATIVE ? " - " : " + ");
      bool unit = i < 4 && mag == FT(1);
      if (!unit) text += k_.to_text(mag) + (i < 4 ? "*" : "");
      if (i < 4) text += names[i];
    }
    if (text.empty()) text = "0";
    json coeffs = json::array();
    for (int i = 0; i < 4; ++i) coeffs.push_back(k_.to_text(h.n[i]));
    coeffs.push_back(k_.to_text(h.c));
    return {{"text", text + " <= 0"}, {"coefficients", coeffs}};
  }
};

} // namespace clash4d

#endif
