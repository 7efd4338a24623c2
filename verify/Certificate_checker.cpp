#include "verify/Certificate_checker.h"
#include "verify/Turning_checker.h"
#include <algorithm>
#include <functional>

namespace clash4d::verifier {
namespace {

std::array<mpq_class, 5> as_rationals(const std::array<mpz_class, 5>& l)
{
  return {mpq_class(l[0]), mpq_class(l[1]), mpq_class(l[2]), mpq_class(l[3]), mpq_class(l[4])};
}

} // namespace

Certificate_checker::Certificate_checker(const Scene& scene)
  : scene_(scene), t_lo_(scene.t_lo.mpq()), t_hi_(scene.t_hi.mpq())
{
  for (const Scene_object& o : scene.objects) objects_.emplace_back(o);
}

int Certificate_checker::intern(const std::array<mpq_class, 5>& literal)
{
  Literal l = coprime(literal);
  auto it = ids_.find(l);
  if (it != ids_.end()) return it->second;
  Literal neg = l;
  for (mpz_class& c : neg) c = -c;
  int id = static_cast<int>(forms_.size());
  forms_.push_back(l), forms_.push_back(neg);
  ids_.emplace(l, id), ids_.emplace(neg, id + 1);
  return id;
}

// An object's formula on a segment with its atoms as literal ids (2.2).
const Lit_tree& Certificate_checker::tree(int object, int segment)
{
  auto key = std::make_pair(object, segment);
  auto it = trees_.find(key);
  if (it != trees_.end()) return it->second;
  std::function<Lit_tree(const Formula&)> build = [&](const Formula& f) {
    Lit_tree t;
    t.op = f.op;
    if (f.op == Formula::Op::Atom) t.lit = intern(objects_[object].extrude(f.atom, segment));
    for (const Formula& k : f.kids) t.kids.push_back(build(k));
    return t;
  };
  return trees_.emplace(key, build(objects_[object].formula())).first->second;
}

std::string Certificate_checker::check(const Json& cert)
{
  expect_keys(cert, "", {"format", "semantics", "time", "claim", "pairs"}, {"scene"});
  // Section 8: a scene where some object turns needs turning-1, and only it;
  // a turning object is never read as one that rests.
  std::string format = read_text(cert["format"], "format");
  auto turning = std::find_if(objects_.begin(), objects_.end(), [](const Object_model& m) { return m.turns(); });
  if (format == CLASH4D_TURNING_FORMAT) {
    if (turning == objects_.end())
      reject("format", std::string("no object of the scene turns: its certificates are \"clash4d-certificate/1\", not \"") + CLASH4D_TURNING_FORMAT + "\" (section 8)");
    return Turning_checker(scene_, objects_).check(cert);
  }
  if (format != "clash4d-certificate/1")
    throw Cert_failure(CLASH4D_VERIFY_UNREADABLE, "format", "expected \"clash4d-certificate/1\" or \"" + std::string(CLASH4D_TURNING_FORMAT) + "\"");
  if (turning != objects_.end())
    reject("format", "object " + turning->name() + " turns: the scene's certificates are \"" + CLASH4D_TURNING_FORMAT + "\", not \"clash4d-certificate/1\" (section 8)");
  semantics_ = read_text(cert["semantics"], "semantics");
  if (semantics_ != "regularised" && semantics_ != "closed")
    throw Cert_failure(CLASH4D_VERIFY_UNREADABLE, "semantics", "expected \"regularised\" or \"closed\"");
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

// Rules 2-5 of section 3, once every PAIR's own proof holds.
std::string Certificate_checker::check_claim(const Json& claim, const std::vector<Pair_result>& pairs)
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
    if (single && pairs[i].until < pairs[hits[0]].t_star)
      reject(at, "apart until " + text(pairs[i].until) + " only, before t* = " + text(pairs[hits[0]].t_star));
    if (!single && pairs[i].until != t_hi_) reject(at, "apart until " + text(pairs[i].until) + ", not until tH = " + text(t_hi_));
    if (!single && !regularised_ && pairs[i].open_end)
      reject(key_at(index_at("pairs", i), "apart.open_end"), "closed semantics: apart until tH must include t = tH (open_end false)");
  }
  std::string sem = " (" + semantics_ + "): ";
  auto names = [&](const Pair_result& p, const char* sep) { return objects_[p.a].name() + sep + objects_[p.b].name(); };
  std::size_t apart = pairs.size() - hits.size();
  if (!collide) return "verified: no collision in [" + text(t_lo_) + ", " + text(t_hi_) + "]" + sem + plural(apart, "pair") + " apart";
  if (all) {
    std::string s = "verified: colliding pairs" + sem;
    for (std::size_t k = 0; k < hits.size(); ++k)
      s += (k ? ", " : "") + names(pairs[hits[k]], "/") + (earliest ? " at t* = " + text(pairs[hits[k]].t_star) : "");
    return s + "; " + std::to_string(apart) + " other " + (apart == 1 ? "pair" : "pairs") + " apart";
  }
  const Pair_result& p = pairs[hits[0]];
  if (earliest) return "verified: earliest collision" + sem + names(p, " and ") + " at t* = " + text(p.t_star) + ", contact " + text(p.shown);
  return "verified: collision" + sem + names(p, " and ") + " at " + text(p.shown);
}

