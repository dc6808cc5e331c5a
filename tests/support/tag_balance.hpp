// tag_balance.hpp: the tests' check that markup (HTML, SVG, WordprocessingML)
// closes every element in order.
#pragma once

#include <regex>
#include <set>
#include <string>
#include <vector>

/// "" when every element of `markup` is closed in order (a self-closed
/// element and a name of `void_tags`, HTML's <br>, <meta> ..., need no end
/// tag), else the first problem ("unexpected </p>", "unclosed <div>").
inline std::string tag_balance(const std::string& markup, const std::set<std::string>& void_tags = {}) {
  static const std::regex tag(R"(<(/?)([A-Za-z][A-Za-z0-9:._-]*)[^>]*?(/?)>)");
  std::vector<std::string> stack;
  for (auto it = std::sregex_iterator(markup.begin(), markup.end(), tag); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[2];
    if (void_tags.count(name) || (*it)[3] == "/") continue;
    if ((*it)[1] == "") {
      stack.push_back(name);
    } else {
      if (stack.empty() || stack.back() != name) return "unexpected </" + name + ">";
      stack.pop_back();
    }
  }
  return stack.empty() ? "" : "unclosed <" + stack.back() + ">";
}
