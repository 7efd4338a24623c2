#include "scene/Mesh_repair.h"
#include "geometry/kernel_ft4.h"
#include "scene/Mesh_check.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

namespace clash4d {
namespace {

using P3 = std::array<Rational, 3>;

P3 minus(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

bool is_zero(const P3& a) { return CGAL::is_zero(a[0]) && CGAL::is_zero(a[1]) && CGAL::is_zero(a[2]); }

// A polygon cut into triangles by ears, in its projection along the largest
// component of N, oriented by N: an ear's tip turns strictly left and its
// closed triangle holds no other vertex, so no triangle has zero area and
// none leaves a vertex on another's edge. The first ear tried is the second
// vertex, so a strictly convex polygon is the fan from its first vertex.
// Empty when no ear is left (a polygon whose projection is not simple).
std::vector<std::array<int, 3>> ear_triangles(std::vector<int> F, const P3& N, const std::vector<P3>& V)
{
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (CGAL::abs(N[i]) > CGAL::abs(N[k])) k = i;
  int u = (k + 1) % 3, v = (k + 2) % 3, s = CGAL::sign(N[k]);
  auto left = [&](int a, int b, int c) {   // s * orient2d(a, b, c)
    const P3 &A = V[a], &B = V[b], &C = V[c];
    return s * CGAL::sign((B[u] - A[u]) * (C[v] - A[v]) - (B[v] - A[v]) * (C[u] - A[u]));
  };
  std::vector<std::array<int, 3>> out;
  while (F.size() > 3) {
    std::size_t n = F.size(), tip = n;
    for (std::size_t step = 0; step < n && tip == n; ++step) {
      std::size_t i = (1 + step) % n;
      int p = F[(i + n - 1) % n], c = F[i], q = F[(i + 1) % n];
      if (left(p, c, q) <= 0) continue;
      bool empty = std::none_of(F.begin(), F.end(), [&](int w) {
        return w != p && w != c && w != q && left(p, c, w) >= 0 && left(c, q, w) >= 0 && left(q, p, w) >= 0;
      });
      if (empty) tip = i;
    }
    if (tip == n) return {};
    out.push_back({F[(tip + n - 1) % n], F[tip], F[(tip + 1) % n]});
    F.erase(F.begin() + static_cast<std::ptrdiff_t>(tip));
  }
  if (left(F[0], F[1], F[2]) <= 0) return {};
  out.push_back({F[0], F[1], F[2]});
  return out;
}

bool distinct(const std::vector<int>& F) { return std::set<int>(F.begin(), F.end()).size() == F.size(); }

// "triangulate": each facet of more than three vertices that the check
// would refuse as not planar or not strictly convex, cut into ears.
void triangulate(Repaired_mesh& m)
{
  const auto& V = m.mesh.vertices;
  std::vector<std::vector<int>> facets;
  std::vector<int> origin;
  int cut = 0, first = -1;
  for (std::size_t f = 0; f < m.mesh.facets.size(); ++f) {
    const std::vector<int>& F = m.mesh.facets[f];
    P3 N = F.size() > 3 && distinct(F) ? newell_normal(F, V) : P3{};
    std::vector<std::array<int, 3>> ears;
    if (F.size() > 3 && distinct(F) && !is_zero(N) && !polygon_fault(F, N, V).empty()) ears = ear_triangles(F, N, V);
    if (ears.empty()) {
      facets.push_back(F);
      origin.push_back(m.file_facet[f]);
      continue;
    }
    if (cut++ == 0) first = m.file_facet[f];
    for (const auto& t : ears) {
      facets.push_back({t[0], t[1], t[2]});
      origin.push_back(m.file_facet[f]);
    }
  }
  if (cut)
    m.repairs.push_back("triangulate: " + std::to_string(cut) + " facet(s) not exactly planar or not strictly convex "
                        "cut into triangles on their own vertices (the first: facet " + std::to_string(first) + ")");
  m.mesh.facets = std::move(facets);
  m.file_facet = std::move(origin);
}

// The points of D strictly inside the segment from a to b, from a to b.
std::vector<int> points_on(int a, int b, const std::set<int>& D, const std::vector<P3>& V)
{
  P3 d = minus(V[b], V[a]);
  Rational length = dot(d, d);
  std::vector<std::pair<Rational, int>> on;
  for (int m : D) {
    if (m == a || m == b) continue;
    P3 w = minus(V[m], V[a]);
    Rational along = dot(w, d);
    if (is_zero(cross(d, w)) && along > 0 && along < length) on.push_back({along, m});
  }
  std::sort(on.begin(), on.end());
  std::vector<int> out;
  for (const auto& p : on) out.push_back(p.second);
  return out;
}

// The facet with the points of D that lie inside its unmatched edges put
// into them: a zero-area facet's middle vertex, where its neighbour across
// the long edge now meets two facets (a T-junction).
std::vector<int> spliced(const std::vector<int>& F, const std::set<std::pair<int, int>>& used, const std::set<int>& D,
                         const std::vector<P3>& V)
{
  std::vector<int> out;
  for (std::size_t i = 0; i < F.size(); ++i) {
    int a = F[i], b = F[(i + 1) % F.size()];
    out.push_back(a);
    if (used.count({b, a})) continue;
    std::vector<int> on = points_on(a, b, D, V);
    out.insert(out.end(), on.begin(), on.end());
  }
  return out;
}

// "drop-zero-area": facets of zero area dropped (they bound nothing, so the
// solid is the same), and their vertices spliced into the edges they lie in,
// each facet so changed cut into ears again.
void drop_zero_area(Repaired_mesh& m)
{
  const auto& V = m.mesh.vertices;
  std::vector<std::vector<int>> kept;
  std::vector<int> origin;
  std::set<int> D;
  std::string dropped;
  for (std::size_t f = 0; f < m.mesh.facets.size(); ++f) {
    const std::vector<int>& F = m.mesh.facets[f];
    if (!is_zero(newell_normal(F, V))) {
      kept.push_back(F);
      origin.push_back(m.file_facet[f]);
      continue;
    }
    D.insert(F.begin(), F.end());
    dropped += (dropped.empty() ? "" : ", ") + std::to_string(m.file_facet[f]);
  }
  if (D.empty()) return;
  std::set<std::pair<int, int>> used;
  for (const auto& F : kept)
    for (std::size_t i = 0; i < F.size(); ++i) used.insert({F[i], F[(i + 1) % F.size()]});
  std::vector<std::vector<int>> facets;
  std::vector<int> file_facet;
  int recut = 0;
  for (std::size_t f = 0; f < kept.size(); ++f) {
    std::vector<int> G = spliced(kept[f], used, D, V);
    std::vector<std::array<int, 3>> ears;
    if (G.size() > kept[f].size()) ears = ear_triangles(G, newell_normal(kept[f], V), V);
    recut += !ears.empty();
    if (ears.empty()) facets.push_back(G.size() > kept[f].size() ? G : kept[f]);
    for (const auto& t : ears) facets.push_back({t[0], t[1], t[2]});
    file_facet.insert(file_facet.end(), ears.empty() ? 1 : ears.size(), origin[f]);
  }
  m.repairs.push_back("drop-zero-area: " + std::to_string(m.mesh.facets.size() - kept.size()) +
                      " zero-area facet(s) dropped (facet " + dropped + "), " + std::to_string(recut) +
                      " neighbour(s) cut at their vertices");
  m.mesh.facets = std::move(facets);
  m.file_facet = std::move(file_facet);
}

// The facets of each shell (joined across edges of exactly two facets),
// in order of their lowest facet.
std::vector<std::vector<int>> shell_facets(const std::vector<std::vector<int>>& facets)
{
  std::vector<int> parent(facets.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::map<std::pair<int, int>, std::vector<int>> edges;
  for (std::size_t f = 0; f < facets.size(); ++f)
    for (std::size_t i = 0; i < facets[f].size(); ++i) {
      int a = facets[f][i], b = facets[f][(i + 1) % facets[f].size()];
      edges[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(f));
    }
  for (const auto& [e, users] : edges)
    if (users.size() == 2) parent[root(users[0])] = root(users[1]);
  std::map<int, std::size_t> shell_of_root;
  std::vector<std::vector<int>> shells;
  for (std::size_t f = 0; f < facets.size(); ++f) {
    auto [it, added] = shell_of_root.emplace(root(static_cast<int>(f)), shells.size());
    if (added) shells.emplace_back();
    shells[it->second].push_back(static_cast<int>(f));
  }
  return shells;
}

bool runs(const std::vector<int>& F, int a, int b)
{
  for (std::size_t i = 0; i < F.size(); ++i)
    if (F[i] == a && F[(i + 1) % F.size()] == b) return true;
  return false;
}

// One shell's facets turned to agree with its first facet across each edge
// of two facets (breadth first), then all turned if the shell's signed
// volume is negative; the count of facets reversed.
int orient_shell(const std::vector<int>& shell, std::vector<std::vector<int>>& facets, const std::vector<P3>& V)
{
  std::map<std::pair<int, int>, std::vector<int>> edges;
  for (int f : shell)
    for (std::size_t i = 0; i < facets[f].size(); ++i) {
      int a = facets[f][i], b = facets[f][(i + 1) % facets[f].size()];
      edges[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  std::set<int> done{shell.front()}, reversed;
  std::vector<int> queue{shell.front()};
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const std::vector<int>& F = facets[queue[q]];
    for (std::size_t i = 0; i < F.size(); ++i) {
      int a = F[i], b = F[(i + 1) % F.size()];
      const std::vector<int>& users = edges[{std::min(a, b), std::max(a, b)}];
      if (users.size() != 2) continue;
      int g = users[0] == queue[q] ? users[1] : users[0];
      if (!done.insert(g).second) continue;
      if (runs(facets[g], a, b)) std::reverse(facets[g].begin(), facets[g].end()), reversed.insert(g);
      queue.push_back(g);
    }
  }
  Rational six_volume(0);
  for (int f : shell)
    for (std::size_t i = 1; i + 1 < facets[f].size(); ++i)
      six_volume += dot(V[facets[f][0]], cross(V[facets[f][i]], V[facets[f][i + 1]]));
  if (six_volume >= 0) return static_cast<int>(reversed.size());
  for (int f : shell) std::reverse(facets[f].begin(), facets[f].end());
  return static_cast<int>(shell.size() - reversed.size());
}

// "orient": each shell's facets consistently oriented and outward.
void orient(Repaired_mesh& m)
{
  int turned = 0, shells = 0;
  for (const std::vector<int>& shell : shell_facets(m.mesh.facets)) {
    int n = orient_shell(shell, m.mesh.facets, m.mesh.vertices);
    turned += n;
    shells += n > 0;
  }
  if (turned)
    m.repairs.push_back("orient: " + std::to_string(turned) + " facet(s) reversed in " + std::to_string(shells) +
                        " shell(s), each shell outward");
}

// The fans of facets around each vertex: the facets that use it, joined
// across the edges from it that exactly two facets share. Only a vertex
// whose every edge has two facets is given (an edge of one or of three
// facets is refused by the check as before, and is not mended by a split);
// each fan is its facets' indices, in order of the lowest.
std::map<int, std::vector<std::vector<int>>> fans_of_vertices(const std::vector<std::vector<int>>& facets)
{
  std::map<std::pair<int, int>, std::vector<int>> edges;   // undirected edge -> its facets
  std::map<int, std::vector<int>> around;                  // vertex -> its facets
  for (std::size_t f = 0; f < facets.size(); ++f)
    for (std::size_t i = 0; i < facets[f].size(); ++i) {
      int a = facets[f][i], b = facets[f][(i + 1) % facets[f].size()];
      edges[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(f));
      around[a].push_back(static_cast<int>(f));
    }
  std::map<int, std::map<int, int>> joined;   // vertex -> facet -> a facet of its fan (union-find)
  auto root = [](std::map<int, int>& parent, int f) {
    while (parent.count(f) && parent[f] != f) f = parent[f];
    return f;
  };
  std::set<int> open;                          // vertices on an edge not of two facets
  for (const auto& [e, users] : edges)
    for (int v : {e.first, e.second}) {
      if (users.size() != 2) {
        open.insert(v);
        continue;
      }
      auto& parent = joined[v];
      parent[root(parent, users[0])] = root(parent, users[1]);
    }
  std::map<int, std::vector<std::vector<int>>> fans;
  for (const auto& [v, users] : around) {
    if (open.count(v)) continue;
    std::map<int, std::size_t> fan_of_root;
    for (int f : std::set<int>(users.begin(), users.end())) {
      auto [it, added] = fan_of_root.emplace(root(joined[v], f), fans[v].size());
      if (added) fans[v].emplace_back();
      fans[v][it->second].push_back(f);
    }
  }
  return fans;
}

std::string point_text(const P3& p)
{
  return "(" + to_string(p[0]) + ", " + to_string(p[1]) + ", " + to_string(p[2]) + ")";
}

// "split-pinched": each vertex where separate fans of facets meet becomes
// one vertex per fan, all at the same point (the first fan keeps the
// vertex). The solid is unchanged, since a point bounds no volume; its
// surface then touches itself at the point, which the crossing test
// allows there and nowhere else (scene/Mesh_check.h).
void split_pinched(Repaired_mesh& m)
{
  int split = 0, copies = 0;
  std::string where;
  for (const auto& [v, fans] : fans_of_vertices(m.mesh.facets)) {
    if (fans.size() < 2) continue;
    if (split++ < 5) {
      std::string list;
      for (std::size_t k = 0; k < fans.size(); ++k)
        list += (k == 0 ? "" : k + 1 == fans.size() ? " and " : ", ") + std::to_string(m.file_facet[fans[k].front()]);
      where += (where.empty() ? "" : "; ") + point_text(m.mesh.vertices[v]) + " between facets " + list;
    }
    for (std::size_t k = 1; k < fans.size(); ++k, ++copies) {
      int copy = static_cast<int>(m.mesh.vertices.size());
      m.mesh.vertices.push_back(m.mesh.vertices[v]);
      for (int f : fans[k]) std::replace(m.mesh.facets[f].begin(), m.mesh.facets[f].end(), v, copy);
    }
  }
  if (split > 5) where += "; and " + std::to_string(split - 5) + " more";
  if (split)
    m.repairs.push_back("split-pinched: " + std::to_string(split) + " pinched vertex(es) split into one vertex per fan of "
                        "facets (" + std::to_string(copies) + " added; the surface touches itself there): " + where);
}

} // namespace

Repaired_mesh repaired_mesh(const Mesh& file, const Mesh_options& options, const std::string& file_name)
{
  Repaired_mesh m;
  m.mesh = file;
  if (options.scale != 1)
    for (auto& p : m.mesh.vertices)
      for (Rational& x : p) x *= options.scale;
  m.mesh = merged_points(m.mesh, file_name);
  m.file_facet.resize(m.mesh.facets.size());
  std::iota(m.file_facet.begin(), m.file_facet.end(), 0);
  if (options.triangulate) triangulate(m);
  if (options.drop_zero_area) drop_zero_area(m);
  if (options.orient) orient(m);
  if (options.split_pinched) split_pinched(m);
  return m;
}

std::vector<Repaired_mesh> shells_of(const Repaired_mesh& m)
{
  std::vector<Repaired_mesh> shells;
  for (const std::vector<int>& facets : shell_facets(m.mesh.facets)) {
    shells.emplace_back();
    shells.back().mesh.vertices = m.mesh.vertices;
    for (int f : facets) {
      shells.back().mesh.facets.push_back(m.mesh.facets[f]);
      shells.back().file_facet.push_back(m.file_facet[f]);
    }
  }
  return shells;
}

} // namespace clash4d