int Certificate_checker::object_named(const Json& j, const std::string& at)
{
  std::string name = read_text(j, at);
  for (std::size_t i = 0; i < objects_.size(); ++i)
    if (objects_[i].name() == name) return static_cast<int>(i);
  reject(at, "the scene has no object named '" + name + "'");
}

// A PAIR (section 3): rule 1 for its objects, then its own proof.
Certificate_checker::Pair_result Certificate_checker::check_pair(const Json& p, const std::string& at)
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
    r.until = check_apart(p["apart"], key_at(at, "apart"), r.a, r.b, r.open_end);
  } else if (proofs != 1 || p.contains("apart") != p.contains("earliest")) {
    reject(at, "a colliding PAIR holds one of witness, touch, or earliest with apart");
  } else if (p.contains("witness")) {
    if (!regularised_) reject(key_at(at, "witness"), "a witness is for regularised semantics (closed: touch)");
    r.shown = check_witness(p["witness"], key_at(at, "witness"), r.a, r.b);
  } else if (p.contains("touch")) {
    if (regularised_) reject(key_at(at, "touch"), "a touch is for closed semantics (regularised: witness)");
    std::string t = key_at(at, "touch");
    expect_keys(p["touch"], t, {"point", "inside"});
    r.shown = read_point(p["touch"]["point"], key_at(t, "point"));
    if (r.shown[3] < t_lo_ || r.shown[3] > t_hi_) reject(index_at(key_at(t, "point"), 3), "the time is outside [tL, tH]");
    const Json& in = read_array(p["touch"]["inside"], key_at(t, "inside"), 2);
    check_generic(r.shown, in[0], index_at(key_at(t, "inside"), 0), {r.a});
    check_generic(r.shown, in[1], index_at(key_at(t, "inside"), 1), {r.b});
  } else {
    r.earliest = true;
    r.t_star = check_earliest(p["earliest"], key_at(at, "earliest"), r.a, r.b, r.shown);
    r.until = check_apart(p["apart"], key_at(at, "apart"), r.a, r.b, r.open_end);
    if (r.until != r.t_star) reject(key_at(at, "apart.until"), "an earliest proof's apart must end at t* = " + text(r.t_star));
  }
  return r;
}

// tL < T < tH, T no velocity change, both formulas strictly true (section 3).
Point4 Certificate_checker::check_witness(const Json& j, const std::string& at, int a, int b)
{
  Point4 w = read_point(j, at);
  if (!(t_lo_ < w[3] && w[3] < t_hi_)) reject(index_at(at, 3), "a witness's time must lie strictly inside (tL, tH)");
  for (int o : {a, b}) {
    if (objects_[o].is_change(w[3])) reject(index_at(at, 3), "t = " + text(w[3]) + " is a velocity change of " + objects_[o].name());
    if (!objects_[o].strict_true(objects_[o].segment_at(w[3]), w))
      reject(at, "the point " + text(w) + " is not strictly inside " + objects_[o].name());
  }
  return w;
}

// A generic witness w of c for the objects (section 3).
void Certificate_checker::check_generic(const Point4& c, const Json& j, const std::string& at, std::vector<int> objects)
{
  Point4 w = read_point(j, at);
  for (int o : objects) {
    const Object_model& m = objects_[o];
    if (m.change_between(c[3], w[3])) reject(index_at(at, 3), "a velocity change of " + m.name() + " lies between the contact's time and this one");
    // The segment holding the times strictly between c and w; when c.t =
    // w.t (which may be a velocity change) either segment's literals have
    // the same signs there, D being continuous.
    int k = m.segment_at((c[3] + w[3]) / 2);
    if (!m.strict_true(k, w)) reject(at, "the point " + text(w) + " is not strictly inside " + m.name());
    if (!m.signs_follow(k, c, w)) reject(at, "a literal of " + m.name() + " is non-zero at the contact with a sign other than here");
  }
}

