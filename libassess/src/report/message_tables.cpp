// message_tables.cpp: the report's message tables read from the JSON data
// compiled into the library (message_tables.hpp).
#include "report/message_tables.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <stdexcept>
#include <string_view>

namespace assess {

namespace generated {
// cmake/embed.cmake (libassess/CMakeLists.txt): messages/NAME.json as bytes.
extern const unsigned char messages_catalogue[], messages_ties[], messages_building[], messages_mechanisms[],
    messages_phrases_it[];
extern const std::size_t messages_catalogue_size, messages_ties_size, messages_building_size, messages_mechanisms_size,
    messages_phrases_it_size;
}  // namespace generated

namespace detail {

namespace {

nlohmann::json parsed(const std::string& name) {
  struct Data {
    const char* name;
    const unsigned char* bytes;
    const std::size_t* size;
  };
  static const Data data[] = {
      {"catalogue", generated::messages_catalogue, &generated::messages_catalogue_size},
      {"ties", generated::messages_ties, &generated::messages_ties_size},
      {"building", generated::messages_building, &generated::messages_building_size},
      {"mechanisms", generated::messages_mechanisms, &generated::messages_mechanisms_size},
      {"phrases_it", generated::messages_phrases_it, &generated::messages_phrases_it_size},
  };
  for (const Data& d : data)
    if (name == d.name) {
      try {
        return nlohmann::json::parse(d.bytes, d.bytes + *d.size);
      } catch (const nlohmann::json::exception& e) {
        throw std::logic_error("messages/" + name + ".json: " + e.what());
      }
    }
  throw std::logic_error("messages/" + name + ".json: not embedded in the library");
}

std::string text(const nlohmann::json& v, const std::string& where, const char* lang) {
  if (!v.is_object() || !v.contains(lang) || !v.at(lang).is_string())
    throw std::logic_error(where + ": expected {\"it\": text, \"en\": text}");
  return v.at(lang).get<std::string>();
}

}  // namespace

std::map<std::string, Message> message_table(const std::string& name) {
  const nlohmann::json j = parsed(name);
  if (!j.is_object()) throw std::logic_error("messages/" + name + ".json: expected an object key -> message");
  std::map<std::string, Message> out;
  for (const auto& [key, v] : j.items()) {
    const std::string where = "messages/" + name + ".json: " + key;
    out.emplace(key, Message{text(v, where, "it"), text(v, where, "en")});
  }
  return out;
}

std::vector<std::pair<std::string, std::string>> phrase_table(const std::string& name) {
  const nlohmann::json j = parsed(name);
  if (!j.is_array()) throw std::logic_error("messages/" + name + ".json: expected an array of {\"en\", \"it\"}");
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string where = "messages/" + name + ".json: item " + std::to_string(i);
    out.emplace_back(text(j[i], where, "en"), text(j[i], where, "it"));
  }
  return out;
}

}  // namespace detail
}  // namespace assess
