// number_text.hpp (private to the report layer): a number as a report prints
// it. Reports never print "inf" or "nan" (issues 28, 31): an unbounded
// quantity (a collapse's D/C, an ag the mechanism never reaches) is "∞", an
// undefined one "—"; every other value with the caller's printf layout.
// Padding counts display columns (UTF-8 code points), so "∞" and "—" align
// with the figures of a text table.
#pragma once

#include <fmt/printf.h>

#include <cmath>
#include <cstddef>
#include <string>

namespace assess::detail {

/// Columns a UTF-8 string takes in a terminal (one per code point).
inline std::size_t display_width(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80 ? 1 : 0;
  return n;
}

/// `s` right-aligned (left = false) or left-aligned in `width` display columns.
inline std::string pad(const std::string& s, std::size_t width, bool left = false) {
  const std::size_t w = display_width(s);
  if (w >= width) return s;
  return left ? s + std::string(width - w, ' ') : std::string(width - w, ' ') + s;
}

/// `v` with the printf `layout` ("%.3f"); "∞" for +inf, "-∞" for -inf, "—" for NaN.
inline std::string number_text(double v, const char* layout) {
  if (std::isnan(v)) return "—";
  if (std::isinf(v)) return v > 0 ? "∞" : "-∞";
  return fmt::sprintf(layout, v);
}

/// The same, right-aligned in `width` display columns.
inline std::string number_text(double v, const char* layout, std::size_t width) {
  return pad(number_text(v, layout), width);
}

}  // namespace assess::detail