mpq_class Certificate_checker::check_earliest(const Json& j, const std::string& at, int a, int b, Point4& contact)
{
  expect_keys(j, at, {"t", "point", "inside"});
  mpq_class t = read_number(j["t"], key_at(at, "t"));
  contact = read_point(j["point"], key_at(at, "point"));
  if (contact[3] != t) reject(index_at(key_at(at, "point"), 3), "the contact's time must equal t*");
  if (t < t_lo_ || t > t_hi_ || (regularised_ && t == t_hi_))
    reject(key_at(at, "t"), std::string("t* must lie in [tL, tH") + (regularised_ ? ")" : "]"));
  std::string in = key_at(at, "inside");
  const Json& w = read_array(j["inside"], in, regularised_ ? 1 : 2);
  if (regularised_) {   // W: a witness after t*, generic for both objects together
    Point4 p = check_witness(w[0], index_at(in, 0), a, b);
    if (!(p[3] > t)) reject(index_at(index_at(in, 0), 3), "the witness's time must be after t*");
    check_generic(contact, w[0], index_at(in, 0), {a, b});
  } else {
    check_generic(contact, w[0], index_at(in, 0), {a});
    check_generic(contact, w[1], index_at(in, 1), {b});
  }
  return t;
}

// Pieces cover [tL, until] contiguously, no velocity change inside (section 3).
mpq_class Certificate_checker::check_apart(const Json& j, const std::string& at, int a, int b, bool& open_end)
{
  expect_keys(j, at, {"until", "pieces"}, {"open_end"});
  mpq_class until = read_number(j["until"], key_at(at, "until"));
  open_end = j.contains("open_end") && read_bool(j["open_end"], key_at(at, "open_end"));
  if (until > t_hi_) reject(key_at(at, "until"), "until is after tH = " + text(t_hi_));
  const Json& pieces = read_array(j["pieces"], key_at(at, "pieces"));
  mpq_class prev = t_lo_;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    std::string pa = index_at(key_at(at, "pieces"), i), ta = key_at(pa, "t");
    expect_keys(pieces[i], pa, {"t", "proof"});
    read_array(pieces[i]["t"], ta, 2);
    mpq_class lo = read_number(pieces[i]["t"][0], index_at(ta, 0)), hi = read_number(pieces[i]["t"][1], index_at(ta, 1));
    if (lo != prev) reject(index_at(ta, 0), "the piece starts at " + text(lo) + ", not at " + text(prev) + (i ? " (the previous piece's end)" : " (tL)"));
    if (!(lo < hi)) reject(index_at(ta, 1), "a piece needs lo < hi");
    for (int o : {a, b})
      if (objects_[o].change_between(lo, hi)) reject(ta, "a velocity change of " + objects_[o].name() + " lies inside the piece");
    mpq_class mid = (lo + hi) / 2;
    Piece piece{a, b, objects_[a].segment_at(mid), objects_[b].segment_at(mid), {}, -1};
    piece.slab = {intern({0, 0, 0, -1, lo}), intern({0, 0, 0, 1, -hi})};   // lo - t, t - hi
    if (open_end && !regularised_ && hi == until) piece.strict_end = piece.slab[1];
    std::vector<int> path;
    check_node(pieces[i]["proof"], key_at(pa, "proof"), piece, path);
    prev = hi;
  }
  if (prev != until) reject(key_at(at, "until"), "the pieces end at " + text(prev) + ", not at until = " + text(until));
  return until;
}

void Certificate_checker::check_node(const Json& j, const std::string& at, const Piece& piece, std::vector<int>& path)
{
  if (!j.is_object() || !j.contains("split")) return check_leaf(j, at, piece, path);
  expect_keys(j, at, {"split", "below", "above"});
  if (path.size() >= 2000) reject(at, "splits nested deeper than 2000");   // section 4: paths grow with depth
  std::array<mpz_class, 5> s = read_literal(j["split"], key_at(at, "split"));
  // The hyperplane s = 0 must be a null set, or a split would prove anything.
  if (s[0] == 0 && s[1] == 0 && s[2] == 0 && s[3] == 0) reject(key_at(at, "split"), "a split needs a non-zero coefficient of x, y, z or t");
  int id = intern(as_rationals(s));
  path.push_back(id);   // s < 0 below, -s < 0 above
  check_node(j["below"], key_at(at, "below"), piece, path);
  path.back() = id ^ 1;
  check_node(j["above"], key_at(at, "above"), piece, path);
  path.pop_back();
}

