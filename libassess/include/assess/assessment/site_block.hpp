// site_block.hpp: a case file's "site" block on its own (the Python module's
// site dictionaries, assess.spectrum and assess.records.select): the same
// keys, defaults and checks as in a case file (docs/user/case-file.md).
#pragma once

#include "assess/hazard/site.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace assess {

/// Parses a site block; errors name `file` and the path within the block
/// (e.g. "site: /soil: ..."). Defined beside the case file's parser (case_file.cpp).
SiteSpec parse_site_block(const nlohmann::json& site, const std::string& file);

}  // namespace assess
