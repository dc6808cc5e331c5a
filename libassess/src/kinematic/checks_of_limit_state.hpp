// checks_of_limit_state.hpp (private): the code checks of one limit state
// alone, for the safety index of a check (check_index.cpp), which re-runs its
// check along the hazard axis: the rows of the other limit states are not
// built. The rows it gives are run_code_checks's of that limit state, bit for
// bit (the same function, the other rows skipped).
#pragma once

#include "assess/kinematic/code_checks.hpp"

#include <vector>

namespace assess {
namespace detail {

std::vector<CheckRow> code_checks_of_limit_state(const KinematicResult& r, const CheckInput& in, LimitState ls);

}  // namespace detail
}  // namespace assess
