// A downstream program: the NTC 2018 return period of SLV for VN = 50, CU = 1.
#include <assess/hazard/seismic_action.hpp>
#include <cmath>
#include <cstdio>
int main() {
  const double tr = assess::return_period(50.0, 1.0, assess::LimitState::SLV);
  std::printf("TR(SLV, VN 50, CU 1) = %.4f years\n", tr);
  return std::fabs(tr - 474.5611) < 1e-3 ? 0 : 1;
}
