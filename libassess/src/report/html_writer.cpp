// html_writer.cpp: Document -> printable HTML5 (issue 28, items 9 and 12).
#include "assess/report/html_writer.hpp"

#include "report/xml_escape.hpp"

#include <regex>

namespace assess {

namespace {

using detail::xml_escape;

// Print style sheet (issue 28, item 9): A4, a fixed type size that prints
// (body 10.5 pt, tables 8.5 pt, notes 8 pt: nothing below 8 pt), tables at
// full width whose cells wrap (a long word breaks rather than widening the
// page: Chromium would otherwise shrink the whole page to fit, and the
// contents' numbers laid over it would miss their rows: report_files.cpp
// numbers_on_rows; the two widest tables, the building's summary and the
// acceptability checks, with narrower cell padding: 7-9 px too wide for the
// house), headings kept
// with the block that follows, figures and table rows never split, one
// colour per verdict.
constexpr const char* kCss = R"(
  @page { size: A4; margin: 16mm 15mm 18mm 15mm; }
  html { -webkit-text-size-adjust: none; }
  body { font-family: "DejaVu Sans", sans-serif; font-size: 10.5pt; line-height: 1.35; max-width: 180mm; margin: 1em auto; color: #111; }
  h1 { font-size: 17pt; margin: 0 0 0.3em 0; }
  h2 { font-size: 13.5pt; border-bottom: 1px solid #999; margin: 1.4em 0 0.5em 0; }
  h3 { font-size: 12pt; margin: 1.1em 0 0.4em 0; } h4 { font-size: 11pt; margin: 1em 0 0.3em 0; }
  h5, h6 { font-size: 10.5pt; margin: 0.9em 0 0.3em 0; }
  h2, h3, h4, h5, h6 { break-after: avoid; page-break-after: avoid; break-inside: avoid; }
  span.secno { margin-right: 0.2em; }
  p { margin: 0.45em 0; orphans: 3; widows: 3; }
  p.meta { font-size: 9.5pt; color: #333; } p.note { font-size: 9pt; color: #333; }
  table { border-collapse: collapse; margin: 0.5em 0 0.8em 0; font-size: 8.5pt; width: 100%; }
  table.narrow { width: auto; min-width: 60%; }
  caption { caption-side: top; text-align: left; font-style: italic; font-size: 9.5pt; padding-bottom: 0.3em; }
  th, td { border: 1px solid #bbb; padding: 0.18em 0.35em; text-align: left; vertical-align: top; overflow-wrap: break-word; }
  table.building-summary th, table.building-summary td, table.acceptability th, table.acceptability td { padding: 0.18em 0.22em; }
  th { background: #eee; font-size: 8.5pt; }
  td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; } td.num { white-space: nowrap; }
  th.num .note, td.num .note { white-space: normal; text-align: left; }
  th .note, td .note { display: block; font-weight: normal; font-size: 8pt; color: #444; }
  .dc-ok, td.dc-ok { color: #11661f; font-weight: bold; } .dc-fail, td.dc-fail { color: #b3001b; font-weight: bold; }
  td.ok, span.ok { color: #11661f; } td.fail, span.fail { color: #b3001b; font-weight: bold; }
  td.gov { background: #fff6d6; }
  tr { break-inside: avoid; page-break-inside: avoid; }
  thead { display: table-header-group; }
  figure { margin: 0.8em 0; break-inside: avoid; page-break-inside: avoid; }
  figure svg { width: 100%; height: auto; max-width: 170mm; max-height: 115mm; display: block; margin: 0 auto; }
  figure[id$="fig-mechanism"] svg, figure[id$="ties-drawing"] svg { max-height: 105mm; }
  figcaption { font-size: 9.5pt; font-style: italic; margin-top: 0.3em; }
  div.grid { display: grid; grid-template-columns: repeat(3, 1fr); gap: 0.3em; }
  div.grid div.panel { font-size: 8pt; text-align: center; break-inside: avoid; }
  div.grid svg { width: 100%; height: auto; display: block; }
  pre { font-size: 8pt; white-space: pre-wrap; overflow-wrap: anywhere; border: 1px solid #ccc; padding: 0.5em; background: #fafafa; }
  ul.legend, ul.normativa { font-size: 10pt; }
  div.box { border: 2px solid #777; border-radius: 4px; padding: 0.4em 0.8em; margin: 0.6em 0; break-inside: avoid; }
  div.box.ok { border-color: #11661f; background: #eef8ef; } div.box.fail { border-color: #b3001b; background: #fdeeee; }
  div.box.conclusion { border-width: 3px; font-size: 11.5pt; }
  div.box.conclusion .outcome, div.box.verdict .outcome { font-weight: bold; }
  div.box.ok .outcome { color: #11661f; } div.box.fail .outcome { color: #b3001b; }
  div.box.verdicts { border: none; padding: 0; display: flex; flex-wrap: wrap; gap: 0.6em; background: none; }
  div.box.verdicts > div.box { flex: 1 1 40%; margin: 0; }
  div.box.verdict > p:first-child { font-size: 9.5pt; color: #333; margin-top: 0; }
  div.box.verdict p { font-size: 9.5pt; }
  div.box.probabilistic { border-color: #4a5a7a; background: #f2f4f8; }
  div.box.note { border-width: 1px; border-color: #999; background: #f7f7f7; font-size: 9.5pt; }
  nav.toc ol { list-style: none; padding-left: 0; margin: 0.3em 0; }
  nav.toc li { display: flex; align-items: baseline; font-size: 10pt; margin: 0.08em 0; }
  nav.toc li.l3 { padding-left: 1.6em; font-size: 9.5pt; } nav.toc li.l4 { padding-left: 3.2em; font-size: 9pt; }
  nav.toc li a { color: #111; text-decoration: none; }
  nav.toc li span.fill { flex: 1; border-bottom: 1px dotted #999; margin: 0 0.3em; }
  nav.toc li span.page { min-width: 2.2em; text-align: right; }
  div.signature { margin-top: 2.5em; break-inside: avoid; } div.signature p { margin: 1.5em 0; }
  @media print {
    body { margin: 0; max-width: none; }
    .page-break { break-before: page; page-break-before: always; }
    a { color: inherit; text-decoration: none; }
  }
)";

std::string page_numbers(const std::string& lang) {
  const bool it = lang == "it";
  return std::string("\n  @page { @bottom-right { content: \"") + (it ? "pag. " : "page ") + "\" counter(page) \"" +
         (it ? " di " : " of ") +
         "\" counter(pages); font-family: \"DejaVu Sans\", sans-serif; font-size: 8pt; color: #555; } }\n";
}

const char* tone_class(Tone t) { return t == Tone::ok ? "ok" : t == Tone::fail ? "fail" : ""; }

// The href of a link into `doc` ("" this page): "#a", "other.html#a", or ""
// when that document has no file beside this one (HtmlOptions::documents).
std::string href(const HtmlOptions& o, const std::string& link, const std::string& doc) {
  if (link.empty()) return "";
  if (doc.empty()) return "#" + link;
  const auto f = o.documents.find(doc);
  return f == o.documents.end() ? "" : f->second + "#" + link;
}

std::string inline_html(const Inline& text, const HtmlOptions& o) {
  std::string s;
  for (const Span& x : text) {
    std::string t = xml_escape(x.text);
    if (x.strong) t = "<strong>" + t + "</strong>";
    if (x.tone != Tone::plain) t = std::string("<span class=\"") + tone_class(x.tone) + "\">" + t + "</span>";
    const std::string h = href(o, x.link, x.doc);
    if (!h.empty()) t = "<a href=\"" + xml_escape(h) + "\"" + (x.doc.empty() ? "" : " class=\"xref\"") + ">" + t + "</a>";
    if (x.user) t = "<span class=\"user\">" + t + "</span>";
    s += t;
  }
  return s;
}

// The SVG element of a figure, its ids made unique on the page: id="x" ->
// id="<fig>-x", and the references href="#x", url(#x) likewise.
std::string svg_body(const std::string& svg, const std::string& id) {
  const auto begin = svg.find("<svg");
  const auto end = svg.rfind("</svg>");
  std::string body = svg.substr(begin, end + 6 - begin);
  static const std::regex ids(R"(\bid=(["']))"), hrefs(R"(href=(["'])#)"), urls(R"(url\(#)");
  body = std::regex_replace(body, ids, "id=$1" + id + "-");
  body = std::regex_replace(body, hrefs, "href=$1#" + id + "-");
  body = std::regex_replace(body, urls, "url(#" + id + "-");
  return body;
}

std::string cell_class(const Cell& c) {
  std::string cls;
  auto add = [&](const std::string& k) { cls += (cls.empty() ? "" : " ") + k; };
  if (c.numeric) add("num");
  if (c.tone != Tone::plain) add(c.strong ? (c.tone == Tone::ok ? "dc-ok" : "dc-fail") : tone_class(c.tone));
  if (c.highlight) add("gov");
  return cls;
}

// A cell's text with a line-break opportunity after each "_" and "/" (record
// ids such as RSN286_ITALY_A-BIS000, "fatto / progetto"): a long identifier
// wraps in its cell instead of widening the table past the page.
std::string breakable(const std::string& escaped) {
  std::string s;
  for (char ch : escaped) {
    s += ch;
    if (ch == '_' || ch == '/') s += "<wbr>";
  }
  return s;
}

std::string cell_html(const char* tag, const Cell& c, const HtmlOptions& o) {
  const std::string cls = cell_class(c);
  std::string text = c.numeric ? xml_escape(c.text) : breakable(xml_escape(c.text));
  const std::string h = href(o, c.link, c.doc);
  if (!h.empty()) text = "<a href=\"" + xml_escape(h) + "\"" + (c.doc.empty() ? "" : " class=\"xref\"") + ">" + text + "</a>";
  if (c.user) text = "<span class=\"user\">" + text + "</span>";
  std::string s = std::string("<") + tag + (cls.empty() ? "" : " class=\"" + cls + "\"") + ">" + text;
  if (!c.note.empty()) s += "<span class=\"note\">" + xml_escape(c.note) + "</span>";
  return s + "</" + tag + ">";
}

struct Writer {
  const Document& d;
  const HtmlOptions& o;
  std::vector<std::string> numbers;
  std::size_t heading = 0;  // index of the next heading in `numbers`

  std::string blocks(const std::vector<DocBlock>& bs) {
    std::string s;
    for (const DocBlock& b : bs) s += std::visit([&](const auto& x) { return block(x); }, b.value);
    return s;
  }

  std::string block(const Heading& h) {
    const std::string n = heading < numbers.size() ? numbers[heading] : "";
    ++heading;
    const std::string tag = "h" + std::to_string(h.level);
    return "<" + tag + " id=\"" + xml_escape(h.anchor) + "\"" + (h.new_page ? " class=\"page-break\"" : "") + ">" +
           (n.empty() ? "" : "<span class=\"secno\">" + n + "</span> ") + xml_escape(h.text) + "</" + tag + ">\n";
  }
  std::string block(const Paragraph& p) {
    std::string attrs;
    if (!p.style.empty()) attrs += " class=\"" + xml_escape(p.style) + "\"";
    if (!p.lang.empty()) attrs += " lang=\"" + xml_escape(p.lang) + "\"";
    return "<p" + attrs + ">" + inline_html(p.text, o) + "</p>\n";
  }
  std::string block(const List& l) {
    std::string s = "<ul" + (l.style.empty() ? std::string() : " class=\"" + xml_escape(l.style) + "\"") + ">\n";
    for (const Inline& i : l.items) s += "<li>" + inline_html(i, o) + "</li>\n";
    return s + "</ul>\n";
  }
  std::string block(const Table& t) {
    std::string s = t.style.empty() ? "<table>\n" : "<table class=\"" + xml_escape(t.style) + "\">\n";
    if (!t.caption.empty()) s += "<caption>" + xml_escape(t.caption) + "</caption>\n";
    s += "<thead><tr>";
    for (const Cell& h : t.header) s += cell_html("th", h, o);
    s += "</tr></thead>\n<tbody>\n";
    for (const auto& r : t.rows) {
      s += "<tr>";
      for (const Cell& c : r) s += cell_html("td", c, o);
      s += "</tr>\n";
    }
    return s + "</tbody>\n</table>\n";
  }
  std::string block(const Figure& f) {
    std::string s = "<figure id=\"" + xml_escape(f.id) + "\">\n";
    if (f.grid) {
      s += "<div class=\"grid\">\n";
      for (std::size_t i = 0; i < f.panels.size(); ++i)
        s += "<div class=\"panel\">" + svg_body(f.panels[i].svg, f.id + "-" + std::to_string(i)) + "<div>" +
             xml_escape(f.panels[i].label) + "</div></div>\n";
      s += "</div>\n";
    } else if (!f.panels.empty()) {
      s += svg_body(f.panels.front().svg, f.id) + "\n";
    }
    if (!f.caption.empty()) s += "<figcaption>" + xml_escape(f.caption) + "</figcaption>\n";
    return s + "</figure>\n";
  }
  std::string block(const Box& b) {
    std::string cls = "box";
    if (!b.style.empty()) cls += " " + b.style;
    if (b.tone != Tone::plain) cls += std::string(" ") + tone_class(b.tone);
    std::string attrs;
    for (const auto& [k, v] : b.data) attrs += " data-" + xml_escape(k) + "=\"" + xml_escape(v) + "\"";
    return "<div class=\"" + cls + "\"" + attrs + ">\n" + blocks(b.content) + "</div>\n";
  }
  std::string block(const Preformatted& p) { return "<pre>" + xml_escape(p.text) + "</pre>\n"; }
  std::string block(const Signature& sg) {
    std::string s = "<div class=\"signature\">";
    for (const std::string& l : sg.lines) s += "<p>" + xml_escape(l) + "</p>";
    return s + "</div>\n";
  }
  std::string block(const Contents& c) {
    std::string s = "<nav class=\"toc\">\n<h2 class=\"toc-heading\">" + xml_escape(c.title) + "</h2>\n<ol>\n";
    for (const auto& [h, n] : contents_entries(d, c.depth)) {
      const auto p = o.pages.find(h->anchor);
      s += "<li class=\"l" + std::to_string(h->level) + "\"><a href=\"#" + xml_escape(h->anchor) +
           "\"><span class=\"secno\">" + n + "</span> " + xml_escape(h->text) + "</a>" +
           (o.page_column ? "<span class=\"fill\"></span><span class=\"page\">" +
                                (p == o.pages.end() ? std::string() : std::to_string(p->second)) + "</span>"
                          : std::string()) +
           "</li>\n";
    }
    return s + "</ol>\n</nav>\n";
  }
  std::string block(const RawHtml& r) { return r.html + "\n"; }
};

}  // namespace

// The contents' page numbers alone (HtmlOptions::contents_overlay): every
// other box laid out but not painted (no text of it in the PDF), no footer.
const char* kOverlayCss = R"(
  body { visibility: hidden; }
  nav.toc li span.page { visibility: visible; color: #111; }
  @page { @bottom-right { content: none; } }
)";

std::string to_html(const Document& d, const HtmlOptions& options) {
  Writer w{d, options, heading_numbers(d)};
  // The contents' page numbers alone: the blocks up to the contents (the front
  // page, the verdict box) lay it out where the full print has it.
  std::vector<DocBlock> head;
  if (options.contents_overlay)
    for (const DocBlock& b : d.blocks) {
      head.push_back(b);
      if (std::holds_alternative<Contents>(b.value)) break;
    }
  const std::vector<DocBlock>& printed = options.contents_overlay ? head : d.blocks;
  std::string body = w.blocks(printed);
  if (options.heading_destinations) {
    body += "<div class=\"destinations\" hidden>";
    for (const DocBlock& b : printed)
      if (const Heading* h = std::get_if<Heading>(&b.value)) body += "<a href=\"#" + xml_escape(h->anchor) + "\"></a>";
    body += "</div>\n";
  }
  return "<!DOCTYPE html>\n<html lang=\"" + xml_escape(d.lang) + "\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         xml_escape(d.title) + "</title>\n<style>" + kCss + page_numbers(d.lang) +
         (options.contents_overlay ? kOverlayCss : "") + "</style>\n</head>\n<body>\n<h1>" +
         xml_escape(d.title) + "</h1>\n" +
         (d.subtitle.empty() ? "" : "<p class=\"meta\">" + xml_escape(d.subtitle) + "</p>\n") + body +
         "</body>\n</html>\n";
}

}  // namespace assess
