// document.cpp: the document model's builder (issue 28, item 12).
#include "assess/report/document.hpp"

#include "assess/support/error.hpp"

#include <algorithm>
#include <map>
#include <regex>
#include <stdexcept>

namespace assess {

DocumentBuilder::DocumentBuilder(std::string title, std::string lang) {
  doc_.title = std::move(title);
  doc_.lang = std::move(lang);
}

std::string DocumentBuilder::add_heading(const std::string& text, int level, bool new_page, bool numbered,
                                         const std::string& anchor) {
  if (level < 2 || level > 5) throw InputError("report: heading level must be 2..5");
  level += heading_shift_;  // a report nested in another (the building's mechanisms)
  if (level > 6) level = 6;
  Heading h;
  h.level = level;
  h.text = text;
  ++anchors_;
  h.anchor = id_prefix_ + (anchor.empty() ? "sec-" + std::to_string(anchors_) : anchor);
  h.numbered = numbered;
  if (level == 2) {
    h.new_page = has_section_ && new_page;
    has_section_ = true;
  }
  doc_.blocks.push_back(h);
  return h.anchor;
}

void DocumentBuilder::add_paragraph(const std::string& text, const std::string& style) {
  add_paragraph(Inline{Span{text}}, style);
}

void DocumentBuilder::add_paragraph(Inline text, const std::string& style, const std::string& lang) {
  doc_.blocks.push_back(Paragraph{std::move(text), style, lang});
}

void DocumentBuilder::add_list(std::vector<Inline> items, const std::string& style) {
  doc_.blocks.push_back(List{std::move(items), style});
}

void DocumentBuilder::add_table(const std::vector<std::string>& header,
                                const std::vector<std::vector<std::string>>& rows, const std::string& caption) {
  std::vector<Cell> h(header.begin(), header.end());
  std::vector<std::vector<Cell>> r;
  for (const auto& row : rows) r.emplace_back(row.begin(), row.end());
  add_cell_table(h, r, caption);
}

void DocumentBuilder::add_cell_table(const std::vector<Cell>& header, const std::vector<std::vector<Cell>>& rows,
                                     const std::string& caption, const std::string& style) {
  for (const auto& r : rows)
    if (r.size() != header.size())
      throw InputError("report: table row has " + std::to_string(r.size()) + " cells, header has " +
                       std::to_string(header.size()));
  doc_.blocks.push_back(Table{header, rows, caption, style});
}

void DocumentBuilder::check_figure_id(const std::string& id) {
  static const std::regex id_re("[A-Za-z][A-Za-z0-9_-]*");
  if (!std::regex_match(id, id_re)) throw InputError("report: figure id '" + id + "' is not a valid id");
  if (std::find(figure_ids_.begin(), figure_ids_.end(), id) != figure_ids_.end())
    throw InputError("report: duplicate figure id '" + id + "'");
  figure_ids_.push_back(id);
}

namespace {
void check_svg(const std::string& svg, const std::string& id) {
  const auto begin = svg.find("<svg");
  const auto end = svg.rfind("</svg>");
  if (begin == std::string::npos || end == std::string::npos || end < begin)
    throw InputError("report: figure '" + id + "' is not an SVG document");
}
}  // namespace

void DocumentBuilder::add_svg(const std::string& svg, const std::string& caption, const std::string& id_in) {
  const std::string id = id_prefix_ + id_in;
  check_figure_id(id);
  check_svg(svg, id);
  doc_.blocks.push_back(Figure{id, caption, {Panel{svg, ""}}, false});
}

void DocumentBuilder::add_svg_grid(const std::vector<std::pair<std::string, std::string>>& svgs,
                                   const std::string& caption, const std::string& id_in) {
  const std::string id = id_prefix_ + id_in;
  check_figure_id(id);
  Figure f{id, caption, {}, true};
  for (const auto& [svg, label] : svgs) {
    check_svg(svg, id);
    f.panels.push_back(Panel{svg, label});
  }
  doc_.blocks.push_back(std::move(f));
}

void DocumentBuilder::add_pre(const std::string& text) { doc_.blocks.push_back(Preformatted{text}); }

void DocumentBuilder::add_box(Box box) { doc_.blocks.push_back(std::move(box)); }

void DocumentBuilder::add_signature(std::vector<std::string> lines) { doc_.blocks.push_back(Signature{std::move(lines)}); }

void DocumentBuilder::add_contents(const std::string& title, int depth) { doc_.blocks.push_back(Contents{title, depth}); }

void DocumentBuilder::add_raw_html(const std::string& html) { doc_.blocks.push_back(RawHtml{html}); }

void DocumentBuilder::add_block(DocBlock b) { doc_.blocks.push_back(std::move(b)); }

std::vector<DocBlock> DocumentBuilder::take_blocks() {
  std::vector<DocBlock> out;
  out.swap(doc_.blocks);
  return out;
}

std::string plain_text(const Inline& text) {
  std::string s;
  for (const Span& x : text) s += x.text;
  return s;
}

std::vector<std::string> heading_numbers(const Document& d) {
  std::vector<std::string> out;
  int count[7] = {0, 0, 0, 0, 0, 0, 0};
  for (const DocBlock& b : d.blocks) {
    const Heading* h = std::get_if<Heading>(&b.value);
    if (!h) continue;
    if (!h->numbered || h->level < 2) {
      out.push_back("");
      continue;
    }
    ++count[h->level];
    for (int l = h->level + 1; l < 7; ++l) count[l] = 0;
    std::string n;
    for (int l = 2; l <= h->level; ++l) n += (n.empty() ? "" : ".") + std::to_string(count[l]);
    out.push_back(d.number_prefix + n);
  }
  return out;
}

namespace {

// The anchors of a document: a heading's with its number, a figure's with none.
struct Anchors {
  std::map<std::string, std::string> number;  // anchor -> section number ("" unnumbered, figure)
  std::map<std::string, bool> heading;
};

// (heading_numbers counts the document's own headings, not those of a box.)
void collect(const std::vector<DocBlock>& blocks, const std::vector<std::string>& numbers, std::size_t& k, Anchors& a,
             bool top = true) {
  for (const DocBlock& b : blocks) {
    if (const Heading* h = std::get_if<Heading>(&b.value)) {
      a.number[h->anchor] = top && k < numbers.size() ? numbers[k] : "";
      a.heading[h->anchor] = true;
      if (top) ++k;
    } else if (const Figure* f = std::get_if<Figure>(&b.value)) {
      a.number[f->id] = "";
      a.heading[f->id] = false;
    } else if (const Box* x = std::get_if<Box>(&b.value)) {
      collect(x->content, numbers, k, a, false);
    }
  }
}

struct Resolver {
  const std::map<std::string, Anchors>& anchors;
  const Document& self;

