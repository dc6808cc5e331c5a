// tie_catalogue.hpp: every constant of the tie-rod model (issue 23) in ONE
// place: steel grades, partial factors, the steel's modulus and ultimate
// strain, the masonry partial factor, and the commercial lists of rod
// diameters and anchor plates the design searches. Each value carries its
// clause or source and a certainty tag as code_rules.hpp does:
// [V-T] seen in a transcription of the official text; [V-S] secondary
// source; [R] recalled, not verified: correct it HERE; [I] our choice.
// docs/theory/ties.md explains each one.
#pragma once

#include <array>
#include <string>

namespace assess::tie_catalogue {

/// A steel grade: characteristic yield and tensile strengths (Pa) and the
/// minimum elongation at failure of the product standard (fraction).
struct SteelGrade {
  const char* name;
  double fyk;    ///< Pa
  double ftk;    ///< Pa
  double A_min;  ///< elongation after fracture (fraction), informative
};

/// Structural steels of rods and plates, thickness t <= 40 mm: NTC 2018
/// Tab. 11.3.IX (EN 10025-2) [R]; elongation A of EN 10025-2 Tab. 7 [R].
/// B450C reinforcing bar (threaded rebar used as a rod): NTC 2018 §11.3.2.1,
/// fy,nom = 450 MPa, ft,nom = 540 MPa, Agt >= 7.5 % [R].
inline constexpr std::array<SteelGrade, 4> steel_grades{{
    {"S235", 235e6, 360e6, 0.26},
    {"S275", 275e6, 430e6, 0.23},
    {"S355", 355e6, 510e6, 0.22},
    {"B450C", 450e6, 540e6, 0.075},
}};

/// The grade named `name` ("S235", ...); nullptr if unknown.
inline const SteelGrade* find_grade(const std::string& name) {
  for (const SteelGrade& g : steel_grades)
    if (name == g.name) return &g;
  return nullptr;
}

/// Elastic modulus of steel E = 210 000 MPa: NTC 2018 §11.3.4.1 [R].
inline constexpr double steel_E = 210e9;  // Pa
/// Partial factor of the resistance of cross sections gamma_M0 = 1.05:
/// NTC 2018 §4.2.4.1.1 Tab. 4.2.VII [R]; used in N_pl,Rd = A fyk / gamma_M0
/// [4.2.6] (§4.2.4.1.2) [R].
inline constexpr double gamma_M0 = 1.05;
/// Design ultimate strain of the rod, eps_ud = 0.9 eps_uk with eps_uk = 7.5 %
/// (the Agt of B450C, NTC 2018 §11.3.2.1 and §4.1.2.1.2.3 eps_ud = 0.9 eps_uk
/// [R]), used for every grade [I]: structural steels have larger uniform
/// elongations, so this is conservative for them.
inline constexpr double eps_uk = 0.075;
inline constexpr double eps_ud_over_eps_uk = 0.9;
/// Partial factor of masonry in the checks of the anchor (local compression,
/// punching): gamma_M = 2.0 [I] (the lower end of NTC 2018 Tab. 4.5.II for
/// new masonry, 2.0-3.0 [R]; Circ. 2019 C8.7.1 uses the mean strengths / FC
/// for existing masonry [R]). Overridable per tie ("gamma_M").
inline constexpr double masonry_gamma_M = 2.0;
/// Spread of the punched masonry wedge from the anchor's edge: 45 degrees
/// through the wall's thickness [R] (the usual "cono di punzonamento" of
/// Italian practice; no code formula).
inline constexpr double punching_angle_deg = 45.0;

/// Commercial rod diameters (m) searched by the design: the usual sizes of
/// tie rods (tondi / barre filettate) 12-40 mm [I: a list of the trade's
/// common sizes, edit here].
inline constexpr std::array<double, 13> rod_diameters{{0.012, 0.014, 0.016, 0.018, 0.020, 0.022, 0.024, 0.026,
                                                       0.028, 0.030, 0.032, 0.036, 0.040}};

/// A commercial square anchor plate a x a x t (m).
struct Plate {
  double a;  ///< side (m)
  double t;  ///< thickness (m)
};
/// Commercial square anchor plates (capochiave a piastra) searched by the
/// design, smallest first [I: common sizes, edit here].
inline constexpr std::array<Plate, 9> plates{{{0.15, 0.012},
                                             {0.20, 0.015},
                                             {0.25, 0.015},
                                             {0.30, 0.020},
                                             {0.35, 0.020},
                                             {0.40, 0.025},
                                             {0.50, 0.030},
                                             {0.60, 0.030},
                                             {0.70, 0.035}}};

}  // namespace assess::tie_catalogue
