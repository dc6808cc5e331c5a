// text_format.hpp (private to the report layer): the two ways the reports
// build a message, both type-safe through {fmt} (Debian's libfmt-dev,
// issue 24): no C varargs, so an argument of the wrong type is a
// fmt::format_error, never undefined behaviour or stray memory in a report.
//   format(literal, args...)  printf-style layout of the text tables (widths,
//                             precisions: "%-*s %8.4f"), by fmt::sprintf;
//   msgf(lang, key, args...)  a catalogue message with "{}" placeholders
//                             (messages.cpp), by fmt::format: a "%" in a
//                             message is text, never a conversion.
#pragma once

#include "assess/report/messages.hpp"

#include <fmt/format.h>
#include <fmt/printf.h>

#include <string>

namespace assess {

template <class... Args>
std::string format(const char* layout, const Args&... args) {
  return fmt::sprintf(layout, args...);
}

template <class... Args>
std::string msgf(Lang lang, const std::string& key, const Args&... args) {
  return fmt::format(fmt::runtime(msg(lang, key)), args...);
}

}  // namespace assess
