#include "float/Ccd_double_kernel.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace clash4d {

namespace {

// The query's nearest doubles; a number beyond the double range cannot be
// read by this instantiation.
const std::array<Vector3<double>, 8>& double_rows(const Ccd_query& q)
{
  for (std::size_t i = 0; i < 8; ++i)
    for (std::size_t k = 0; k < 3; ++k)
      if (!std::isfinite(q.nearest()[i][k]))
        throw std::range_error("the number " + to_string(q.rows()[i][k]) + " is beyond the range of double");
  return q.nearest();
}

// The roots of g in [0, 1], ascending: the derivative's roots cut [0, 1]
// into pieces where g is monotone, and a piece whose ends' signs differ
// holds one root, found by bisection to the last bit; an end where g is
// exactly zero is a root.
void numeric_roots(const Polynomial<double>& g, std::vector<double>& out)
{
  int size = g.size();
  while (size > 0 && g[size - 1] == 0) --size;
  if (size <= 1) return;
  std::vector<double> cuts{0};
  if (size > 2) numeric_roots(g.derivative(), cuts);
  cuts.push_back(1);
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    double a = cuts[i], b = cuts[i + 1], ga = g.at(a), gb = g.at(b);
    if (ga == 0 && (out.empty() || out.back() != a)) out.push_back(a);
    if (ga == 0 || gb == 0 || (ga > 0) == (gb > 0)) continue;
    for (int step = 0; step < 100; ++step) {
      double m = a + (b - a) / 2;
      if (!(a < m && m < b)) break;
      double gm = g.at(m);
      if (gm == 0) {
        a = b = m;
        break;
      }
      if ((gm > 0) == (ga > 0)) a = m;
      else b = m;
    }
    double root = a + (b - a) / 2;
    if (out.empty() || out.back() < root) out.push_back(root);
  }
  if (g.at(1.0) == 0 && (out.empty() || out.back() != 1)) out.push_back(1);
}

} // namespace

Ccd_double_kernel::Ccd_double_kernel(const Ccd_query& q, double tolerance, double separation)
  : tolerance_(tolerance), separation_(separation), rows_(double_rows(q)),
    p_(q.type(), rows_, separation > 0 ? std::optional<double>(separation * separation) : std::nullopt)
{
}

const std::vector<double>& Ccd_double_kernel::roots(int name)
{
  auto& r = roots_[static_cast<std::size_t>(name)];
  if (!r) {
    r.emplace();
    numeric_roots(p_(name), *r);
  }
  return *r;
}

int Ccd_double_kernel::sign_at(int name, const Time& t)
{
  if (name == t.name) return 0;
  return sign(p_(name).at(t.value));
}

int Ccd_double_kernel::sign_after(int name, const Time& t)
{
  Polynomial<double> g = p_(name);
  for (int order = 0; order < Polynomial<double>::capacity; ++order, g = g.derivative()) {
    int s = order == 0 ? sign_at(name, t) : sign(g.at(t.value));
    if (s != 0) return s;
  }
  return 0;
}

Ccd_double_kernel::Time Ccd_double_kernel::next_time(const Ccd_path& names, const Time& t)
{
  Time best{1, -1};
  for (int name : names)
    for (double r : roots(name))
      if (r > t.value) {
        if (r < best.value) best = {r, name};
        break;
      }
  return best;
}

} // namespace clash4d
