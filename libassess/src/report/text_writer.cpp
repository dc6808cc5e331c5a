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
    std::vector<std::size_t> w(t.header.size(), 0);
    for (std::size_t j = 0; j < t.header.size(); ++j) w[j] = display_width(t.header[j].text);
    for (const auto& r : t.rows)
      for (std::size_t j = 0; j < r.size(); ++j) w[j] = std::max(w[j], display_width(r[j].text));
    std::size_t total = display_width(indent);
    for (std::size_t x : w) total += x + 2;
    if (total > width) {  // row by row
      for (const auto& r : t.rows) {
        s += indent + "*\n";
        for (std::size_t j = 0; j < r.size(); ++j)
          if (!cell_text(r[j]).empty())
            s += wrap(cell_text(r[j]), width, indent + "    ", indent + "  " + t.header[j].text + ": ");
      }
      return s;
    }
    auto line = [&](const std::vector<Cell>& cells) {
      std::string out = indent;
      for (std::size_t j = 0; j < cells.size(); ++j)
        out += pad(cells[j].text, w[j], !cells[j].numeric) + (j + 1 < cells.size() ? "  " : "");
      while (!out.empty() && out.back() == ' ') out.pop_back();
      return out + "\n";
    };
    s += line(t.header);
    s += indent + std::string(total - display_width(indent) - 2, '-') + "\n";
    for (const auto& r : t.rows) {
      s += line(r);
      for (const Cell& c : r)
        if (!c.note.empty()) s += wrap(c.note, width, indent + "    ", indent + "    ");
    }
    return s;
  }
  std::string block(const Figure& f, const std::string& indent) {
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

std::string to_text(const Document& d, std::size_t width) {
  Writer w{d, width, heading_numbers(d)};
  std::string s = d.title + "\n" + std::string(std::min(display_width(d.title), width), '#') + "\n";
  if (!d.subtitle.empty()) s += wrap(d.subtitle, width, "", "");
  return s + w.blocks(d.blocks, "");
}

}  // namespace assess
