#include "verify/Turning_checker.h"
#include <algorithm>
#include <functional>

namespace clash4d::verifier {
namespace {

// "[c0, c1, ...]", each number in lowest terms (section 8.5).
std::string list_text(const std::vector<mpq_class>& c)
{
  std::string s = "[";
  for (std::size_t i = 0; i < c.size(); ++i) s += (i ? ", " : "") + text(c[i]);
  return (c.empty() ? s + "0" : s) + "]";
}

std::string poly_text(const Rational_poly& p) { return list_text(p.coefficients()); }

// A FIELD (8.1): a number, or {"at_t": POLY}, that polynomial at the time.
Rational_poly read_field(const Json& j, const std::string& at, std::string& shown)
{
  if (!j.is_object()) {
    mpq_class q = read_number(j, at);
    shown = text(q);
    return Rational_poly::constant(q);
  }
  expect_keys(j, at, {"at_t"});
  Rational_poly p = read_poly(j["at_t"], key_at(at, "at_t"), &shown);
  shown += "(t)";
  return p;
}

} // namespace

// A POLY (8.1): at least one number, from the constant term up.
Rational_poly read_poly(const Json& j, const std::string& at, std::string* shown)
{
  const Json& a = read_array(j, at);
  if (a.empty()) unreadable(at, "a polynomial needs at least one coefficient (section 8.1)");
  std::vector<mpq_class> c;
  for (std::size_t i = 0; i < a.size(); ++i) c.push_back(read_number(a[i], index_at(at, i)));
  if (shown) *shown = list_text(c);
  return Rational_poly(c);
}

// A TIME (8.1): a number, or the one root of an integer poly in (lo, hi).
Real_time read_time(const Json& j, const std::string& at, std::string* shown)
{
  if (!j.is_object()) {
    mpq_class q = read_number(j, at);
    if (shown) *shown = text(q);
    return Real_time(q);
  }
  expect_keys(j, at, {"poly", "between"}, {"approx"});
  if (j.contains("approx")) read_text(j["approx"], key_at(at, "approx"));   // never read as a number
  std::string pa = key_at(at, "poly"), ba = key_at(at, "between");
  const Json& coefficients = read_array(j["poly"], pa);
  if (coefficients.empty()) unreadable(pa, "a polynomial needs at least one coefficient (section 8.1)");
  std::vector<mpq_class> c;
  for (std::size_t i = 0; i < coefficients.size(); ++i) c.push_back(mpq_class(read_integer(coefficients[i], index_at(pa, i))));
  const Json& between = read_array(j["between"], ba, 2);
  mpq_class lo = read_number(between[0], index_at(ba, 0)), hi = read_number(between[1], index_at(ba, 1));
  Rational_poly p(c);
  if (!(lo < hi)) reject(ba, "the interval needs lo < hi");
  if (p.is_zero()) reject(pa, "the zero polynomial defines no time");
  switch (valid_root(p, lo, hi)) {
  case Root_check::root_at_lo: reject(index_at(ba, 0), "the polynomial is zero at " + text(lo));
  case Root_check::root_at_hi: reject(index_at(ba, 1), "the polynomial is zero at " + text(hi));
  case Root_check::not_one_root:
    reject(at, "the polynomial has " + std::to_string(count_roots(p, lo, hi)) + " distinct roots in (" + text(lo) + ", " + text(hi) + "), not exactly one");
  case Root_check::ok: break;
  }
  if (shown) *shown = "root of " + list_text(c) + " in (" + text(lo) + ", " + text(hi) + ")";
  return Real_time(p, lo, hi);
}

Time_point read_time_point(const Json& j, const std::string& at)
{
  const Json& a = read_array(j, at, 4);
  Time_point p;
  std::string shown[4];
  for (std::size_t i = 0; i < 3; ++i) p.xyz[i] = read_field(a[i], index_at(at, i), shown[i]);
  p.t = read_time(a[3], index_at(at, 3), &shown[3]);
  p.text = "(" + shown[0] + ", " + shown[1] + ", " + shown[2] + ", " + shown[3] + ")";
  return p;
}

Turning_checker::Turning_checker(const Scene& scene, const std::vector<Object_model>& models)
  : scene_(scene), t_lo_(scene.t_lo.mpq()), t_hi_(scene.t_hi.mpq())
{
  for (std::size_t i = 0; i < scene.objects.size(); ++i) objects_.emplace_back(scene.objects[i], models[i]);
}

// Section 8.2: the four polynomials times the one positive rational making
// their coefficients coprime integers (trailing zeros are already dropped).
int Turning_checker::intern(const Lit& l)
{
  mpz_class den = 1, g = 0;
  for (const Rational_poly& p : l)
    for (const mpq_class& q : p.coefficients()) mpz_lcm(den.get_mpz_t(), den.get_mpz_t(), q.get_den_mpz_t());
  Form f, neg;
  for (int i = 0; i < 4; ++i)
    for (const mpq_class& q : l[i].coefficients()) {
      f[i].push_back(q.get_num() * (den / q.get_den()));
      mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), f[i].back().get_mpz_t());
    }
  if (g == 0) g = 1;   // no zero LIT comes here (read_lit), but never divide by 0
  for (int i = 0; i < 4; ++i)
    for (mpz_class& c : f[i]) c /= g, neg[i].push_back(-c);
  auto it = ids_.find(f);
  if (it != ids_.end()) return it->second;
  int id = static_cast<int>(forms_.size());
  forms_.push_back(f), forms_.push_back(neg);
  ids_.emplace(f, id), ids_.emplace(neg, id + 1);
  return id;
}

