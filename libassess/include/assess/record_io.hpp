// record_io.hpp: TEMPORARY stand-in on branch campaign until branch rocking
// provides the real reader (same signature). PEER AT2 only.
#pragma once

#include "assess/record.hpp"

#include <string>

namespace assess {

/// Reads a PEER AT2 accelerogram (units of g, converted with units::g_n).
/// @throws InputError naming the file and what was wrong
Record read_record(const std::string& path);

}  // namespace assess
