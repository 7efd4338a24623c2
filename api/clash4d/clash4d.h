// clash4d's public C++ API: exact collision detection for moving polyhedral
// CSG solids (Cameron's four-dimensional intersection testing).
//
//   find_package(clash4d)                                  # CMake
//   target_link_libraries(app PRIVATE clash4d::clash4d)
//   #include <clash4d/clash4d.h>
//
// This header needs only the C++17 standard library: CGAL, GMP, TBB and the
// rest stay inside libclash4d. Everything is in namespace clash4d::api.
//
//   namespace c4 = clash4d::api;
//   c4::Scene_builder b("approach", 0, 10);
//   b.object("box", c4::Solid::block({0, 0, 0}, {1, 1, 1}));
//   b.object("ram", c4::Solid::block({2, 0, 0}, {3, 1, 1}), c4::Motion::steady({-1, 0, 0}));
//   c4::Check_options o;
//   o.earliest = true;
//   c4::Check_result r = c4::check(b.build(), o);
//   // r.collide == true; r.reported()->earliest->t == c4::Rational(1)
//
// Scenes are those of the scene format (docs/scene-format.md in
// the project; `clash4d validate --help`): a scene built here is written in
// that format and read back by the same reader as `clash4d check`, so it is
// validated exactly like a file. Every number is an exact rational: nothing
// on the exact path goes through a double.
//
// Errors: invalid input throws clash4d::api::Input_error (file, place,
// message, exit code 2 = invalid or 3 = a resource limit, as the command line
// exits), and so does a check, a comparison or a CCD batch past its
// max_seconds (exit code 3). One stopped through its cancel flag throws
// clash4d::api::Cancelled. An internal error (a bug) throws std::logic_error.
//
// Objects may turn (Motion::poses, the scene format's pose motions): check
// then decides by time slices, and its t*, contact points and closed
// witnesses are exact algebraic numbers (Algebraic), irrational where they
// must be. CCD queries (vertex-face, edge-edge; `clash4d ccd`) answer with
// Algebraic numbers too: see "CCD" below.
//
// Not here yet: certificates (clash4d check --certificate, clash4d verify).
#ifndef CLASH4D_API_CLASH4D_H
#define CLASH4D_API_CLASH4D_H

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

// The library is built with hidden visibility; what this header declares
// is its interface (default visibility, also when a user builds hidden).
#if defined(__GNUC__) || defined(__clang__)
#define CLASH4D_API __attribute__((visibility("default")))
#else
#define CLASH4D_API
#endif

namespace clash4d {
namespace api {

// The library's version, "major.minor.patch".
CLASH4D_API const char* version();

// ---------------------------------------------------------------- numbers

// An exact rational p/q in lowest terms with q > 0, its numerator and
// denominator as decimal digit strings (of any length).
class CLASH4D_API Rational {
public:
  Rational();                                  // 0
  Rational(long long n);                       // n (implicit: Rational r = 3;)
  Rational(long long p, long long q);          // p/q; throws std::invalid_argument when q = 0
  // Exactly the number the text means, in the scene format's forms: an
  // integer "-3", a decimal with an optional exponent "0.1" (= 1/10),
  // "-2.5e-3" (= -1/400), or a fraction "p/q". Beyond the scene reader's
  // limits (1000 characters, exponents within +-1000) only "p" and "p/q"
  // are read, of any length: every number this library returns has that
  // form. Throws std::invalid_argument on anything else.
  explicit Rational(const std::string& text);

