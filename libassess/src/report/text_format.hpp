// text_format.hpp (private to the report layer): the two ways the reports
// build a message, both type-safe through {fmt} (Debian's libfmt-dev,
// issue 24): no C varargs, so an argument of the wrong type is a
// fmt::format_error, never undefined behaviour or stray memory in a report.
//   format(literal, args...)  printf-style layout of the text tables (widths,
//                             precisions: "%-*s %8.4f"), by fmt::sprintf;
//   msgf(lang, key, args...)  a catalogue message with "{}" placeholders
//                             (messages.cpp), by fmt::format: a "%" in a
//                             message is text, never a conversion.
//
// Both are also the reports' guard against "inf" and "nan" (issue 31): a
// number that is not finite never reaches the page as inf, -inf, nan or -nan;
// it is shown as unbounded_mark ("—", in the width its column asked for).
// Where an unbounded quantity has a meaning ("non raggiungibile", "no
// overturning") the report says it with finite_or(); the guard covers every
// other place, so that a number that cannot be trusted is never printed as a
// result.
#pragma once

#include "assess/report/messages.hpp"

#include <fmt/format.h>
#include <fmt/printf.h>

#include <cmath>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace assess {

/// What a report prints for a number that is not finite (an em dash).
inline constexpr const char* unbounded_mark = "\xE2\x80\x94";

/// `v` in `layout` (printf-style, one conversion) when finite, else `meaning`
/// ("non raggiungibile", "—", "no overturning"): the one helper for an
/// unbounded quantity shown with its meaning.
inline std::string finite_or(double v, const char* layout, const std::string& meaning) {
  return std::isfinite(v) ? fmt::sprintf(layout, v) : meaning;
}

namespace detail {

template <class T>
bool non_finite(const T& v) {
  if constexpr (std::is_floating_point_v<T>) return !std::isfinite(v);
  else return false;
}

using FormatArg = std::variant<long long, unsigned long long, double, std::string>;

template <class T>
FormatArg to_format_arg(const T& v) {
  if constexpr (std::is_floating_point_v<T>) return static_cast<double>(v);
  else if constexpr (std::is_integral_v<T> && std::is_signed_v<T>) return static_cast<long long>(v);
  else if constexpr (std::is_integral_v<T>) return static_cast<unsigned long long>(v);
  else return std::string(v);
}

// The layout formatted conversion by conversion: a floating conversion
// (%f %e %g %a) of a number that is not finite prints unbounded_mark with
// the conversion's width and alignment; everything else as fmt::sprintf.
// Only taken when some argument is not finite (the usual path is one
// fmt::sprintf call).
inline std::string guarded_sprintf(const char* layout, const std::vector<FormatArg>& args) {
  std::string out;
  std::size_t next = 0;
  auto take = [&]() -> const FormatArg& {
    static const FormatArg none = std::string();
    return next < args.size() ? args[next++] : none;
  };
  auto as_int = [](const FormatArg& a) -> long long {
    if (const auto* i = std::get_if<long long>(&a)) return *i;
    if (const auto* u = std::get_if<unsigned long long>(&a)) return static_cast<long long>(*u);
    return 0;
  };
  for (const char* p = layout; *p;) {
    if (*p != '%') {
      out += *p++;
      continue;
    }
    if (p[1] == '%') {
      out += '%';
      p += 2;
      continue;
    }
    // %[flags][width][.precision][length]conversion, '*' from the arguments.
    std::string spec = "%", flags;
    ++p;
    while (*p && std::string("-+ #0").find(*p) != std::string::npos) flags += *p++;
    spec += flags;
    std::string width;
    if (*p == '*') {
      width = std::to_string(as_int(take()));
      ++p;
    } else {
      while (*p >= '0' && *p <= '9') width += *p++;
    }
    spec += width;
    if (*p == '.') {
      spec += *p++;
      if (*p == '*') {
        spec += std::to_string(as_int(take()));
        ++p;
      } else {
        while (*p >= '0' && *p <= '9') spec += *p++;
      }
    }
    while (*p && std::string("hlLqjzt").find(*p) != std::string::npos) ++p;  // length modifiers: fmt ignores them
    if (!*p) break;
    const char conv = *p++;
    const FormatArg& a = take();
    const bool floating = std::string("fFeEgGaA").find(conv) != std::string::npos;
    if (floating && std::holds_alternative<double>(a) && !std::isfinite(std::get<double>(a))) {
      out += fmt::sprintf("%" + std::string(flags.find('-') != std::string::npos ? "-" : "") + width + "s",
                          std::string(unbounded_mark));
      continue;
    }
    spec += conv;
    out += std::visit([&](const auto& v) { return fmt::sprintf(spec, v); }, a);
  }
  return out;
}

/// A double for msgf: "{}" and "{:.2f}" of a finite number as usual,
/// unbounded_mark otherwise.
struct GuardedDouble {
  double v;
};
template <class T>
decltype(auto) guard_arg(const T& v) {
  if constexpr (std::is_floating_point_v<T>) return GuardedDouble{static_cast<double>(v)};
  else return (v);
}

}  // namespace detail

template <class... Args>
std::string format(const char* layout, const Args&... args) {
  if ((detail::non_finite(args) || ...))
    return detail::guarded_sprintf(layout, std::vector<detail::FormatArg>{detail::to_format_arg(args)...});
  return fmt::sprintf(layout, args...);
}

template <class... Args>
std::string msgf(Lang lang, const std::string& key, const Args&... args) {
  return fmt::format(fmt::runtime(msg(lang, key)), detail::guard_arg(args)...);
}

}  // namespace assess

template <>
struct fmt::formatter<assess::detail::GuardedDouble> : fmt::formatter<double> {
  template <class FormatContext>
  auto format(const assess::detail::GuardedDouble& d, FormatContext& ctx) const -> decltype(ctx.out()) {
    if (std::isfinite(d.v)) return fmt::formatter<double>::format(d.v, ctx);
    return fmt::format_to(ctx.out(), "{}", assess::unbounded_mark);
  }
};
