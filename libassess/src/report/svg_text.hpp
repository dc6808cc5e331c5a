// svg_text.hpp (private): text and numbers for the SVG plots written by
// render_svg(): user text cleaned and escaped for XML, its width estimated
// from the advance widths of DejaVu Sans (the widest of the common sans-serif
// fonts, so the layout also holds with Liberation Sans, Arial or Helvetica),
// line wrapping, and coordinates with two decimals.
#pragma once

#include <string>
#include <vector>

namespace assess::detail {

/// `s` as XML text: invalid UTF-8 bytes, U+FFFE and U+FFFF become U+FFFD,
/// control characters (C0, DEL, C1) blanks, and & < > " ' entities.
std::string svg_escape(const std::string& s);

/// Width (SVG user units) of `s` set in a sans-serif font of size `font_size`.
double text_width(const std::string& s, double font_size);

/// `s` broken at blanks into lines no wider than `max_width` (a word wider
/// than that is cut between code points). Empty text: no line. With
/// `max_lines` > 0, at most that many lines, the last ending in "…".
std::vector<std::string> wrap_text(const std::string& s, double max_width, double font_size, std::size_t max_lines = 0);

/// Appends v rounded to 0.01 with trailing zeros dropped ("12.5", "-0.05",
/// "3"); never "-0".
void append_coord(std::string& out, double v);
std::string coord(double v);

/// Appends an integer number of hundredths as a decimal ("1234" -> 12.34).
void append_hundredths(std::string& out, long long h);

}  // namespace assess::detail
