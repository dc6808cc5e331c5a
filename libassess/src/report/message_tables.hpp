// message_tables.hpp (private to the report layer): the report's message
// tables are data (issue 41, item 6): libassess/src/report/messages/*.json,
// compiled into the library at build time (cmake/embed.cmake; nothing is read
// at run time). A table is an object key -> {"it": ..., "en": ...}; the
// phrase list (phrases_it.json) an array of {"en": ..., "it": ...} in order.
// "{}" in a text is a placeholder of msgf (messages.hpp).
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace assess::detail {

/// One message in the relazione's two languages.
struct Message {
  std::string it, en;
};

/// The table messages/NAME.json ("catalogue", "ties", "building", "mechanisms").
/// @throws std::logic_error for a table the build did not embed or a malformed one.
std::map<std::string, Message> message_table(const std::string& name);

/// The phrase list messages/NAME.json ("phrases_it"): (English, Italian) pairs in order.
std::vector<std::pair<std::string, std::string>> phrase_table(const std::string& name);

}  // namespace assess::detail
