// version.hpp: the version of libassess and the stamp of every JSON document
// its front ends print (`assess ... --json`, the Python module `assess`), so
// that both carry the same two keys.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace assess {

/// The project's version ("0.1.0"), as `assess --version` prints it and as
/// the Python module's `assess.__version__`.
const char* version();

/// Version of the JSON documents printed by --json (bumped when a key changes
/// meaning or disappears; new keys do not bump it).
inline constexpr int json_schema_version = 1;

/// Adds "assess_version" and "schema_version" to `j`; returns it.
nlohmann::json& stamp_version(nlohmann::json& j);

/// The last guard on a message shown to a user (issue 31: "-nan" and "TR =
/// inf" in messages): a word inf, -inf, nan or -nan, as std::to_string and
/// iostreams print a number that is not finite, reads "infinite" / "not a
/// number". The messages format their numbers with number_for_message
/// (number_rules.hpp); this catches one that did not. Every front end passes
/// its error and warning messages through it.
std::string plain_numbers(const std::string& message);

}  // namespace assess