  void fix(std::string& text, const std::string& link, const std::string& doc) const {
    if (link.empty()) {
      if (text.find(section_number_mark) != std::string::npos)
        throw std::logic_error("report: '" + text + "' asks for a section number without a link");
      return;
    }
    const std::string key = doc.empty() ? self.key : doc;
    const auto d = anchors.find(key);
    if (d == anchors.end()) throw std::logic_error("report: reference '" + text + "' to an unknown document '" + doc + "'");
    const auto n = d->second.number.find(link);
    if (n == d->second.number.end())
      throw std::logic_error("report: reference '" + text + "' to '#" + link + "'" + (doc.empty() ? "" : " of '" + doc + "'") +
                             " does not resolve");
    const std::size_t at = text.find(section_number_mark);
    if (at == std::string::npos) return;
    if (n->second.empty())
      throw std::logic_error("report: reference '" + text + "' asks the number of '#" + link + "', which has none");
    text.replace(at, std::string(section_number_mark).size(), n->second);
  }
  void blocks(std::vector<DocBlock>& bs) const {
    for (DocBlock& b : bs) {
      if (Paragraph* p = std::get_if<Paragraph>(&b.value)) spans(p->text);
      else if (List* l = std::get_if<List>(&b.value))
        for (Inline& i : l->items) spans(i);
      else if (Table* t = std::get_if<Table>(&b.value)) {
        for (Cell& c : t->header) fix(c.text, c.link, c.doc);
        for (auto& r : t->rows)
          for (Cell& c : r) fix(c.text, c.link, c.doc);
      } else if (Box* x = std::get_if<Box>(&b.value))
        blocks(x->content);
    }
  }
  void spans(Inline& text) const {
    for (Span& s : text) fix(s.text, s.link, s.doc);
  }
};

}  // namespace

void resolve_references(const std::vector<Document*>& docs) {
  std::map<std::string, Anchors> anchors;
  for (const Document* d : docs) {
    std::size_t k = 0;
    collect(d->blocks, heading_numbers(*d), k, anchors[d->key]);
  }
  for (Document* d : docs) Resolver{anchors, *d}.blocks(d->blocks);
}

std::vector<ContentsEntry> contents_entries(const Document& d, int depth) {
  const std::vector<std::string> numbers = heading_numbers(d);
  std::vector<ContentsEntry> out;
  std::size_t k = 0;
  for (const DocBlock& b : d.blocks) {
    const Heading* h = std::get_if<Heading>(&b.value);
    if (!h) continue;
    const std::string& n = numbers[k++];
    if (!n.empty() && h->level <= depth) out.push_back({h, n});
  }
  return out;
}

}  // namespace assess
