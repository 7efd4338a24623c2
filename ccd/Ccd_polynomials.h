// The polynomials in t whose signs decide a CCD query (docs/ccd-queries.md),
// each named by an index and made once, when first asked, over any number
// type: doubles, intervals or rationals. The static tests (Ccd_contact.h)
// read only their signs, so a kernel can decide a sign in intervals and,
// where that is uncertain, on the same named polynomial in rationals.
//
// Vertex-face, with P = p - a, E1 = b - a, E2 = c - a (each linear in t) and
// N = E1 x E2: P = u E1 + v E2 gives E1 x P = v N, P x E2 = u N and
// (E2 - E1) x (P - E1) = (1 - u - v) N.
// Edge-edge, with A = a1 - a0, B = b1 - b0, D = b0 - a0 and N = A x B:
// u A - v B = D gives D x B = u N and D x A = v N.
// In both, F = N . (P or D) is the coplanarity cubic: zero wherever the
// primitives meet.
#ifndef CLASH4D_CCD_CCD_POLYNOMIALS_H
#define CLASH4D_CCD_CCD_POLYNOMIALS_H

#include "ccd/Ccd_query.h"
#include "geometry/kernel_ft4.h"
#include "numbers/Polynomial.h"
#include <array>
#include <optional>

namespace clash4d {

// The names. A point-in-segment test of X against [S, S + U] (W = X - S)
// asks, from its first name o: U at o..o+2, W at o+3..o+5, U x W at
// o+6..o+8, W . U at o+9 and U . U - W . U at o+10.
namespace ccd_name {
constexpr int F = 0;            // the coplanarity cubic N . P (vertex-face), N . D (edge-edge)
constexpr int N = 1;            // N's components, 1..3
constexpr int segment_names = 11;
// Vertex-face.
constexpr int face_v = 4;       // (E1 x P)_k = v N_k
constexpr int face_u = 7;       // (P x E2)_k = u N_k
constexpr int face_w = 10;      // ((E2 - E1) x (P - E1))_k = (1 - u - v) N_k
constexpr int vf_segment = 13;  // P against [0, E1], [0, E2], [E1, E2]
constexpr int vf_count = vf_segment + 3 * segment_names;
// Edge-edge.
constexpr int cut_u = 4;        // (D x B)_k = u N_k
constexpr int cut_v = 7;        // (D x A)_k = v N_k
constexpr int cut_u1 = 10;      // N_k - (D x B)_k = (1 - u) N_k
constexpr int cut_v1 = 13;      // N_k - (D x A)_k = (1 - v) N_k
constexpr int ee_segment = 16;  // D, D + B against [0, A]; 0, A against [D, D + B]
constexpr int ee_count = ee_segment + 4 * segment_names;
constexpr int max_count = ee_count;

// With a minimum separation D (Delta = D^2): distances squared against
// Delta. NN = |N|^2 > 0 when the triangle is proper (the edges are not
// parallel). A point-to-segment test of X against [S, S + U] (W = X - S)
// asks, from its first name o: U . U at o, W . U at o+1, U . U - W . U at
// o+2, Delta - |W|^2 at o+3 (the start within D), Delta - |W - U|^2 at o+4
// (the end), Delta |U|^2 - |U x W|^2 at o+5 (the line).
namespace separated {
constexpr int NN = 0;           // |N|^2
constexpr int plane = 1;        // Delta |N|^2 - F^2: the plane (lines) within D
// Vertex-face: P's projection on the plane is (u, v) with u NN = face_u,
// v NN = face_v, (1 - u - v) NN = face_w.
constexpr int face_u = 2;       // (P x E2) . N
constexpr int face_v = 3;       // (E1 x P) . N
constexpr int face_w = 4;       // ((E2 - E1) x (P - E1)) . N
constexpr int vf_segment = 5;   // P against [0, E1], [0, E2], [E1, E2]
// Edge-edge: the lines' closest points are at u NN = cut_u, v NN = cut_v.
constexpr int cut_u = 2;        // (D x B) . N
constexpr int cut_u1 = 3;       // NN - cut_u
constexpr int cut_v = 4;        // (D x A) . N
constexpr int cut_v1 = 5;       // NN - cut_v
constexpr int ee_segment = 6;   // D, D + B against [0, A]; 0, A against [D, D + B]
constexpr int segment_names = 6;
constexpr int vf_count = vf_segment + 3 * segment_names;
constexpr int ee_count = ee_segment + 4 * segment_names;
} // namespace separated
} // namespace ccd_name

template <class FT>
class Ccd_polynomials {
public:
  using Poly = Polynomial<FT>;
  using Vector = Vector3<Poly>;

  // rows: the query's eight rows (Ccd_query::rows) in FT, kept by
  // reference (the kernel's, for its lifetime); delta: D^2 for a minimum
  // separation D > 0 (the names of ccd_name::separated), or none. Nothing
  // is computed until a polynomial is asked for: most queries of a
  // simulation end at the swept boxes.
  Ccd_polynomials(Ccd_type type, const std::array<Vector3<FT>, 8>& rows, std::optional<FT> delta = std::nullopt)
    : type_(type), rows_(rows), delta_(std::move(delta))
  {
  }

  Ccd_type type() const { return type_; }
  bool separated() const { return delta_.has_value(); }

  const Poly& operator()(int name)
  {
    auto& p = table_[static_cast<std::size_t>(name)];
    if (!p) make(name);
    return *p;
  }

