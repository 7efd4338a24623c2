#include "verify/Solid_formula.h"
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

// Every plane through three non-collinear points with all points on its
// <= 0 side, oriented so; a plane found twice is one atom (section 2.1).
// In the scaled points P = L p the plane is n.P + e <= 0, that is
// n.p + e / L <= 0 in the scene's.
std::vector<Atom> hull_atoms(const Solid& s)
{
  mpz_class L;
  const auto p = integer_points(s, L);
  std::vector<Atom> atoms;
  std::set<std::array<mpz_class, 4>> seen;   // coprime forms
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      for (std::size_t k = j + 1; k < p.size(); ++k) {
        std::array<mpz_class, 3> u, v;
        for (int c = 0; c < 3; ++c) u[c] = p[j][c] - p[i][c], v[c] = p[k][c] - p[i][c];
        std::array<mpz_class, 4> h{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0], 0};
        if (h[0] == 0 && h[1] == 0 && h[2] == 0) continue;   // collinear
        h[3] = -(h[0] * p[i][0] + h[1] * p[i][1] + h[2] * p[i][2]);
        int side = 0;
        bool mixed = false;
        for (std::size_t m = 0; m < p.size() && !mixed; ++m) {
          int sg = sgn(h[0] * p[m][0] + h[1] * p[m][1] + h[2] * p[m][2] + h[3]);
          if (sg != 0 && side != 0 && sg != side) mixed = true;
          if (sg != 0) side = sg;
        }
        if (mixed || side == 0) continue;
        mpz_class g = gcd(gcd(h[0], h[1]), gcd(h[2], h[3]));
        if (side > 0) g = -g;
        for (mpz_class& c : h) c /= g;
        if (!seen.insert(h).second) continue;
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
