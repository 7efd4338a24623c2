// The literals of one piece of a pair's proof, each once, in the coprime
// integer form the certificate format matches them by (section 2.2).
#ifndef CLASH4D_SEARCH_LITERAL_TABLE_H
#define CLASH4D_SEARCH_LITERAL_TABLE_H

#include "search/Motzkin_lp.h"
#include <map>
#include <vector>

namespace clash4d {

class Literal_table {
public:
  // The id of the literal with these coefficients (any positive multiple).
  int id(Literal_coefficients h)
  {
    scale_to_coprime_integers(h.data(), h.size());
    auto [it, added] = ids_.emplace(h, static_cast<int>(forms_.size()));
    if (added) forms_.push_back(h);
    return it->second;
  }
  // The id of -h, for h an id.
  int negation(int h)
  {
    Literal_coefficients n = forms_[h];
    for (auto& x : n) x = -x;
    return id(n);
  }
  const Literal_coefficients& form(int h) const { return forms_[h]; }
  std::size_t size() const { return forms_.size(); }

private:
  std::map<Literal_coefficients, int> ids_;
  std::vector<Literal_coefficients> forms_;
};

} // namespace clash4d

#endif
