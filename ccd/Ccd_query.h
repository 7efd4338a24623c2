// A CCD query (docs/ccd-queries.md): four vertices moving linearly over
// t in [0, 1], read exactly, as a vertex-face or an edge-edge question.
#ifndef CLASH4D_CCD_CCD_QUERY_H
#define CLASH4D_CCD_CCD_QUERY_H

#include "geometry/kernel_ft4.h"
#include "numbers/Rational.h"
#include <CGAL/Interval_nt.h>
#include <array>
#include <optional>
#include <string>

namespace clash4d {

enum class Ccd_type { vertex_face, edge_edge };

// "vertex-face", "edge-edge": the names of the documents, files and folders.
inline const char* ccd_type_name(Ccd_type t) { return t == Ccd_type::vertex_face ? "vertex-face" : "edge-edge"; }
// The type a name stands for: the long names, and vf / ee (--type).
inline std::optional<Ccd_type> ccd_type_from_name(const std::string& s)
{
  if (s == "vertex-face" || s == "vf") return Ccd_type::vertex_face;
  if (s == "edge-edge" || s == "ee") return Ccd_type::edge_edge;
  return std::nullopt;
}

class Ccd_query {
public:
  using Point = std::array<Rational, 3>;
  using Rows = std::array<Point, 8>;

  Ccd_query() : Ccd_query(Ccd_type::vertex_face, Rows{}) {}
  // rows: the benchmark's row order, the four vertices at t = 0, then the
  // same four at t = 1 (vertex-face: v, f0, f1, f2; edge-edge: ea0, ea1,
  // eb0, eb1).
  Ccd_query(Ccd_type type, const Rows& rows);

  Ccd_type type() const { return type_; }
  void set_type(Ccd_type t) { type_ = t; }
  const Rows& rows() const { return rows_; }
  const Point& row(int i) const { return rows_[static_cast<std::size_t>(i)]; }
  // A row changed, with its approximations.
  void set_row(int i, const Point& p);

  // Each number's nearest double (+-inf beyond the double range) and
  // tightest enclosure in doubles, made once with the rows: the double and
  // filtered kernels read these, never converting a rational per check.
  const std::array<Vector3<double>, 8>& nearest() const { return nearest_; }
  const std::array<Vector3<CGAL::Interval_nt<false>>, 8>& enclosure() const { return enclosure_; }

  std::optional<bool> label;   // the file's expected verdict, when it gives one
  std::size_t line = 0;        // the query's first line in its file (messages)

private:
  void approximate(std::size_t i);

  Ccd_type type_;
  Rows rows_;
  std::array<Vector3<double>, 8> nearest_;
  std::array<Vector3<CGAL::Interval_nt<false>>, 8> enclosure_;
};

} // namespace clash4d

#endif