  const std::string& numerator() const { return num_; }      // "-1"
  const std::string& denominator() const { return den_; }    // "2"
  // "p/q", or "p" when q = 1 (the form of the scene format and of --json).
  std::string to_string() const;
  // The double nearest to it (ties to even); for display only.
  double to_double() const;

private:
  std::string num_ = "0", den_ = "1";
};
CLASH4D_API bool operator==(const Rational& a, const Rational& b);
CLASH4D_API bool operator<(const Rational& a, const Rational& b);
// Exact arithmetic; division by zero throws std::domain_error.
CLASH4D_API Rational operator+(const Rational& a, const Rational& b);
CLASH4D_API Rational operator-(const Rational& a, const Rational& b);
CLASH4D_API Rational operator*(const Rational& a, const Rational& b);
CLASH4D_API Rational operator/(const Rational& a, const Rational& b);
CLASH4D_API Rational operator-(const Rational& a);
inline bool operator!=(const Rational& a, const Rational& b) { return !(a == b); }
inline bool operator>(const Rational& a, const Rational& b) { return b < a; }
inline bool operator<=(const Rational& a, const Rational& b) { return !(b < a); }
inline bool operator>=(const Rational& a, const Rational& b) { return !(a < b); }

// A real algebraic number, exactly: a rational, or the one root of its
// minimal polynomial (integer coefficients, irreducible, degree at least 2)
// in an open interval (the scene format's "Exact numbers that are not
// rational"). The answers of CCD queries (t*, u, v) are such numbers.
// Immutable and cheap to copy (shared); usable from several threads.
class CLASH4D_API Algebraic {
public:
  Algebraic();                                 // 0
  explicit Algebraic(const Rational& q);       // q

  bool is_rational() const;
  // The number when is_rational(); throws std::logic_error otherwise.
  Rational rational() const;
  // The minimal polynomial's integer coefficients as decimal strings, the
  // constant term first, no common factor, the last one positive: {"-1",
  // "0", "8"} is 8x^2 - 1. For a rational p/q it is q x - p: {"-p", "q"}.
  std::vector<std::string> polynomial() const;
  // An open interval (lo, hi) holding this number and no other root of
  // polynomial(), with short decimal ends (the coarsest [n / 10^k, (n + 1) /
  // 10^k]; a function of the number alone): {0, 1} for 1/(2 sqrt 2), {3/5,
  // 7/10} for the root of 32x^2 - 32x + 7 near 0.68 (the other is near 0.32).
  // Both ends are the number when it is rational.
  std::array<Rational, 2> between() const;
  // The double nearest to the number (ties to even), and the shortest
  // decimal that reads back to it ("0.3535533905932738").
  double to_double() const;
  std::string approx() const;
  // "p/q" (or "p") when rational, otherwise
  // "root of 8x^2 - 1 in (0, 1) ~ 0.3535533905932738".
  std::string text() const;

