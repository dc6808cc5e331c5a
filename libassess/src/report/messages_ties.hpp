// messages_ties.hpp (private to the report layer): the tie rods' part of the
// message catalogue (issue 29), Italian and English, keys "tie.*"; msg() and
// message_keys() of messages.cpp look them up after the main table.
#pragma once

#include <map>
#include <string>
#include <utility>

namespace assess::detail {

/// key -> (Italian, English).
const std::map<std::string, std::pair<std::string, std::string>>& tie_messages();

}  // namespace assess::detail
