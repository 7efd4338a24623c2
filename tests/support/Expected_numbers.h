// The fixtures' expected numbers (fixtures/rotation/*/expected.json), read
// as the manifests write them: "p/q", or {"poly", "between"} for the one
// root of the polynomial (constant term first) in that interval; and a
// coordinate, which may be {"range": [lo, hi]} where the contact set
// leaves it free. Shared by the rotation and number-field tests.
#ifndef CLASH4D_TESTS_SUPPORT_EXPECTED_NUMBERS_H
#define CLASH4D_TESTS_SUPPORT_EXPECTED_NUMBERS_H

#include <boost/test/unit_test.hpp>
#include "numbers/Algebraic.h"
#include "numbers/Rational.h"
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace clash4d {

// The one root of p (constant term first) in (lo, hi); a test that names
// an interval holding another root, or none, fails here.
inline Algebraic only_root(const std::vector<Rational>& p, const Rational& lo, const Rational& hi)
{
  std::vector<Algebraic> roots = Algebraic::real_roots(p, lo, hi);
  BOOST_REQUIRE_EQUAL(roots.size(), 1u);
  return roots[0];
}

inline Algebraic expected_number(const nlohmann::json& e)
{
  auto q = [](const nlohmann::json& s) { return rational_from_string(s.get<std::string>()); };
  if (e.is_string()) return Algebraic(q(e));
  std::vector<Rational> poly;
  for (const auto& c : e["poly"]) poly.push_back(q(c));
  return only_root(poly, q(e["between"][0]), q(e["between"][1]));
}

inline void check_coordinate(const Algebraic& x, const nlohmann::json& e, const std::string& what)
{
  BOOST_TEST_CONTEXT(what << " = " << x.to_text() << ", expected " << e.dump())
  {
    if (e.is_object() && e.contains("range")) {
      BOOST_TEST(compare(x, rational_from_string(e["range"][0].get<std::string>())) >= 0);
      BOOST_TEST(compare(x, rational_from_string(e["range"][1].get<std::string>())) <= 0);
    } else {
      BOOST_TEST(compare(x, expected_number(e)) == 0);
    }
  }
}

} // namespace clash4d

#endif
