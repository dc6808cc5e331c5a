// seed_fig2: Fig. 2 of Lipo & de Felice (2017) for the block 2b = 0.25 m,
// 2h = 3 m, 12.06 kN/m^3: (a) moment-rotation curves of the smooth block for
// several Winkler moduli k and of the rigid block; (b) the free-rocking period
// against the amplitude (no dissipation, two-sided). Writes fig2a.svg,
// fig2b.svg and fig2.csv into the folder given (default: .).
// Usage: example_seed_fig2 [OUTDIR]
#include <assess/report/plot.hpp>
#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/support/units.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

using namespace assess;

namespace {
// Period of free rocking from theta0 (two-sided, e = none): 4 x the time of
// the first crossing of theta = 0, from the event-driven integration.
double free_period(const RockingModel& m, double theta0) {
  RockingOptions o;
  o.record_history = true;
  const RockingResult r = analyse_free(m, {theta0, 0.0}, 60.0, o);
  for (std::size_t i = 1; i < r.history.t.size(); ++i)
    if (r.history.theta[i] <= 0.0) return 4.0 * r.history.t[i];
  return NAN;
}
}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : ".";
  const RockingBody body = RockingBody::rectangle(0.25, 3.0, 12.06 * units::kN);
  const double ks[] = {5e7, 1e8, 1e9, 1e10};  // N/m^3
  Plot a;
  a.title = "Moment-rotation, 2b = 0.25 m, 2h = 3 m, 12.06 kN/m3 (seed Fig. 2a)";
  a.x_label = "theta (rad)";
  a.y_label = "M (kN m/m)";
  Plot b;
  b.title = "Free-rocking period against amplitude (seed Fig. 2b)";
  b.x_label = "theta0 / theta_u (-)";
  b.y_label = "T (s)";
  std::ofstream csv(out + "/fig2.csv");
  csv << "k_N_m3,theta_cr_rad,theta_u_rad,peak_moment_Nm_m,capacity_J_m,theta0_over_theta_u,period_s\n";
  auto add = [&](const RockingModel& m, const std::string& name) {
    PlotSeries s{name, {}, {}, PlotSeries::Style::Line};
    const double tu = m.theta_u(+1);
    for (int i = 0; i <= 300; ++i) {
      const double th = tu * i / 300.0;
      s.x.push_back(th);
      s.y.push_back(m.restoring_moment(th) / units::kN);
    }
    a.series.push_back(s);
    PlotSeries p{name, {}, {}, PlotSeries::Style::LinePoints};
    for (double f : {0.02, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95}) {
      const double T = free_period(m, f * tu);
      p.x.push_back(f);
      p.y.push_back(T);
      csv << (m.foundation().is_rigid() ? 0.0 : m.foundation().k) << ',' << m.theta_cr() << ',' << tu << ','
          << m.peak_moment(+1) << ',' << m.capacity() << ',' << f << ',' << T << '\n';
    }
    b.series.push_back(p);
  };
  for (double k : ks) {
    char name[32];
    std::snprintf(name, sizeof name, "k = %.0e N/m3", k);
    add(RockingModel(body, Foundation::winkler(k), Sidedness::two_sided, Restitution::none()), name);
  }
  add(RockingModel(body, Foundation::rigid(), Sidedness::two_sided, Restitution::given(1.0)), "rigid");
  std::ofstream(out + "/fig2a.svg") << render_svg(a);
  std::ofstream(out + "/fig2b.svg") << render_svg(b);
  std::printf("wrote %s/fig2a.svg, fig2b.svg, fig2.csv\n", out.c_str());
  return 0;
}
