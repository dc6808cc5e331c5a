// docx_writer.cpp: Document -> .docx through pandoc (issue 28, item 10).
#include "assess/report/docx_writer.hpp"

#include "report/external_tool.hpp"
#include "report/xml_escape.hpp"

#include "assess/report/build_info.hpp"
#include "assess/support/error.hpp"

namespace assess {

namespace {

using detail::xml_escape;

std::string figure_file(const std::string& id, std::size_t k) { return id + "-" + std::to_string(k) + ".svg"; }

// A verdict's colour as the Word character style of the reference document
// (tools/docx/make_reference_docx.py): "Verdetto OK" green, "Verdetto KO" red.
std::string toned(const std::string& escaped, Tone tone, bool strong) {
  if (tone == Tone::ok) return "<span data-custom-style=\"Verdetto OK\">" + escaped + "</span>";
  if (tone == Tone::fail) return "<span data-custom-style=\"Verdetto KO\">" + escaped + "</span>";
  return strong ? "<strong>" + escaped + "</strong>" : escaped;
}

// A link within the document becomes a Word hyperlink to the heading's
// bookmark; a link into the other document (the tabulati) stays text.
std::string linked(const std::string& html, const std::string& link, const std::string& doc) {
  return link.empty() || !doc.empty() ? html : "<a href=\"#" + xml_escape(link) + "\">" + html + "</a>";
}

std::string inline_html(const Inline& text) {
  std::string s;
  for (const Span& x : text) s += linked(toned(xml_escape(x.text), x.tone, x.strong), x.link, x.doc);
  return s;
}

std::string cell(const char* tag, const Cell& c) {
  std::string s = linked(toned(xml_escape(c.text), c.tone, c.strong), c.link, c.doc);
  if (!c.note.empty()) s += "<br><span data-custom-style=\"Nota\">" + xml_escape(c.note) + "</span>";
  return std::string("<") + tag + (c.numeric ? " style=\"text-align:right\"" : "") + ">" + s + "</" + tag + ">";
}

struct Writer {
  std::vector<std::string> numbers;
  std::size_t heading = 0;

