// A scene as the continuous-collision libraries take it (FCL, Bullet): each
// object a union of convex polytopes, moving by one translation over the
// whole span, in doubles. Shared by compare/Fcl_subject.h and
// compare/Bullet_subject.h, which then ask their library for each pair's
// time of contact.
//
// The scene's numbers are first rounded to the nearest double (as the double
// subject reads them, and as the library's user would have them); each
// convex piece is then the exact hull of its vertices (CGAL), translated and
// rotated exactly, each vertex rounded once more; the placements at tL and
// tH are the exact displacements, rounded.
#ifndef CLASH4D_COMPARE_CONVEX_MOTION_H
#define CLASH4D_COMPARE_CONVEX_MOTION_H

#include "check/Check_answer.h"
#include "scene/Scene.h"
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace clash4d {

struct Convex_polytope {
  std::vector<std::array<double, 3>> vertices;   // the hull's vertices only
  std::vector<std::vector<int>> faces;           // outward (counter-clockwise seen from outside)
};

struct Convex_motion {
  struct Object {
    std::string name;
    std::vector<Convex_polytope> pieces;
    std::array<double, 3> begin, end;   // translations at tL and tH
    // A turning object (a pose motion that rotates, one pose segment over
    // the span): its orientations at tL and tH as unit quaternions (w, x, y,
    // z), the pieces in the shape's own frame; the libraries turn it at
    // constant angular velocity along the shorter arc between them.
    bool turns = false;
    std::array<double, 4> begin_q{1, 0, 0, 0}, end_q{1, 0, 0, 0};
    // The pose's q(s) = (1 - s) q_L + s q_H relative to q_L is (1 - s) + s r
    // up to scale: the change of time from the libraries' angle to s.
    std::array<double, 4> relative{1, 0, 0, 0};
    bool longer_arc = false;   // q_L . q_H <= 0: the pose turns the longer way
  };
  double t_lo = 0, t_hi = 1;
  std::vector<Object> objects;
  std::vector<std::pair<int, int>> ignore;

  // Converts the scene, or returns why it cannot ("object 'b' is a
  // difference", "... changes velocity at t = 2, inside the span (ENGINE's
  // translation motion has one constant velocity)"); "" when converted.
  std::string convert(const Scene& scene, const std::string& engine);

  // Whether the library's motion of objects i and j passes through the
  // scene's configurations in the same order (regularised-semantics fact
  // 13): nothing turns; or one rests and the other turns about a fixed point
  // along the shorter arc, by at most max_angle radians in one step. When
  // not, why (for the comparer's cause "motion law").
  std::string law_differs(int i, int j, double max_angle) const;
  // Any non-ignored pair's law_differs, or "".
  std::string law_differs(double max_angle) const;

  // The answer in the comparer's form from each pair's time of contact in
  // [0, 1] (none: no contact): every non-ignored pair in pair order,
  // stopping at the first colliding one unless all_pairs or earliest; no
  // points; with earliest, t* = tL + s (tH - tL) as the shortest decimal,
  // s = toc, or, for a turn about a fixed point, the pose's s at the angle
  // the library reached (the change of time of fact 13).
  Check_answer answer(const Check_options& options, const std::string& number,
                      const std::function<std::optional<double>(int, int)>& time_of_contact) const;
};

} // namespace clash4d

#endif
