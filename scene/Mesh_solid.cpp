#include "scene/Mesh_solid.h"
#include "scene/Bsp_pieces.h"
#include "scene/Hull_solid.h"
#include "scene/Input_error.h"
#include "scene/Lazy_point.h"
#include "scene/Mesh_cache.h"
#include "scene/Mesh_options.h"
#include "scene/Mesh_repair.h"

#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Nef_nary_union_3.h>   // after Nef_polyhedron_3.h, which includes Mark_bounded_volumes.h
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_decomposition_3.h>
#include <algorithm>
#include <map>
#include <numeric>

namespace clash4d {
namespace {

// The limit in a refusal, with the way past it (docs/meshes.md, Limits).
std::string pieces_limit(const Mesh_limits& limits)
{
  return std::to_string(limits.pieces) + " convex pieces (raise it with \"max_pieces\" beside \"mesh\", up to " +
         std::to_string(CLASH4D_MAX_MESH_PIECES_ALLOWED) + ")";
}

// The decomposition runs on CGAL's lazy exact kernel (scene/Lazy_point.h):
// its signs are exact, decided on intervals where those tell, and its
// constructions (the pieces' vertices) are handed back as exact rationals.
// On Cartesian<Rational>, where every construction normalises a fraction,
// the 20,000-facet bowl of scripts/decomposition-bench took about 15% longer.
using Exact_geometry = CGAL::Epeck;
using Point_3 = Exact_geometry::Point_3;
using Surface = CGAL::Surface_mesh<Point_3>;
using Nef = CGAL::Nef_polyhedron_3<Exact_geometry>;
using Piece = CGAL::Polyhedron_3<Exact_geometry>;

// The hull of the points; adds six times its volume to *six_volume when given.
Solid hull_of(const std::vector<Rational3>& points, const std::string& file_name, Rational* six_volume = nullptr)
{
  Solid s;
  try {
    Rational six = make_hull_solid(points, s);
    if (six_volume) *six_volume += six;
  } catch (const std::invalid_argument& e) {
    throw Input_error(file_name, e.what());
  }
  return s;
}

Rational3 rational_point(const Point_3& p) { return {rational_of(p.x()), rational_of(p.y()), rational_of(p.z())}; }

using Triangles = std::vector<std::array<int, 3>>;

// The mesh's shells: its triangles joined through shared vertices (the
// copies of a split pinched vertex are distinct vertices, so the two boxes
// of a split pinch are two shells), in order of their lowest vertex's root.
std::map<int, Triangles> shells_by_vertices(const Checked_mesh& mesh)
{
  std::vector<int> shell = shell_of_triangles(mesh);
  std::map<int, Triangles> shells;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) shells[shell[t]].push_back(mesh.triangles[t]);
  return shells;
}

// The closed or open surface of the triangles as a Nef polyhedron (CGAL
// marks the volume a closed one bounds, whatever its orientation). No two
// of its vertices may be at one point.
Nef surface_nef(const Checked_mesh& mesh, const Triangles& triangles)
{
  Surface surface;
  std::map<int, Surface::Vertex_index> handle;
  for (const auto& t : triangles)
    for (int v : t)
      if (!handle.count(v)) handle[v] = surface.add_vertex(lazy_point(mesh.vertices[v]));
  for (const auto& t : triangles) surface.add_face(handle[t[0]], handle[t[1]], handle[t[2]]);
  return Nef(surface);
}

// The union of the triangles as point sets, each a planar Nef polyhedron.
Nef triangles_nef(const Checked_mesh& mesh, const Triangles& triangles)
{
  CGAL::Nef_nary_union_3<Nef> all;
  for (const auto& t : triangles) {
    std::vector<Point_3> corners{lazy_point(mesh.vertices[t[0]]), lazy_point(mesh.vertices[t[1]]),
                                 lazy_point(mesh.vertices[t[2]])};
    all.add_polyhedron(Nef(corners.begin(), corners.end()));
  }
  return all.get_union();
}

// The volume a shell encloses, whatever its orientation. CGAL's
// polygon-mesh constructor makes a Nef vertex per mesh vertex, so a shell
// that touches itself (two vertices at one point: a split pinched vertex)
// would give two at one point, an invalid Nef. Its triangles that use a
// second vertex at a point are set apart, the rest read as an open surface,
// the two joined as point sets, and the bounded volumes marked: the
// complement of one connected closed surface has one bounded part even where
// it touches itself at points (a point does not join or split open sets in
// space), and that part is the inside.
Nef shell_nef(const Checked_mesh& mesh, const Triangles& triangles)
{
  std::map<Rational3, int> first_at;   // the first vertex met at each point
  for (const auto& t : triangles)
    for (int v : t) first_at.emplace(mesh.vertices[v], v);
  Triangles surface, apart;
  for (const auto& t : triangles) {
    bool second = std::any_of(t.begin(), t.end(), [&](int v) { return first_at.at(mesh.vertices[v]) != v; });
    (second ? apart : surface).push_back(t);
  }
  if (apart.empty()) return surface_nef(mesh, surface);
  Nef nef = surface_nef(mesh, surface) + triangles_nef(mesh, apart);
  CGAL::Mark_bounded_volumes<Nef> inside(true);
  nef.delegate(inside);
  return nef;
}

} // namespace

