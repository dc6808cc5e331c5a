// Lift-off from rest (RockingModel::lifts): a smooth block centred on its
// Winkler base has no static threshold, so it leaves rest for any ground
// acceleration of the right sign and never at ug = 0 (no lift-off on a
// rounding error); a rigid block lifts only when |ug| > g tan(alpha)
// (rocking.md §1.1), one-sided only outward (ug < 0).
#include <doctest/doctest.h>

#include <assess/dynamics/rocking_model.hpp>
#include <assess/support/units.hpp>

#include <cmath>

using namespace assess;

TEST_CASE("a centred smooth block at rest does not lift at ug = 0 but does for any ug of the right sign") {
  int checked = 0;
  for (double t : {0.13, 0.25, 0.37, 0.5, 0.65, 0.8})
    for (double h : {1.1, 3.0, 4.7, 7.3, 14.57})
      for (double k : {1e8, 1e9, 1e10}) {
        const RockingBody body = RockingBody::rectangle(t, h, 18e3);
        if (!(k > 3 * body.W * 0.5 * h / (2 * std::pow(0.5 * t, 3)))) continue;  // no restoring branch
        for (Sidedness side : {Sidedness::two_sided, Sidedness::one_sided}) {
          const RockingModel m(body, Foundation::winkler(k), side,
                               side == Sidedness::one_sided ? Restitution::given(-0.5) : Restitution::none());
          CAPTURE(t);
          CAPTURE(h);
          CAPTURE(k);
          CHECK_FALSE(m.lifts(+1, 0.0));
          CHECK_FALSE(m.lifts(-1, 0.0));
          CHECK(m.lifts(+1, -1e-6));  // negative ug drives theta positive (outward)
          CHECK_FALSE(m.lifts(+1, +1e-6));
          CHECK(m.lifts(-1, +1e-6) == (side == Sidedness::two_sided));
          ++checked;
        }
      }
  CHECK(checked > 40);
}

TEST_CASE("a rigid block lifts only beyond g tan(alpha), one-sided only outward") {
  const RockingBody body = RockingBody::rectangle(0.4, 2.0, 18e3);  // tan(alpha) = 0.2
  const double a_lift = units::g * 0.2;                             // m/s^2
  const RockingModel two(body, Foundation::rigid(), Sidedness::two_sided, Restitution::housner());
  const RockingModel one(body, Foundation::rigid(), Sidedness::one_sided, Restitution::one_sided_theory());
  CHECK_FALSE(two.lifts(+1, -0.999 * a_lift));
  CHECK(two.lifts(+1, -1.001 * a_lift));
  CHECK(two.lifts(-1, 1.001 * a_lift));
  CHECK_FALSE(two.lifts(-1, 0.999 * a_lift));
  CHECK(one.lifts(+1, -1.001 * a_lift));
  CHECK_FALSE(one.lifts(-1, 1.001 * a_lift));
}