  // The pipeline's number: the library's own use (its type is not public).
  struct Impl;
  const Impl& impl() const { return *impl_; }

private:
  explicit Algebraic(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
  std::shared_ptr<const Impl> impl_;
};
// -1, 0 or 1 as a < b, a = b, a > b; exact (isolating intervals are refined
// until they separate, a zero is decided on the minimal polynomials).
CLASH4D_API int compare(const Algebraic& a, const Algebraic& b);
CLASH4D_API int compare(const Algebraic& a, const Rational& b);
inline bool operator==(const Algebraic& a, const Algebraic& b) { return compare(a, b) == 0; }
inline bool operator!=(const Algebraic& a, const Algebraic& b) { return compare(a, b) != 0; }
inline bool operator<(const Algebraic& a, const Algebraic& b) { return compare(a, b) < 0; }
inline bool operator>(const Algebraic& a, const Algebraic& b) { return compare(a, b) > 0; }
inline bool operator<=(const Algebraic& a, const Algebraic& b) { return compare(a, b) <= 0; }
inline bool operator>=(const Algebraic& a, const Algebraic& b) { return compare(a, b) >= 0; }
inline bool operator==(const Algebraic& a, const Rational& b) { return compare(a, b) == 0; }
inline bool operator!=(const Algebraic& a, const Rational& b) { return compare(a, b) != 0; }
inline bool operator<(const Algebraic& a, const Rational& b) { return compare(a, b) < 0; }
inline bool operator>(const Algebraic& a, const Rational& b) { return compare(a, b) > 0; }
inline bool operator<=(const Algebraic& a, const Rational& b) { return compare(a, b) <= 0; }
inline bool operator>=(const Algebraic& a, const Rational& b) { return compare(a, b) >= 0; }
inline bool operator==(const Rational& a, const Algebraic& b) { return compare(b, a) == 0; }
inline bool operator!=(const Rational& a, const Algebraic& b) { return compare(b, a) != 0; }
inline bool operator<(const Rational& a, const Algebraic& b) { return compare(b, a) > 0; }
inline bool operator>(const Rational& a, const Algebraic& b) { return compare(b, a) < 0; }
inline bool operator<=(const Rational& a, const Algebraic& b) { return compare(b, a) >= 0; }
inline bool operator>=(const Rational& a, const Algebraic& b) { return compare(b, a) <= 0; }

using Vec3 = std::array<Rational, 3>;      // x, y, z
using Point4 = std::array<Rational, 4>;    // x, y, z, t
using Plane = std::array<Rational, 4>;     // a, b, c, d: the half-space a x + b y + c z + d <= 0

// ---------------------------------------------------------------- errors

constexpr int exit_invalid = 2;   // invalid input (the command line's exit status 2)
constexpr int exit_limit = 3;     // a resource limit was reached (exit status 3)

// Bad input: a scene that is not valid (or cannot be read, or needs more than
// a named limit allows). what() is "file: place: message", the line the
// command line prints.
class CLASH4D_API Input_error : public std::runtime_error {
public:
  Input_error(std::string file, std::string place, std::string message, int exit_code);
  const std::string& file() const { return file_; }        // the scene file, or "<scene>" for text
  const std::string& place() const { return place_; }      // e.g. "objects[1].shape.block.min" (may be empty)
  const std::string& message() const { return message_; }  // e.g. "expected 3 numbers"
  int exit_code() const { return exit_code_; }             // exit_invalid or exit_limit
  bool is_limit() const { return exit_code_ == exit_limit; }

private:
  std::string file_, place_, message_;
  int exit_code_;
};

// A run stopped by its options' cancel flag (see Check_options::cancel).
class CLASH4D_API Cancelled : public std::runtime_error {
public:
  Cancelled();
};

// The scene reader's limits, for callers that build scenes from other data
// (the Python module): containers nested at most max_json_depth() deep (the
// outermost is level 1), and a number at most max_number_chars() characters
// long. Beyond either, reading throws Input_error with exit_limit.
CLASH4D_API std::size_t max_json_depth();
CLASH4D_API std::size_t max_number_chars();

// ---------------------------------------------------------------- scenes

// A solid of the scene format, held as its JSON text. The factories check
// nothing: Scene_builder::build validates the whole scene.
class CLASH4D_API Solid {
public:
  static Solid halfspace(const Plane& h);                          // a x + b y + c z + d <= 0
  static Solid block(const Vec3& min, const Vec3& max);            // axis-aligned box
  static Solid convex(const std::vector<Plane>& halfspaces);        // bounded intersection with interior
  // Strictly convex counter-clockwise base (x, y) times z0 <= z <= z1.
  static Solid prism(const std::vector<std::array<Rational, 2>>& base, const Rational& z0, const Rational& z1);
  static Solid hull(const std::vector<Vec3>& points);              // convex hull, not all coplanar
  static Solid unite(const std::vector<Solid>& solids);            // regularised union ("union")
  static Solid intersection(const std::vector<Solid>& solids);     // regularised intersection
  static Solid difference(const Solid& from, const std::vector<Solid>& removed);   // from minus the union of removed
  static Solid translate(const Vec3& d, const Solid& solid);
  static Solid rotate(const std::array<Rational, 4>& quaternion, const Solid& solid);   // (w, x, y, z), not 0
  // Any solid of the scene format as JSON text, e.g. one the format gains
  // later ({"mesh": "part.stl"}, relative paths from the current directory).
  static Solid from_json(const std::string& json);

