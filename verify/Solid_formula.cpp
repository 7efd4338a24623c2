#include "verify/Solid_formula.h"
#include <algorithm>
#include <set>
#include <stdexcept>

namespace clash4d::verifier {
namespace {

mpq_class num(const Solid& s, std::size_t i)
{
  if (i >= s.numbers.size()) throw std::invalid_argument(s.path + ": too few numbers");
  return mpq_class(s.numbers[i].mpq());
}

Formula leaf(const Atom& h)
{
  Formula f;
  f.op = Formula::Op::Atom;
  f.atom = h;
  return f;
}

Formula conjunction(const std::vector<Atom>& atoms)
{
  Formula f;
  for (const Atom& h : atoms) f.kids.push_back(leaf(h));
  return f;
}

// NOT pushed down: AND <-> OR, atom h -> -h (section 2.1).
Formula negate(const Formula& f)
{
  if (f.op == Formula::Op::Atom) return leaf({-f.atom[0], -f.atom[1], -f.atom[2], -f.atom[3]});
  Formula g;
  g.op = f.op == Formula::Op::And ? Formula::Op::Or : Formula::Op::And;
  for (const Formula& k : f.kids) g.kids.push_back(negate(k));
  return g;
}

template <class Map>
void map_atoms(Formula& f, const Map& map)
{
  if (f.op == Formula::Op::Atom) f.atom = map(f.atom);
  for (Formula& k : f.kids) map_atoms(k, map);
}

// The points scaled by one common denominator L to integers, so the
// brute force below runs on integers (no gcd per operation).
std::vector<std::array<mpz_class, 3>> integer_points(const Solid& s, mpz_class& L)
{
  L = 1;
  for (std::size_t i = 0; i < s.numbers.size(); ++i) L = lcm(L, num(s, i).get_den());
  std::vector<std::array<mpz_class, 3>> p(s.numbers.size() / 3);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      mpq_class v = num(s, 3 * i + c) * L;
      p[i][c] = v.get_num();
    }
  return p;
}

using Ipoint = std::array<mpz_class, 3>;
using Plane = std::array<mpz_class, 4>;   // n.P + e <= 0, coprime integers

Ipoint minus(const Ipoint& a, const Ipoint& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Ipoint cross(const Ipoint& u, const Ipoint& v)
{
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
mpz_class dot(const Ipoint& a, const Ipoint& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool is_zero(const Ipoint& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

// A facet plane of the hull and the points lying on it.
struct Facet {
  Plane h;
  std::vector<std::size_t> on;
};

// The plane through p with normal n (n != 0), coprime and oriented with every
// point on its <= 0 side. The wrapping below only ever builds supporting
// planes; a plane with points on both sides would be a flaw of it.
Facet supporting(const std::vector<Ipoint>& P, const Ipoint& n, const Ipoint& p)
{
  Facet f{{n[0], n[1], n[2], -dot(n, p)}, {}};
  int side = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    int s = sgn(dot(n, P[i]) + f.h[3]);
    if (s == 0) f.on.push_back(i);
    else if (side == 0) side = s;
    else if (s != side) throw std::logic_error("hull wrapping: a plane that does not support the points");
  }
  mpz_class g = gcd(gcd(f.h[0], f.h[1]), gcd(f.h[2], f.h[3]));
  if (side > 0) g = -g;
  for (mpz_class& c : f.h) c /= g;
  return f;
}

// Gift wrapping about the line through P[p] with direction e, which lies in
// the supporting plane f, the points of f off the line being on the side of
// w (w in f, orthogonal to e). Every point s has an angle in [0, pi] about
// the line, from the half-plane of w towards the inside; the plane through
// the line and the point of largest angle supports every point.
Facet pivot(const std::vector<Ipoint>& P, const Facet& f, std::size_t p, const Ipoint& e, const Ipoint& w)
{
  const Ipoint n{f.h[0], f.h[1], f.h[2]};
  std::size_t best = P.size();
  mpz_class ba, bb;   // the best point's (a, b): a along w, b into the inside
  for (std::size_t s = 0; s < P.size(); ++s) {
    Ipoint d = minus(P[s], P[p]);
    mpz_class a = dot(w, d), b = -dot(n, d);
    if (b == 0) continue;   // on f: angle 0 (none lies at pi)
    if (best == P.size() || ba * b - bb * a > 0) best = s, ba = a, bb = b;
  }
  if (best == P.size()) throw std::logic_error("hull wrapping: the points lie in one plane");
  return supporting(P, cross(e, minus(P[best], P[p])), P[p]);
}

// The corners of the points on a facet in order around it (Andrew's monotone
// chain in the projection that drops the normal's first non-zero axis).
std::vector<std::size_t> facet_polygon(const std::vector<Ipoint>& P, const Facet& f)
{
  int drop = f.h[0] != 0 ? 0 : f.h[1] != 0 ? 1 : 2, u = drop == 0 ? 1 : 0, v = drop == 2 ? 1 : 2;
  std::vector<std::size_t> on = f.on;
  std::sort(on.begin(), on.end(), [&](std::size_t a, std::size_t b) {
    return P[a][u] != P[b][u] ? P[a][u] < P[b][u] : P[a][v] < P[b][v];
  });
  auto turn = [&](std::size_t o, std::size_t a, std::size_t b) {
    return sgn((P[a][u] - P[o][u]) * (P[b][v] - P[o][v]) - (P[a][v] - P[o][v]) * (P[b][u] - P[o][u]));
  };
  std::vector<std::size_t> chain(2 * on.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < on.size(); ++i) {   // lower chain
    while (k >= 2 && turn(chain[k - 2], chain[k - 1], on[i]) <= 0) --k;
    chain[k++] = on[i];
  }
  for (std::size_t i = on.size() - 1, lower = k + 1; i-- > 0;) {   // upper chain
    while (k >= lower && turn(chain[k - 2], chain[k - 1], on[i]) <= 0) --k;
    chain[k++] = on[i];
  }
  chain.resize(k > 0 ? k - 1 : 0);
  return chain;
}

// Three of the facet's points not on one line?
bool spans_a_plane(const std::vector<Ipoint>& P, const Facet& f)
{
  for (std::size_t i = 1; i < f.on.size(); ++i) {
    Ipoint e = minus(P[f.on[i]], P[f.on[0]]);
    if (is_zero(e)) continue;
    for (std::size_t j = i + 1; j < f.on.size(); ++j)
      if (!is_zero(cross(e, minus(P[f.on[j]], P[f.on[0]])))) return true;
    return false;
  }
  return false;
}

// A first facet: the plane x = min x supports the lowest point (x, then y,
// then z) p; wrapping about the z line through p gives a supporting plane
// through p and another point, and, if its points lie on one line, wrapping
// about that line gives a facet.
Facet first_facet(const std::vector<Ipoint>& P)
{
  std::size_t p = std::min_element(P.begin(), P.end()) - P.begin();
  Facet f = pivot(P, supporting(P, {-1, 0, 0}, P[p]), p, {0, 0, 1}, {0, 1, 0});
  if (spans_a_plane(P, f)) return f;
  std::size_t q = *std::find_if(f.on.begin(), f.on.end(), [&](std::size_t i) { return P[i] != P[p]; });
  Ipoint e = minus(P[q], P[p]);
  return pivot(P, f, p, e, cross({f.h[0], f.h[1], f.h[2]}, e));   // no point of f off the line: either side
}

// Every plane through three non-collinear points with all points on its
// <= 0 side, oriented so, each once, in increasing coprime form (section
// 2.1): the hull's facet planes, found by gift wrapping from facet to facet
// across the edges of each facet's polygon, O(n) per edge, so O(n h) for h
// facets and at most O(n^2) (issue 59 item 4: the naive O(n^4) was too slow).
// In the scaled points P = L p the plane is n.P + e <= 0, that is
// n.p + e / L <= 0 in the scene's.
std::vector<Atom> hull_atoms(const Solid& s)
{
  mpz_class L;
  const auto P = integer_points(s, L);
  std::set<Plane> seen;
  std::vector<Facet> todo{first_facet(P)};
  seen.insert(todo[0].h);
  while (!todo.empty()) {
    Facet f = std::move(todo.back());
    todo.pop_back();
    const Ipoint n{f.h[0], f.h[1], f.h[2]};
    std::vector<std::size_t> poly = facet_polygon(P, f);
    if (poly.size() < 3) throw std::logic_error("hull wrapping: a facet with fewer than three corners");
    for (std::size_t i = 0; i < poly.size(); ++i) {
      std::size_t p = poly[i], q = poly[(i + 1) % poly.size()], r = poly[(i + 2) % poly.size()];
      Ipoint e = minus(P[q], P[p]), w = cross(n, e);
      if (dot(w, minus(P[r], P[p])) < 0) w = {-w[0], -w[1], -w[2]};   // towards the facet
      Facet g = pivot(P, f, p, e, w);
      if (seen.insert(g.h).second) todo.push_back(std::move(g));
    }
  }
  std::vector<Atom> atoms;
  for (const Plane& h : seen) {
    mpq_class e(h[3], L);
    e.canonicalize();   // GMP wants fractions in lowest terms
    atoms.push_back({mpq_class(h[0]), mpq_class(h[1]), mpq_class(h[2]), e});
  }
  return atoms;
}

std::vector<Atom> prism_atoms(const Solid& s)
{
  std::size_t n = (s.numbers.size() - 2) / 2;
  std::vector<Atom> atoms;
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t j = (i + 1) % n;
    mpq_class xi = num(s, 2 * i), yi = num(s, 2 * i + 1);
    mpq_class dx = num(s, 2 * j) - xi, dy = num(s, 2 * j + 1) - yi;
    atoms.push_back({dy, -dx, 0, -dy * xi + dx * yi});   // dy (x - x_i) - dx (y - y_i)
  }
  atoms.push_back({0, 0, 1, -num(s, 2 * n + 1)});
  atoms.push_back({0, 0, -1, num(s, 2 * n)});
  return atoms;
}

// (n, d) -> (R n, d) with R the quaternion matrix of the scene format.
Atom rotate(const Atom& h, const Solid& s)
{
  mpq_class w = num(s, 0), x = num(s, 1), y = num(s, 2), z = num(s, 3);
  mpq_class n = w * w + x * x + y * y + z * z;
  mpq_class r[3][3] = {{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
                       {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
                       {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
  Atom g{0, 0, 0, h[3]};
  for (int i = 0; i < 3; ++i) g[i] = (r[i][0] * h[0] + r[i][1] * h[1] + r[i][2] * h[2]) / n;
  return g;
}

} // namespace

Formula solid_formula(const Solid& s)
{
  using K = Solid::Kind;
  Formula f;
  switch (s.kind) {
    case K::Halfspace: return leaf({num(s, 0), num(s, 1), num(s, 2), num(s, 3)});
    case K::Block: {
      std::vector<Atom> atoms;
      for (int c = 0; c < 3; ++c) {
        Atom hi{0, 0, 0, -num(s, 3 + c)}, lo{0, 0, 0, num(s, c)};
        hi[c] = 1, lo[c] = -1;
        atoms.push_back(hi), atoms.push_back(lo);
      }
      return conjunction(atoms);
    }
    case K::Convex: {
      std::vector<Atom> atoms;
      for (std::size_t i = 0; i + 3 < s.numbers.size(); i += 4)
        atoms.push_back({num(s, i), num(s, i + 1), num(s, i + 2), num(s, i + 3)});
      return conjunction(atoms);
    }
    case K::Prism: return conjunction(prism_atoms(s));
    case K::Hull: return conjunction(hull_atoms(s));
    case K::Union: f.op = Formula::Op::Or; [[fallthrough]];
    case K::Intersection:
      for (const Solid& k : s.children) f.kids.push_back(solid_formula(k));
      return f;
    case K::Difference:   // S AND NOT T1 AND ...
      for (std::size_t i = 0; i < s.children.size(); ++i)
        f.kids.push_back(i == 0 ? solid_formula(s.children[i]) : negate(solid_formula(s.children[i])));
      return f;
    case K::Translate: {
      if (s.children.size() != 1) break;
      f = solid_formula(s.children[0]);
      mpq_class dx = num(s, 0), dy = num(s, 1), dz = num(s, 2);
      map_atoms(f, [&](const Atom& h) { return Atom{h[0], h[1], h[2], h[3] - h[0] * dx - h[1] * dy - h[2] * dz}; });
      return f;
    }
    case K::Rotate:
      if (s.children.size() != 1) break;
      f = solid_formula(s.children[0]);
      map_atoms(f, [&](const Atom& h) { return rotate(h, s); });
      return f;
  }
  throw std::invalid_argument(s.path + ": a solid the checker cannot read");
}

void collect_atoms(const Formula& f, std::vector<Atom>& out)
{
  if (f.op == Formula::Op::Atom) out.push_back(f.atom);
  for (const Formula& k : f.kids) collect_atoms(k, out);
}

} // namespace clash4d::verifier