const Lit_tree& Turning_checker::tree(int object, int piece)
{
  auto key = std::make_pair(object, piece);
  auto it = trees_.find(key);
  if (it != trees_.end()) return it->second;
  std::function<Lit_tree(const Formula&)> build = [&](const Formula& f) {
    Lit_tree t;
    t.op = f.op;
    if (f.op == Formula::Op::Atom) t.lit = intern(objects_[object].literal(f.atom, piece));
    for (const Formula& k : f.kids) t.kids.push_back(build(k));
    return t;
  };
  return trees_.emplace(key, build(objects_[object].formula())).first->second;
}

std::string Turning_checker::check(const Json& cert)
{
  expect_keys(cert, "", {"format", "semantics", "time", "claim", "pairs"}, {"scene"});
  if (read_text(cert["format"], "format") != CLASH4D_TURNING_FORMAT)
    unreadable("format", std::string("expected \"") + CLASH4D_TURNING_FORMAT + "\"");
  semantics_ = read_text(cert["semantics"], "semantics");
  if (semantics_ != "regularised" && semantics_ != "closed") unreadable("semantics", "expected \"regularised\" or \"closed\"");
  regularised_ = semantics_ == "regularised";
  if (cert.contains("scene")) read_text(cert["scene"], "scene");
  read_array(cert["time"], "time", 2);
  if (read_number(cert["time"][0], "time[0]") != t_lo_) reject("time[0]", "the scene's span starts at " + text(t_lo_));
  if (read_number(cert["time"][1], "time[1]") != t_hi_) reject("time[1]", "the scene's span ends at " + text(t_hi_));
  expect_keys(cert["claim"], "claim", {"collide", "earliest", "all_pairs"});
  std::vector<Pair_result> pairs;
  std::map<std::pair<int, int>, std::size_t> seen;
  const Json& list = read_array(cert["pairs"], "pairs");
  for (std::size_t i = 0; i < list.size(); ++i) {
    std::string at = index_at("pairs", i);
    pairs.push_back(check_pair(list[i], at));
    auto key = pair_key(pairs.back().a, pairs.back().b);
    if (!seen.emplace(key, i).second)   // rule 1
      reject(key_at(at, "objects"), "the pair appears twice (first at " + index_at("pairs", seen[key]) + ")");
  }
  return check_claim(cert["claim"], pairs);
}

