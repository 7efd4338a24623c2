#include "scene/Mesh_check.h"
#include "scene/Input_error.h"
#include "scene/Lazy_point.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <algorithm>
#include <iterator>
#include <map>
#include <numeric>
#include <set>

namespace clash4d {
namespace {

using P3 = std::array<Rational, 3>;

P3 sub(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
P3 cross(const P3& a, const P3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Rational dot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool is_zero(const P3& a) { return CGAL::is_zero(a[0]) && CGAL::is_zero(a[1]) && CGAL::is_zero(a[2]); }

std::string text(const P3& p)
{
  return "(" + to_string(p[0]) + ", " + to_string(p[1]) + ", " + to_string(p[2]) + ")";
}

struct Fail {
  const std::string& file;
  const std::vector<int>& file_facet;   // the file's facet of each facet checked (empty: the same)
  std::string facet(int f) const
  {
    return "facet " + std::to_string(file_facet.empty() ? f : file_facet[f]);
  }
  int file_index(int f) const { return file_facet.empty() ? f : file_facet[f]; }
  [[noreturn]] void operator()(const std::string& where, const std::string& what) const
  {
    throw Input_error(where.empty() ? file : file + ": " + where, what);
  }
};

// One side of an edge: the facet and whether it runs from the smaller
// vertex id to the larger.
struct Edge_use {
  int facet;
  bool forward;
};

int find_root(std::vector<int>& parent, int i)
{
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// The self-intersection test's kernel: CGAL's lazy exact one
// (scene/Lazy_point.h).
using Exact_geometry = CGAL::Epeck;
using Surface = CGAL::Surface_mesh<Exact_geometry::Point_3>;
using Facets = std::vector<std::vector<int>>;                         // vertex ids, per facet
using Edges = std::map<std::pair<int, int>, std::vector<Edge_use>>;  // undirected edge -> its sides

// Facets: distinct vertices, non-zero area, planar, strictly convex. Their
// normals (Newell's, unnormalised), and their fans of triangles in out.
std::vector<P3> check_facets(const Facets& facets, const Fail& fail, Checked_mesh& out)
{
  const auto& V = out.vertices;
  std::vector<P3> normal(facets.size());
  for (std::size_t f = 0; f < facets.size(); ++f) {
    const std::vector<int>& F = facets[f];
    int fi = static_cast<int>(f);
    std::set<int> seen;
    for (std::size_t i = 0; i < F.size(); ++i)
      if (!seen.insert(F[i]).second)
        fail(fail.facet(fi), "vertex " + std::to_string(i) + " " + text(V[F[i]]) + " repeats an earlier vertex of the facet");
    P3 N = newell_normal(F, V);
    if (is_zero(N)) fail(fail.facet(fi), "zero area (its vertices are collinear; \"repair\": [\"drop-zero-area\"] drops it)");
    if (F.size() > 3) {
      std::string fault = polygon_fault(F, N, V);
      if (!fault.empty()) fail(fail.facet(fi), fault);
    }
    normal[f] = N;
    for (std::size_t i = 1; i + 1 < F.size(); ++i) {
      out.triangles.push_back({F[0], F[i], F[i + 1]});
      out.facet_of.push_back(fail.file_index(fi));
    }
  }
  return normal;
}

std::string edge_text(const std::vector<P3>& V, const std::pair<int, int>& e)
{
  return "the edge from " + text(V[e.first]) + " to " + text(V[e.second]);
}

// Each edge shared by exactly two facets: no more (a manifold), no fewer
// (closed). The fault reported is the lowest facet's.
void check_edge_counts(const Edges& edges, const std::vector<P3>& V, const Fail& fail)
{
  int worst = -1;
  std::string why;
  auto note = [&](int facet, const std::string& message) {
    if (worst < 0 || facet < worst) worst = facet, why = message;
  };
  for (const auto& [e, uses] : edges)
    if (uses.size() > 2) {
      std::string list;
      for (const auto& u : uses) list += (list.empty() ? "" : ", ") + std::to_string(fail.file_index(u.facet));
      note(uses.front().facet, "edge shared by " + std::to_string(uses.size()) + " facets (" + list +
                                   "): the mesh is not a manifold along " + edge_text(V, e) + " (\"as\": \"hull\" takes the convex hull)");
    }
  if (worst >= 0) fail(fail.facet(worst), why);
  for (const auto& [e, uses] : edges)
    if (uses.size() == 1)
      note(uses.front().facet, "edge not shared with any other facet: the mesh has a hole (it is not closed) along " + edge_text(V, e) + " (\"as\": \"hull\" takes the convex hull)");
  if (worst >= 0) fail(fail.facet(worst), why);
}

// Edges: each shared by exactly two facets, once in each direction (the
// facets consistently oriented; the one reported is the facet with most
// conflicts).
Edges check_edges(const Facets& facets, const std::vector<P3>& V, const Fail& fail)
{
  Edges edges;
  for (std::size_t f = 0; f < facets.size(); ++f)
    for (std::size_t i = 0; i < facets[f].size(); ++i) {
      int a = facets[f][i], b = facets[f][(i + 1) % facets[f].size()];
      edges[{std::min(a, b), std::max(a, b)}].push_back({static_cast<int>(f), a < b});
    }
  check_edge_counts(edges, V, fail);
  std::vector<int> conflicts(facets.size(), 0);
  std::vector<std::string> example(facets.size());
  for (const auto& [e, uses] : edges)
    if (uses[0].forward == uses[1].forward)
      for (int k = 0; k < 2; ++k) {
        int f = uses[k].facet, g = uses[1 - k].facet;
        if (conflicts[f]++ == 0) example[f] = fail.facet(g) + " across " + edge_text(V, e);
      }
  auto most = std::max_element(conflicts.begin(), conflicts.end());
  if (*most > 0) {
    int f = static_cast<int>(most - conflicts.begin());
    fail(fail.facet(f), "oriented against its neighbours across " + std::to_string(*most) + " of its edges (" + example[f] +
                             "): a flipped facet, or facets not consistently oriented (\"repair\": [\"orient\"] turns them)");
  }
  return edges;
}

// Vertices: the facets around each form one fan (no pinched vertex).
void check_fans(const Facets& facets, const std::vector<P3>& V, const Fail& fail)
{
  std::map<std::pair<int, int>, int> facet_of_edge;   // directed edge -> facet
  std::vector<std::vector<std::pair<int, int>>> around(V.size());   // (facet, position)
  for (std::size_t f = 0; f < facets.size(); ++f)
    for (std::size_t i = 0; i < facets[f].size(); ++i) {
      facet_of_edge[{facets[f][i], facets[f][(i + 1) % facets[f].size()]}] = static_cast<int>(f);
      around[facets[f][i]].push_back({static_cast<int>(f), static_cast<int>(i)});
    }
  for (std::size_t v = 0; v < V.size(); ++v) {
    std::map<int, int> position;
    for (const auto& fp : around[v]) position[fp.first] = fp.second;
    std::set<int> visited;
    int fans = 0;
    for (const auto& fp : around[v]) {
      if (visited.count(fp.first)) continue;
      ++fans;
      int f = fp.first;
      while (visited.insert(f).second) {
        const std::vector<int>& F = facets[f];
        int next = F[(position[f] + 1) % F.size()];
        f = facet_of_edge.at({next, static_cast<int>(v)});
      }
    }
    if (fans > 1)
      fail("vertex " + text(V[v]), "the surface is pinched there: " + std::to_string(fans) +
                                       " separate fans of facets meet at the point (" +
                                       fail.facet(around[v].front().first) +
                                       " is in one; \"repair\": [\"split-pinched\"] splits the vertex, one per fan, "
                                       "for the same solid touching itself there)");
  }
}

// Volume: the sum of the triangles' signed tetrahedra from the origin,
// positive (facets counter-clockwise seen from outside).
Rational checked_volume(const Checked_mesh& m, const Fail& fail)
{
  const auto& V = m.vertices;
  Rational six_volume(0);
  for (const auto& t : m.triangles) six_volume += dot(V[t[0]], cross(V[t[1]], V[t[2]]));
  Rational volume = six_volume / Rational(6);
  if (CGAL::is_zero(volume)) fail("", "the mesh bounds no volume (signed volume 0)");
  if (volume < 0)
    fail("", "the facets are oriented inward (signed volume " + to_string(volume) +
                 " < 0): list each facet's vertices counter-clockwise seen from outside (\"repair\": [\"orient\"] turns them)");
  return volume;
}

// Convex: one connected surface whose every edge is convex (the facet
// beyond the edge is on or below this facet's plane).
bool is_convex(const Facets& facets, const Edges& edges, const std::vector<P3>& normal, const std::vector<P3>& V)
{
  std::vector<int> parent(facets.size());
  std::iota(parent.begin(), parent.end(), 0);
  bool convex = true;
  for (const auto& [e, uses] : edges) {
    int f = uses[0].facet, g = uses[1].facet;
    parent[find_root(parent, f)] = find_root(parent, g);
    for (int w : facets[g])
      if (w != e.first && w != e.second) {
        if (CGAL::sign(dot(normal[f], sub(V[w], V[e.first]))) == CGAL::POSITIVE) convex = false;
        break;
      }
  }
  int components = 0;
  for (std::size_t f = 0; f < facets.size(); ++f) components += find_root(parent, static_cast<int>(f)) == static_cast<int>(f);
  return convex && components == 1;
}

bool has_equal_points(const std::vector<P3>& V)
{
  return std::set<P3>(V.begin(), V.end()).size() != V.size();
}

// A triangle's cone at its vertex p: {a u + b w : a, b >= 0}, with u and w
// its edges from p and n = u x w != 0 (a facet has area), an angle below pi.
struct Cone {
  P3 u, w, n;
};

Cone cone_at(int p, const std::array<int, 3>& t, const std::vector<P3>& V)
{
  int i = static_cast<int>(std::find(t.begin(), t.end(), p) - t.begin());
  P3 u = sub(V[t[(i + 1) % 3]], V[p]), w = sub(V[t[(i + 2) % 3]], V[p]);
  return {u, w, cross(u, w)};
}

// Whether the direction d is in the cone: in its plane, on the inner side
// of u and of w.
bool holds(const Cone& c, const P3& d)
{
  return CGAL::is_zero(dot(c.n, d)) && CGAL::sign(dot(cross(c.u, d), c.n)) >= 0 &&
         CGAL::sign(dot(cross(d, c.w), c.n)) >= 0;
}

// Whether two cones at one point share a direction. In two planes they can
// share only the line where the planes meet, one way or the other; in one
// plane, two sectors below pi that meet share an edge's direction of one
// of them (the intersection is a sector bounded by their edges).
bool share_direction(const Cone& a, const Cone& b)
{
  P3 l = cross(a.n, b.n);
  if (!is_zero(l)) {
    P3 m{-l[0], -l[1], -l[2]};
    return (holds(a, l) && holds(b, l)) || (holds(a, m) && holds(b, m));
  }
  return holds(b, a.u) || holds(b, a.w) || holds(a, b.u) || holds(a, b.w);
}

// Whether triangles s and t, which the crossing test found to meet, meet
// only at a point where a vertex of each lies (the copies of a split pinched
// vertex, distinct vertices at one point). Both are convex and hold that
// point p, so another common point q would put q - p in both cones at p:
// they meet only at p exactly when their cones share no direction.
bool meet_only_at_a_split_point(const std::array<int, 3>& s, const std::array<int, 3>& t, const std::vector<P3>& V)
{
  for (int i : s)
    for (int j : t)
      if (i != j && V[i] == V[j]) return !share_direction(cone_at(i, s, V), cone_at(j, t, V));
  return false;
}

} // namespace

// Equal points are one vertex (STL writes each facet's own copies): the
// distinct points a facet uses, in the order of first use.
Mesh merged_points(const Mesh& mesh, const std::string& file_name, const std::vector<int>& file_facet,
                   Equal_points equal)
{
  Fail fail{file_name, file_facet};
  Mesh out;
  std::map<P3, int> id_of;
  std::vector<int> id(mesh.vertices.size(), -1);
  out.facets.resize(mesh.facets.size());
  for (std::size_t f = 0; f < mesh.facets.size(); ++f)
    for (int v : mesh.facets[f]) {
      if (v < 0 || static_cast<std::size_t>(v) >= mesh.vertices.size())
        fail(fail.facet(static_cast<int>(f)), "vertex index " + std::to_string(v) + " out of range");
      if (id[v] < 0 && equal == Equal_points::keep) {
        id[v] = static_cast<int>(out.vertices.size());
        out.vertices.push_back(mesh.vertices[v]);
      }
      if (id[v] < 0) {
        auto it = id_of.emplace(mesh.vertices[v], static_cast<int>(out.vertices.size())).first;
        if (it->second == static_cast<int>(out.vertices.size())) out.vertices.push_back(mesh.vertices[v]);
        id[v] = it->second;
      }
      out.facets[f].push_back(id[v]);
    }
  return out;
}

P3 newell_normal(const std::vector<int>& F, const std::vector<P3>& V)
{
  P3 N{Rational(0), Rational(0), Rational(0)};
  for (std::size_t i = 0; i < F.size(); ++i) {
    P3 c = cross(V[F[i]], V[F[(i + 1) % F.size()]]);
    for (int k = 0; k < 3; ++k) N[k] += c[k];
  }
  return N;
}

// Planar (normal N) and strictly convex: every other vertex strictly left of
// each edge.
std::string polygon_fault(const std::vector<int>& F, const P3& N, const std::vector<P3>& V)
{
  std::size_t n = F.size();
  for (std::size_t i = 1; i < n; ++i)
    if (!CGAL::is_zero(dot(N, sub(V[F[i]], V[F[0]]))))
      return "not planar: vertex " + std::to_string(i) + " " + text(V[F[i]]) + " is off the plane of the facet" +
             " (\"repair\": [\"triangulate\"] cuts it into triangles)";
  for (std::size_t i = 0; i < n; ++i) {
    const P3 &a = V[F[i]], &b = V[F[(i + 1) % n]];
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i || j == (i + 1) % n) continue;
      if (CGAL::sign(dot(cross(sub(b, a), sub(V[F[j]], a)), N)) != CGAL::POSITIVE)
        return "not a strictly convex polygon (vertices " + std::to_string(i) + ", " + std::to_string((i + 1) % n) +
               " and " + std::to_string(j) + "): facets must be strictly convex, with no three vertices on a line" +
               " (\"repair\": [\"triangulate\"] cuts it into triangles)";
    }
  }
  return {};
}

// The checks in order, each failing at the first fault it finds
// (docs/meshes.md): facets, edges, vertices, volume, and then crossings.
Checked_mesh check_mesh(const Mesh& mesh, const std::string& file_name, const std::vector<int>& file_facet)
{
  Checked_mesh out = check_mesh_surface(mesh, file_name, file_facet);
  check_no_crossing(out, file_name);
  return out;
}

// No two facets cross (CGAL's exact self-intersection test on the
// triangles); the pair reported is the one with the lowest facet.
void check_no_crossing(const Checked_mesh& m, const std::string& file_name)
{
  static const std::vector<int> same;   // m.facet_of holds the file's facets
  Fail fail{file_name, same};
  Surface surface;
  std::vector<Surface::Vertex_index> handle;
  for (const auto& p : m.vertices) handle.push_back(surface.add_vertex(lazy_point(p)));
  std::vector<int> facet_of_face;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& T = m.triangles[t];
    if (surface.add_face(handle[T[0]], handle[T[1]], handle[T[2]]) == Surface::null_face())
      fail("facet " + std::to_string(m.facet_of[t]), "the facet cannot be joined to its neighbours into one surface");
    facet_of_face.push_back(m.facet_of[t]);
  }
  std::vector<std::pair<Surface::Face_index, Surface::Face_index>> crossing;
  CGAL::Polygon_mesh_processing::self_intersections(surface, std::back_inserter(crossing));
  if (has_equal_points(m.vertices))
    crossing.erase(std::remove_if(crossing.begin(), crossing.end(), [&](const auto& c) {
                     return meet_only_at_a_split_point(m.triangles[c.first], m.triangles[c.second], m.vertices);
                   }), crossing.end());
  if (crossing.empty()) return;
  int a = facet_of_face[crossing.front().first], b = facet_of_face[crossing.front().second];
  for (const auto& c : crossing) {
    int x = facet_of_face[c.first], y = facet_of_face[c.second];
    if (std::min(x, y) < std::min(a, b)) a = x, b = y;
  }
  if (a > b) std::swap(a, b);
  std::vector<int> shell = shell_of_triangles(m);
  auto triangle_of = [&](int facet) { return std::find(m.facet_of.begin(), m.facet_of.end(), facet) - m.facet_of.begin(); };
  // "shells": "union" helps only where two shells cross; a shell that crosses
  // itself has no repair here (docs/meshes.md: the winding-number rule is not built).
  std::string repair = shell[triangle_of(a)] == shell[triangle_of(b)]
                         ? "one shell crosses itself, which no repair reads as a solid"
                         : "\"shells\": \"union\" reads crossing shells as their union";
  fail("facet " + std::to_string(a), "crosses facet " + std::to_string(b) + ": the surface intersects itself (" + repair +
                                         "; \"as\": \"hull\" takes the convex hull)");
}

std::vector<int> shell_of_triangles(const Checked_mesh& mesh)
{
  std::vector<int> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& t : mesh.triangles) {
    parent[root(t[1])] = root(t[0]);
    parent[root(t[2])] = root(t[0]);
  }
  std::vector<int> shell;
  for (const auto& t : mesh.triangles) shell.push_back(root(t[0]));
  return shell;
}

Checked_mesh check_mesh_surface(const Mesh& mesh, const std::string& file_name, const std::vector<int>& file_facet,
                                Equal_points equal)
{
  Fail fail{file_name, file_facet};
  if (mesh.facets.empty()) fail("", "no facets");
  Checked_mesh out;
  Mesh merged = merged_points(mesh, file_name, file_facet, equal);
  out.vertices = std::move(merged.vertices);
  const Facets& facets = merged.facets;
  std::vector<P3> normal = check_facets(facets, fail, out);
  Edges edges = check_edges(facets, out.vertices, fail);
  check_fans(facets, out.vertices, fail);
  out.volume = checked_volume(out, fail);
  // A surface that touches itself bounds no convex solid (and its hull
  // would fill the gap at the point): never the hull of its vertices.
  out.convex = is_convex(facets, edges, normal, out.vertices) && !has_equal_points(out.vertices);
  return out;
}

} // namespace clash4d
