#include "certify/Certificate_writer.h"

#include "certify/Apart_prover.h"
#include "scene/Files.h"
#include "verify/Certificate_checker.h"
#include <map>

namespace clash4d {
namespace {

using json = nlohmann::ordered_json;

// The answer's numbers are printed by to_string, of any length: read back by
// its inverse, not by the scene reader, whose 1000-character limit is for
// input (issue 59 item 2: a long t* made a right answer an internal error).
Rational rational(const std::string& text)
{
  try {
    return rational_from_string(text);
  } catch (const std::invalid_argument& e) {
    throw std::logic_error(std::string("certificate: the answer's number is not exact: ") + e.what());
  }
}

json point(const std::array<std::string, 4>& p) { return json::array({p[0], p[1], p[2], p[3]}); }

// What the claim says of one colliding pair (section 3, PAIR).
json colliding_entry(const Pair_answer& p, const Check_options& o, bool closed)
{
  json e{{"objects", json::array({p.a, p.b})}, {"collide", true}};
  if (o.earliest) {
    json inside = json::array({point(p.contact_cells[0])});
    if (closed) inside.push_back(point(p.contact_cells[1]));
    e["earliest"] = json{{"t", p.t_star}, {"point", point(p.contact)}, {"inside", inside}};
  } else if (closed) {
    e["touch"] = json{{"point", point(p.witness)},
                      {"inside", json::array({point(p.witness_cells[0]), point(p.witness_cells[1])})}};
  } else {
    e["witness"] = point(p.witness);
  }
  return e;
}

class Writer {
public:
  Writer(const Scene& s, const Check_answer& a, const Check_options& o)
      : scene_(s), answer_(a), options_(o), closed_(a.semantics == Semantics::closed),
        prover_(s, a.semantics, certificate_step_limit)
  {
    for (std::size_t i = 0; i < s.objects.size(); ++i) index_[s.objects[i].name] = static_cast<int>(i);
  }

  json run(Certificate_stats* stats)
  {
    json pairs = json::array();
    std::map<std::pair<int, int>, const Pair_answer*> colliding;
    for (const Pair_answer* p : claimed()) colliding[key(*p)] = p;
    // The earliest claim without all pairs: nothing collides before t*.
    const Pair_answer* first = options_.earliest && !options_.all_pairs ? answer_.reported() : nullptr;
    bool every_pair = !answer_.collide || options_.all_pairs || first;
    for (int i = 0; i < static_cast<int>(scene_.objects.size()); ++i)
      for (int j = i + 1; j < static_cast<int>(scene_.objects.size()); ++j) {
        if (scene_.ignored(i, j)) continue;
        auto it = colliding.find({i, j});
        if (it != colliding.end()) pairs.push_back(with_proof(*it->second));
        else if (every_pair) pairs.push_back(apart_entry(i, j, first));
      }
    if (stats) stats->pairs_apart = apart_, stats->conflicts = prover_.conflicts(), stats->steps = prover_.steps();
    return json{{"format", "clash4d-certificate/1"},
                {"scene", scene_.name},
                {"semantics", semantics_name(answer_.semantics)},
                {"time", json::array({to_string(scene_.t_lo), to_string(scene_.t_hi)})},
                {"claim", json{{"collide", answer_.collide}, {"earliest", options_.earliest}, {"all_pairs", options_.all_pairs}}},
                {"pairs", pairs}};
  }

private:
  const Scene& scene_;
  const Check_answer& answer_;
  const Check_options& options_;
  bool closed_;
  Apart_prover prover_;
  std::map<std::string, int> index_;
  std::size_t apart_ = 0;

  // The colliding pairs the answer claims: all with --all-pairs, else the
  // reported one.
  std::vector<const Pair_answer*> claimed() const
  {
    std::vector<const Pair_answer*> out;
    if (options_.all_pairs)
      for (const auto& p : answer_.pairs) out.push_back(&p);
    else if (answer_.reported())
      out.push_back(answer_.reported());
    return out;
  }

  std::pair<int, int> key(const Pair_answer& p) const
  {
    int i = index_.at(p.a), j = index_.at(p.b);
    return {std::min(i, j), std::max(i, j)};
  }

  // A and B are the answer's order, which "inside" and "of" refer to.
  json with_proof(const Pair_answer& p)
  {
    json e = colliding_entry(p, options_, closed_);
    if (options_.earliest) e["apart"] = prover_.prove(index_.at(p.a), index_.at(p.b), rational(p.t_star), closed_);
    return e;
  }

  // Apart until tH, or before the earliest pair's t* (rule 4: in closed
  // semantics t* itself is left out, another pair may touch then too).
  json apart_entry(int i, int j, const Pair_answer* first)
  {
    ++apart_;
    Rational until = first ? rational(first->t_star) : scene_.t_hi;
    return json{{"objects", json::array({scene_.objects[i].name, scene_.objects[j].name})},
                {"collide", false},
                {"apart", prover_.prove(i, j, until, closed_ && first)}};
  }
};

} // namespace

json make_certificate(const Scene& scene, const Check_answer& answer, const Check_options& options, Certificate_stats* stats)
{
  if (answer.number == "double") throw std::logic_error("certificates come from an exact kernel (--number exact or rational)");
  try {
    Writer writer(scene, answer, options);
    json certificate = writer.run(stats);
    check_before_writing(scene, certificate);
    return certificate;
  } catch (const Term_limit& e) {
    throw Certificate_limit(std::string("certificate too costly to check: ") + e.what() +
                            " (the checker's limit, docs/certificate-format.md section 4)");
  } catch (const Term_feasible& e) {
    throw std::logic_error(std::string("certificate: ") + e.what());
  }
}

// Every certificate is checked here by the independent checker of verify/
// before anyone sees it: never an unproved certificate (a split tree's proof
// is argued on paper, certify/Split_prover.h), nor one the checker would
// refuse as too costly (its steps count conflicts' literal updates, which the
// prover's term search does not: a UR5 pair's 95,398-conflict leaf passed
// the prover's limit and not the checker's).
void check_before_writing(const Scene& scene, const json& certificate)
{
  verifier::Verify_result r = verifier::verify_certificate(scene, verifier::parse_certificate(certificate.dump()));
  if (r.ok) return;
  if (r.past_step_limit)
    throw Certificate_limit("certificate too costly to check: " + r.reason + " (docs/certificate-format.md section 4)");
  throw std::logic_error("certificate: the checker rejects the proof at " + r.where + ": " + r.reason);
}

void write_certificate(const std::string& path, const json& certificate, std::size_t max_bytes, Certificate_stats* stats)
{
  std::string text = certificate.dump(1) + "\n";
  if (text.size() > max_bytes)
    throw Certificate_limit("the certificate would take " + std::to_string(text.size()) + " bytes, over the limit of " +
                            std::to_string(max_bytes) + " (--certificate-max-mb); nothing was written");
  if (stats) stats->bytes = text.size();
  write_file_atomically(path, text);
}

} // namespace clash4d
