#include "scene/Bsp_pieces.h"
#include "scene/Input_error.h"

#include <gmpxx.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

namespace clash4d {
namespace {

// Integers throughout: the mesh's vertices times the common denominator D
// of their coordinates, so a facet's plane has integer coefficients and a
// point made from planes is homogeneous (x, y, z, w), w > 0. No fraction is
// reduced until a piece's corners are handed back.
struct Point {
  mpz_class x, y, z, w;
};

struct Plane {
  mpz_class a, b, c, d;   // a x + b y + c z + d w; > 0 outside a facet's solid
};

mpz_class value(const Plane& h, const Point& p) { return h.a * p.x + h.b * p.y + h.c * p.z + h.d * p.w; }

// The side of p on plane h: sign(a x + b y + c z + d w) (w > 0). Decided on
// doubles when the error bound tells (each integer read with relative error
// under 2^-52, products and three sums adding under 3 more units: 1e-14
// of the terms' magnitudes covers it), else on the integers.
int side(const Plane& h, const Point& p)
{
  double t[4] = {h.a.get_d() * p.x.get_d(), h.b.get_d() * p.y.get_d(), h.c.get_d() * p.z.get_d(),
                 h.d.get_d() * p.w.get_d()};
  double guess = t[0] + t[1] + t[2] + t[3];
  double bound = 1e-14 * (std::abs(t[0]) + std::abs(t[1]) + std::abs(t[2]) + std::abs(t[3]));
  if (std::isfinite(bound) && std::abs(guess) > bound) return guess > 0 ? 1 : -1;
  return sgn(value(h, p));
}

Point homogeneous(mpz_class x, mpz_class y, mpz_class z, mpz_class w)
{
  if (sgn(w) < 0) return {-x, -y, -z, -w};
  return {std::move(x), std::move(y), std::move(z), std::move(w)};
}

// Where planes a, b, c meet, if in one point: with normals n and offsets
// d, x det = -(d_a n_b x n_c + d_b n_c x n_a + d_c n_a x n_b), det =
// n_a . (n_b x n_c) (Cramer).
std::optional<Point> meet(const Plane& a, const Plane& b, const Plane& c)
{
  auto cross = [](const Plane& u, const Plane& v) {
    return std::array<mpz_class, 3>{u.b * v.c - u.c * v.b, u.c * v.a - u.a * v.c, u.a * v.b - u.b * v.a};
  };
  auto bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
  mpz_class det = a.a * bc[0] + a.b * bc[1] + a.c * bc[2];
  if (sgn(det) == 0) return std::nullopt;
  std::array<mpz_class, 3> x;
  for (int i = 0; i < 3; ++i) x[i] = -(a.d * bc[i] + b.d * ca[i] + c.d * ab[i]);
  return homogeneous(x[0], x[1], x[2], det);
}

// Where segment p q (s_p, s_q: their values on h, of opposite signs) meets
// h: (s_q p - s_p q) / (s_q - s_p), for p and q with w = 1.
Point cut_point(const Point& p, const Point& q, const mpz_class& sp, const mpz_class& sq)
{
  return homogeneous(sq * p.x - sp * q.x, sq * p.y - sp * q.y, sq * p.z - sp * q.z, sq - sp);
}

// A point and its double approximation: the approximation only ranks
// candidate planes (a heuristic); every sign that decides is exact.
struct Corner {
  Point p;
  std::array<double, 3> guess;
};

Corner corner_of(Point p)
{
  double w = p.w.get_d();
  std::array<double, 3> g{p.x.get_d() / w, p.y.get_d() / w, p.z.get_d() / w};
  return {std::move(p), g};
}

// A convex piece of one triangle: corners in the triangle's order, and for
// each edge (from corner i to i + 1) its line: edge k of the triangle
// (-1 - k) or the triangle's plane met by cut plane c (c >= 0).
struct Fragment {
  int triangle = 0;
  std::vector<Corner> corners;
  std::vector<int> lines;
};

// A cell of the partition: its corners, each with the planes through it
// (sorted ids): the box's six and the cuts that split a cell above it.
struct Cell_corner {
  Point p;
  std::vector<int> on;
};
using Cell = std::vector<Cell_corner>;

struct Node_work {
  std::vector<Fragment> fragments;
  Cell cell;
};

template <class F> void for_each_pair(const std::vector<int>& on, F f)
{
  for (std::size_t a = 0; a < on.size(); ++a)
    for (std::size_t b = a + 1; b < on.size(); ++b) f(on[a], on[b]);
}

class Partition {
public:
  Partition(const Checked_mesh& mesh, const std::string& file_name, std::size_t max_pieces)
      : mesh_(mesh), file_name_(file_name), max_pieces_(max_pieces), denominator_(1)
  {
    for (const auto& v : mesh.vertices)
      for (const Rational& x : v) mpz_lcm(denominator_.get_mpz_t(), denominator_.get_mpz_t(), mpq_denref(x.mpq()));
    for (const auto& v : mesh.vertices) points_.push_back(corner_of({scaled(v[0]), scaled(v[1]), scaled(v[2]), 1}));
    for (const auto& t : mesh.triangles) planes_.push_back(plane_through(t));
  }

