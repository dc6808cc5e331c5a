// svg_text.cpp: text and numbers of the SVG plots (see svg_text.hpp).
#include "report/svg_text.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace assess::detail {

namespace {

constexpr char32_t kReplacement = 0xFFFD;

/// Decodes one code point at s[i] (strict UTF-8: no overlong forms, no
/// surrogates, nothing above U+10FFFF); advances i. Invalid: U+FFFD, one byte.
char32_t next_code_point(const std::string& s, std::size_t& i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  if (c < 0x80) return ++i, c;
  const auto cont = [&](std::size_t k, unsigned char lo = 0x80, unsigned char hi = 0xBF) {
    return k < s.size() && b(k) >= lo && b(k) <= hi;
  };
  if (c >= 0xC2 && c <= 0xDF && cont(i + 1)) {
    const char32_t cp = (char32_t(c & 0x1F) << 6) | (b(i + 1) & 0x3F);
    return i += 2, cp;
  }
  if (c >= 0xE0 && c <= 0xEF) {
    const unsigned char lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
    if (cont(i + 1, lo, hi) && cont(i + 2)) {
      const char32_t cp = (char32_t(c & 0x0F) << 12) | (char32_t(b(i + 1) & 0x3F) << 6) | (b(i + 2) & 0x3F);
      return i += 3, cp;
    }
  }
  if (c >= 0xF0 && c <= 0xF4) {
    const unsigned char lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
    if (cont(i + 1, lo, hi) && cont(i + 2) && cont(i + 3)) {
      const char32_t cp = (char32_t(c & 0x07) << 18) | (char32_t(b(i + 1) & 0x3F) << 12) |
                          (char32_t(b(i + 2) & 0x3F) << 6) | (b(i + 3) & 0x3F);
      return i += 4, cp;
    }
  }
  return ++i, kReplacement;
}

/// The code point as printed: controls blank, non-characters replaced.
char32_t clean(char32_t cp) {
  if (cp < 0x20 || cp == 0x7F || (cp >= 0x80 && cp <= 0x9F)) return U' ';
  if (cp == 0xFFFE || cp == 0xFFFF) return kReplacement;
  return cp;
}

void append_utf8(std::string& out, char32_t cp) {
  if (cp < 0x80) {
    out += char(cp);
  } else if (cp < 0x800) {
    out += char(0xC0 | (cp >> 6));
    out += char(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += char(0xE0 | (cp >> 12));
    out += char(0x80 | ((cp >> 6) & 0x3F));
    out += char(0x80 | (cp & 0x3F));
  } else {
    out += char(0xF0 | (cp >> 18));
    out += char(0x80 | ((cp >> 12) & 0x3F));
    out += char(0x80 | ((cp >> 6) & 0x3F));
    out += char(0x80 | (cp & 0x3F));
  }
}

// Advance widths of DejaVu Sans 2.37 (Debian fonts-dejavu-core), per mille of
// the em, read from the font's hmtx table (2048 units per em): ASCII 32..126,
// Latin-1 160..255 and Greek U+0391..U+03C9.
constexpr std::uint16_t kAscii[95] = {
    318, 401, 460, 838, 636, 950, 780, 275, 390, 390, 500, 838, 318, 361, 318, 337, 636, 636, 636, 636,
    636, 636, 636, 636, 636, 636, 337, 337, 838, 838, 838, 531, 1000, 684, 686, 698, 770, 632, 575, 775,
    752, 295, 295, 656, 557, 863, 748, 787, 603, 787, 695, 635, 611, 732, 684, 989, 685, 611, 685, 390,
    337, 390, 838, 500, 500, 613, 635, 550, 635, 615, 352, 635, 634, 278, 278, 579, 278, 974, 634, 612,
    635, 635, 411, 521, 392, 634, 592, 818, 592, 592, 525, 636, 337, 636, 838};
constexpr std::uint16_t kLatin1[96] = {
    318, 401, 636, 636, 636, 636, 337, 500, 500, 1000, 471, 612, 838, 361, 1000, 500, 500, 838, 401, 401,
    500, 636, 636, 318, 500, 401, 471, 612, 969, 969, 969, 531, 684, 684, 684, 684, 684, 684, 974, 698,
    632, 632, 632, 632, 295, 295, 295, 295, 775, 748, 787, 787, 787, 787, 787, 838, 787, 732, 732, 732,
    732, 611, 605, 630, 613, 613, 613, 613, 613, 613, 982, 550, 615, 615, 615, 615, 278, 278, 278, 278,
    612, 634, 612, 612, 612, 612, 612, 838, 612, 634, 634, 634, 634, 592, 635, 592};
constexpr std::uint16_t kGreek[57] = {
    684, 686, 557, 684, 632, 685, 752, 787, 295, 656, 684, 863, 748, 632, 787, 752, 603, 600, 632, 611,
    611, 787, 685, 787, 764, 295, 611, 659, 541, 634, 338, 579, 659, 638, 592, 612, 541, 544, 634, 612,
    338, 589, 592, 636, 559, 558, 612, 602, 635, 587, 634, 602, 579, 660, 578, 660, 837};

/// Advance width of a code point, per mille of the em.
int advance(char32_t cp) {
  if (cp >= 32 && cp <= 126) return kAscii[cp - 32];
  if (cp >= 0xA0 && cp <= 0xFF) return kLatin1[cp - 0xA0];
  if (cp >= 0x391 && cp <= 0x3C9) return kGreek[cp - 0x391];
  if (cp >= 0x300 && cp <= 0x36F) return 0;  // combining marks
  switch (cp) {
    case 0x2013: return 500;   // en dash
    case 0x2014: return 1000;  // em dash
    case 0x2018: case 0x2019: return 318;
    case 0x201C: case 0x201D: return 518;
    case 0x2026: return 1000;  // ellipsis
    case 0x221A: return 637;   // square root
    case 0x221E: return 833;   // infinity
    default: break;
  }
  if (cp >= 0x2070 && cp <= 0x209F) return 401;  // superscripts and subscripts
  if (cp >= 0x2190 && cp <= 0x22FF) return 838;  // arrows, mathematical operators
  const bool wide = (cp >= 0x1100 && cp <= 0x115F) || (cp >= 0x2E80 && cp <= 0xA4CF) ||
                    (cp >= 0xAC00 && cp <= 0xD7A3) || (cp >= 0xF900 && cp <= 0xFAFF) ||
                    (cp >= 0xFE30 && cp <= 0xFE4F) || (cp >= 0xFF00 && cp <= 0xFF60) ||
                    (cp >= 0xFFE0 && cp <= 0xFFE6) || cp >= 0x1F000;
  return wide ? 1000 : 700;
}

}  // namespace

std::string svg_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const char32_t cp = clean(next_code_point(s, i));
    switch (cp) {
      case U'&': out += "&amp;"; break;
      case U'<': out += "&lt;"; break;
      case U'>': out += "&gt;"; break;
      case U'"': out += "&quot;"; break;
      case U'\'': out += "&#39;"; break;
      default: append_utf8(out, cp);
    }
  }
  return out;
}

