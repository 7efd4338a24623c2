// The checker of certificates of scenes where objects turn (format
// clash4d-certificate/turning-1, docs/certificate-format.md, section 8):
// polynomial multipliers, Sturm positivity, algebraic piece ends.
#ifndef CLASH4D_VERIFY_TURNING_CHECKER_H
#define CLASH4D_VERIFY_TURNING_CHECKER_H

#include "verify/Cert_reader.h"
#include "verify/Term_enumerator.h"
#include "verify/Turning_model.h"
#include <map>

namespace clash4d::verifier {

constexpr const char* CLASH4D_TURNING_FORMAT = "clash4d-certificate/turning-1";

// A point [X, Y, Z, T] with FIELD coordinates at a TIME T (8.1, 8.4), and
// its text for the verified line (8.5).
struct Time_point {
  Field_point xyz;
  Real_time t;
  std::string text;
};

// Reading section 8.1's values; failures as Cert_failure at their place.
Rational_poly read_poly(const Json& j, const std::string& at, std::string* shown = nullptr);
Real_time read_time(const Json& j, const std::string& at, std::string* shown = nullptr);
Time_point read_time_point(const Json& j, const std::string& at);

class Turning_checker {
public:
  // models: the scene's objects in order, as Certificate_checker built them
  // (their formulas and ROBMOD displacements; hulls are wrapped once).
  Turning_checker(const Scene& scene, const std::vector<Object_model>& models);
  // The claim proved; throws Cert_failure on the first failure.
  std::string check(const Json& cert);

private:
  // shown: the point the verified line names (empty for a regularised
  // earliest proof, a path); t_star and its text as read when earliest.
  struct Pair_result {
    int a = 0, b = 0;
    bool collide = false, open_end = false, earliest = false;
    Real_time until, t_star;
    std::string until_text, shown, t_star_text;
  };
  // An APART piece [lo, hi]: the objects' motion pieces, and whether the
  // non-strict sums need only be positive on [lo, hi) (open_end, 8.3).
  // member_a, member_b: the members whose formulas the leaf closes off
  // (8.3's members form), -1 for the whole formula.
  struct Piece {
    int a, b, piece_a, piece_b;
    Real_time lo, hi;
    bool half_open = false;
    int member_a = -1, member_b = -1;
  };

  Pair_result check_pair(const Json& p, const std::string& at);
  std::string check_claim(const Json& claim, const std::vector<Pair_result>& pairs);
  std::string check_witness(const Json& j, const std::string& at, int a, int b);
  std::string check_touch(const Json& j, const std::string& at, int a, int b);
  void check_generic(const Time_point& c, const Json& w, const std::string& at, int o);
  std::string check_earliest(const Json& j, const std::string& at, int a, int b, Real_time& t_star, std::string& t_text);
  void check_path(const Json& j, const std::string& at, int a, int b, const Real_time& t_star);
  Real_time check_apart(const Json& j, const std::string& at, int a, int b, bool& open_end, std::string& until_text);
  Real_time check_pieces(const Json& j, const std::string& at, int a, int b, bool open_end, int member_a, int member_b,
                         std::string& end_text);
  void check_members(const Json& j, const std::string& at, int a, int b, bool open_end, const Real_time& until,
                     const std::string& until_text);
  void check_leaf(const Json& j, const std::string& at, const Piece& piece);
  Leaf_conflict check_conflict(const Json& j, const std::string& at, const Piece& piece);
  Lit read_lit(const Json& j, const std::string& at);
  int object_named(const Json& j, const std::string& at);
  int intern(const Lit& l);
  const Lit_tree& tree(int object, int piece);
  std::string describe(const std::vector<std::pair<int, Side>>& term, const Piece& piece) const;

  const Scene& scene_;
  std::vector<Turning_model> objects_;
  mpq_class t_lo_, t_hi_;
  bool regularised_ = true;
  std::string semantics_;
  using Form = std::array<std::vector<mpz_class>, 4>;
  std::map<Form, int> ids_;   // coprime form -> id; id ^ 1 is the negation
  std::vector<Form> forms_;
  std::map<std::pair<int, int>, Lit_tree> trees_;
  long long steps_ = 0;
  Term_enumerator terms_{steps_};
};

} // namespace clash4d::verifier

#endif