Solid mesh_solid(const Checked_mesh& mesh, const std::string& file_name, const Mesh_limits& limits, Mesh_record* record,
                 Mesh_decomposition method)
{
  if (record) record->triangles = static_cast<int>(mesh.triangles.size());
  if (record) record->pieces = 1;
  if (record) record->decomposition.clear();
  auto crossings = [&] { check_no_crossing(mesh, file_name); };
  if (mesh.convex || !record) {   // no cache
    crossings();
    return mesh.convex ? hull_of(mesh.vertices, file_name) : decomposed_solid(mesh, file_name, limits, method);
  }
  // The pieces depend on the checked mesh (the scale and the repairs are
  // in it already) and the method alone, so no other option is part of
  // the key. An entry exists only for a mesh that passed the crossing
  // test, so a hit skips it.
  record->decomposition = decomposition_name(method);
  Solid s = Mesh_cache::from_environment().decomposed(mesh, file_name, limits, method, *record, crossings);
  record->pieces = static_cast<int>(s.children.size());
  return s;
}

namespace {

// The convex pieces of CGAL's Nef polyhedron of the mesh, each as its
// vertices; past limits.pieces it stops, with more than that (the caller
// refuses).
std::vector<std::vector<Rational3>> nef_pieces(const Checked_mesh& mesh, const std::string& file_name,
                                              const Mesh_limits& limits)
{
  // Each shell (connected surface) encloses a volume, whatever its
  // orientation: CGAL's Nef from a polygon mesh reads it so. The shells do
  // not cross (check_mesh; they may touch at the points of split pinched
  // vertices), so they nest, and the solid is the points inside
  // an odd number of them: the symmetric difference of their volumes. The
  // volume test of decomposed_solid then holds it to the facets' orientation.
  Nef nef;
  bool first = true;
  for (const auto& [r, triangles] : shells_by_vertices(mesh)) {
    Nef shell = shell_nef(mesh, triangles);
    nef = first ? shell : nef ^ shell;
    first = false;
  }
  nef.regularization();
  CGAL::convex_decomposition_3(nef);
  std::vector<std::vector<Rational3>> pieces;
  for (auto volume = ++nef.volumes_begin(); volume != nef.volumes_end(); ++volume) {
    if (!volume->mark()) continue;
    if (pieces.size() > limits.pieces) break;   // decomposed_solid refuses
    Piece piece;
    nef.convert_inner_shell_to_polyhedron(volume->shells_begin(), piece);
    // A piece is convex: the hull of its vertices is the piece itself.
    std::vector<Rational3> points;
    for (auto p = piece.vertices_begin(); p != piece.vertices_end(); ++p)
      points.push_back(rational_point(p->point()));
    pieces.push_back(std::move(points));
  }
  return pieces;
}

} // namespace

Solid decomposed_solid(const Checked_mesh& mesh, const std::string& file_name, const Mesh_limits& limits,
                       Mesh_decomposition method)
{
  std::vector<std::vector<Rational3>> pieces = method == Mesh_decomposition::bsp
                                                   ? bsp_pieces(mesh, file_name, limits.pieces)
                                                   : nef_pieces(mesh, file_name, limits);
  if (pieces.size() > limits.pieces)
    throw Input_error(file_name, "the decomposition has more than the limit of " + pieces_limit(limits),
                      CLASH4D_EXIT_LIMIT);
  Solid u;
  u.kind = Solid::Kind::Union;
  Rational total(0);
  for (const auto& corners : pieces) u.children.push_back(hull_of(corners, file_name, &total));
  // The pieces fill the solid exactly once: their volumes add up to the
  // facets' signed volume (shells nested and oriented as a solid's are).
  if (total / Rational(6) != mesh.volume)
    throw Input_error(file_name, "the facets do not bound one solid: the solid read from them has volume " +
                                     to_string(total / Rational(6)) + ", their signed volume is " + to_string(mesh.volume) +
                                     " (a shell inside out or shells overlapping?)");
  if (u.children.empty()) throw Input_error(file_name, "the mesh bounds no volume");
  return u;
}

