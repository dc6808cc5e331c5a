// tie_catalogue.hpp: every constant of the tie-rod model (issues 23, 29) in
// ONE place: steel grades (strengths and the uniform elongation, issue 37),
// partial factors, the capacity-design factors, the ISO metric thread table
// (stress areas, nuts, washers), the bounds of every tie input, and the
// commercial lists of rod diameters and anchor plates the design searches.
// Each value carries its clause or source and a certainty tag as
// code_rules.hpp does: [V-T] seen in a transcription of the official text;
// [V-S] secondary source; [R] recalled, not verified: correct it HERE; [I]
// our choice. docs/theory/ties.md explains each one.
#pragma once

#include <array>
#include <string>

namespace assess::tie_catalogue {

/// A steel grade: characteristic yield and tensile strengths (Pa) and the
/// characteristic uniform elongation eps_uk (the strain at the maximum force,
/// before necking: what a rod yielding along its whole length delivers; issue
/// 37), with its source.
struct SteelGrade {
  const char* name;
  double fyk;             ///< Pa
  double ftk;             ///< Pa
  double eps_uk;          ///< characteristic uniform elongation (fraction)
  const char* eps_source; ///< where eps_uk comes from
};

/// Elastic modulus of steel E = 210 000 MPa: NTC 2018 §11.3.4.1 [R].
inline constexpr double steel_E = 210e9;  // Pa
/// The uniform elongation of a structural steel: eps_u >= 15 eps_y, eps_y =
/// fy / E, the lower bound EN 1993-1-1 §3.2.2(1) requires of every steel it
/// admits (recommended value) [R]: EN 10025-2, the product standard of the S
/// grades, guarantees no uniform elongation; it gives only the elongation
/// after fracture A (26 %, 23 %, 22 % for S235, S275, S355, on 5.65 sqrt(S0)),
/// which includes the necking of a short gauge and overstates what a long rod
/// delivers (issue 37): it is not used.
inline constexpr double eps_u_over_eps_y = 15.0;

/// Structural steels of rods and plates, nominal thickness t <= 40 mm: fyk,
/// ftk of NTC 2018 Tab. 11.3.IX [R] (235/360, 275/430, 355/510 MPa; the
/// EN 10025-2:2019 Tab. 7 values for 3 < t <= 100 mm are lower for ftk, 410
/// and 470 MPa for S275 and S355 [V-S], ties.md §3: the NTC values are used).
/// eps_uk: 15 fyk / E (above) for the S grades; B450C (threaded rebar used as a
/// rod): NTC 2018 §11.3.2.1 Tab. 11.3.Ib, fy,nom 450, ft,nom 540 MPa,
/// (Agt)k >= 7.5 % [R] (Agt is the uniform elongation by definition).
inline constexpr std::array<SteelGrade, 4> steel_grades{{
    {"S235", 235e6, 360e6, eps_u_over_eps_y * 235e6 / steel_E, "EN 1993-1-1 §3.2.2(1): eps_u >= 15 fy/E"},
    {"S275", 275e6, 430e6, eps_u_over_eps_y * 275e6 / steel_E, "EN 1993-1-1 §3.2.2(1): eps_u >= 15 fy/E"},
    {"S355", 355e6, 510e6, eps_u_over_eps_y * 355e6 / steel_E, "EN 1993-1-1 §3.2.2(1): eps_u >= 15 fy/E"},
    {"B450C", 450e6, 540e6, 0.075, "NTC 2018 Tab. 11.3.Ib: (Agt)k >= 7.5 %"},
}};

/// The grade named `name` ("S235", ...); nullptr if unknown.
inline const SteelGrade* find_grade(const std::string& name) {
  for (const SteelGrade& g : steel_grades)
    if (name == g.name) return &g;
  return nullptr;
}

/// Partial factor of the resistance of cross sections gamma_M0 = 1.05:
/// NTC 2018 §4.2.4.1.1 Tab. 4.2.VII [R]; N_pl,Rd = A fyk / gamma_M0 [4.2.6] [R].
inline constexpr double gamma_M0 = 1.05;
/// Partial factor of bolts gamma_M2 = 1.25: NTC 2018 Tab. 4.2.XII [R]. The
/// threaded end of a rod is checked as a bolt in tension, NTC 2018
/// §4.2.8.1.1: F_t,Rd = 0.9 ftb A_res / gamma_M2 [R], with ftb the ftk of the
/// rod's steel [I] (the rod is the bolt).
inline constexpr double gamma_M2 = 1.25;
inline constexpr double thread_k2 = 0.9;
/// Capacity design (gerarchia delle resistenze) of a ductile tie: every
/// brittle capacity (thread, local compression, punching, anchor) at least
/// gamma_Rd gamma_ov A fyk, the rod's plastic resistance on its yield
/// strength amplified for the steel's overstrength. gamma_ov = 1.25:
/// EN 1998-1 §6.1.3(2) (recommended value) and NTC 2008 §7.5.1 [R];
/// NTC 2018 Tab. 7.5.I gives grade-dependent values not above 1.20 [R]: the
/// larger 1.25 is kept [I]. gamma_Rd = 1.1: EN 1998-1 §6.5.5(3),
/// R_d >= 1.1 gamma_ov R_fy for the connections of dissipative members [R].
inline constexpr double gamma_ov = 1.25;
inline constexpr double gamma_Rd = 1.1;
/// Design elongation of a yielding (ductile) rod (issue 37): eps_ud = 0.9
/// eps_uk, the 0.9 of NTC 2018 §4.1.2.1.2.3 (eps_ud = 0.9 eps_uk for
/// reinforcing steel) applied to the uniform elongation of the rod's grade
/// [R]/[I]; the rod yields over its free length L between the ends (upset or
/// welded ends, stronger than the rod by the capacity design), so its ultimate
/// elongation is eps_ud L. A rod threaded on its own diameter is never ductile
/// (its thread is weaker than its body, ties.md §3): no elongation is credited.
inline constexpr double eps_ud_over_eps_uk = 0.9;
/// Corrosion allowance (issue 37): a loss of thickness delta on every face of
/// the rod, its gross section and its thread's stress section reduced to
/// pi/4 (d - 2 delta)^2 in the rod and thread checks. Default 0.5 mm: 50 years
/// at the 0.01 mm/year of a normal atmosphere, EN 1993-5 §4.4 [R] (a rod
/// inside the building, galvanized or painted, loses less) [I]; case key
/// "corrosion_mm" per tie.
inline constexpr double corrosion_loss = 0.5e-3;  // m
/// Temperature action on a rod restrained at both ends (issue 37): the force
/// E A alpha_T dT of a uniform variation dT (NTC 2018 §3.5.5 Tab. 3.5.II,
/// steel structures protected from the weather: +/-15 degC [R]), alpha_T = 12e-6
/// /K (NTC 2018 §3.5.7 Tab. 3.5.III, steel [R]). It is not combined with the
/// earthquake (psi2 = 0 for temperature, NTC 2018 Tab. 2.5.I [R]): the rod and
/// thread are checked in the fundamental combination gamma_P P0 + gamma_Q E A
/// alpha_T dT (gamma_P = 1.0, gamma_Q = 1.5, NTC 2018 Tab. 2.6.I [R]), and the
/// pretension of a new tie must take up the range (P0 >= E A alpha_T dT: the
/// rod, warmed by dT, does not go slack). Case key "delta_T_K" per tie.
inline constexpr double thermal_alpha = 12e-6;   // 1/K
inline constexpr double delta_T = 15.0;          // K
inline constexpr double gamma_P = 1.0, gamma_Q = 1.5;
/// Partial factor of masonry in the checks of the anchor (local compression,
/// punching): gamma_M = 2.0 [I] (the lower end of NTC 2018 Tab. 4.5.II for
/// new masonry, 2.0-3.0 [R]; Circ. 2019 C8.7.1 uses the mean strengths / FC
/// for existing masonry [R]). Overridable per tie ("gamma_M").
inline constexpr double masonry_gamma_M = 2.0;
/// Spread of the punched masonry wedge from the anchor's edge: 45 degrees
/// through the wall's thickness [R] (the usual "cono di punzonamento" of
/// Italian practice; no code formula). Issue 37: the wedge is cut by the
/// wall's crown, its ends, its openings and the wedges of the adjacent ties
/// (ties.md §3.1); its capacity is the shear strength on the lateral surface
/// that lies in masonry.
inline constexpr double punching_angle_deg = 45.0;
/// Sliding of the masonry above the anchor on the bed joint at the anchor's
/// lower edge (issue 37, ties.md §3.2): cohesion f_v0 (default: the tau of the
/// tie's masonry, the lower value of Circ. 2019 Tab. C8.5.I gives f_v0 only
/// for regular masonry, where it exceeds tau0 [I]) and friction mu sigma_n,
/// mu = 0.4 (NTC 2018 §4.5.6.1, f_vk = f_vk0 + 0.4 sigma_n [R]).
inline constexpr double sliding_mu = 0.4;
/// Local compression under the anchor: f_d beta A_b with beta = 1 [I] (no
/// enhancement for a concentrated load; EN 1996-1-1 §6.1.3 allows beta >= 1,
/// NTC 2018 §4.5.6.2 [R]).
inline constexpr double bearing_beta = 1.0;

/// An ISO metric coarse thread: nominal diameter d and pitch P (ISO 261/262),
/// nominal stress area A_s (ISO 898-1:2013 Tab. 4: A_s = pi/4 ((d2 + d3)/2)^2,
/// d2, d3 of ISO 724) [R, checked in the tests against the formula
/// A_s = pi/4 (d - 0.9382 P)^2]; the hexagon nut ISO 4032 (width across flats
/// s, height m) and the plain washer ISO 7089 (outer diameter, thickness) [R].
struct Thread {
  double d;      ///< m
  double P;      ///< m
  double As;     ///< m^2
  double s;      ///< nut width across flats (m)
  double m;      ///< nut height (m)
  double dw;     ///< washer outer diameter (m)
  double hw;     ///< washer thickness (m)
};
inline constexpr std::array<Thread, 17> threads{{
    {0.012, 0.00175, 84.3e-6, 0.018, 0.0108, 0.024, 0.0025},
    {0.014, 0.002, 115e-6, 0.021, 0.0128, 0.028, 0.0025},
    {0.016, 0.002, 157e-6, 0.024, 0.0148, 0.030, 0.003},
    {0.018, 0.0025, 192e-6, 0.027, 0.0155, 0.034, 0.003},
    {0.020, 0.0025, 245e-6, 0.030, 0.018, 0.037, 0.003},
    {0.022, 0.0025, 303e-6, 0.034, 0.0194, 0.039, 0.003},
    {0.024, 0.003, 353e-6, 0.036, 0.0215, 0.044, 0.004},
    {0.027, 0.003, 459e-6, 0.041, 0.0238, 0.050, 0.004},
    {0.030, 0.0035, 561e-6, 0.046, 0.0256, 0.056, 0.004},
    {0.033, 0.0035, 694e-6, 0.050, 0.0287, 0.060, 0.005},
    {0.036, 0.004, 817e-6, 0.055, 0.031, 0.066, 0.005},
    {0.039, 0.004, 976e-6, 0.060, 0.0334, 0.072, 0.006},
    {0.042, 0.0045, 1120e-6, 0.065, 0.034, 0.078, 0.008},
    {0.045, 0.0045, 1310e-6, 0.070, 0.036, 0.085, 0.008},
    {0.048, 0.005, 1470e-6, 0.075, 0.038, 0.092, 0.008},
    {0.052, 0.005, 1760e-6, 0.080, 0.042, 0.098, 0.010},
    {0.056, 0.0055, 2030e-6, 0.085, 0.045, 0.105, 0.010},
}};
/// The thread of nominal diameter d (m, within 0.1 mm); nullptr if the table has none.
inline const Thread* find_thread(double d) {
  for (const Thread& t : threads)
    if (t.d > d - 1e-4 && t.d < d + 1e-4) return &t;
  return nullptr;
}

/// Commercial rod diameters (m) searched by the design, each with an ISO
/// coarse thread of the same nominal diameter (a rod threaded at its ends) [I:
/// a list of the trade's sizes, edit here]. The design starts from
/// min_rod_diameter (case key "min_rod_diameter_mm").
inline constexpr std::array<double, 15> rod_diameters{{0.012, 0.014, 0.016, 0.018, 0.020, 0.022, 0.024, 0.027,
                                                       0.030, 0.033, 0.036, 0.039, 0.042, 0.045, 0.048}};
/// Smallest rod the design proposes: 16 mm [I] (tie rods in historic masonry
/// are 16 mm and up in practice; case key "min_rod_diameter_mm").
inline constexpr double min_rod_diameter = 0.016;
/// An upset end (estremità ringrossata) may be up to this times the rod's
/// diameter [I] (hot upsetting of a round bar; edit here).
inline constexpr double max_upset_ratio = 1.6;

/// A commercial square anchor plate a x a x t (m).
struct Plate {
  double a;  ///< side (m)
  double t;  ///< thickness (m)
};
/// Commercial square anchor plates (capochiave a piastra) searched by the
/// design, smallest first [I: common sizes, edit here].
inline constexpr std::array<Plate, 12> plates{{{0.15, 0.012},
                                              {0.20, 0.015},
                                              {0.25, 0.015},
                                              {0.25, 0.020},
                                              {0.30, 0.020},
                                              {0.30, 0.025},
                                              {0.35, 0.025},
                                              {0.40, 0.025},
                                              {0.40, 0.030},
                                              {0.50, 0.030},
                                              {0.60, 0.035},
                                              {0.70, 0.040}}};

/// A commercial bar anchor (capochiave a paletto, issue 37): a round bar of
/// length a and diameter b laid horizontally along the wall, the rod through
/// its middle [I: common sizes, edit here], shortest first.
struct Bar {
  double a;  ///< length (m)
  double b;  ///< diameter (m)
};
inline constexpr std::array<Bar, 8> bars{{{0.50, 0.040},
                                          {0.60, 0.040},
                                          {0.60, 0.050},
                                          {0.80, 0.050},
                                          {0.80, 0.060},
                                          {1.00, 0.060},
                                          {1.00, 0.070},
                                          {1.20, 0.080}}};

/// Bounds of every tie input (SI), enforced by the case-file reader (with the
/// JSON path and unit) and by Tie::validate(). Chosen to hold every real tie
/// with margin and to keep every capacity and count finite [I].
namespace bounds {
inline constexpr double rod_diameter_min = 0.006, rod_diameter_max = 0.1;    // m
inline constexpr double rod_area_min = 20e-6, rod_area_max = 8000e-6;        // m^2
inline constexpr double fyk_min = 100e6, fyk_max = 1000e6;                   // Pa
inline constexpr double plate_side_min = 0.05, plate_side_max = 2.0;         // m
inline constexpr double plate_t_min = 0.003, plate_t_max = 0.1;              // m
inline constexpr double bar_length_min = 0.1, bar_length_max = 2.0;          // m (paletto)
inline constexpr double bar_diameter_min = 0.01, bar_diameter_max = 0.2;     // m
inline constexpr double fm_min = 0.1e6, fm_max = 50e6;                       // Pa
inline constexpr double tau_min = 1e3, tau_max = 5e6;                        // Pa
inline constexpr double thickness_min = 0.05, thickness_max = 5.0;           // m
inline constexpr double free_length_min = 0.5, free_length_max = 200.0;      // m
inline constexpr double wall_length_min = 0.3, wall_length_max = 500.0;      // m
inline constexpr double spacing_min = 0.1, spacing_max = 500.0;              // m
inline constexpr int count_max = 1000;                                       // ties per level
inline constexpr int levels_max = 16;                                        // tie levels per case
inline constexpr double pretension_max = 1e7;                                // N (1000 t)
inline constexpr double delta_T_max = 80.0;                                  // K
inline constexpr double corrosion_max = 0.01;                                // m (loss per face)
inline constexpr double unit_weight_min = 5e3, unit_weight_max = 40e3;       // N/m^3
inline constexpr double crown_load_max = 1e6;                                // N/m
inline constexpr int openings_max = 100;                                     // per tie level
}  // namespace bounds

}  // namespace assess::tie_catalogue
