// case_default.hpp: a value the case did not give and the engine assumed
// (issue 41: no silent default that moves a number). Every such default is
// listed with its JSON path, its value and what it sets, in the JSON
// ("defaults") and in the relazione's modelling choices; the site's soil has
// none (it is required).
#pragma once

#include <string>
#include <vector>

namespace assess {

struct CaseDefault {
  std::string path;    ///< where the case would give it ("/site/topography")
  std::string value;   ///< the value assumed, with its unit ("T1", "8 %")
  std::string effect;  ///< message key of what it sets ("default.topography": ST = 1 ...)
};

}  // namespace assess
