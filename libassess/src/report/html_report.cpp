// html_report.cpp: self-contained printable HTML5 report builder.
#include "assess/report/html_report.hpp"

#include "report/xml_escape.hpp"

#include "assess/support/error.hpp"

#include <algorithm>
#include <regex>

namespace assess {

namespace {

using detail::xml_escape;

// Print-friendly inline style sheet: A4 pages, a page break before each
// section but the first, figures and table rows never split across pages.
constexpr const char* kCss = R"(
  @page { size: A4; margin: 16mm 14mm; }
  body { font-family: sans-serif; font-size: 11pt; line-height: 1.4; max-width: 180mm; margin: 1em auto; color: #111; }
  h1 { font-size: 18pt; margin-bottom: 0.2em; }
  h2 { font-size: 14pt; border-bottom: 1px solid #999; margin-top: 1.6em; }
  body { counter-reset: sec; } h2:not(.verdicts-heading) { counter-increment: sec; counter-reset: sub; }
  h2:not(.verdicts-heading)::before { content: counter(sec) ". "; }
  h3 { counter-increment: sub; } h2 ~ h3::before { content: counter(sec) "." counter(sub) " "; }
  div.signature { margin-top: 2.5em; break-inside: avoid; } div.signature p { margin: 1.5em 0; }
  h3 { font-size: 12pt; } h4 { font-size: 11pt; }
  table { border-collapse: collapse; margin: 0.6em 0; font-size: 9pt; max-width: 100%; }
  td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
  td.num { white-space: nowrap; }
  th .note, td .note { display: block; font-weight: normal; font-size: 7.5pt; color: #555; }
  .dc-ok { color: #11661f; font-weight: bold; } .dc-fail { color: #b3001b; font-weight: bold; }
  td.ok { color: #11661f; white-space: nowrap; } td.fail { color: #b3001b; font-weight: bold; white-space: nowrap; }
  td.gov { background: #fff6d6; font-weight: bold; }
  tr.governing td { background: #fff6d6; }
  div.verdicts { display: flex; flex-wrap: wrap; gap: 0.8em; margin: 0.8em 0; }
  div.verdict { flex: 1 1 40%; border: 2px solid; border-radius: 4px; padding: 0.5em 0.8em; break-inside: avoid; }
  div.verdict.ok { border-color: #11661f; background: #eef8ef; } div.verdict.fail { border-color: #b3001b; background: #fdeeee; }
  div.verdict .code { font-size: 10pt; color: #333; } div.verdict .outcome { font-size: 16pt; font-weight: bold; white-space: nowrap; }
  div.verdict.ok .outcome { color: #11661f; } div.verdict.fail .outcome { color: #b3001b; }
  div.verdict .governing { font-size: 9pt; }
  div.verdict .method { margin: 0.25em 0; font-size: 10pt; } div.verdict .method .outcome { font-size: 11pt; }
  div.verdict .method.ok .outcome { color: #11661f; } div.verdict .method.fail .outcome { color: #b3001b; }
  div.conclusion { border: 3px solid; border-radius: 4px; padding: 0.5em 0.8em; margin: 0.6em 0; font-size: 12pt; break-inside: avoid; }
  div.conclusion.ok { border-color: #11661f; background: #eef8ef; } div.conclusion.fail { border-color: #b3001b; background: #fdeeee; }
  div.conclusion .outcome { font-size: 16pt; font-weight: bold; }
  div.conclusion.ok .outcome { color: #11661f; } div.conclusion.fail .outcome { color: #b3001b; }
  p.meta { font-size: 9.5pt; color: #333; margin-top: 0; }
  div.grid { display: grid; grid-template-columns: repeat(3, 1fr); gap: 0.3em; }
  div.grid div.panel { font-size: 8pt; text-align: center; break-inside: avoid; }
  div.grid svg { width: 100%; height: auto; display: block; }
  pre { font-size: 7.5pt; white-space: pre-wrap; word-break: break-all; border: 1px solid #ccc; padding: 0.5em; background: #fafafa; }
  ul.legend { font-size: 9.5pt; }
  caption { caption-side: top; text-align: left; font-style: italic; padding-bottom: 0.3em; }
  th, td { border: 1px solid #bbb; padding: 0.2em 0.35em; text-align: left; vertical-align: top; }
  th { background: #eee; font-size: 8pt; }
  figure { margin: 1em 0; break-inside: avoid; page-break-inside: avoid; }
  figure svg { width: 100%; height: auto; max-width: 170mm; display: block; }
  figcaption { font-size: 10pt; font-style: italic; margin-top: 0.3em; }
  tr { break-inside: avoid; page-break-inside: avoid; }
  @media print {
    body { margin: 0; max-width: none; }
    h2.section-break { break-before: page; page-break-before: always; }
  }
)";

// Page numbers "pag. x di y" (Italian) or "page x of y" in the printed
// report's bottom margin (CSS paged-media margin boxes, printed by Chromium).
std::string page_numbers(const std::string& lang) {
  const bool it = lang == "it";
  return std::string("\n  @page { @bottom-right { content: \"") + (it ? "pag. " : "page ") +
         "\" counter(page) \"" + (it ? " di " : " of ") +
         "\" counter(pages); font-family: sans-serif; font-size: 8pt; color: #555; } }\n";
}

}  // namespace

HtmlReport::HtmlReport(std::string title) : title_(std::move(title)) {}

void HtmlReport::add_heading(const std::string& text, int level, bool new_page) {
  if (level < 2 || level > 4) throw InputError("HtmlReport: heading level must be 2..4");
  level += heading_shift_;  // a report nested in another (the building's mechanisms)
  const std::string tag = "h" + std::to_string(level);
  std::string cls;
  if (level == 2) {
    if (has_section_ && new_page) cls = " class=\"section-break\"";
    has_section_ = true;
  }
  body_ += "<" + tag + cls + ">" + xml_escape(text) + "</" + tag + ">\n";
}

void HtmlReport::add_paragraph(const std::string& text) { body_ += "<p>" + xml_escape(text) + "</p>\n"; }

void HtmlReport::add_table(const std::vector<std::string>& header,
                           const std::vector<std::vector<std::string>>& rows, const std::string& caption) {
  for (const auto& r : rows)
    if (r.size() != header.size())
      throw InputError("HtmlReport: table row has " + std::to_string(r.size()) + " cells, header has " +
                       std::to_string(header.size()));
  body_ += "<table>\n";
  if (!caption.empty()) body_ += "<caption>" + xml_escape(caption) + "</caption>\n";
  body_ += "<thead><tr>";
  for (const auto& h : header) body_ += "<th>" + xml_escape(h) + "</th>";
  body_ += "</tr></thead>\n<tbody>\n";
  for (const auto& r : rows) {
    body_ += "<tr>";
    for (const auto& c : r) body_ += "<td>" + xml_escape(c) + "</td>";
    body_ += "</tr>\n";
  }
  body_ += "</tbody>\n</table>\n";
}

std::string HtmlReport::svg_body(const std::string& svg, const std::string& id) const {
  const auto begin = svg.find("<svg");
  const auto end = svg.rfind("</svg>");
  if (begin == std::string::npos || end == std::string::npos || end < begin)
    throw InputError("HtmlReport: figure '" + id + "' is not an SVG document");
  std::string body = svg.substr(begin, end + 6 - begin);
  // Make the SVG's ids unique on the page: id="x" -> id="<fig>-x", and the
  // references href="#x", url(#x) likewise.
  static const std::regex ids(R"(\bid=(["']))"), hrefs(R"(href=(["'])#)");
  body = std::regex_replace(body, ids, "id=$1" + id + "-");
  body = std::regex_replace(body, hrefs, "href=$1#" + id + "-");
  static const std::regex urls(R"(url\(#)");
  body = std::regex_replace(body, urls, "url(#" + id + "-");
  return body;
}

namespace {
void check_figure_id(const std::vector<std::string>& ids, const std::string& id) {
  static const std::regex id_re("[A-Za-z][A-Za-z0-9_-]*");
  if (!std::regex_match(id, id_re)) throw InputError("HtmlReport: figure id '" + id + "' is not a valid id");
  if (std::find(ids.begin(), ids.end(), id) != ids.end())
    throw InputError("HtmlReport: duplicate figure id '" + id + "'");
}
}  // namespace

void HtmlReport::add_svg(const std::string& svg, const std::string& caption, const std::string& id_in) {
  const std::string id = id_prefix_ + id_in;
  check_figure_id(figure_ids_, id);
  const std::string body = svg_body(svg, id);
  body_ += "<figure id=\"" + id + "\">\n" + body + "\n";
  if (!caption.empty()) body_ += "<figcaption>" + xml_escape(caption) + "</figcaption>\n";
  body_ += "</figure>\n";
  figure_ids_.push_back(id);
}

void HtmlReport::add_svg_grid(const std::vector<std::pair<std::string, std::string>>& svgs,
                              const std::string& caption, const std::string& id_in) {
  const std::string id = id_prefix_ + id_in;
  check_figure_id(figure_ids_, id);
  body_ += "<figure id=\"" + id + "\">\n<div class=\"grid\">\n";
  for (std::size_t i = 0; i < svgs.size(); ++i)
    body_ += "<div class=\"panel\">" + svg_body(svgs[i].first, id + "-" + std::to_string(i)) + "<div>" +
             xml_escape(svgs[i].second) + "</div></div>\n";
  body_ += "</div>\n";
  if (!caption.empty()) body_ += "<figcaption>" + xml_escape(caption) + "</figcaption>\n";
  body_ += "</figure>\n";
  figure_ids_.push_back(id);
}

void HtmlReport::add_cell_table(const std::vector<HtmlCell>& header, const std::vector<std::vector<HtmlCell>>& rows,
                           const std::string& caption, const std::string& cls) {
  for (const auto& r : rows)
    if (r.size() != header.size())
      throw InputError("HtmlReport: table row has " + std::to_string(r.size()) + " cells, header has " +
                       std::to_string(header.size()));
  auto cell = [](const char* tag, const HtmlCell& c) {
    std::string s = std::string("<") + tag;
    if (!c.cls.empty()) s += " class=\"" + xml_escape(c.cls) + "\"";
    s += ">" + xml_escape(c.text);
    if (!c.note.empty()) s += "<span class=\"note\">" + xml_escape(c.note) + "</span>";
    return s + "</" + tag + ">";
  };
  body_ += cls.empty() ? "<table>\n" : "<table class=\"" + xml_escape(cls) + "\">\n";
  if (!caption.empty()) body_ += "<caption>" + xml_escape(caption) + "</caption>\n";
  body_ += "<thead><tr>";
  for (const auto& h : header) body_ += cell("th", h);
  body_ += "</tr></thead>\n<tbody>\n";
  for (const auto& r : rows) {
    body_ += "<tr>";
    for (const auto& c : r) body_ += cell("td", c);
    body_ += "</tr>\n";
  }
  body_ += "</tbody>\n</table>\n";
}

void HtmlReport::add_pre(const std::string& text) { body_ += "<pre>" + xml_escape(text) + "</pre>\n"; }

void HtmlReport::add_raw_html(const std::string& html) { body_ += html + "\n"; }

std::string HtmlReport::str() const {
  return "<!DOCTYPE html>\n<html lang=\"" + xml_escape(lang_) + "\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         xml_escape(title_) + "</title>\n<style>" + kCss + page_numbers(lang_) + "</style>\n</head>\n<body>\n<h1>" + xml_escape(title_) +
         "</h1>\n" + (subtitle_.empty() ? "" : "<p class=\"meta\">" + xml_escape(subtitle_) + "</p>\n") + body_ + "</body>\n</html>\n";
}

}  // namespace assess