  std::vector<std::vector<Rational3>> pieces()
  {
    std::vector<Node_work> stack(1);
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
      Fragment f;
      f.triangle = static_cast<int>(t);
      for (int k = 0; k < 3; ++k) {
        f.corners.push_back(points_[mesh_.triangles[t][k]]);
        f.lines.push_back(-1 - k);
      }
      stack.front().fragments.push_back(std::move(f));
    }
    stack.front().cell = bounding_box();
    while (!stack.empty() && inside_.size() <= max_pieces_) {
      Node_work node = std::move(stack.back());
      stack.pop_back();
      split(std::move(node), stack);
    }
    return std::move(inside_);
  }

private:
  mpz_class scaled(const Rational& x) const
  {
    mpz_class n(mpq_numref(x.mpq())), d(mpq_denref(x.mpq()));
    return n * (denominator_ / d);
  }

  // The plane of an outward triangle p q r: normal (q - p) x (r - p),
  // pointing out of the solid (right-hand rule).
  Plane plane_through(const std::array<int, 3>& t) const
  {
    const Point &p = points_[t[0]].p, &q = points_[t[1]].p, &r = points_[t[2]].p;
    mpz_class u[3] = {q.x - p.x, q.y - p.y, q.z - p.z}, v[3] = {r.x - p.x, r.y - p.y, r.z - p.z};
    Plane h{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0], 0};
    h.d = -(h.a * p.x + h.b * p.y + h.c * p.z);
    return h;
  }

