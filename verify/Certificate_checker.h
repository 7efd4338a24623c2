// The independent certificate checker of `clash4d verify` (namespace
// clash4d::verifier, apart from the pipeline's names): proves a
// certificate's claim about a scene by docs/certificate-format.md alone. It
// shares nothing with the decision pipeline but the scene reader (section 7).
#ifndef CLASH4D_VERIFY_CERTIFICATE_CHECKER_H
#define CLASH4D_VERIFY_CERTIFICATE_CHECKER_H

#include "verify/Cert_reader.h"
#include "verify/Term_enumerator.h"
#include <map>

namespace clash4d::verifier {

// ok: claim is the line `verify` prints (section 5). Otherwise exit_code is 1
// (rejected), 2 (unreadable), 3 (out of memory) or 4 (a flaw of the checker),
// where the JSON path of the failure. past_step_limit: exit 1 because the
// step limit of section 4 was passed, not because a step was refuted.
struct Verify_result {
  bool ok = false;
  int exit_code = 0;
  bool past_step_limit = false;
  std::string claim, where, reason;
};

Verify_result verify_certificate(const Scene& scene, const Json& certificate);

class Certificate_checker {
public:
  explicit Certificate_checker(const Scene& scene);
  // The claim proved; throws Cert_failure on the first failure.
  std::string check(const Json& cert);

private:
  struct Pair_result {
    int a = 0, b = 0;
    bool collide = false, earliest = false, open_end = false;
    mpq_class until, t_star;   // apart until; earliest time
    Point4 shown;              // witness, touch or contact point
  };
  // A piece of an APART: its objects' segments and slab literals (section 3).
  struct Piece {
    int a, b, seg_a, seg_b;
    std::vector<int> slab;
    int strict_end = -1;       // closed: `t - hi` at an earliest proof's until
  };

  Pair_result check_pair(const Json& p, const std::string& at);
  std::string check_claim(const Json& claim, const std::vector<Pair_result>& pairs);
  Point4 check_witness(const Json& j, const std::string& at, int a, int b);
  void check_generic(const Point4& c, const Json& w, const std::string& at, std::vector<int> objects);
  mpq_class check_earliest(const Json& j, const std::string& at, int a, int b, Point4& contact);
  mpq_class check_apart(const Json& j, const std::string& at, int a, int b, bool& open_end);
  void check_node(const Json& j, const std::string& at, const Piece& piece, std::vector<int>& path);
  void check_leaf(const Json& j, const std::string& at, const Piece& piece, const std::vector<int>& path);
  Leaf_conflict check_conflict(const Json& j, const std::string& at, const Piece& piece);
  int object_named(const Json& j, const std::string& at);
  int intern(const std::array<mpq_class, 5>& literal);
  const Lit_tree& tree(int object, int segment);
  std::string describe(const std::vector<std::pair<int, Side>>& term, const Piece& piece) const;

  const Scene& scene_;
  std::vector<Object_model> objects_;
  mpq_class t_lo_, t_hi_;
  bool regularised_ = true;
  std::string semantics_;
  std::map<Literal, int> ids_;        // coprime form -> id; id ^ 1 is the negation
  std::vector<Literal> forms_;
  std::map<std::pair<int, int>, Lit_tree> trees_;
  long long steps_ = 0;
  Term_enumerator terms_{steps_};
};

} // namespace clash4d::verifier

#endif
