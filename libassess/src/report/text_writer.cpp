// text_writer.cpp: Document -> plain text within a width (issue 28, item 12).
#include "assess/report/text_writer.hpp"

#include "report/number_text.hpp"

#include <algorithm>
#include <sstream>

namespace assess {

namespace {

using detail::display_width;
using detail::pad;

// `text` wrapped at `width` display columns, each line prefixed by `prefix`
// (the first by `first` when given).
std::string wrap(const std::string& text, std::size_t width, const std::string& prefix, const std::string& first) {
  std::istringstream in(text);
  std::string word, line = first, out;
  std::size_t used = display_width(first);
  bool empty = true;
  while (in >> word) {
    const std::size_t w = display_width(word);
    if (!empty && used + 1 + w > width) {
      out += line + "\n";
      line = prefix;
      used = display_width(prefix);
      empty = true;
    }
    line += (empty ? "" : " ") + word;
    used += (empty ? 0 : 1) + w;
    empty = false;
  }
  if (!empty || out.empty()) out += line + "\n";
  return out;
}

std::string inline_text(const Inline& text) {
  std::string s;
  for (const Span& x : text) s += x.text;
  return s;
}

std::string cell_text(const Cell& c) { return c.note.empty() ? c.text : c.text + " (" + c.note + ")"; }

struct Writer {
  const Document& d;
  std::size_t width;
  bool figures;
  std::vector<std::string> numbers;
  std::size_t heading = 0;