// Rules 2 to 5 of section 3, with TIMEs compared exactly (8.4).
std::string Turning_checker::check_claim(const Json& claim, const std::vector<Pair_result>& pairs)
{
  bool collide = read_bool(claim["collide"], "claim.collide"), earliest = read_bool(claim["earliest"], "claim.earliest");
  bool all = read_bool(claim["all_pairs"], "claim.all_pairs");
  std::vector<std::size_t> hits;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (pairs[i].collide) hits.push_back(i);
  if (collide && hits.empty()) reject("claim.collide", "the claim is a collision but no PAIR collides");
  if (!collide && !hits.empty()) reject("claim.collide", "the claim is no collision but " + index_at("pairs", hits[0]) + " collides");
  for (std::size_t i : hits)
    if (earliest && !pairs[i].earliest) reject(index_at("pairs", i), "the claim is earliest: a colliding PAIR needs an earliest proof");
  bool single = collide && earliest && !all;   // rule 4, second sentence
  if (single && hits.size() != 1) reject(index_at("pairs", hits[1]), "the claim is earliest without all_pairs: exactly one PAIR may collide");
  if (!collide || all || single)   // rules 3 and 4: every pair not ignored has a PAIR
    for (std::size_t i = 0; i < objects_.size(); ++i)
      for (std::size_t j = i + 1; j < objects_.size(); ++j) {
        bool found = scene_.ignored(int(i), int(j));
        for (const Pair_result& p : pairs) found = found || pair_key(p.a, p.b) == std::make_pair(int(i), int(j));
        if (!found) reject("pairs", "no PAIR for " + objects_[i].name() + "/" + objects_[j].name());
      }
  for (std::size_t i = 0; i < pairs.size(); ++i) {   // rule 5, and rule 4's ">= t*"
    if (pairs[i].collide) continue;
    std::string at = key_at(index_at("pairs", i), "apart.until");
    if (single) {
      const Pair_result& hit = pairs[hits[0]];
      if (less(pairs[i].until, hit.t_star)) reject(at, "apart until " + pairs[i].until_text + " only, before t* = " + hit.t_star_text);
      continue;
    }
    if (!equal(pairs[i].until, Real_time(t_hi_))) reject(at, "apart until " + pairs[i].until_text + ", not until tH = " + text(t_hi_));
    if (!regularised_ && pairs[i].open_end)
      reject(key_at(index_at("pairs", i), "apart.open_end"), "closed semantics: apart until tH must include t = tH (open_end false)");
  }
  std::string sem = " (" + semantics_ + "): ";
  auto names = [&](const Pair_result& p, const char* sep) { return objects_[p.a].name() + sep + objects_[p.b].name(); };
  std::size_t apart = pairs.size() - hits.size();
  if (!collide) return "verified: no collision in [" + text(t_lo_) + ", " + text(t_hi_) + "]" + sem + plural(apart, "pair") + " apart";
  if (all) {
    std::string s = "verified: colliding pairs" + sem;
    for (std::size_t k = 0; k < hits.size(); ++k)
      s += (k ? ", " : "") + names(pairs[hits[k]], "/") + (earliest ? " at t* = " + pairs[hits[k]].t_star_text : "");
    return s + "; " + std::to_string(apart) + " other " + (apart == 1 ? "pair" : "pairs") + " apart";
  }
  const Pair_result& p = pairs[hits[0]];
  // 8.5: a regularised earliest proof is a path, and names no contact.
  if (earliest) return "verified: earliest collision" + sem + names(p, " and ") + " at t* = " + p.t_star_text + (p.shown.empty() ? "" : ", contact " + p.shown);
  if (p.shown.empty()) return "verified: collision" + sem + names(p, " and ") + " at t* = " + p.t_star_text;
  return "verified: collision" + sem + names(p, " and ") + " at " + p.shown;
}

int Turning_checker::object_named(const Json& j, const std::string& at)
{
  std::string name = read_text(j, at);
  for (std::size_t i = 0; i < objects_.size(); ++i)
    if (objects_[i].name() == name) return static_cast<int>(i);
  reject(at, "the scene has no object named '" + name + "'");
}