Solid read_mesh_solid(const std::string& path, const std::string& file_name, const Mesh_limits& limits,
                      Mesh_record* record)
{
  Mesh mesh = read_mesh_file(path, file_name, limits);
  if (record) record->facets = static_cast<int>(mesh.facets.size());
  return mesh_solid(check_mesh_surface(mesh, file_name), file_name, limits, record);
}

namespace {

int piece_count(const Solid& s) { return s.kind == Solid::Kind::Union ? static_cast<int>(s.children.size()) : 1; }

// The solid of one checked surface, its pieces added to u.
void add_pieces(const Repaired_mesh& m, const std::string& name, const Mesh_limits& limits,
                Mesh_decomposition method, Mesh_record& record, Solid& u)
{
  Checked_mesh checked = check_mesh_surface(m.mesh, name, m.file_facet, Equal_points::keep);
  record.triangles += static_cast<int>(checked.triangles.size());
  Mesh_record shell;
  Solid s = mesh_solid(checked, name, limits, &shell, method);
  if (!shell.decomposition.empty()) record.decomposition = shell.decomposition;
  record.decomposition_seconds += shell.decomposition_seconds;
  // The union's status: a miss when any shell was decomposed, else off, else a hit.
  auto rank = [](const std::string& c) { return c == "miss" ? 3 : c == "off" ? 2 : c == "hit" ? 1 : 0; };
  if (rank(shell.cache) > rank(record.cache)) record.cache = shell.cache;
  if (s.kind == Solid::Kind::Union)
    for (Solid& c : s.children) u.children.push_back(std::move(c));
  else
    u.children.push_back(std::move(s));
  if (u.children.size() > limits.pieces)
    throw Input_error(name, "the solid has more than the limit of " + pieces_limit(limits), CLASH4D_EXIT_LIMIT);
}

// "shells": "union": each shell a solid by itself (checked alone, so shells
// may cross one another), the solid their union.
Solid union_of_shells(const Repaired_mesh& m, const std::string& file_name, const Mesh_limits& limits,
                      Mesh_decomposition method, Mesh_record& record)
{
  std::vector<Repaired_mesh> shells = shells_of(m);
  Solid u;
  u.kind = Solid::Kind::Union;
  for (std::size_t k = 0; k < shells.size(); ++k)
    add_pieces(shells[k], file_name + ": shell " + std::to_string(k) + " (with facet " +
                              std::to_string(shells[k].file_facet.front()) + ")", limits, method, record, u);
  return u.children.size() == 1 ? u.children.front() : u;
}

} // namespace

Solid read_mesh_solid(const std::string& path, const std::string& file_name, const Mesh_options& options,
                      Mesh_record& record, const Mesh_limits& limits)
{
  return repaired_solid(read_mesh_file(path, file_name, limits), file_name, options, record, limits);
}

Solid repaired_solid(const Mesh& file, const std::string& file_name, const Mesh_options& options, Mesh_record& record,
                     const Mesh_limits& limits)
{
  record.facets = static_cast<int>(file.facets.size());
  record.scale = to_string(options.scale);
  Repaired_mesh m = repaired_mesh(file, options, file_name);
  record.repairs = m.repairs;
  Solid s;
  switch (options.rule) {
    case Mesh_options::Solid_rule::Hull:
      record.solid_rule = "hull of the vertices";
      s = hull_of(m.mesh.vertices, file_name);
      break;
    case Mesh_options::Solid_rule::Union_of_shells:
      record.solid_rule = "union of shells";
      s = union_of_shells(m, file_name, limits, options.decomposition, record);
      break;
    case Mesh_options::Solid_rule::Odd_shells:
      record.solid_rule = "odd shells";
      Checked_mesh checked = check_mesh_surface(m.mesh, file_name, m.file_facet, Equal_points::keep);
      record.triangles = static_cast<int>(checked.triangles.size());
      s = mesh_solid(checked, file_name, limits, &record, options.decomposition);
      break;
  }
  record.pieces = piece_count(s);
  return s;
}

} // namespace clash4d