  std::string blocks(const std::vector<DocBlock>& bs) {
    std::string s;
    for (const DocBlock& b : bs) s += std::visit([&](const auto& x) { return block(x); }, b.value);
    return s;
  }
  std::string block(const Heading& h) {
    const std::string n = heading < numbers.size() ? numbers[heading] : "";
    ++heading;
    // Word's Heading 1 is the section (the title is the document's title).
    const std::string tag = "h" + std::to_string(std::max(1, h.level - 1));
    return "<" + tag + " id=\"" + xml_escape(h.anchor) + "\">" + (n.empty() ? "" : n + " ") + xml_escape(h.text) + "</" + tag +
           ">\n";
  }
  std::string block(const Paragraph& p) {
    const std::string t = inline_html(p.text);
    // Notes and meta lines in the small grey type of the PDF.
    return p.style == "note" || p.style == "meta" ? "<p><span data-custom-style=\"Nota\">" + t + "</span></p>\n"
                                                  : "<p>" + t + "</p>\n";
  }
  std::string block(const List& l) {
    std::string s = "<ul>\n";
    for (const Inline& i : l.items) s += "<li>" + inline_html(i) + "</li>\n";
    return s + "</ul>\n";
  }
  std::string block(const Table& t) {
    std::string s = "<table>\n";
    if (!t.caption.empty()) s += "<caption>" + xml_escape(t.caption) + "</caption>\n";
    s += "<thead><tr>";
    for (const Cell& h : t.header) s += cell("th", h);
    s += "</tr></thead>\n<tbody>\n";
    for (const auto& r : t.rows) {
      s += "<tr>";
      for (const Cell& c : r) s += cell("td", c);
      s += "</tr>\n";
    }
    return s + "</tbody>\n</table>\n";
  }
  std::string block(const Figure& f) {
    std::string s;
    for (std::size_t k = 0; k < f.panels.size(); ++k) {
      const std::string alt = f.panels[k].label.empty() ? f.caption : f.panels[k].label;
      s += "<figure><img src=\"" + figure_file(f.id, k) + "\" alt=\"" + xml_escape(alt) + "\">";
      if (f.grid && !f.panels[k].label.empty()) s += "<figcaption>" + xml_escape(f.panels[k].label) + "</figcaption>";
      else if (!f.grid) s += "<figcaption>" + xml_escape(f.caption) + "</figcaption>";
      s += "</figure>\n";
    }
    if (f.grid && !f.caption.empty()) s += "<p><em>" + xml_escape(f.caption) + "</em></p>\n";
    return s;
  }
  std::string block(const Box& b) { return blocks(b.content); }
  std::string block(const Preformatted& p) { return "<pre>" + xml_escape(p.text) + "</pre>\n"; }
  std::string block(const Signature& sg) {
    std::string s;
    for (const std::string& l : sg.lines) s += "<p>" + xml_escape(l) + "</p>\n";
    return s;
  }
  std::string block(const Contents&) { return ""; }  // Word's own table of contents (pandoc --toc)
  std::string block(const RawHtml& r) { return r.html + "\n"; }
};

void write_figures(const std::vector<DocBlock>& blocks, const std::filesystem::path& dir) {
  for (const DocBlock& b : blocks) {
    if (const Figure* f = std::get_if<Figure>(&b.value))
      for (std::size_t k = 0; k < f->panels.size(); ++k) {
        const std::string& svg = f->panels[k].svg;
        const auto begin = svg.find("<svg");
        detail::write_file(dir / figure_file(f->id, k), begin == std::string::npos ? svg : svg.substr(begin),
                           "--docx");
      }
    if (const Box* x = std::get_if<Box>(&b.value)) write_figures(x->content, dir);
  }
}

}  // namespace

std::string to_pandoc_html(const Document& d) {
  Writer w{heading_numbers(d)};
  return "<!DOCTYPE html>\n<html lang=\"" + xml_escape(d.lang) + "\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
         xml_escape(d.title) + "</title>\n</head>\n<body>\n" +
         (d.subtitle.empty() ? "" : "<p><em>" + xml_escape(d.subtitle) + "</em></p>\n") + w.blocks(d.blocks) +
         "</body>\n</html>\n";
}

void write_docx(const Document& d, const std::string& path, const std::string& shown) {
  const std::string what = shown.empty() ? "--docx " + path : shown;
  detail::TempDir dir("assess_docx_");
  write_figures(d.blocks, dir.path());
  detail::write_file(dir.path() / "report.html", to_pandoc_html(d), "--docx");
  // The page, margins, page numbers, type and verdict colours of the PDF (issue 36, item 6).
  const std::string_view ref = docx_reference(d.lang == "it" ? Lang::it : Lang::en);
  detail::write_file(dir.path() / "reference.docx", std::string(ref), "--docx");
  const std::filesystem::path out = dir.path() / "report.docx", log = dir.path() / "pandoc.log";
  const int code = detail::run_program({"pandoc", "--from=html", "--to=docx", "--toc", "--toc-depth=3",
                                        "--reference-doc=" + (dir.path() / "reference.docx").string(),
                                        "--metadata=title:" + d.title, "--metadata=lang:" + d.lang,
                                        "--resource-path=" + dir.path().string(), "--output=" + out.string(),
                                        (dir.path() / "report.html").string()},
                                       log);
  if (code == detail::program_not_found)
    throw InputError(what + ": pandoc was not found on PATH: install it (Debian: apt-get install pandoc librsvg2-bin)");
  if (code == detail::program_timed_out)
    throw InputError(what + ": pandoc did not finish within its time limit (180 s)");
  if (code != 0 || !std::filesystem::exists(out)) {
    std::string msg = detail::read_file(log);
    if (msg.size() > 400) msg = msg.substr(0, 400) + "…";
    throw InputError(what + ": pandoc could not write the document (exit " + std::to_string(code) + "): " + msg);
  }
  std::error_code ec;
  std::filesystem::copy_file(out, path, std::filesystem::copy_options::overwrite_existing, ec);
  if (ec) throw InputError(what + ": cannot write the file (" + ec.message() + ")");
}

}  // namespace assess