  const std::string& json() const { return json_; }

private:
  explicit Solid(std::string json) : json_(std::move(json)) {}
  std::string json_;
};

// One pose of a motion with rotation (the scene format's "Motion with
// rotation (poses)"): at time t the object occupies { R(rotate) p +
// translate : p in shape }, R the rotation of the quaternion (w, x, y, z),
// not 0 and not necessarily unit. Between poses both are interpolated
// linearly (the quaternion not normalised); before the first pose and after
// the last the object rests there.
struct Pose {
  Rational t;
  Vec3 translate{Rational(0), Rational(0), Rational(0)};
  std::array<Rational, 4> rotate{Rational(1), Rational(0), Rational(0), Rational(0)};   // identity
};

// A motion: piecewise-constant velocity, D(0) = 0 (the scene format's
// ROBMOD notation, e.g. "rest until 0 vel 1 0 0 until 5 rest"), or poses
// (Motion::poses), which may turn the object.
class CLASH4D_API Motion {
public:
  static Motion rest();                          // the default: never moves
  static Motion steady(const Vec3& velocity);    // this velocity at all times
  // velocities[0] before times[0], velocities[i] between times[i-1] and
  // times[i], the last after the last time (velocities.size() = times.size() + 1).
  static Motion piecewise(const std::vector<Vec3>& velocities, const std::vector<Rational>& times);
  static Motion from_text(const std::string& robmod);
  // Poses with strictly increasing times (checked when the scene is built
  // or the motion is used, as the scene reader checks them). Poses that
  // never rotate are the piecewise-linear translation they describe: the
  // same answers as that ROBMOD motion.
  static Motion poses(const std::vector<Pose>& poses);

  bool has_poses() const { return has_poses_; }
  // The ROBMOD text; empty for a pose motion.
  const std::string& text() const { return text_; }
  // The poses of a pose motion; empty for a ROBMOD one.
  const std::vector<Pose>& pose_list() const { return poses_; }
  // The scene format's "motion" value: a JSON string (ROBMOD) or
  // {"poses": [...]}, every number an exact string.
  std::string json() const;

private:
  explicit Motion(std::string text) : text_(std::move(text)) {}
  std::string text_;
  std::vector<Pose> poses_;
  bool has_poses_ = false;
};

// A scene read and validated: immutable, cheap to copy (shared). Its first
// exact check (Number::exact) prepares it (model, bounds, pairs) and its
// copies keep that for the next exact checks: the same answers, faster.
class CLASH4D_API Scene {
public:
  // A scene file (JSON); throws Input_error naming the file and the place.
  // Its mesh files must be under the file's folder or one of
  // allowed_mesh_folders (docs/meshes.md, "Where a mesh file may be").
  // cancel, when not null, may be set by another thread to stop the
  // reading (a mesh's convex decomposition can take minutes): it then
  // throws Cancelled. It must outlive the call.
  static Scene read_file(const std::string& path, const std::vector<std::string>& allowed_mesh_folders = {},
                         const std::atomic<bool>* cancel = nullptr);
  // A scene as JSON text; `file` names it in error messages. Its mesh files
  // are relative to, and must be under, the current directory or one of
  // allowed_mesh_folders. cancel as in read_file.
  static Scene parse(const std::string& json, const std::string& file = "<scene>",
                     const std::vector<std::string>& allowed_mesh_folders = {},
                     const std::atomic<bool>* cancel = nullptr);

  const std::string& file() const;                 // the path, or the name given to parse
  const std::string& name() const;                 // the scene's "name" ("" when none)
  Rational t_lo() const;                           // the time span [t_lo, t_hi]
  Rational t_hi() const;
  std::vector<std::string> object_names() const;
  // The scene in the file format, every number an exact string.
  std::string to_json() const;