// A PAIR (8.4): rule 1 for its objects, then apart, witness, touch, or
// earliest with apart.
Turning_checker::Pair_result Turning_checker::check_pair(const Json& p, const std::string& at)
{
  expect_keys(p, at, {"objects", "collide"}, {"apart", "witness", "touch", "earliest"});
  Pair_result r;
  std::string objects = key_at(at, "objects");
  read_array(p["objects"], objects, 2);
  r.a = object_named(p["objects"][0], index_at(objects, 0));
  r.b = object_named(p["objects"][1], index_at(objects, 1));
  if (r.a == r.b) reject(objects, "a PAIR names two distinct objects");
  if (scene_.ignored(r.a, r.b)) reject(objects, "the scene ignores this pair");
  r.collide = read_bool(p["collide"], key_at(at, "collide"));
  int proofs = int(p.contains("witness")) + int(p.contains("touch")) + int(p.contains("earliest"));
  if (!r.collide) {
    if (proofs != 0 || !p.contains("apart")) reject(at, "a PAIR with collide false holds apart and nothing else");
    r.until = check_apart(p["apart"], key_at(at, "apart"), r.a, r.b, r.open_end, r.until_text);
  } else if (proofs != 1 || p.contains("apart") != p.contains("earliest")) {
    reject(at, "a colliding PAIR holds one of witness, touch, or earliest with apart");
  } else if (p.contains("earliest")) {
    r.earliest = true;
    r.shown = check_earliest(p["earliest"], key_at(at, "earliest"), r.a, r.b, r.t_star, r.t_star_text);
    r.until = check_apart(p["apart"], key_at(at, "apart"), r.a, r.b, r.open_end, r.until_text);
    if (!equal(r.until, r.t_star))
      reject(key_at(at, "apart.until"), "an earliest proof's apart must end at t* = " + r.t_star_text + ", not at " + r.until_text);
  } else if (p.contains("witness")) {
    if (!regularised_) reject(key_at(at, "witness"), "a witness is for regularised semantics (closed: touch)");
    r.shown = check_witness(p["witness"], key_at(at, "witness"), r.a, r.b);
  } else {
    if (regularised_) reject(key_at(at, "touch"), "a touch is for closed semantics (regularised: witness)");
    r.shown = check_touch(p["touch"], key_at(at, "touch"), r.a, r.b);
  }
  return r;
}

// 8.4: rational, tL < T < tH, T no breakpoint, both formulas strictly true.
std::string Turning_checker::check_witness(const Json& j, const std::string& at, int a, int b)
{
  Point4 w = read_point(j, at);
  if (!(t_lo_ < w[3] && w[3] < t_hi_)) reject(index_at(at, 3), "a witness's time must lie strictly inside (tL, tH)");
  Real_time t(w[3]);
  Field_point p{Rational_poly::constant(w[0]), Rational_poly::constant(w[1]), Rational_poly::constant(w[2])};
  for (int o : {a, b}) {
    if (objects_[o].is_break(w[3])) reject(index_at(at, 3), "t = " + text(w[3]) + " is a breakpoint of " + objects_[o].name());
    if (!objects_[o].strict_true(objects_[o].piece_at(t), p, t))
      reject(at, "the point " + text(w) + " is not strictly inside " + objects_[o].name());
  }
  return text(w);
}

// 8.4: a contact C at a TIME in [tL, tH], generic witnesses WA, WB at its time.
std::string Turning_checker::check_touch(const Json& j, const std::string& at, int a, int b)
{
  expect_keys(j, at, {"point", "inside"});
  std::string pa = key_at(at, "point"), in = key_at(at, "inside");
  Time_point c = read_time_point(j["point"], pa);
  if (less(c.t, Real_time(t_lo_)) || less(Real_time(t_hi_), c.t)) reject(index_at(pa, 3), "the time is outside [tL, tH]");
  const Json& w = read_array(j["inside"], in, 2);
  check_generic(c, w[0], index_at(in, 0), a);
  check_generic(c, w[1], index_at(in, 1), b);
  return c.text;
}

