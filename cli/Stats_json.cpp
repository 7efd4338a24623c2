#include "cli/Stats_json.h"
#include "exact/Interval_kernel.h"
#include "float/Double_kernel.h"

#include <cstdio>
#include <sstream>

namespace clash4d {
namespace {

using json = nlohmann::ordered_json;

std::string range_text(const Stat_range& r) { return "[" + stat_text(r.lo) + ", " + stat_text(r.hi) + "]"; }

// Per axis, "[lo, hi] x [lo, hi] x ..."; "" for none.
std::string box_text(const std::vector<Stat_range>& box)
{
  std::string text;
  for (std::size_t q = 0; q < box.size(); ++q) text += (q ? " x " : "") + range_text(box[q]);
  return text;
}

json span_json(const Span_stats& p)
{
  std::string frame;
  for (std::size_t q = 0; q < p.frame.size(); ++q) frame += (q ? " " : "") + stat_text(p.frame[q]);
  return {{"pair", p.pair},
          {"span", range_text(p.span)},
          {"narrowed", p.narrowed ? range_text(*p.narrowed) : "empty"},
          {"primitives", p.primitives},
          {"primitives_alive", p.primitives_alive},
          {"leaves", p.leaves},
          {"region", box_text(p.region)},
          {"frame", frame}};
}

} // namespace

std::string stat_text(const Stat_number& x)
{
  switch (x.kind) {
    case Stat_number::Kind::Exact: return to_string(x.exact);
    case Stat_number::Kind::Double: return Double_kernel().to_text(x.lo);
    case Stat_number::Kind::Enclosure: return Interval_kernel().to_text(Interval(x.lo, x.hi));
  }
  return "";
}

json stats_json(const Check_stats& s)
{
  json spans = json::array();
  for (const auto& p : s.spans) spans.push_back(span_json(p));
  std::string before = s.span_before ? range_text(*s.span_before) : "";
  std::string after = !s.span_before ? "" : s.span_after ? range_text(*s.span_after) : "empty";
  return {{"object_pairs", s.object_pairs},
          {"candidate_pairs_after_sweep", s.candidate_pairs},
          {"exact_sweep_ties", s.exact_sweep_ties},
          {"pairs", s.pairs},
          {"sub_spans", s.sub_spans},
          {"sub_spans_pruned_by_sbounds", s.sub_spans_pruned},
          {"sbound_passes", s.sbound_passes},
          {"primitives", s.primitives},
          {"primitives_pruned", s.primitives_pruned},
          {"span_before", before},
          {"span_after", after},
          {"spans", spans},
          {"regions_per_depth", s.regions_per_depth},
          {"conquered_box", box_text(s.conquered_box)},
          {"conquers", s.conquers},
          {"leaves_at_conquer", s.leaves_at_conquer},
          {"max_leaves_at_conquer", s.max_leaves_at_conquer},
          {"lines", s.lines},
          {"points_classified", s.points_classified},
          {"cells_tested", s.cells_tested},
          {"convex_spans", s.convex_spans},
          {"convex_undecided", s.convex_undecided},
          {"exact_fallbacks", s.exact_fallbacks},
          {"exact_witness_runs", s.exact_witness_runs},
          {"exact_regions", s.exact_regions},
          {"exact_lines", s.exact_lines},
          {"exact_ties", s.exact_ties},
          {"exact_cut_orders", s.exact_cut_orders},
          {"exact_zeros", s.exact_zeros},
          {"exact_plane_tests", s.exact_plane_tests},
          {"exact_region_stages", s.exact_region_stages},
          {"doubtful_stages_pruned", s.doubtful_stages_pruned},
          {"witnesses_by_intervals", s.witnesses_by_intervals},
          {"earliest_by_intervals", s.earliest_by_intervals},
          {"apart_proofs", s.apart_proofs},
          {"apart_attempts", s.apart_attempts},
          {"apart_spans", s.apart_spans},
          {"replay_stages_adopted", s.replay_stages_adopted},
          {"earliest_lines_rerun", s.earliest_lines_rerun},
          {"witness_lines_rerun", s.witness_lines_rerun},
          {"closed_cells_by_intervals", s.closed_cells_by_intervals},
          {"witnesses_by_terms", s.witnesses_by_terms},
          {"convex_exact_signs", s.convex_exact_signs},
          {"seconds", {{"model", s.seconds_model}, {"sweep", s.seconds_sweep}, {"sbounds", s.seconds_sbounds},
                       {"divide_and_conquer", s.seconds_divide}, {"witness", s.seconds_witness}}}};
}

json meshes_json(const std::vector<Mesh_record>& meshes)
{
  json out = json::array();
  for (const Mesh_record& m : meshes)
    out.push_back({{"file", m.file},
                   {"place", m.place},
                   {"facets", m.facets},
                   {"triangles", m.triangles},
                   {"pieces", m.pieces},
                   {"scale", m.scale},
                   {"solid_rule", m.solid_rule},
                   {"repairs", m.repairs},
                   {"decomposition", m.decomposition},
                   {"decomposition_seconds", m.decomposition_seconds},
                   {"cache", m.cache}});
  return out;
}

std::string meshes_text(const std::vector<Mesh_record>& meshes, const std::string& indent)
{
  std::ostringstream out;
  for (const Mesh_record& m : meshes) {
    out << indent << m.file << " (" << m.place << "): " << m.facets << " facets, " << m.triangles << " triangles, "
        << m.pieces << (m.pieces == 1 ? " piece" : " pieces");
    if (!m.scale.empty() && m.scale != "1") out << ", scale " << m.scale;
    if (!m.solid_rule.empty()) out << ", " << m.solid_rule;
    // A convex mesh is one hull: no decomposition, nothing cached.
    if (!m.cache.empty()) {
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%.3f s", m.decomposition_seconds);
      out << ", decomposition " << (m.decomposition.empty() ? "" : m.decomposition + " ")
          << (m.cache == "hit" ? std::string("from the cache") : seconds) << " (cache " << m.cache
          << ")";
    }
    out << "\n";
    for (const std::string& r : m.repairs) out << indent << "  repair: " << r << "\n";
  }
  return out.str();
}

} // namespace clash4d
