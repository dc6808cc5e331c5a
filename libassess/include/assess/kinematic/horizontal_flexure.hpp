// horizontal_flexure.hpp: horizontal flexure of a wall strip between two
// transverse walls, the three-hinge horizontal arch (issue 33; "flessione
// orizzontale"; docs/theory/mechanisms.md §1).
//
// A horizontal strip (height h, thickness t) spans the clear distance L
// between two transverse walls. Pushed outward it splits by three vertical
// cracks into two blocks turning about vertical hinges: at the supports on
// the OUTER face, in between on the INNER face. The blocks can only move if
// the supports separate: the arch's thrust H resists. H is limited by the
// masonry's compressive strength at the hinges (stress block of depth a,
// hinges set back, Circ. 2019 C8.7.1.2.1 d) [V-T]) and by the restraint of
// the supports (a tie across the span, the side walls' sliding, a given
// force). With the rectangular block (stress f over a, resultant at a/2) and
// equal sections: H (t - a) = (w + n) L^2 / 8 alpha, H = f h a, so
//   alpha0 = 8 H (t - H/(f h)) / ((w + n) L^2)                         (1.1) [D]
// and the crushing optimum a = t/2, H_c = f h t / 2,
//   alpha0,c = 2 f h t^2 / ((w + n) L^2)                               (1.2) [D]
// (Brady & Brown, voussoir beam, the same statics [V]). The chain is drawn in
// PLAN (Block::weight_in_plane false): x outward, the chain's z = distance
// along the wall from the first support; weights do no work, their masses
// take part. A ring beam bending in plan (simply supported, plastic moment
// M_Rd) adds the constant inward force M_Rd L/(u (L - u)) at the middle hinge.
#pragma once

#include "assess/kinematic/mechanism_catalogue.hpp"

#include <limits>
#include <optional>
#include <vector>

namespace assess {

/// An opening crossing a strip: `from`..`to` along the wall from the first
/// support (m), taking `height` (m) of the strip's height (0 < height < h).
struct StripOpening {
  double from = 0.0, to = 0.0, height = 0.0;
};

/// One horizontal strip of the wall.
struct HorizontalStrip {
  double base_z = 0.0;   ///< bottom of the strip above the foundation (m), >= 0
  double height = 0.0;   ///< h (m), > 0
  /// n: weight per metre of wall carried by the strip whose mass moves with
  /// it (a roof or floor on the top strip) (N/m), >= 0.
  double carried_weight = 0.0;
  std::vector<StripOpening> openings;
  /// The middle hinge's distance from the first support (m), in (0, L);
  /// none: mid-span for a uniform strip, searched (minimum of alpha0) with openings.
  std::optional<double> middle_hinge;
};

enum class StressBlock {
  Rectangular,  ///< stress f over depth a: H = f h a, resultant a/2 from the face
  Triangular,   ///< elastic no-tension: H = f h a / 2, resultant a/3 from the face
};

struct HorizontalFlexureParams {
  double span = 0.0;         ///< L, clear distance between the transverse walls (m)
  double thickness = 0.0;    ///< t (m); of a double-leaf wall, the leaf that forms the arch
  double unit_weight = 0.0;  ///< gamma (N/m^3)
  /// f: the compressive strength at the hinges (N/m^2): the mean strength
  /// divided by the confidence factor (Circ. 2019 C8.7.1.2.1 d), C8.5.4).
  double strength = 0.0;
  StressBlock stress_block = StressBlock::Rectangular;
  /// The supports: rigid abutments (only the masonry's crushing limits H),
  /// or the sum of a tie's design strength across the span at the strip, the
  /// side walls' sliding mu N (each end) and a given restraint force (N).
  bool rigid_supports = false;
  double tie = 0.0;                  ///< N
  double side_wall_friction = 0.0;   ///< mu (-)
  double side_wall_load = 0.0;       ///< N on the side wall's bed joint at the strip, each end (N)
  double restraint = 0.0;            ///< a given restraint force (N)
  double ring_beam_moment = 0.0;     ///< M_Rd of a ring beam in plan at the strip (N m), >= 0
  std::vector<HorizontalStrip> strips;  ///< >= 1; each is a candidate
  /// With openings: the middle hinge searched on this grid along the span,
  /// plus the openings' edges, then refined by golden section.
  int search_points = 19;
};

/// One candidate per strip (the middle hinge at the minimum of alpha0);
/// type "horizontal_flexure", Z = the strip's mid-height.
MechanismSet horizontal_flexure(const HorizontalFlexureParams& p);

/// alpha0 of a strip with its middle hinge at `um` (m from the first
/// support, 0 < um < L), in closed form (docs/theory/mechanisms.md (1.3)):
///   alpha0 = L/(L - u_m) (H z + M_Rd) / (sum_left W_i u_i + u_m/(L - u_m) sum_right W_i (L - u_i))
/// over the segments between the supports, the openings' edges and u_m (W_i
/// their weights with the carried weight, u_i their middles); the same
/// number as the kinematic analysis of the strip's chain, by the virtual
/// work of the same motion. The middle hinge's search uses it.
double strip_alpha0(const HorizontalFlexureParams& p, const HorizontalStrip& s, double um);

/// The thrust of the arch (N) and the depths of the stress blocks (m) at
/// the supports and at the middle hinge for sections of net heights h_s
/// (supports) and h_m (middle hinge).
struct ArchThrust {
  double H = 0.0;          ///< the thrust used: min(H_c, H_lim)
  double H_c = 0.0;        ///< crushing optimum (lever arm t/2)
  double H_lim = 0.0;      ///< the supports' restraint (infinity: rigid)
  double e_support = 0.0;  ///< distance of the support hinges from the outer face (m)
  double e_middle = 0.0;   ///< distance of the middle hinge from the inner face (m)
  bool crushing = false;   ///< H = H_c
};
ArchThrust arch_thrust(const HorizontalFlexureParams& p, double h_support, double h_middle);

}  // namespace assess