void Turning_checker::check_generic(const Time_point& c, const Json& j, const std::string& at, int o)
{
  Time_point w = read_time_point(j, at);
  const Turning_model& m = objects_[o];
  if (!equal(w.t, c.t)) reject(index_at(at, 3), "a generic witness's time must equal the contact's time");
  // At a breakpoint either piece's literals have the same signs (8.2).
  int k = m.piece_at(c.t);
  if (!m.strict_true(k, w.xyz, c.t)) reject(at, "the point " + w.text + " is not strictly inside " + m.name());
  if (!m.signs_follow(k, c.xyz, w.xyz, c.t)) reject(at, "a literal of " + m.name() + " is non-zero at the contact with a sign other than here");
}

// 8.4's earliest: t* in [tL, tH) with a witness path after it (regularised),
// in [tL, tH] with the touch at t* (closed). Returns the contact's text
// for the verified line, empty for a path (8.5).
std::string Turning_checker::check_earliest(const Json& j, const std::string& at, int a, int b, Real_time& t_star, std::string& t_text)
{
  if (regularised_) expect_keys(j, at, {"t", "path"});
  else expect_keys(j, at, {"t", "point", "inside"});
  std::string ta = key_at(at, "t");
  t_star = read_time(j["t"], ta, &t_text);
  if (less(t_star, Real_time(t_lo_)) || (regularised_ ? !less(t_star, Real_time(t_hi_)) : less(Real_time(t_hi_), t_star)))
    reject(ta, std::string("t* must lie in [tL, tH") + (regularised_ ? ")" : "]") + " = [" + text(t_lo_) + ", " + text(t_hi_) + (regularised_ ? ")" : "]"));
  if (regularised_) {
    check_path(j["path"], key_at(at, "path"), a, b, t_star);
    return "";
  }
  std::string pa = key_at(at, "point"), in = key_at(at, "inside");
  Time_point c = read_time_point(j["point"], pa);
  if (!equal(c.t, t_star)) reject(index_at(pa, 3), "the contact's time must equal t*");
  const Json& w = read_array(j["inside"], in, 2);
  check_generic(c, w[0], index_at(in, 0), a);
  check_generic(c, w[1], index_at(in, 1), b);
  return c.text;
}

// 8.4: W(t) = (x, y, z)(t) / w(t) on (t*, T1] is inside both objects: T1
// rational in (t*, tH), no breakpoint in (t*, T1], w > 0 on (t*, T1], every
// literal's L = n . (x, y, z) + e w non-zero at T1 and without a root in
// (t*, T1), both formulas strictly true at W(T1).
void Turning_checker::check_path(const Json& j, const std::string& at, int a, int b, const Real_time& t_star)
{
  expect_keys(j, at, {"x", "y", "z", "w", "to"});
  Field_point xyz;
  const char* name[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) xyz[i] = read_poly(j[name[i]], key_at(at, name[i]));
  std::string wa = key_at(at, "w"), to = key_at(at, "to");
  Rational_poly w = read_poly(j["w"], wa);
  if (j["to"].is_object()) {
    read_time(j["to"], to);   // its own failures first, at their place
    reject(to, "T1 must be a rational number, not a TIME object (section 8.4)");
  }
  mpq_class t1 = read_number(j["to"], to);
  Real_time end(t1);
  if (!less(t_star, end)) reject(to, "T1 = " + text(t1) + " must be after t*");
  if (!(t1 < t_hi_)) reject(to, "T1 = " + text(t1) + " must be before tH = " + text(t_hi_));
  for (int o : {a, b}) {
    if (objects_[o].is_break(t1)) reject(to, "T1 = " + text(t1) + " is a breakpoint of " + objects_[o].name());
    if (objects_[o].break_between(t_star, end)) reject(to, "a breakpoint of " + objects_[o].name() + " lies between t* and T1");
  }
  // W(t) is needed on (t*, T1] only: w may vanish at t* (a vertex whose
  // planes meet in a line there).
  if (!(w(t1) > 0) || count_roots(w, t_star, end) != 0) reject(wa, "w must be > 0 on (t*, T1]");
  Field_point at_end;
  Point4 shown{xyz[0](t1) / w(t1), xyz[1](t1) / w(t1), xyz[2](t1) / w(t1), t1};
  for (int i = 0; i < 3; ++i) at_end[i] = Rational_poly::constant(shown[i]);
  for (int o : {a, b}) {
    const Turning_model& m = objects_[o];
    int k = m.piece_of(t_star);   // the piece holding (t*, T1)
    for (const Atom& h : m.atoms()) {
      Lit l = m.literal(h, k);
      Rational_poly big_l = l[0] * xyz[0] + l[1] * xyz[1] + l[2] * xyz[2] + l[3] * w;   // n . (x, y, z) + e w
      auto lit_text = [&] { return "[" + poly_text(l[0]) + ", " + poly_text(l[1]) + ", " + poly_text(l[2]) + ", " + poly_text(l[3]) + "]"; };
      if (big_l(t1) == 0) reject(at, "the literal " + lit_text() + " of " + m.name() + " is zero on the path at T1 = " + text(t1));
      if (count_roots(big_l, t_star, end) != 0)
        reject(at, "the literal " + lit_text() + " of " + m.name() + " on the path, " + poly_text(big_l) + ", has a root between t* and T1");
    }
    if (!m.strict_true(k, at_end, end))
      reject(at, "the path's point at T1, " + text(shown) + ", is not strictly inside " + m.name());
  }
}

