// version.cpp: the project's version and the JSON stamp (support/version.hpp).
#include "assess/support/version.hpp"

#include <cctype>

namespace assess {

const char* version() { return ASSESS_VERSION; }

nlohmann::json& stamp_version(nlohmann::json& j) {
  j["assess_version"] = ASSESS_VERSION;
  j["schema_version"] = json_schema_version;
  return j;
}

std::string plain_numbers(const std::string& m) {
  std::string out;
  auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '/' || c == '\''; };
  for (std::size_t i = 0; i < m.size();) {
    const bool start = i == 0 || !word(m[i - 1]);
    const std::size_t sign = (m[i] == '-') ? 1 : 0;
    if (start && i + sign + 3 <= m.size()) {
      const std::string w = m.substr(i + sign, 3);
      const bool end = i + sign + 3 == m.size() || !word(m[i + sign + 3]);
      if (end && (w == "inf" || w == "nan")) {
        out += w == "nan" ? "not a number" : (sign ? "minus infinite" : "infinite");
        i += sign + 3;
        continue;
      }
    }
    out += m[i++];
  }
  return out;
}

}  // namespace assess