double text_width(const std::string& s, double font_size) {
  long units = 0;
  for (std::size_t i = 0; i < s.size();) units += advance(clean(next_code_point(s, i)));
  return font_size * double(units) / 1000.0;
}

std::vector<std::string> wrap_text(const std::string& s, double max_width, double font_size, std::size_t max_lines) {
  std::vector<std::string> words;
  std::string word;
  for (char c : s) {
    if (c == ' ' || (static_cast<unsigned char>(c) < 0x20)) {
      if (!word.empty()) words.push_back(word), word.clear();
    } else {
      word += c;
    }
  }
  if (!word.empty()) words.push_back(word);
  // A word wider than the line is cut between code points.
  std::vector<std::string> pieces;
  for (const std::string& w : words) {
    if (text_width(w, font_size) <= max_width) {
      pieces.push_back(w);
      continue;
    }
    std::string piece;
    double pw = 0.0;
    for (std::size_t i = 0; i < w.size();) {
      const std::size_t start = i;
      const double cw = font_size * advance(clean(next_code_point(w, i))) / 1000.0;
      if (!piece.empty() && pw + cw > max_width) pieces.push_back(piece), piece.clear(), pw = 0.0;
      piece.append(w, start, i - start);
      pw += cw;
    }
    if (!piece.empty()) pieces.push_back(piece);
  }
  words.swap(pieces);
  std::vector<std::string> lines;
  std::string line;
  for (const std::string& w : words) {
    const std::string candidate = line.empty() ? w : line + " " + w;
    if (!line.empty() && text_width(candidate, font_size) > max_width) {
      lines.push_back(line);
      line = w;
    } else {
      line = candidate;
    }
  }
  if (!line.empty()) lines.push_back(line);
  if (max_lines > 0 && lines.size() > max_lines) {  // the last line kept ends in an ellipsis
    lines.resize(max_lines);
    std::string& last = lines.back();
    while (!last.empty() && text_width(last + "…", font_size) > max_width) {
      do last.pop_back();
      while (!last.empty() && (static_cast<unsigned char>(last.back()) & 0xC0) == 0x80);
      if (!last.empty() && static_cast<unsigned char>(last.back()) >= 0xC0) last.pop_back();
    }
    last += "…";
  }
  return lines;
}

void append_hundredths(std::string& out, long long h) {
  if (h < 0) out += '-', h = -h;
  const long long whole = h / 100, frac = h % 100;
  out += std::to_string(whole);
  if (frac != 0) {
    out += '.';
    out += char('0' + frac / 10);
    if (frac % 10 != 0) out += char('0' + frac % 10);
  }
}

void append_coord(std::string& out, double v) {
  // Coordinates are bounded by the clipping (|v| well below 1e12); the
  // guard keeps a wild value from overflowing the integer.
  if (!std::isfinite(v)) v = 0.0;
  v = std::fmax(-1e12, std::fmin(1e12, v));
  append_hundredths(out, std::llround(v * 100.0));
}

std::string coord(double v) {
  std::string s;
  append_coord(s, v);
  return s;
}

}  // namespace assess::detail