namespace {

// 8.3's members of a formula: an OR's members are its children's, an AND
// of one child has that child's, any other node is one member.
void members_of(const Lit_tree& t, std::vector<const Lit_tree*>& out)
{
  if (t.op == Formula::Op::Or || (t.op == Formula::Op::And && t.kids.size() == 1)) {
    for (const Lit_tree& k : t.kids) members_of(k, out);
    return;
  }
  out.push_back(&t);
}

std::vector<const Lit_tree*> members_of(const Lit_tree& t)
{
  std::vector<const Lit_tree*> out;
  members_of(t, out);
  return out;
}

} // namespace

// 8.3: pieces cover [tL, until] exactly, no breakpoint inside one; or one
// such cover per pair of members.
Real_time Turning_checker::check_apart(const Json& j, const std::string& at, int a, int b, bool& open_end, std::string& until_text)
{
  expect_keys(j, at, {"until"}, {"open_end", "pieces", "members"});
  Real_time until = read_time(j["until"], key_at(at, "until"), &until_text);
  open_end = j.contains("open_end") && read_bool(j["open_end"], key_at(at, "open_end"));
  if (less(Real_time(t_hi_), until)) reject(key_at(at, "until"), "until is after tH = " + text(t_hi_));
  if (j.contains("pieces") == j.contains("members")) reject(at, "an APART holds one of pieces and members");
  if (j.contains("members")) {
    check_members(j["members"], key_at(at, "members"), a, b, open_end, until, until_text);
    return until;
  }
  std::string end_text;
  Real_time end = check_pieces(j["pieces"], key_at(at, "pieces"), a, b, open_end, -1, -1, end_text);
  if (!equal(end, until)) reject(key_at(at, "until"), "the pieces end at " + end_text + ", not at until = " + until_text);
  return until;
}

// 8.3's members form: one entry per pair of members, each with pieces
// covering [tL, until] whose leaves close off that pair's terms.
void Turning_checker::check_members(const Json& j, const std::string& at, int a, int b, bool open_end,
                                    const Real_time& until, const std::string& until_text)
{
  std::size_t count_a = members_of(tree(a, 0)).size(), count_b = members_of(tree(b, 0)).size();
  const Json& list = read_array(j, at);
  std::vector<bool> seen(count_a * count_b, false);
  for (std::size_t e = 0; e < list.size(); ++e) {
    std::string ea = index_at(at, e);
    expect_keys(list[e], ea, {"a", "b", "pieces"});
    mpq_class ma = read_number(list[e]["a"], key_at(ea, "a")), mb = read_number(list[e]["b"], key_at(ea, "b"));
    if (ma.get_den() != 1 || ma < 0 || ma >= count_a)
      reject(key_at(ea, "a"), "not a member of " + objects_[a].name() + " (it has " + std::to_string(count_a) + ")");
    if (mb.get_den() != 1 || mb < 0 || mb >= count_b)
      reject(key_at(ea, "b"), "not a member of " + objects_[b].name() + " (it has " + std::to_string(count_b) + ")");
    int i = static_cast<int>(ma.get_num().get_si()), k = static_cast<int>(mb.get_num().get_si());
    if (seen[i * count_b + k]) reject(ea, "a second entry for members " + std::to_string(i) + " and " + std::to_string(k));
    seen[i * count_b + k] = true;
    std::string end_text;
    Real_time end = check_pieces(list[e]["pieces"], key_at(ea, "pieces"), a, b, open_end, i, k, end_text);
    if (!equal(end, until)) reject(key_at(ea, "pieces"), "the pieces end at " + end_text + ", not at until = " + until_text);
  }
  for (std::size_t x = 0; x < seen.size(); ++x)
    if (!seen[x])
      reject(at, "no entry for members " + std::to_string(x / count_b) + " of " + objects_[a].name() + " and " +
                     std::to_string(x % count_b) + " of " + objects_[b].name());
}