  std::string blocks(const std::vector<DocBlock>& bs, const std::string& indent) {
    std::string s;
    for (const DocBlock& b : bs) s += std::visit([&](const auto& x) { return block(x, indent); }, b.value);
    return s;
  }
  std::string block(const Heading& h, const std::string& indent) {
    const std::string n = heading < numbers.size() ? numbers[heading] : "";
    ++heading;
    const std::string line = (n.empty() ? "" : n + " ") + h.text;
    std::string s = "\n" + indent + line + "\n";
    if (h.level <= 3) s += indent + std::string(std::min(display_width(line), width), h.level == 2 ? '=' : '-') + "\n";
    return s;
  }
  std::string block(const Paragraph& p, const std::string& indent) {
    return wrap(inline_text(p.text), width, indent, indent);
  }
  std::string block(const List& l, const std::string& indent) {
    std::string s;
    for (const Inline& i : l.items) s += wrap(inline_text(i), width, indent + "  ", indent + "- ");
    return s;
  }
  std::string block(const Table& t, const std::string& indent) {
    std::string s;
    if (!t.caption.empty()) s += wrap(t.caption, width, indent, indent);
    // Column widths of the cells' main text; the notes go under each row.
    const std::size_t n = t.header.size();
    std::vector<std::size_t> w(n, 0), least(n, 0);
    auto widest_word = [](const std::string& text) {
      std::istringstream in(text);
      std::size_t m = 0;
      for (std::string word; in >> word;) m = std::max(m, display_width(word));
      return m;
    };
    for (std::size_t j = 0; j < n; ++j) {
      w[j] = display_width(t.header[j].text);
      least[j] = widest_word(t.header[j].text);
    }
    for (const auto& r : t.rows)
      for (std::size_t j = 0; j < r.size() && j < n; ++j) {
        w[j] = std::max(w[j], display_width(r[j].text));
        // A number is never broken; a text column may wrap at its longest word (at least 8 columns).
        least[j] = std::max(least[j], r[j].numeric ? display_width(r[j].text) : widest_word(r[j].text));
      }
    for (std::size_t j = 0; j < n; ++j) least[j] = std::min(w[j], std::max<std::size_t>(least[j], 8));
    const std::size_t fixed = display_width(indent) + 2 * (n > 0 ? n - 1 : 0);
    auto total = [&] {
      std::size_t x = fixed;
      for (std::size_t v : w) x += v;
      return x;
    };
    // Too wide: the widest text columns wrap within their cells, down to their longest word.
    while (total() > width) {
      std::size_t k = n;
      for (std::size_t j = 0; j < n; ++j)
        if (w[j] > least[j] && (k == n || w[j] > w[k])) k = j;
      if (k == n) break;
      --w[k];
    }
    if (total() > width) {  // even wrapped it does not fit: row by row
      for (const auto& r : t.rows) {
        s += indent + "*\n";
        for (std::size_t j = 0; j < r.size(); ++j)
          if (!cell_text(r[j]).empty())
            s += wrap(cell_text(r[j]), width, indent + "    ", indent + "  " + t.header[j].text + ": ");
      }
      return s;
    }
    // A row: each cell wrapped within its column, the row as tall as its tallest cell.
    auto line = [&](const std::vector<Cell>& cells) {
      std::vector<std::vector<std::string>> lines(cells.size());
      std::size_t height = 1;
      for (std::size_t j = 0; j < cells.size() && j < n; ++j) {
        std::istringstream in(wrap(cells[j].text, w[j], "", ""));
        for (std::string l; std::getline(in, l);) lines[j].push_back(l);
        height = std::max(height, lines[j].size());
      }
      std::string out;
      for (std::size_t k = 0; k < height; ++k) {
        std::string row = indent;
        for (std::size_t j = 0; j < cells.size() && j < n; ++j)
          row += pad(k < lines[j].size() ? lines[j][k] : "", w[j], !cells[j].numeric) + (j + 1 < cells.size() ? "  " : "");
        while (!row.empty() && row.back() == ' ') row.pop_back();
        out += row + "\n";
      }
      return out;
    };
    s += line(t.header);
    s += indent + std::string(total() - display_width(indent), '-') + "\n";
    for (const auto& r : t.rows) {
      s += line(r);
      // Several notes in a row: each named by its column.
      const std::size_t notes = std::size_t(std::count_if(r.begin(), r.end(), [](const Cell& c) { return !c.note.empty(); }));
      for (std::size_t j = 0; j < r.size(); ++j)
        if (!r[j].note.empty())
          s += wrap((notes > 1 && j < n ? t.header[j].text + ": " : std::string()) + r[j].note, width, indent + "    ",
                    indent + "    ");
    }
    return s;
  }
  std::string block(const Figure& f, const std::string& indent) {
    if (!figures) return "";
    return wrap("[" + (f.caption.empty() ? f.id : f.caption) + "]", width, indent + " ", indent);
  }
  std::string block(const Box& b, const std::string& indent) { return blocks(b.content, indent + "| "); }
  std::string block(const Preformatted& p, const std::string& indent) {
    std::string s;
    std::istringstream in(p.text);
    for (std::string l; std::getline(in, l);) s += indent + l + "\n";
    return s;
  }
  std::string block(const Signature& sg, const std::string& indent) {
    std::string s = "\n";
    for (const std::string& l : sg.lines) s += indent + l + "\n\n";
    return s;
  }
  std::string block(const Contents& c, const std::string& indent) {
    std::string s = "\n" + indent + c.title + "\n";
    for (const auto& [h, n] : contents_entries(d, c.depth)) {
      s += wrap(n + " " + h->text, width, indent + std::string(std::size_t(2 * (h->level - 1)), ' '),
                indent + std::string(std::size_t(2 * (h->level - 2)), ' '));
    }
    return s;
  }
  std::string block(const RawHtml&, const std::string&) { return ""; }
};

}  // namespace

std::string to_text(const Document& d, std::size_t width, bool figures) {
  Writer w{d, width, figures, heading_numbers(d)};
  std::string s = d.title + "\n" + std::string(std::min(display_width(d.title), width), '#') + "\n";
  if (!d.subtitle.empty()) s += wrap(d.subtitle, width, "", "");
  return s + w.blocks(d.blocks, "");
}

}  // namespace assess
