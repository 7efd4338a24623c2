#include "certify/Turning_certificate.h"

#include "certify/Apart_prover.h"
#include "certify/Touch_witness.h"
#include "certify/Turning_prover.h"
#include "certify/Witness_path.h"
#include "exact/Exact_instantiation.h"
#include "scene/Number_json.h"
#include <map>

namespace clash4d {
namespace {

using json = nlohmann::ordered_json;

json rational_point(const std::array<Algebraic, 4>& p)
{
  json out = json::array();
  for (const Algebraic& x : p) {
    if (!x.is_rational()) throw std::logic_error("certificate: a regularised witness that is not rational");
    out.push_back(to_string(x.rational()));
  }
  return out;
}

// x, y, z of a static answer's point, at time t.
json at_time(const std::array<std::string, 4>& p, const Rational& t)
{
  return json::array({p[0], p[1], p[2], to_string(t)});
}

class Turning_writer {
public:
  Turning_writer(const Scene& s, const Rotating_check_answer& a, const Check_options& o)
      : scene_(s), answer_(a), options_(o), closed_(a.semantics == Semantics::closed),
        prover_(s, a.semantics, certificate_step_limit, o.feature_events)
  {
    for (std::size_t i = 0; i < s.objects.size(); ++i) index_[s.objects[i].name] = static_cast<int>(i);
  }

  json run(Certificate_stats* stats)
  {
    std::map<std::pair<int, int>, const Rotating_pair_answer*> colliding;
    if (options_.all_pairs)
      for (const auto& p : answer_.pairs) colliding[key(p)] = &p;
    else if (answer_.reported())
      colliding[key(*answer_.reported())] = answer_.reported();
    // The earliest claim without all pairs: nothing collides before t*.
    first_ = options_.earliest && !options_.all_pairs ? answer_.reported() : nullptr;
    bool every_pair = !answer_.collide || options_.all_pairs || first_;
    json pairs = json::array();
    for (int i = 0; i < static_cast<int>(scene_.objects.size()); ++i)
      for (int j = i + 1; j < static_cast<int>(scene_.objects.size()); ++j) {
        if (scene_.ignored(i, j)) continue;
        auto it = colliding.find({i, j});
        if (it != colliding.end()) pairs.push_back(colliding_entry(*it->second));
        else if (every_pair) pairs.push_back(apart_entry(i, j));
      }
    if (stats) stats->pairs_apart = apart_, stats->conflicts = prover_.conflicts(), stats->steps = prover_.steps();
    return json{{"format", "clash4d-certificate/turning-1"},
                {"scene", scene_.name},
                {"semantics", semantics_name(answer_.semantics)},
                {"time", json::array({to_string(scene_.t_lo), to_string(scene_.t_hi)})},
                {"claim", json{{"collide", answer_.collide}, {"earliest", options_.earliest}, {"all_pairs", options_.all_pairs}}},
                {"pairs", pairs}};
  }

private:
  const Scene& scene_;
  const Rotating_check_answer& answer_;
  const Check_options& options_;
  bool closed_;
  Turning_prover prover_;
  std::map<std::string, int> index_;
  std::size_t apart_ = 0;
  const Rotating_pair_answer* first_ = nullptr;

  std::pair<int, int> key(const Rotating_pair_answer& p) const
  {
    int i = index_.at(p.a), j = index_.at(p.b);
    return {std::min(i, j), std::max(i, j)};
  }

  json colliding_entry(const Rotating_pair_answer& p)
  {
    json e{{"objects", json::array({p.a, p.b})}, {"collide", true}};
    if (options_.earliest) {
      json earliest{{"t", number_json(p.answer.t_star)}};
      json proof = closed_ ? touch(p) : earliest_path(p);
      for (auto& [key, value] : proof.items()) earliest[key] = value;
      e["earliest"] = earliest;
      e["apart"] = prover_.prove(index_.at(p.a), index_.at(p.b), p.answer.t_star, closed_);
    } else if (!closed_) {
      e["witness"] = rational_point(p.answer.witness);
    } else {
      e["touch"] = touch(p);
    }
    return e;
  }

  // Regularised: the path inside both after t*, from the witness at the
  // sample of t*'s critical interval (8.4).
  json earliest_path(const Rotating_pair_answer& p)
  {
    Rotating_object a = Rotating_object::make(scene_.objects[index_.at(p.a)]);
    Rotating_object b = Rotating_object::make(scene_.objects[index_.at(p.b)]);
    std::array<Rational, 3> w;
    for (int k = 0; k < 3; ++k) w[k] = p.answer.witness[k].rational();
    return json{{"path", witness_path(a, b, p.answer.t_star, w, p.answer.witness[3].rational())}};
  }

  // The closed pair at the touch's time, rational: the static closed
  // answer of the posed pair gives the point and its generic witnesses
  // (section 8.4), which are points at that time.
  json touch(const Rotating_pair_answer& p)
  {
    const Algebraic& t = p.answer.witness[3];
    const Scene_object &oa = scene_.objects[index_.at(p.a)], &ob = scene_.objects[index_.at(p.b)];
    if (!t.is_rational())
      return touch_at_irrational(Object_parts(oa, scene_.t_lo, scene_.t_hi), Object_parts(ob, scene_.t_lo, scene_.t_hi), t,
                                 scene_.t_lo, scene_.t_hi);
    Rotating_object a = Rotating_object::make(oa), b = Rotating_object::make(ob);
    Check_options o;
    o.semantics = Semantics::closed;
    Check_answer s = check_exact(posed_pair(a, b, t.rational()), o);
    if (!s.collide) throw std::logic_error("certificate: the closed objects do not meet at the time of their touch");
    const Pair_answer& q = s.pairs.front();
    return json{{"point", at_time(q.witness, t.rational())},
                {"inside", json::array({at_time(q.witness_cells[0], t.rational()), at_time(q.witness_cells[1], t.rational())})}};
  }

  json apart_entry(int i, int j)
  {
    ++apart_;
    return json{{"objects", json::array({scene_.objects[i].name, scene_.objects[j].name})},
                {"collide", false},
                {"apart", first_ ? prover_.prove(i, j, first_->answer.t_star, closed_)
                                 : prover_.prove(i, j, Algebraic(scene_.t_hi), false)}};
  }
};

} // namespace

json make_turning_certificate(const Scene& scene, const Rotating_check_answer& answer, const Check_options& options,
                              Certificate_stats* stats)
{
  if (answer.number == "double") throw std::logic_error("certificates come from an exact kernel (--number exact or rational)");
  try {
    json certificate = Turning_writer(scene, answer, options).run(stats);
    check_before_writing(scene, certificate);
    return certificate;
  } catch (const Term_limit& e) {
    throw Certificate_limit(std::string("certificate too costly to check: ") + e.what() +
                            " (the checker's limit, docs/certificate-format.md section 4)");
  } catch (const Term_feasible& e) {
    throw std::logic_error(std::string("certificate: ") + e.what());
  }
}

} // namespace clash4d
