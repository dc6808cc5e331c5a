// xml_escape.hpp (private): escape text for HTML/SVG element content and
// attribute values (& < > " '). Control characters, which XML 1.0 forbids
// (a NUL byte made the page invalid, issue 31), become U+FFFD; tab, line feed
// and carriage return stay.
#pragma once

#include <string>

namespace assess::detail {

inline std::string xml_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r')
          out += "\xEF\xBF\xBD";  // U+FFFD REPLACEMENT CHARACTER
        else
          out += c;
    }
  }
  return out;
}

}  // namespace assess::detail
