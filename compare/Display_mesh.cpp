#include "compare/Display_mesh.h"

#include <algorithm>
#include <cmath>

namespace clash4d {
namespace {

using P3 = std::array<double, 3>;
using Plane = Plane3<double>;   // a x + b y + c z + d <= 0
using Cell = std::vector<Plane>;

// A DNF larger than this is cut short (and said so): drawing, not deciding.
constexpr std::size_t max_cells = 4096;

struct Face {
  Plane plane;
  std::vector<P3> points;   // counter-clockwise seen from outside
  bool box = false;         // a face of the drawing box
};

P3 minus(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot3(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
P3 cross(const P3& a, const P3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
P3 normal_of(const Plane& p) { return {p[0], p[1], p[2]}; }
double value(const Plane& p, const P3& x) { return p[0] * x[0] + p[1] * x[1] + p[2] * x[2] + p[3]; }
bool near(const P3& a, const P3& b, double eps)
{
  P3 d = minus(a, b);
  return std::abs(d[0]) <= eps && std::abs(d[1]) <= eps && std::abs(d[2]) <= eps;
}

// ---------------------------------------------------------------- DNF

void append(std::vector<Cell>& to, const std::vector<Cell>& from, bool& truncated)
{
  for (const Cell& c : from) {
    if (to.size() >= max_cells) { truncated = true; return; }
    to.push_back(c);
  }
}

// Every cell of a with every cell of b: their intersection.
std::vector<Cell> product(const std::vector<Cell>& a, const std::vector<Cell>& b, bool& truncated)
{
  std::vector<Cell> out;
  for (const Cell& x : a)
    for (const Cell& y : b) {
      if (out.size() >= max_cells) { truncated = true; return out; }
      Cell c = x;
      c.insert(c.end(), y.begin(), y.end());
      out.push_back(std::move(c));
    }
  return out;
}

// The cells of node i, or of its complement when negated (De Morgan; the
// complement of a convex primitive is the union of its flipped half-spaces).
std::vector<Cell> cells_of(const Csg_model<double>& m, int i, bool negated, bool& truncated)
{
  const Csg_node& n = m.nodes[i];
  if (n.op == Csg_node::Op::Primitive) {
    const std::vector<Plane>& planes = m.primitives[n.primitive].planes;
    if (!negated) return {Cell(planes.begin(), planes.end())};
    std::vector<Cell> out;
    for (const Plane& p : planes) out.push_back({Plane{-p[0], -p[1], -p[2], -p[3]}});
    return out;
  }
  // A - B - C is A and not B and not C; its complement not A or B or C.
  bool difference = n.op == Csg_node::Op::Difference;
  bool joins = difference ? negated : (n.op == Csg_node::Op::Union) != negated;
  std::vector<Cell> out = cells_of(m, n.children[0], negated, truncated);
  for (std::size_t k = 1; k < n.children.size(); ++k) {
    std::vector<Cell> c = cells_of(m, n.children[k], difference ? !negated : negated, truncated);
    if (joins) append(out, c, truncated);
    else out = product(out, c, truncated);
  }
  return out;
}

// ---------------------------------------------------------------- clipping

// The points around normal n, counter-clockwise seen from its tip, near
// duplicates dropped.
std::vector<P3> around(const std::vector<P3>& points, const P3& n, double eps)
{
  std::vector<P3> pts;
  for (const P3& p : points)
    if (std::none_of(pts.begin(), pts.end(), [&](const P3& q) { return near(p, q, eps); })) pts.push_back(p);
  if (pts.size() < 3) return {};
  P3 c{0, 0, 0};
  for (const P3& p : pts)
    for (int a = 0; a < 3; ++a) c[a] += p[a] / pts.size();
  P3 u = minus(pts[0], c), v = cross(n, u);
  std::vector<std::pair<double, P3>> keyed;
  for (const P3& p : pts) keyed.push_back({std::atan2(dot3(minus(p, c), v), dot3(minus(p, c), u)), p});
  std::sort(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  for (std::size_t i = 0; i < pts.size(); ++i) pts[i] = keyed[i].second;
  return pts;
}

std::vector<Face> box_faces(const P3& lo, const P3& hi, double eps)
{
  std::vector<Face> faces;
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      Plane p{0, 0, 0, 0};
      p[a] = side ? 1 : -1;
      p[3] = side ? -hi[a] : lo[a];
      std::vector<P3> corners;
      for (int k = 0; k < 4; ++k) {
        P3 x = lo;
        x[a] = side ? hi[a] : lo[a];
        int b = (a + 1) % 3, c = (a + 2) % 3;
        x[b] = (k & 1) ? hi[b] : lo[b];
        x[c] = (k & 2) ? hi[c] : lo[c];
        corners.push_back(x);
      }
      faces.push_back({p, around(corners, normal_of(p), eps), true});
    }
  return faces;
}

// The polyhedron cut by p (keeping p <= 0), with its cap; false when
// nothing of volume is left.
bool clip(std::vector<Face>& faces, const Plane& p, double eps)
{
  double scale = std::sqrt(dot3(normal_of(p), normal_of(p)));
  if (scale == 0) return p[3] <= 0;
  double tol = eps * scale;
  bool outside = false, inside = false;
  for (const Face& f : faces)
    for (const P3& x : f.points) {
      outside = outside || value(p, x) > tol;
      inside = inside || value(p, x) < -tol;
    }
  if (!outside) return true;
  if (!inside) return false;
  std::vector<Face> out;
  std::vector<P3> cap;
  for (const Face& f : faces) {
    std::vector<P3> kept;
    for (std::size_t i = 0; i < f.points.size(); ++i) {
      const P3& a = f.points[i];
      const P3& b = f.points[(i + 1) % f.points.size()];
      double sa = value(p, a), sb = value(p, b);
      if (sa <= tol) kept.push_back(a);
      if (std::abs(sa) <= tol) cap.push_back(a);
      if ((sa < -tol && sb > tol) || (sa > tol && sb < -tol)) {
        double s = sa / (sa - sb);
        P3 x{a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
        kept.push_back(x);
        cap.push_back(x);
      }
    }
    if (kept.size() >= 3) out.push_back({f.plane, kept, f.box});
  }
  std::vector<P3> capped = around(cap, normal_of(p), eps);
  if (capped.size() >= 3) out.push_back({p, capped, false});
  faces = std::move(out);
  return !faces.empty();
}

// The cell's faces as triangles (each face fanned), vertices shared in the cell.
void add_faces(Display_mesh& mesh, const std::vector<Face>& faces, double eps)
{
  std::size_t first = mesh.vertices.size();
  auto index_of = [&](const P3& x) {
    for (std::size_t i = first; i < mesh.vertices.size(); ++i)
      if (near(mesh.vertices[i], x, eps)) return static_cast<int>(i);
    mesh.vertices.push_back(x);
    return static_cast<int>(mesh.vertices.size() - 1);
  };
  for (const Face& f : faces) {
    std::vector<int> ids;
    for (const P3& x : f.points) {
      int id = index_of(x);
      if (ids.empty() || ids.back() != id) ids.push_back(id);
    }
    if (ids.size() > 1 && ids.front() == ids.back()) ids.pop_back();
    for (std::size_t k = 1; k + 1 < ids.size(); ++k) mesh.triangles.push_back({ids[0], ids[k], ids[k + 1]});
  }
}

} // namespace

Display_mesh display_mesh(const Csg_model<double>& m, const std::array<double, 3>& lo,
                          const std::array<double, 3>& hi)
{
  Display_mesh mesh;
  if (m.nodes.empty()) return mesh;
  // A relative tolerance: the box's size sets the scale of every coordinate drawn.
  double size = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300});
  double eps = 1e-9 * size;
  for (const Cell& cell : cells_of(m, 0, false, mesh.truncated)) {
    std::vector<Face> faces = box_faces(lo, hi, eps);
    bool left = true;
    for (std::size_t k = 0; left && k < cell.size(); ++k) left = clip(faces, cell[k], eps);
    if (!left) continue;
    ++mesh.cells;
    mesh.clipped = mesh.clipped || std::any_of(faces.begin(), faces.end(), [](const Face& f) { return f.box; });
    add_faces(mesh, faces, eps);
  }
  return mesh;
}

Box<double, 3> node_box(const Csg_model<double>& m, int i)
{
  const Csg_node& n = m.nodes[i];
  if (n.op == Csg_node::Op::Primitive) return m.primitives[n.primitive].box;
  Box<double, 3> b = node_box(m, n.children[0]);
  if (n.op == Csg_node::Op::Difference) return b;
  for (std::size_t k = 1; k < n.children.size(); ++k)
    b = n.op == Csg_node::Op::Union ? join(b, node_box(m, n.children[k])) : meet(b, node_box(m, n.children[k]));
  return b;
}

} // namespace clash4d
