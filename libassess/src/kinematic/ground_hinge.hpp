// ground_hinge.hpp (private to the kinematic layer): the one ground hinge of
// a mechanism that rotates about a single base hinge, as the rotation cap of
// the kinematic analysis and the bearing-part bound of the catalogue need it.
#pragma once

#include "assess/kinematic/chain.hpp"
#include "assess/support/error.hpp"

#include <string>

namespace assess::detail {

/// The chain's single ground hinge. @throws InputError "<what>: the mechanism
/// has more than one ground hinge" or "<what>: the mechanism has no ground hinge".
inline const Constraint& single_ground_hinge(const Chain& chain, const std::string& what) {
  const Constraint* hinge = nullptr;
  for (const Constraint& c : chain.constraints())
    if (c.type == ConstraintType::GroundHinge) {
      if (hinge) throw InputError(what + ": the mechanism has more than one ground hinge");
      hinge = &c;
    }
  if (!hinge) throw InputError(what + ": the mechanism has no ground hinge");
  return *hinge;
}

}  // namespace assess::detail