// Pieces covering [tL, ...] in order (8.3); returns where they end.
Real_time Turning_checker::check_pieces(const Json& j, const std::string& at, int a, int b, bool open_end, int member_a,
                                        int member_b, std::string& end_text)
{
  const Json& pieces = read_array(j, at);
  Real_time prev(t_lo_);
  std::string prev_text = text(t_lo_);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    std::string pa = index_at(at, i), ta = key_at(pa, "t"), lo_text, hi_text;
    expect_keys(pieces[i], pa, {"t", "proof"});
    const Json& t = read_array(pieces[i]["t"], ta, 2);
    Real_time lo = read_time(t[0], index_at(ta, 0), &lo_text), hi = read_time(t[1], index_at(ta, 1), &hi_text);
    if (!equal(lo, prev)) reject(index_at(ta, 0), "the piece starts at " + lo_text + ", not at " + prev_text + (i ? " (the previous piece's end)" : " (tL)"));
    if (!less(lo, hi)) reject(index_at(ta, 1), "a piece needs lo < hi");
    for (int o : {a, b})
      if (objects_[o].break_between(lo, hi)) reject(ta, "a breakpoint of " + objects_[o].name() + " lies inside the piece");
    Piece piece{a, b, objects_[a].piece_of(lo), objects_[b].piece_of(lo), lo, hi, open_end && i + 1 == pieces.size(),
                member_a, member_b};
    const Json& proof = pieces[i]["proof"];
    std::string pp = key_at(pa, "proof");
    if (proof.is_object() && proof.contains("split")) reject(key_at(pp, "split"), "unknown key 'split': a proof of turning-1 is a leaf (section 8.3)");
    check_leaf(proof, pp, piece);
    prev = hi, prev_text = hi_text;
  }
  end_text = prev_text;
  return prev;
}

void Turning_checker::check_leaf(const Json& j, const std::string& at, const Piece& piece)
{
  expect_keys(j, at, {"conflicts"});
  const Json& list = read_array(j["conflicts"], key_at(at, "conflicts"));
  std::vector<Leaf_conflict> conflicts;
  for (std::size_t k = 0; k < list.size(); ++k) conflicts.push_back(check_conflict(list[k], index_at(key_at(at, "conflicts"), k), piece));
  const Lit_tree& whole_a = tree(piece.a, piece.piece_a);
  const Lit_tree& whole_b = tree(piece.b, piece.piece_b);
  const Lit_tree& fa = piece.member_a < 0 ? whole_a : *members_of(whole_a)[piece.member_a];
  const Lit_tree& fb = piece.member_b < 0 ? whole_b : *members_of(whole_b)[piece.member_b];
  bool closed;
  try {   // no path or slab literals: time is a parameter (8.3)
    closed = terms_.all_closed(regularised_, fa, fb, {}, {}, conflicts, forms_.size());
  } catch (const Step_limit_reached& e) {
    reject_past_step_limit(at, e.what());
  }
  if (!closed) reject(at, "no conflict closes off the term " + describe(terms_.uncovered(), piece));
}