  // The segment test's vectors: segment s's start S, direction U and point X.
  struct Segment {
    Vector start, direction, point;
  };
  Segment segment(int s)
  {
    const Vector zero{};
    const auto& v = vectors();
    if (type_ == Ccd_type::vertex_face) {
      const Vector &P = v[0], &E1 = v[1], &E2 = v[2];
      if (s == 0) return {zero, E1, P};
      if (s == 1) return {zero, E2, P};
      return {E1, minus(E2, E1), P};
    }
    const Vector &A = v[0], &B = v[1], &D = v[2];
    if (s == 0) return {zero, A, D};
    if (s == 1) return {zero, A, plus(D, B)};
    if (s == 2) return {D, B, zero};
    return {D, B, A};
  }

private:
  static Vector minus(const Vector& a, const Vector& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
  static Vector plus(const Vector& a, const Vector& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

  // P, E1, E2 (vertex-face) or A, B, D (edge-edge), linear in t.
  const std::array<Vector, 3>& vectors()
  {
    if (!v_) {
      std::array<Vector, 4> x;
      for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k) x[i][k] = Poly(rows_[i][k], rows_[i + 4][k] - rows_[i][k]);
      if (type_ == Ccd_type::vertex_face) v_ = {minus(x[0], x[1]), minus(x[2], x[1]), minus(x[3], x[1])};
      else v_ = {minus(x[1], x[0]), minus(x[3], x[2]), minus(x[2], x[0])};
    }
    return *v_;
  }

  // Makes a name, and the names made with it: the three components of one
  // vector, or every name of one segment test (each is asked with the
  // others).
  void make(int name)
  {
    using namespace ccd_name;
    auto set = [&](int at, const Poly& q) { table_[static_cast<std::size_t>(at)] = q; };
    if (delta_) return set(name, make_separated(name));
    const auto& v = vectors();   // P, E1, E2 or A, B, D
    bool vf = type_ == Ccd_type::vertex_face;
    if (name == F) return set(F, dot(n(), vf ? v[0] : v[2]));
    int segment_start = vf ? vf_segment : ee_segment;
    if (name >= segment_start) return make_segment((name - segment_start) / segment_names);
    int group = name < 4 ? N : 4 + 3 * ((name - 4) / 3);
    Vector x;
    if (group == N) x = n();
    else if (vf) x = group == face_v ? cross(v[1], v[0]) : group == face_u ? cross(v[0], v[2])
                                                                           : cross(minus(v[2], v[1]), minus(v[0], v[1]));
    else x = group == cut_u || group == cut_u1 ? cross(v[2], v[1]) : cross(v[2], v[0]);
    if (!vf && (group == cut_u1 || group == cut_v1)) x = minus(n(), x);
    for (int k = 0; k < 3; ++k) set(group + k, x[k]);
  }

  // A segment test's eleven names (ccd_name: U, W, U x W, W . U, U . U - W . U).
  void make_segment(int s)
  {
    Segment g = segment(s);
    Vector w = minus(g.point, g.start), c = cross(g.direction, w);
    int first = (type_ == Ccd_type::vertex_face ? ccd_name::vf_segment : ccd_name::ee_segment) +
                s * ccd_name::segment_names;
    Poly wu = dot(w, g.direction);
    for (int k = 0; k < 3; ++k) {
      table_[static_cast<std::size_t>(first + k)] = g.direction[k];
      table_[static_cast<std::size_t>(first + 3 + k)] = w[k];
      table_[static_cast<std::size_t>(first + 6 + k)] = c[k];
    }
    table_[static_cast<std::size_t>(first + 9)] = wu;
    table_[static_cast<std::size_t>(first + 10)] = dot(g.direction, g.direction) - wu;
  }

  // N = E1 x E2 or A x B, kept once made (F and the face or cut names use it).
  const Vector& n()
  {
    const auto& v = vectors();
    if (!n_) n_ = type_ == Ccd_type::vertex_face ? cross(v[1], v[2]) : cross(v[0], v[1]);
    return *n_;
  }

  Poly make_separated(int name)
  {
    using namespace ccd_name::separated;
    const Vector &first = vectors()[0], &second = vectors()[1], &third = vectors()[2];
    const Poly delta(*delta_);
    if (name == NN) return dot(n(), n());
    if (name == plane) {
      Poly f = dot(n(), type_ == Ccd_type::vertex_face ? first : third);
      return delta * dot(n(), n()) - f * f;
    }
    int segment_start = type_ == Ccd_type::vertex_face ? vf_segment : ee_segment;
    if (name >= segment_start) {
      Segment g = segment((name - segment_start) / segment_names);
      Vector w = minus(g.point, g.start);
      const Vector& u = g.direction;
      switch ((name - segment_start) % segment_names) {
        case 0: return dot(u, u);
        case 1: return dot(w, u);
        case 2: return dot(u, u) - dot(w, u);
        case 3: return delta - dot(w, w);
        case 4: return delta - dot(minus(w, u), minus(w, u));
        default: return delta * dot(u, u) - dot(cross(u, w), cross(u, w));
      }
    }
    if (type_ == Ccd_type::vertex_face) {
      const Vector &P = first, &E1 = second, &E2 = third;
      if (name == face_u) return dot(cross(P, E2), n());
      if (name == face_v) return dot(cross(E1, P), n());
      return dot(cross(minus(E2, E1), minus(P, E1)), n());
    }
    const Vector &A = first, &B = second, &D = third;
    if (name == cut_u) return dot(cross(D, B), n());
    if (name == cut_u1) return dot(n(), n()) - dot(cross(D, B), n());
    if (name == cut_v) return dot(cross(D, A), n());
    return dot(n(), n()) - dot(cross(D, A), n());
  }



  Ccd_type type_;
  const std::array<Vector3<FT>, 8>& rows_;
  std::optional<FT> delta_;
  std::optional<std::array<Vector, 3>> v_;
  std::optional<Vector> n_;
  std::array<std::optional<Poly>, ccd_name::max_count> table_;   // made when first asked
};

} // namespace clash4d

#endif
