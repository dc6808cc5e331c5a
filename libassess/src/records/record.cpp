// record.cpp: sampled accelerogram helpers.
#include "assess/records/record.hpp"

#include <cmath>

namespace assess {

double Record::pga() const {
  double m = 0.0;
  for (double a : acc) m = std::max(m, std::fabs(a));
  return m;
}

double Record::t_pga() const {
  double m = -1.0;
  std::size_t k = 0;
  for (std::size_t i = 0; i < acc.size(); ++i)
    if (std::fabs(acc[i]) > m) m = std::fabs(acc[i]), k = i;
  return dt * double(k);
}

Record Record::scaled(double factor, bool reverse) const {
  Record r = *this;
  const double f = reverse ? -factor : factor;
  for (double& a : r.acc) a *= f;
  return r;
}

double Record::at(double t) const {
  if (acc.empty() || t < 0.0) return 0.0;
  const double x = t / dt;
  const std::size_t i = static_cast<std::size_t>(x);
  if (i + 1 >= acc.size()) return i + 1 == acc.size() && x - double(i) < 1e-12 ? acc.back() : 0.0;
  const double f = x - double(i);
  return acc[i] + f * (acc[i + 1] - acc[i]);
}

}  // namespace assess