Lit Turning_checker::read_lit(const Json& j, const std::string& at)
{
  const Json& a = read_array(j, at, 4);
  Lit l;
  for (std::size_t i = 0; i < 4; ++i) l[i] = read_poly(a[i], index_at(at, i));
  if (l[0].is_zero() && l[1].is_zero() && l[2].is_zero()) reject(at, "a LIT needs a non-zero polynomial of x, y or z (section 8.2)");
  return l;
}

// Section 8.3: identity, lambda >= 0 on the piece, the sum of lambda e.
Leaf_conflict Turning_checker::check_conflict(const Json& j, const std::string& at, const Piece& piece)
{
  expect_keys(j, at, {"literals", "lambda"}, {"of"});
  Leaf_conflict c;
  std::string of = j.contains("of") ? read_text(j["of"], key_at(at, "of")) : "both";
  if (of != "both" && of != "A" && of != "B") reject(key_at(at, "of"), "of must be \"both\", \"A\" or \"B\"");
  c.of = of == "A" ? Of_A : of == "B" ? Of_B : Of_both;
  std::string la = key_at(at, "literals"), lb = key_at(at, "lambda");
  const Json& lits = read_array(j["literals"], la);
  const Json& lambda = read_array(j["lambda"], lb);
  if (lits.empty()) reject(la, "a conflict needs at least one literal");
  if (lambda.size() != lits.size()) reject(lb, "lambda needs one polynomial per literal");
  Lit sum;
  bool some_lambda = false;
  for (std::size_t i = 0; i < lits.size(); ++i) {
    Lit l = read_lit(lits[i], index_at(la, i));
    Rational_poly m = read_poly(lambda[i], index_at(lb, i));
    if (!nonnegative_on(m, piece.lo, piece.hi)) reject(index_at(lb, i), "lambda must be >= 0 on the piece");
    for (int k = 0; k < 4; ++k) sum[k] = sum[k] + m * l[k];   // with the literal as written
    some_lambda = some_lambda || !m.is_zero();
    c.lits.push_back(intern(l));
  }
  std::sort(c.lits.begin(), c.lits.end());
  c.lits.erase(std::unique(c.lits.begin(), c.lits.end()), c.lits.end());
  const char* var[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k)
    if (!sum[k].is_zero())
      reject(at, std::string("the sum of lambda times the ") + var[k] + " polynomials is " + poly_text(sum[k]) + ", not 0");
  if (regularised_ || c.of != Of_both) {   // strict literals
    if (!some_lambda) reject(lb, "every lambda is the zero polynomial");
    if (!nonnegative_on(sum[3], piece.lo, piece.hi))
      reject(at, "the sum of lambda times e, " + poly_text(sum[3]) + ", is not >= 0 on the piece");
  } else if (piece.half_open ? !positive_on_half_open(sum[3], piece.lo, piece.hi) : !positive_on(sum[3], piece.lo, piece.hi)) {
    reject(at, "the sum of lambda times e, " + poly_text(sum[3]) + ", is not > 0 on the piece" + (piece.half_open ? " [lo, hi)" : ""));
  }
  return c;
}

std::string Turning_checker::describe(const std::vector<std::pair<int, Side>>& term, const Piece& piece) const
{
  const std::string side[4] = {objects_[piece.a].name(), objects_[piece.b].name(), "path", "slab"};
  auto form_text = [](const Form& f) {
    std::string s = "[";
    for (int i = 0; i < 4; ++i) {
      s += i ? ",[" : "[";
      for (std::size_t k = 0; k < f[i].size(); ++k) s += (k ? "," : "") + f[i][k].get_str();
      s += f[i].empty() ? "0]" : "]";
    }
    return s + "]";
  };
  std::string s = "{";
  for (std::size_t i = 0; i < term.size() && i < 40; ++i)
    s += (i ? ", " : "") + form_text(forms_[term[i].first]) + " (" + side[term[i].second] + ")";
  if (term.size() > 40) s += ", ... " + std::to_string(term.size() - 40) + " more";
  return s + "} (LITs [n_x, n_y, n_z, e] as polynomials in t, constant term first)";
}

} // namespace clash4d::verifier