// Section 4: lambda > 0, sum over the four variables 0, the constant sum's sign.
Leaf_conflict Certificate_checker::check_conflict(const Json& j, const std::string& at, const Piece& piece)
{
  expect_keys(j, at, {"literals", "lambda"}, {"of"});
  Leaf_conflict c;
  std::string of = j.contains("of") ? read_text(j["of"], key_at(at, "of")) : "both";
  if (of != "both" && of != "A" && of != "B") reject(key_at(at, "of"), "of must be \"both\", \"A\" or \"B\"");
  c.of = of == "A" ? Of_A : of == "B" ? Of_B : Of_both;
  const Json& lits = read_array(j["literals"], key_at(at, "literals"));
  const Json& lambda = read_array(j["lambda"], key_at(at, "lambda"));
  if (lits.empty()) reject(key_at(at, "literals"), "a conflict needs at least one literal");
  if (lambda.size() != lits.size()) reject(key_at(at, "lambda"), "lambda needs one multiplier per literal");
  std::array<mpq_class, 5> sum{0, 0, 0, 0, 0};
  bool strict_part = false;
  for (std::size_t i = 0; i < lits.size(); ++i) {
    std::array<mpz_class, 5> l = read_literal(lits[i], index_at(key_at(at, "literals"), i));
    mpq_class m = read_number(lambda[i], index_at(key_at(at, "lambda"), i));
    if (m <= 0) reject(index_at(key_at(at, "lambda"), i), "lambda must be positive");
    for (int k = 0; k < 5; ++k) sum[k] += m * l[k];   // with the literal as written
    c.lits.push_back(intern(as_rationals(l)));
    strict_part = strict_part || c.lits.back() == piece.strict_end;
  }
  // Which literals are there is all the enumeration asks: each id once
  // (a literal repeated N times must not cost N at every step).
  std::sort(c.lits.begin(), c.lits.end());
  c.lits.erase(std::unique(c.lits.begin(), c.lits.end()), c.lits.end());
  const char* var[4] = {"x", "y", "z", "t"};
  for (int k = 0; k < 4; ++k)
    if (sum[k] != 0) reject(at, std::string("the sum of lambda times the ") + var[k] + " coefficients is " + text(sum[k]) + ", not 0");
  // Strict: every literal strict (regularised; closed "of" A or B). Closed "both": non-strict but t - hi.
  bool strict = regularised_ || c.of != Of_both;
  if (sum[4] < 0 || (!strict && sum[4] == 0 && !strict_part))
    reject(at, "the sum of lambda times the constants is " + text(sum[4]) + (strict ? ", below 0" : ", not > 0 and no strict literal has lambda > 0"));
  return c;
}

void Certificate_checker::check_leaf(const Json& j, const std::string& at, const Piece& piece, const std::vector<int>& path)
{
  expect_keys(j, at, {"conflicts"});
  const Json& list = read_array(j["conflicts"], key_at(at, "conflicts"));
  std::vector<Leaf_conflict> conflicts;
  for (std::size_t k = 0; k < list.size(); ++k) conflicts.push_back(check_conflict(list[k], index_at(key_at(at, "conflicts"), k), piece));
  const Lit_tree& fa = tree(piece.a, piece.seg_a);
  const Lit_tree& fb = tree(piece.b, piece.seg_b);
  bool closed;
  try {
    closed = terms_.all_closed(regularised_, fa, fb, path, piece.slab, conflicts, forms_.size());
  } catch (const Step_limit_reached& e) {
    reject_past_step_limit(at, e.what());
  }
  if (!closed) reject(at, "no conflict closes off the term " + describe(terms_.uncovered(), piece));
}

std::string Certificate_checker::describe(const std::vector<std::pair<int, Side>>& term, const Piece& piece) const
{
  const std::string side[4] = {objects_[piece.a].name(), objects_[piece.b].name(), "path", "slab"};
  std::string s = "{";
  for (std::size_t i = 0; i < term.size() && i < 40; ++i)
    s += (i ? ", " : "") + text(forms_[term[i].first]) + " (" + side[term[i].second] + ")";
  if (term.size() > 40) s += ", ... " + std::to_string(term.size() - 40) + " more";
  return s + "} (with the path and the slab; literals [a,b,c,e_t,e] as a x + b y + c z + e_t t + e < 0)";
}

Verify_result verify_certificate(const Scene& scene, const Json& certificate)
{
  Verify_result r;
  try {
    r.claim = Certificate_checker(scene).check(certificate);
    r.ok = true;
  } catch (const Cert_failure& e) {
    r.exit_code = e.exit_code(), r.where = e.where(), r.reason = e.what();
    r.past_step_limit = e.past_step_limit();
  } catch (const std::bad_alloc&) {   // section 6: a limit, nothing proved
    r.exit_code = CLASH4D_VERIFY_LIMIT, r.reason = "out of memory";
  } catch (const std::exception& e) {   // a flaw of the checker: nothing proved
    r.exit_code = CLASH4D_VERIFY_INTERNAL, r.reason = std::string("internal error of the checker: ") + e.what();
  }
  return r;
}

} // namespace clash4d::verifier
