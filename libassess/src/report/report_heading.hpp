// report_heading.hpp (private): the small pieces both relazioni (façade,
// facade_html.cpp; building, building_html.cpp) write the same way: the code
// edition's name, the date of the report and the case file as shown.
#pragma once

#include <ctime>
#include <filesystem>
#include <string>

namespace assess::detail {

/// "NTC 2008" / "NTC 2018" for "NTC2008" / "NTC2018"; other names as given.
inline std::string code_name(const std::string& code) {
  if (code == "NTC2008") return "NTC 2008";
  if (code == "NTC2018") return "NTC 2018";
  return code;
}

/// Today's date, UTC, "YYYY-MM-DD".
inline std::string today_utc() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char b[16];
  std::strftime(b, sizeof b, "%Y-%m-%d", &tm);
  return b;
}

/// The case file as shown: a relative path as given, an absolute one by its
/// file name only (a signed report carries no machine paths; issue 24).
inline std::string shown_file(const std::string& f) {
  const std::filesystem::path p(f);
  return p.is_absolute() ? p.filename().string() : f;
}

}  // namespace assess::detail