  // The mesh's bounding box as a cell: planes x <= hi and x >= lo, each
  // with the box on its negative side, ids past the facets'.
  Cell bounding_box()
  {
    std::array<mpz_class, 3> lo{points_[0].p.x, points_[0].p.y, points_[0].p.z}, hi = lo;
    for (const Corner& c : points_) {
      const mpz_class* x[3] = {&c.p.x, &c.p.y, &c.p.z};
      for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], *x[i]), hi[i] = std::max(hi[i], *x[i]);
    }
    int first = static_cast<int>(planes_.size());
    for (int i = 0; i < 3; ++i) {
      mpz_class n[3] = {0, 0, 0};
      n[i] = 1;
      planes_.push_back({n[0], n[1], n[2], -hi[i]});
      planes_.push_back({-n[0], -n[1], -n[2], lo[i]});
    }
    Cell box;
    for (int m = 0; m < 8; ++m) {
      mpz_class x[3];
      std::vector<int> on;
      for (int i = 0; i < 3; ++i) {
        bool upper = (m >> i) & 1;
        x[i] = upper ? hi[i] : lo[i];
        on.push_back(first + 2 * i + (upper ? 0 : 1));
      }
      box.push_back({{x[0], x[1], x[2], 1}, on});
    }
    return box;
  }

  // Fragments cut by plane h, guessed in doubles: the rank of h as a
  // node's plane (fewer fragments cut, sides more even).
  long guessed_cost(int h, const std::vector<Fragment>& fragments) const
  {
    const Plane& p = planes_[h];
    std::array<double, 4> g{p.a.get_d(), p.b.get_d(), p.c.get_d(), p.d.get_d()};
    double scale = std::abs(g[0]) + std::abs(g[1]) + std::abs(g[2]);
    long front = 0, back = 0, cut = 0;
    for (const Fragment& f : fragments) {
      bool plus = false, minus = false;
      for (const Corner& c : f.corners) {
        double s = g[0] * c.guess[0] + g[1] * c.guess[1] + g[2] * c.guess[2] + g[3];
        double tolerance = 1e-9 * scale * (std::abs(c.guess[0]) + std::abs(c.guess[1]) + std::abs(c.guess[2]) + 1);
        plus = plus || s > tolerance;
        minus = minus || s < -tolerance;
      }
      cut += plus && minus;
      front += plus && !minus;
      back += minus && !plus;
    }
    return 4 * cut + std::abs(front - back);
  }

  // The node's plane: the best guessed of a few fragments' planes, chosen
  // by a fixed rule so a mesh always gets the same pieces.
  struct Ranked {
    int plane;
    long cost;   // guessed_cost
  };
  Ranked node_plane(const std::vector<Fragment>& fragments) const
  {
    constexpr std::size_t candidates = 6;
    std::size_t n = fragments.size();
    if (n <= 2) return {fragments.front().triangle, 0};
    int best = -1;
    long best_cost = 0;
    std::uint64_t state = 0x9e3779b97f4a7c15ull ^ n;
    for (std::size_t k = 0; k < std::min(candidates, n); ++k) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      int h = fragments[(state >> 33) % n].triangle;
      long cost = guessed_cost(h, fragments);
      if (best < 0 || cost < best_cost) best = h, best_cost = cost;
    }
    return {best, best_cost};
  }

  // The point where fragment f's edge i (its ends on both sides of h)
  // meets plane h: made from the facet's own points or planes, never from
  // the fragment's corners, so no construction grows with the tree.
  Point edge_point(const Fragment& f, std::size_t i, int h) const
  {
    int line = f.lines[i];
    if (line >= 0) {
      if (auto p = meet(planes_[f.triangle], planes_[line], planes_[h])) return *p;
      throw std::logic_error("bsp_pieces: a cut edge does not meet the plane in one point");
    }
    const auto& t = mesh_.triangles[f.triangle];
    int k = -1 - line;
    const Point &p = points_[t[k]].p, &q = points_[t[(k + 1) % 3]].p;
    return cut_point(p, q, value(planes_[h], p), value(planes_[h], q));
  }

  // f cut by h into its parts on h's positive and negative sides (s: its
  // corners' sides, mixed).
  void cut_fragment(const Fragment& f, const std::vector<int>& s, int h, std::vector<Fragment>& front,
                    std::vector<Fragment>& back) const
  {
    std::size_t n = f.corners.size();
    std::vector<std::optional<Corner>> crossing(n);
    for (std::size_t i = 0; i < n; ++i)
      if (s[i] * s[(i + 1) % n] < 0) crossing[i] = corner_of(edge_point(f, i, h));
    for (int side : {1, -1}) {
      Fragment part;
      part.triangle = f.triangle;
      for (std::size_t i = 0; i < n; ++i) {
        int here = side * s[i], next = side * s[(i + 1) % n];
        if (here >= 0) {
          part.corners.push_back(f.corners[i]);
          // A corner on h whose next corner is across it leaves along h.
          part.lines.push_back(here == 0 && next < 0 ? h : f.lines[i]);
        }
        if (crossing[i]) {
          part.corners.push_back(*crossing[i]);
          part.lines.push_back(here > 0 ? h : f.lines[i]);
        }
      }
      (side > 0 ? front : back).push_back(std::move(part));
    }
  }

  // The cell cut by h into front and back; when h leaves it whole, all of
  // it goes to the side it lies on and the other stays empty.
  void cut_cell(Cell cell, int h, Cell& front, Cell& back) const
  {
    std::vector<int> s;
    bool plus = false, minus = false;
    for (const auto& c : cell) {
      s.push_back(side(planes_[h], c.p));
      plus = plus || s.back() > 0;
      minus = minus || s.back() < 0;
    }
    if (!(plus && minus)) {
      (plus ? front : back) = std::move(cell);
      return;
    }
    // A new corner on each edge that h crosses: two corners on two common
    // planes of the cell are the ends of an edge (both planes support the
    // cell, so they meet it in a face holding both corners: an edge).
    // The corners on h's side with fewer, by each pair of their planes:
    int few = std::count(s.begin(), s.end(), 1) <= std::count(s.begin(), s.end(), -1) ? 1 : -1;
    std::map<std::pair<int, int>, std::vector<std::size_t>> by_pair;
    for (std::size_t j = 0; j < cell.size(); ++j)
      if (s[j] == few) for_each_pair(cell[j].on, [&](int a, int b) { by_pair[{a, b}].push_back(j); });
    std::set<std::pair<std::size_t, std::size_t>> edges;
    for (std::size_t i = 0; i < cell.size(); ++i)
      if (s[i] == -few)
        for_each_pair(cell[i].on, [&](int a, int b) {
          if (auto it = by_pair.find({a, b}); it != by_pair.end())
            for (std::size_t j : it->second) edges.insert({i, j});
        });
    for (auto [i, j] : edges) {
      std::vector<int> common;
      std::set_intersection(cell[i].on.begin(), cell[i].on.end(), cell[j].on.begin(), cell[j].on.end(),
                            std::back_inserter(common));
      auto p = meet(planes_[common[0]], planes_[common[1]], planes_[h]);
      if (!p) throw std::logic_error("bsp_pieces: a cell edge does not meet the plane in one point");
      common.insert(std::upper_bound(common.begin(), common.end(), h), h);
      front.push_back({*p, common});
      back.push_back({std::move(*p), std::move(common)});
    }
    for (std::size_t i = 0; i < cell.size(); ++i) {
      if (s[i] == 0) {
        cell[i].on.insert(std::upper_bound(cell[i].on.begin(), cell[i].on.end(), h), h);
        front.push_back(cell[i]);
      }
      if (s[i] <= 0) back.push_back(std::move(cell[i]));
      else front.push_back(std::move(cell[i]));
    }
  }

  // One node: its plane, its fragments sorted to the sides, each side a
  // node of its own or a leaf cell.
  // The fragments sorted to h's sides; the coplanar ones are counted in
  // facing_out (outward normal along h's) or facing_in (against it).
  void sort_fragments(const std::vector<Fragment>& fragments, int h, std::vector<Fragment>& front,
                      std::vector<Fragment>& back, bool& facing_out, bool& facing_in) const
  {
    for (const Fragment& f : fragments) {
      std::vector<int> s;
      bool plus = false, minus = false;
      for (const Corner& c : f.corners) {
        s.push_back(side(planes_[h], c.p));
        plus = plus || s.back() > 0;
        minus = minus || s.back() < 0;
      }
      if (plus && minus) cut_fragment(f, s, h, front, back);
      else if (plus) front.push_back(f);
      else if (minus) back.push_back(f);
      else (same_facing(f.triangle, h) ? facing_out : facing_in) = true;
    }
  }

  // A plane x_i = k through the middle of many fragments whose facet
  // planes would each split off one side only (a convex cap: every facet
  // has all the others behind it, so the facets' planes make a chain as
  // deep as the cap, and sorting there costs its square). Kept only when it
  // leaves fragments on both sides and none on it, so every leaf still
  // comes from a facet's plane.
  bool axis_split(const std::vector<Fragment>& fragments, const Ranked& facet, std::vector<Fragment>& front,
                  std::vector<Fragment>& back)
  {
    constexpr std::size_t many = 256;
    if (fragments.size() < many || facet.cost < static_cast<long>(fragments.size() / 2)) return false;
    std::array<std::vector<double>, 3> middles;
    for (const Fragment& f : fragments)
      for (int i = 0; i < 3; ++i) {
        double sum = 0;
        for (const Corner& c : f.corners) sum += c.guess[i];
        middles[i].push_back(sum / f.corners.size());
      }
    int axis = 0;
    double widest = -1;
    for (int i = 0; i < 3; ++i) {
      auto [lo, hi] = std::minmax_element(middles[i].begin(), middles[i].end());
      if (*hi - *lo > widest) widest = *hi - *lo, axis = i;
    }
    auto& m = middles[axis];
    std::nth_element(m.begin(), m.begin() + m.size() / 2, m.end());
    if (!std::isfinite(m[m.size() / 2])) return false;
    mpz_class k(std::floor(m[m.size() / 2]));   // the guesses are of the points times D
    Plane h{0, 0, 0, -k};
    (axis == 0 ? h.a : axis == 1 ? h.b : h.c) = 1;
    planes_.push_back(h);
    bool facing_out = false, facing_in = false;
    sort_fragments(fragments, static_cast<int>(planes_.size()) - 1, front, back, facing_out, facing_in);
    if (!front.empty() && !back.empty() && !facing_out && !facing_in) return true;
    planes_.pop_back();
    front.clear();
    back.clear();
    return false;
  }

  void split(Node_work node, std::vector<Node_work>& stack)
  {
    std::vector<Fragment> front, back;
    bool facing_out = false, facing_in = false;
    int h = static_cast<int>(planes_.size());
    Ranked facet = node_plane(node.fragments);
    if (!axis_split(node.fragments, facet, front, back)) {
      h = facet.plane;
      sort_fragments(node.fragments, h, front, back, facing_out, facing_in);
    }
    Node_work sides[2];
    cut_cell(std::move(node.cell), h, sides[0].cell, sides[1].cell);
    sides[0].fragments = std::move(front);
    sides[1].fragments = std::move(back);
    for (int k = 0; k < 2; ++k) {
      Node_work& part = sides[k];
      if (part.cell.empty()) {   // h leaves the cell whole on the other side
        if (!part.fragments.empty()) throw std::logic_error("bsp_pieces: fragments outside their cell");
        continue;
      }
      if (!part.fragments.empty()) {
        stack.push_back(std::move(part));
        continue;
      }
      // A leaf, wholly in or out: in on the side the node's fragments face
      // away from (a valid solid's fragments there all face one way, else
      // a facet would cross the leaf between the two).
      if (facing_out && facing_in)
        throw Input_error(file_name_, "the facets do not bound one solid: facets in one plane face both ways "
                                      "with no facet between them (a shell inside out?)");
      if ((k == 1) == facing_out) add_piece(part.cell);
    }
  }

  bool same_facing(int triangle, int h) const
  {
    const Plane &a = planes_[triangle], &b = planes_[h];
    return sgn(a.a * b.a + a.b * b.b + a.c * b.c) > 0;
  }

  Rational coordinate(const mpz_class& x, const mpz_class& w) const
  {
    Rational r;
    mpz_set(mpq_numref(r.mpq()), x.get_mpz_t());
    mpz_class d = w * denominator_;
    mpz_set(mpq_denref(r.mpq()), d.get_mpz_t());
    mpq_canonicalize(r.mpq());
    return r;
  }

  void add_piece(const Cell& cell)
  {
    std::vector<Rational3> corners;
    for (const auto& c : cell) corners.push_back({coordinate(c.p.x, c.p.w), coordinate(c.p.y, c.p.w), coordinate(c.p.z, c.p.w)});
    inside_.push_back(std::move(corners));
  }

  const Checked_mesh& mesh_;
  const std::string& file_name_;
  std::size_t max_pieces_;
  mpz_class denominator_;                      // D: the vertices' coordinates' common denominator
  std::vector<Corner> points_;                 // the vertices times D
  std::vector<Plane> planes_;                  // the triangles', then the box's, then the axis cuts
  std::vector<std::vector<Rational3>> inside_;
};

} // namespace

std::vector<std::vector<Rational3>> bsp_pieces(const Checked_mesh& mesh, const std::string& file_name,
                                               std::size_t max_pieces)
{
  return Partition(mesh, file_name, max_pieces).pieces();
}

} // namespace clash4d