  // The pipeline's scene: the library's own use (its type is not public).
  struct Impl;
  const Impl& impl() const { return *impl_; }

private:
  explicit Scene(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
  std::shared_ptr<const Impl> impl_;
};

// Builds a scene in code: objects with solids and motions over a time span.
class CLASH4D_API Scene_builder {
public:
  Scene_builder(std::string name, const Rational& t_lo, const Rational& t_hi);
  Scene_builder& object(const std::string& name, const Solid& shape, const Motion& motion = Motion::rest());
  Scene_builder& ignore(const std::string& a, const std::string& b);   // never test this pair
  // The scene file text.
  std::string json() const;
  // Validates and returns the scene; throws Input_error (file "<built scene>"
  // and the place in json()) when it is not valid.
  Scene build() const;

private:
  std::string name_;
  Rational t_lo_, t_hi_;
  std::vector<std::string> objects_, ignore_;   // JSON text of each
};

// Throws Input_error when the file is not a valid scene (`clash4d validate`).
CLASH4D_API void validate(const std::string& path);

// ---------------------------------------------------------------- check

enum class Number {
  exact,      // filtered exact: intervals, falling back to rationals (the default)
  rational,   // every sign in rationals (the reference; same answers, slower)
  double_     // plain doubles: the float answer, to hold against exact
};
enum class Semantics {
  regularised,   // a collision is a common interior point: touching is not one (the default)
  closed         // the closed objects meet within the closed span: touching counts
};

struct Check_options {
  Number number = Number::exact;
  Semantics semantics = Semantics::regularised;
  bool earliest = false;     // the earliest collision (closed: first contact) time t* and a contact point
  bool all_pairs = false;    // every colliding pair, not only the first
  double tolerance = 0;      // Number::double_ only: |value| <= tolerance counts as zero
  // A time limit, as `clash4d check --max-seconds`: when the check takes
  // longer than this many seconds it stops, with no answer, throwing
  // Input_error (exit_limit, place "max_seconds"). 0 (the default) is
  // unlimited; a negative or NaN value throws std::invalid_argument. The
  // work looks at the clock once per region of its search, so it stops
  // within about one region's work of the limit.
  double max_seconds = 0;
  // When not null, another thread may set it to true to stop the check at
  // the same places: it then throws Cancelled. It must outlive the call.
  const std::atomic<bool>* cancel = nullptr;
};

// The earliest collision of a pair: t* (the infimum of collision times) and
// a contact point x* with (x*, t*) in the closure of the collision region.
// Exact numbers: with rotation (pose motions) t* and x* may be irrational
// (roots of polynomials); without it they are always rational.
struct Earliest {
  Algebraic t;
  std::array<Algebraic, 3> point;
  bool at_start = false;   // t* = t_lo: already colliding when the span starts
  // Generic points that make the answer checkable: one strictly inside each
  // object (the same point twice in regularised semantics), each with
  // (x*, t*) in the closure of its cell. None for a scene with rotation,
  // whose answers (time slices) give no such points.
  std::optional<std::array<Point4, 2>> inside;
};

struct Colliding_pair {
  std::string a, b;            // object names, in scene order
  // Regularised: a point (x, y, z, t), t_lo < t < t_hi, strictly inside both
  // objects, always rational. Closed: a point of both closed objects, t_lo
  // <= t <= t_hi, which with rotation may be irrational (a first contact at
  // an irrational time).
  std::array<Algebraic, 4> witness;
  bool witness_verified = false;   // checked against the scene exactly
  // Closed semantics only: a generic point strictly inside each object whose
  // cell's closure holds the witness. None for a scene with rotation.
  std::optional<std::array<Point4, 2>> witness_inside;
  std::optional<Earliest> earliest;   // with Check_options::earliest
};

struct CLASH4D_API Check_result {
  Number number = Number::exact;
  Semantics semantics = Semantics::regularised;
  bool collide = false;
  // The colliding pairs found: the first one in pair order, or (earliest)
  // the one with the smallest t*, or (all_pairs) every one in pair order.
  std::vector<Colliding_pair> pairs;
  // The pair whose witness is reported (the earliest with `earliest`); null
  // when nothing collides.
  const Colliding_pair* reported() const;
  int reported_index = -1;
};
// With Number::double_ the numbers are those of the double run's shortest
// round-trip decimal text (so "0.1" is 1/10), not exact answers.

// Scenes with rotation (some pose motion turns its object) are decided by
// time slices (`clash4d check` does the same): exactly with Number::exact
// or rational; with Number::double_ the same stage runs in doubles (the
// float subject: its numbers are doubles' exact values). A rotating question this release cannot
// decide exactly (a named degenerate case) throws Input_error with
// exit_invalid at that place, its message beginning "object \"NAME\": not
// decided: "; too large a polynomial system, Input_error with exit_limit.
CLASH4D_API Check_result check(const Scene& scene, const Check_options& options = {});
// The scene's shapes with object i moving by motions[i] (one per object, in
// scene order) instead of the scene's motions: the answer check gives on
// that scene. With Number::exact the scene's preparation is kept across
// such checks (as a peer engine keeps its shapes and takes new transforms
// per query): only what depends on motions is made again (not with
// rotation: each such check is made afresh). A motion that is not valid
// throws Input_error at place "motions[i]" (pose motions
// "motions[i].poses[j]..."); a count that is not the scene's,
// std::invalid_argument. Rotation as for check, the places "motions[i]".
CLASH4D_API Check_result check(const Scene& scene, const std::vector<Motion>& motions,
                               const Check_options& options = {});

CLASH4D_API const char* name(Number n);        // "exact", "rational", "double"
CLASH4D_API const char* name(Semantics s);     // "regularised", "closed"
// Throws std::invalid_argument on an unknown name.
CLASH4D_API Number number_from_name(const std::string& name);
CLASH4D_API Semantics semantics_from_name(const std::string& name);

// ---------------------------------------------------------------- CCD

// Continuous collision detection queries (docs/ccd-queries.md, `clash4d
// ccd`): four vertices, each moving linearly from its position at t = 0 to
// its position at t = 1, as a vertex-face or an edge-edge question. Closed:
// touching counts.
//   vertex-face: vertex p, triangle a, b, c; collides when p(t) = a(t) +
//     u (b(t) - a(t)) + v (c(t) - a(t)) for some t in [0, 1], u, v >= 0,
//     u + v <= 1 (a degenerate triangle is the segment or point it spans);
//   edge-edge: edges a0 a1 and b0 b1; collides when a0(t) + u (a1(t) -
//     a0(t)) = b0(t) + v (b1(t) - b0(t)) for some t, u, v in [0, 1].
// t* is the first such t, (u, v) those of a contact at t* (any one where
// the contact is not unique). With a separation D > 0 a query collides when
// the closed primitives come within distance D, and (u, v) are then the
// parameters of a closest pair of points at t* (on the triangle, or one on
// each edge).
enum class Ccd_type { vertex_face, edge_edge };

CLASH4D_API const char* name(Ccd_type type);   // "vertex-face", "edge-edge"
// "vertex-face" or "vf", "edge-edge" or "ee"; throws std::invalid_argument otherwise.
CLASH4D_API Ccd_type ccd_type_from_name(const std::string& name);

struct Ccd_options {
  Number number = Number::exact;   // exact (filtered), rational (the reference) or double_
  bool earliest = true;            // also t* and (u, v)
  Rational separation = 0;         // minimum separation D >= 0 (0: the plain contract)
  double tolerance = 0;            // Number::double_ only: |value| <= tolerance counts as zero
  double max_seconds = 0;          // as Check_options::max_seconds (ccd_batch looks once per query)
  const std::atomic<bool>* cancel = nullptr;   // as Check_options::cancel
};

// A query: the four vertices at t = 0 and the same four at t = 1, in the
// order of the CCD benchmark's rows (vertex-face: p, a, b, c; edge-edge:
// a0, a1, b0, b1).
struct Ccd_query {
  std::array<Vec3, 4> t0, t1;
};

struct Ccd_result {
  bool collide = false;
  // With Ccd_options::earliest, when it collides: t* and the contact's (u, v).
  // Exact numbers (Number::exact, rational) are rational or irrational
  // algebraic numbers; with Number::double_ each is the rational of the
  // double's shortest round-trip decimal text (as check gives double
  // answers), not an exact answer.
  std::optional<Algebraic> t, u, v;
};

// One query. A number beyond the double range with Number::double_ throws
// Input_error (file "<query>", place "t0[i][k]" or "t1[i][k]": vertex i,
// coordinate k, in the order above); a negative separation, or a tolerance
// with another number than Number::double_, std::invalid_argument.
CLASH4D_API Ccd_result ccd_vertex_face(const Vec3& p_t0, const Vec3& a_t0, const Vec3& b_t0, const Vec3& c_t0,
                                       const Vec3& p_t1, const Vec3& a_t1, const Vec3& b_t1, const Vec3& c_t1,
                                       const Ccd_options& options = {});
CLASH4D_API Ccd_result ccd_edge_edge(const Vec3& a0_t0, const Vec3& a1_t0, const Vec3& b0_t0, const Vec3& b1_t0,
                                     const Vec3& a0_t1, const Vec3& a1_t1, const Vec3& b0_t1, const Vec3& b1_t1,
                                     const Ccd_options& options = {});
CLASH4D_API Ccd_result ccd(Ccd_type type, const Ccd_query& query, const Ccd_options& options = {});
// Many queries of one type, decided in parallel (TBB); the results are in
// the queries' order. Invalid input is found before any query is decided:
// Input_error at place "queries[j].t0[i][k]".
CLASH4D_API std::vector<Ccd_result> ccd_batch(Ccd_type type, const std::vector<Ccd_query>& queries,
                                              const Ccd_options& options = {});

// ---------------------------------------------------------------- compare

// `clash4d compare`: every subject (double, double with tolerances, exact on
// the rounded scene, optionally FCL and Bullet) held against the exact
// answer in the subject's own semantics.
struct Compare_options {
  Semantics semantics = Semantics::regularised;   // of the toolkit's own float subjects
  std::vector<double> tolerances{1e-9};           // one "double tol=EPS" subject each
  bool earliest = false;                          // also compare t*
  bool rounded = true;                            // the exact-rounded subject
  bool fcl = false;                               // FCL's continuous collision, where built in
  bool bullet = false;                            // Bullet's, likewise
  double max_seconds = 0;                         // as Check_options::max_seconds (`clash4d compare --max-seconds`)
  const std::atomic<bool>* cancel = nullptr;      // as Check_options::cancel
};

// A witness or an earliest contact as a subject gave it.
struct Located {
  std::array<std::string, 2> objects;
  std::optional<Point4> point;       // none when the subject gives no point (or, below, an irrational one)
  std::optional<Rational> t;         // earliest only, when rational
  // The numbers as the comparer writes them, always present: a rational,
  // a double's decimal, or, where a turning scene's exact answer is
  // irrational, "root of [...] in (lo, hi) ~ approx" (point and t are then
  // none: never a rounded stand-in).
  std::array<std::string, 4> point_text;
  std::string t_text;
};

// One subject's answer held against exact.
struct Subject_row {
  std::string subject;               // "exact", "exact closed", "double", "double tol=1e-09", ...
  std::string semantics;             // "regularised" or "closed"
  std::optional<double> tolerance;
  bool reference = false;            // the exact subject
  bool ok = true;                    // it answered (false: error, in `error`)
  std::string error;
  std::optional<std::string> skipped;   // did not run, and why
  std::optional<bool> collide;
  std::optional<Located> witness;
  std::optional<bool> witness_valid;    // checked exactly
  std::optional<Located> earliest;
  std::optional<std::string> t_error;   // |t* - exact t*|, 3 significant digits
  std::optional<bool> agrees;
  // Why it disagrees ("arithmetic", "input rounding", "contact", "invalid
  // witness"), or what went wrong with it.
  std::optional<std::string> cause;
};

struct Disagreement {
  std::string subject, cause, detail, semantics;
};

struct Comparison {
  std::string file, name;
  // Where exact (regularised) says no collision: whether the closed objects
  // meet all the same.
  std::optional<bool> closed_touch;
  std::vector<Subject_row> subjects;
  std::vector<Disagreement> disagreements;
  bool agree() const { return disagreements.empty(); }
  std::string json;   // the form of `clash4d compare --json` (one scene)
};

CLASH4D_API Comparison compare(const Scene& scene, const Compare_options& options = {});
// The scene's shapes with object i moving by motions[i] instead, as
// check(scene, motions, options): every subject sees the moved scene. Bad
// motions throw as check's.
CLASH4D_API Comparison compare(const Scene& scene, const std::vector<Motion>& motions,
                               const Compare_options& options = {});

} // namespace api
} // namespace clash4d

#endif
