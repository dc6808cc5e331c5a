// docx_writer.cpp: Document -> .docx, WordprocessingML written here (issue
// 28, item 10; issue 36, items 6 and 7: the page of the PDF, and no pandoc:
// the house's two documents took 11.6 CPU-seconds through pandoc and
// rsvg-convert). The page, margins, styles, footer ("pag. x di y"), fonts and
// theme are the reference document's (tools/docx/reference-{it,en}.docx,
// compiled in: build_info.hpp), its parts copied into the new package with
// its section properties; the writer adds the body, the pictures, a bulleted
// list definition and Word's "update fields on opening" (the contents).
#include "assess/report/docx_writer.hpp"

#include "report/svg_picture.hpp"
#include "report/xml_escape.hpp"
#include "report/zip_archive.hpp"

#include "assess/report/build_info.hpp"
#include "assess/support/error.hpp"
#include "assess/support/output_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace assess {

namespace {

using detail::xml_escape;

// DrawingML's English Metric Units (ECMA-376 Part 1, §20.1.2.1: 914400 an
// inch) and WordprocessingML's twips (1440 an inch).
constexpr double emu_per_mm = 36000.0;
constexpr double twips_per_mm = 1440.0 / 25.4;
// The PDF's figure (html_writer.cpp's print style): at most 170 mm wide and
// 115 mm tall (the mechanism and tie drawings 105 mm); a grid three panels a
// row with a small gap.
constexpr double figure_max_width_mm = 170.0;
constexpr double figure_max_height_mm = 115.0;
constexpr double drawing_max_height_mm = 105.0;
constexpr double grid_gap_mm = 3.0;
// The PNG fallback's resolution (the SVG itself is exact at any size): 120
// pixels an inch, a full-width figure about 800 pixels wide.
constexpr double png_dpi = 120.0;
// The bulleted list's numbering (numbering.xml): ids above the reference's (990, 1000).
constexpr const char* bullet_abstract_id = "991";
constexpr const char* bullet_num_id = "1001";

const char* tone_style(Tone t) { return t == Tone::ok ? "VerdettoOK" : t == Tone::fail ? "VerdettoKO" : ""; }

// Text as run content: line feeds as breaks, tabs as tabs.
std::string run_text(const std::string& text) {
  std::string s, piece;
  auto flush = [&] {
    if (!piece.empty()) s += "<w:t xml:space=\"preserve\">" + xml_escape(piece) + "</w:t>";
    piece.clear();
  };
  for (char c : text) {
    if (c == '\n') {
      flush();
      s += "<w:br/>";
    } else if (c == '\t') {
      flush();
      s += "<w:tab/>";
    } else if (c != '\r') {
      piece += c;
    }
  }
  flush();
  return s;
}

// One run: its character style (a verdict's colour, a note, a link), bold, language.
std::string run(const std::string& text, const std::string& style, bool bold = false, const std::string& lang = "") {
  std::string props;
  if (!style.empty()) props += "<w:rStyle w:val=\"" + style + "\"/>";
  if (bold) props += "<w:b/><w:bCs/>";
  if (!lang.empty()) props += "<w:lang w:val=\"" + xml_escape(lang) + "\"/>";
  return "<w:r>" + (props.empty() ? "" : "<w:rPr>" + props + "</w:rPr>") + run_text(text) + "</w:r>";
}

// A link within the document: a hyperlink to the bookmark of its heading or
// figure. A link into the other document (the tabulati) stays text.
std::string linked(const std::string& runs, const std::string& link, const std::string& doc) {
  if (link.empty() || !doc.empty()) return runs;
  return "<w:hyperlink w:anchor=\"" + xml_escape(link) + "\" w:history=\"1\">" + runs + "</w:hyperlink>";
}

// A piece of text with its tone, strength and link. The verdict's colour wins
// over the link's and the note's character styles (one style a run).
std::string span(const std::string& text, Tone tone, bool strong, const std::string& link, const std::string& doc,
                 const std::string& base_style = "", const std::string& lang = "") {
  std::string style = tone_style(tone);
  if (style.empty()) style = !link.empty() && doc.empty() ? "Hyperlink" : base_style;
  return linked(run(text, style, strong, lang), link, doc);
}

std::string paragraph(const std::string& runs, const std::string& style, const std::string& props = "") {
  const std::string ppr = (style.empty() ? "" : "<w:pStyle w:val=\"" + style + "\"/>") + props;
  return "<w:p>" + (ppr.empty() ? "" : "<w:pPr>" + ppr + "</w:pPr>") + runs + "</w:p>";
}

// The text of HTML without its tags (a block's or a line break's a space, an
// inline element's nothing), the five XML entities decoded, spaces collapsed.
std::string strip_tags(const std::string& html) {
  static const std::vector<std::string> inline_tags = {"a", "b", "strong", "i", "em", "span", "sub", "sup", "code", "small", "wbr"};
  std::string text, tag;
  bool in_tag = false;
  for (char c : html) {
    if (c == '<') {
      in_tag = true;
      tag.clear();
    } else if (c == '>' && in_tag) {
      in_tag = false;
      std::string name;
      for (char t : tag) {
        if (t == '/' && name.empty()) continue;
        if (!std::isalnum(static_cast<unsigned char>(t))) break;
        name += char(std::tolower(static_cast<unsigned char>(t)));
      }
      if (std::find(inline_tags.begin(), inline_tags.end(), name) == inline_tags.end()) text += ' ';
    } else if (in_tag) {
      tag += c;
    } else {
      text += c;
    }
  }
  for (const auto& [entity, ch] : {std::pair{"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}})
    for (std::size_t at = 0; (at = text.find(entity, at)) != std::string::npos; at += 1)
      text.replace(at, std::string(entity).size(), ch);
  std::string out;
  for (char c : text) {
    const bool space = c == ' ' || c == '\n' || c == '\t' || c == '\r';
    if (space && (out.empty() || out.back() == ' ')) continue;
    out += space ? ' ' : c;
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// The value of attribute `name` of the first element `tag` of `xml` ("" if none).
std::string attribute(const std::string& xml, const std::string& tag, const std::string& name) {
  const auto at = xml.find("<" + tag + " ");
  if (at == std::string::npos) return "";
  const auto end = xml.find('>', at);
  const auto a = xml.find(" " + name + "=\"", at);
  if (a == std::string::npos || a > end) return "";
  const auto v = a + name.size() + 3;
  return xml.substr(v, xml.find('"', v) - v);
}

// The parts of the reference document the new package keeps, and what the writer needs of them.
struct Reference {
  std::vector<detail::ZipEntry> parts;
  std::string section;     // its <w:sectPr>: A4, margins, the footer
  double text_width_mm = 180.0;

  std::string& part(const std::string& name, const std::string& what) {
    for (detail::ZipEntry& e : parts)
      if (e.name == name) return e.data;
    throw InputError(what + ": the Word reference document has no " + name);
  }
};

Reference read_reference(const Document& d, const std::string& what) {
  Reference r;
  r.parts = detail::read_zip(docx_reference(d.lang == "it" ? Lang::it : Lang::en), what);
  const std::string& body = r.part("word/document.xml", what);
  const auto s = body.find("<w:sectPr");
  const auto e = body.find("</w:sectPr>", s);
  if (s == std::string::npos || e == std::string::npos)
    throw InputError(what + ": the Word reference document has no section properties");
  r.section = body.substr(s, e + 11 - s);
  const double page = std::atof(attribute(r.section, "w:pgSz", "w:w").c_str());
  const double left = std::atof(attribute(r.section, "w:pgMar", "w:left").c_str());
  const double right = std::atof(attribute(r.section, "w:pgMar", "w:right").c_str());
  if (page - left - right > 0) r.text_width_mm = (page - left - right) / twips_per_mm;
  return r;
}

// `text` with `insert` put before the first `before` (at the end when absent).
std::string insert_before(std::string text, const std::string& before, const std::string& insert) {
  const auto at = text.find(before);
  text.insert(at == std::string::npos ? text.size() : at, insert);
  return text;
}

// Characters of UTF-8 text (its code points).
std::size_t characters(const std::string& s) {
  return std::size_t(std::count_if(s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

// The columns' widths in twips, summing to `total`, as a browser's automatic
// layout gives them (the PDF's tables): each column at least its longest word
// (a number whole: it does not wrap, the PDF's td.num) and, room allowing, its
// longest line (capped), the rest shared in proportion. When even the words do
// not fit, what must not break (a number, a verdict, a short code) keeps its
// width, a column of words at least 8 characters, and the longer words share
// the rest.
// Widths in DejaVu Sans at the tables' 8.5 pt (170 twips), measured on the
// Word file printed by LibreOffice: a number about 0.6 em a character (digits
// 0.64, the comma 0.32), other text about 0.56 em, bold 10 % wider (a
// verdict's styles are bold), a note's 8 pt 6 % narrower; a cell's margins
// 2 x 108 twips (the reference's table style).
std::vector<long> column_widths(const Table& t, long total) {
  constexpr double em = 170.0, margins = 216.0;
  // A header's line counts up to 15 characters (a heading wraps over its column), a cell's up to 120.
  constexpr std::size_t widest_header = 15, widest_line = 120, widest_word = 25;
  const std::size_t n = std::max<std::size_t>(1, t.header.size());
  std::vector<double> hard(n, margins), least(n, margins), want(n, margins);
  auto measure = [&](const Cell& c, std::size_t k, std::size_t widest) {
    for (const std::string* text : {&c.text, &c.note}) {
      const bool note = text == &c.note;
      const double per_char = em * (c.numeric && !note ? 0.6 : 0.56) * (!note && (c.strong || c.tone != Tone::plain) ? 1.1 : 1.0) *
                              (note ? 8.0 / 8.5 : 1.0);
      std::size_t word = 0, longest = 0;
      for (std::size_t at = 0; at <= text->size(); ++at) {
        if (at == text->size() || (*text)[at] == ' ') {
          longest = std::max(longest, characters(text->substr(at - word, word)));
          word = 0;
        } else {
          ++word;
        }
      }
      const bool number = c.numeric && !note && widest == widest_line;  // a body cell's number; a heading wraps
      if (number) longest = characters(*text);
      const double word_width = margins + per_char * double(std::min(longest, widest_word));
      least[k] = std::max(least[k], word_width);
      // Never broken inside: a number, a verdict, a short word ("M10", "Cod.").
      if (number || (!note && (c.strong || c.tone != Tone::plain)) || longest <= 5) hard[k] = std::max(hard[k], word_width);
      want[k] = std::max(want[k], margins + per_char * double(std::min(characters(*text), widest)));
    }
  };
  for (std::size_t k = 0; k < n && k < t.header.size(); ++k) measure(t.header[k], k, widest_header);
  for (const auto& row : t.rows)
    for (std::size_t k = 0; k < n && k < row.size(); ++k) measure(row[k], k, widest_line);
  double sum_hard = 0, sum_least = 0, sum_want = 0;
  for (std::size_t k = 0; k < n; ++k) {
    hard[k] = std::max(hard[k], std::min(least[k], margins + 8 * em * 0.56));  // a column of words keeps 8 characters

    sum_hard += hard[k];
    sum_least += least[k];
    sum_want += want[k];
  }
  const double room = double(total);
  std::vector<double> w(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (sum_want <= room) w[k] = want[k] * room / sum_want;  // all fits: widen in proportion
    else if (sum_least <= room) w[k] = least[k] + (want[k] - least[k]) * (room - sum_least) / (sum_want - sum_least);
    else if (sum_hard < room)  // the words do not fit: those that must not break keep their width
      w[k] = hard[k] + (least[k] - hard[k]) * (room - sum_hard) / (sum_least - sum_hard);
    else w[k] = hard[k] * room / sum_hard;
  }
  std::vector<long> out(n);
  long used = 0;
  for (std::size_t k = 0; k < n; ++k) used += out[k] = std::lround(w[k]);
  out.back() += total - used;
  return out;
}

struct Picture {
  std::string svg, png;
  long cx = 0, cy = 0;  // EMU
};

struct Writer {
  Writer(const Document& doc, const std::string& what_, double width) : d(doc), what(what_), text_width_mm(width) {}
  const Document& d;
  const std::string& what;
  double text_width_mm;
  std::vector<std::string> numbers = heading_numbers(d);
  std::size_t heading = 0;
  int bookmark = 0;
  std::vector<Picture> pictures;

  std::string bookmarked(const std::string& name, const std::string& inner) {
    const std::string id = std::to_string(bookmark++);
    return "<w:bookmarkStart w:id=\"" + id + "\" w:name=\"" + xml_escape(name) + "\"/>" + inner +
           "<w:bookmarkEnd w:id=\"" + id + "\"/>";
  }

  std::string inline_runs(const Inline& text, const std::string& base_style = "", const std::string& lang = "") {
    std::string s;
    for (const Span& x : text) s += span(x.text, x.tone, x.strong, x.link, x.doc, base_style, lang);
    return s;
  }

  std::string blocks(const std::vector<DocBlock>& bs) {
    std::string s;
    for (const DocBlock& b : bs) s += std::visit([&](const auto& x) { return block(x); }, b.value);
    return s;
  }

  // Word's Heading 1 is the section (the title is the document's title), as before.
  std::string block(const Heading& h) {
    const std::string n = heading < numbers.size() ? numbers[heading] : "";
    ++heading;
    const int word_level = std::max(1, h.level - 1);
    std::string props;
    if (h.new_page) props += "<w:pageBreakBefore/>";
    // An unnumbered heading stays out of the contents (contents_entries), as in the HTML and the PDF.
    if (!h.numbered || n.empty()) props += "<w:outlineLvl w:val=\"9\"/>";
    return paragraph(bookmarked(h.anchor, run((n.empty() ? "" : n + " ") + h.text, "")),
                     "Heading" + std::to_string(word_level), props);
  }
  std::string block(const Paragraph& p) {
    // Notes and meta lines in the small grey type of the PDF; a caption as a caption.
    if (p.style == "note" || p.style == "meta") return paragraph(inline_runs(p.text, "Nota", p.lang), "BodyText");
    return paragraph(inline_runs(p.text, "", p.lang), p.style == "caption" ? "Caption" : "BodyText");
  }
  std::string block(const List& l) {
    std::string s;
    const std::string numbering = std::string("<w:numPr><w:ilvl w:val=\"0\"/><w:numId w:val=\"") + bullet_num_id +
                                  "\"/></w:numPr>";
    for (const Inline& i : l.items) s += paragraph(inline_runs(i), "Compact", numbering);
    return s;
  }
  std::string cell(const Cell& c, long width_twips, bool header) {
    std::string props = "<w:tcW w:w=\"" + std::to_string(width_twips) + "\" w:type=\"dxa\"/>";
    if (header) props += "<w:shd w:val=\"clear\" w:color=\"auto\" w:fill=\"EEEEEE\"/>";
    else if (c.highlight) props += "<w:shd w:val=\"clear\" w:color=\"auto\" w:fill=\"FFF6D6\"/>";  // the governing row
    std::string runs = span(c.text, c.tone, c.strong, c.link, c.doc);
    if (!c.note.empty()) runs += "<w:r><w:br/></w:r>" + run(c.note, "Nota");
    return "<w:tc><w:tcPr>" + props + "</w:tcPr>" +
           paragraph(runs, "Compact", c.numeric ? "<w:jc w:val=\"right\"/>" : "") + "</w:tc>";
  }
  std::string row(const std::vector<Cell>& cells, const std::vector<long>& widths, bool header) {
    std::string s = std::string("<w:tr><w:trPr><w:cantSplit/>") + (header ? "<w:tblHeader/>" : "") + "</w:trPr>";
    for (std::size_t k = 0; k < cells.size(); ++k) s += cell(cells[k], widths[std::min(k, widths.size() - 1)], header);
    return s + "</w:tr>";
  }
  std::string block(const Table& t) {
    std::string s;
    if (!t.caption.empty()) s += paragraph(run(t.caption, ""), "TableCaption");
    const std::vector<long> widths = column_widths(t, std::lround(text_width_mm * twips_per_mm));
    s += "<w:tbl><w:tblPr><w:tblStyle w:val=\"Table\"/><w:tblW w:w=\"5000\" w:type=\"pct\"/>"
         "<w:tblLook w:firstRow=\"1\" w:lastRow=\"0\" w:firstColumn=\"0\" w:lastColumn=\"0\" w:noHBand=\"0\" "
         "w:noVBand=\"0\" w:val=\"0020\"/></w:tblPr><w:tblGrid>";
    for (long width : widths) s += "<w:gridCol w:w=\"" + std::to_string(width) + "\"/>";
    s += "</w:tblGrid>" + row(t.header, widths, true);
    for (const auto& r : t.rows) s += row(r, widths, false);
    // Word needs a paragraph between two tables, or it joins them.
    return s + "</w:tbl>" + paragraph("", "", "<w:spacing w:before=\"0\" w:after=\"0\"/>");
  }

  // The drawing of one picture (an inline DrawingML picture: the PNG in the
  // blip, the SVG in its Office 2016 extension, as Word writes it), its size
  // the SVG's aspect at `width_mm`, no taller than `max_height_mm`.
  std::string picture(const Panel& p, double width_mm, double max_height_mm, const std::string& alt) {
    detail::SvgPicture svg(p.svg, what);
    double w = width_mm, h = width_mm * svg.aspect();
    if (h > max_height_mm) {
      w *= max_height_mm / h;
      h = max_height_mm;
    }
    auto pixels = [](double mm) { return std::clamp(int(std::lround(mm / 25.4 * png_dpi)), 1, 8000); };
    Picture pic;
    const auto begin = p.svg.find("<svg");
    pic.svg = begin == std::string::npos ? p.svg : p.svg.substr(begin);
    pic.png = svg.png(pixels(w), pixels(h));
    pic.cx = std::lround(w * emu_per_mm);
    pic.cy = std::lround(h * emu_per_mm);
    pictures.push_back(std::move(pic));
    const std::string n = std::to_string(pictures.size());
    const std::string cx = std::to_string(pictures.back().cx), cy = std::to_string(pictures.back().cy);
    return "<w:r><w:drawing><wp:inline distT=\"0\" distB=\"0\" distL=\"0\" distR=\"0\"><wp:extent cx=\"" + cx +
           "\" cy=\"" + cy + "\"/><wp:effectExtent l=\"0\" t=\"0\" r=\"0\" b=\"0\"/><wp:docPr id=\"" + n +
           "\" name=\"Figure " + n + "\" descr=\"" + xml_escape(alt) +
           "\"/><wp:cNvGraphicFramePr><a:graphicFrameLocks noChangeAspect=\"1\"/></wp:cNvGraphicFramePr>"
           "<a:graphic><a:graphicData uri=\"http://schemas.openxmlformats.org/drawingml/2006/picture\"><pic:pic>"
           "<pic:nvPicPr><pic:cNvPr id=\"" + n + "\" name=\"figure" + n + ".svg\"/><pic:cNvPicPr/></pic:nvPicPr>"
           "<pic:blipFill><a:blip r:embed=\"rIdPng" + n + "\"><a:extLst>"
           "<a:ext uri=\"{96DAC541-7B7A-43D3-8B79-37D633B846F1}\"><asvg:svgBlip "
           "xmlns:asvg=\"http://schemas.microsoft.com/office/drawing/2016/SVG/main\" r:embed=\"rIdSvg" + n +
           "\"/></a:ext></a:extLst></a:blip><a:stretch><a:fillRect/></a:stretch></pic:blipFill>"
           "<pic:spPr><a:xfrm><a:off x=\"0\" y=\"0\"/><a:ext cx=\"" + cx + "\" cy=\"" + cy +
           "\"/></a:xfrm><a:prstGeom prst=\"rect\"><a:avLst/></a:prstGeom></pic:spPr></pic:pic></a:graphicData>"
           "</a:graphic></wp:inline></w:drawing></w:r>";
  }
  std::string block(const Figure& f) {
    // The mechanism and tie drawings a little lower, as in the PDF.
    auto ends_with = [&](const std::string& tail) {
      return f.id.size() >= tail.size() && f.id.compare(f.id.size() - tail.size(), tail.size(), tail) == 0;
    };
    const bool drawing = ends_with("fig-mechanism") || ends_with("ties-drawing");
    const double max_h = drawing ? drawing_max_height_mm : figure_max_height_mm;
    const double full = std::min(text_width_mm, figure_max_width_mm);
    std::string s;
    if (!f.grid) {
      for (std::size_t k = 0; k < f.panels.size(); ++k) {
        const std::string alt = f.panels[k].label.empty() ? f.caption : f.panels[k].label;
        std::string pic = picture(f.panels[k], full, max_h, alt);
        if (k == 0) pic = bookmarked(f.id, pic);  // the target of links to the figure
        s += paragraph(pic, "CaptionedFigure", "<w:jc w:val=\"center\"/>");
        if (!f.caption.empty()) s += paragraph(run(f.caption, ""), "ImageCaption");
      }
      return s;
    }
    // Small multiples three a row: each picture centred in its third of the
    // line (centre tab stops), its label below it likewise, then the caption.
    const double panel = (text_width_mm - 2 * grid_gap_mm) / 3.0;
    std::string tabs = "<w:tabs>";
    for (int k = 0; k < 3; ++k)
      tabs += "<w:tab w:val=\"center\" w:pos=\"" + std::to_string(std::lround(text_width_mm * twips_per_mm * (2 * k + 1) / 6.0)) +
              "\"/>";
    tabs += "</w:tabs>";
    for (std::size_t first = 0; first < f.panels.size(); first += 3) {
      std::string pics, labels;
      for (std::size_t k = first; k < std::min(first + 3, f.panels.size()); ++k) {
        const std::string alt = f.panels[k].label.empty() ? f.caption : f.panels[k].label;
        pics += "<w:r><w:tab/></w:r>" + picture(f.panels[k], panel, max_h, alt);
        labels += "<w:r><w:tab/></w:r>" + run(f.panels[k].label, "");
      }
      if (first == 0) pics = bookmarked(f.id, pics);
      s += paragraph(pics, "CaptionedFigure", tabs);
      s += paragraph(labels, "ImageCaption", "<w:keepNext/>" + tabs);
    }
    if (!f.caption.empty()) s += paragraph(run(f.caption, ""), "ImageCaption");
    return s;
  }
  std::string block(const Box& b) { return blocks(b.content); }
  std::string block(const Preformatted& p) {
    return paragraph(run(p.text, "VerbatimChar"), "Compact", "<w:spacing w:before=\"120\" w:after=\"120\"/>");
  }
  std::string block(const Signature& sg) {
    std::string s;
    for (const std::string& l : sg.lines) s += paragraph(run(l, ""), "BodyText", "<w:keepNext/>");
    return s;
  }
  // Word's table of contents: the TOC field of the heading levels the
  // document's contents list (Heading 1 = level 2), updated by Word on
  // opening (settings.xml, w:updateFields); until then it shows the entries
  // with their links, without page numbers.
  std::string block(const Contents& c) {
    const std::vector<ContentsEntry> entries = contents_entries(d, c.depth);
    const std::string levels = "1-" + std::to_string(std::max(1, c.depth - 1));
    const std::string begin = "<w:r><w:fldChar w:fldCharType=\"begin\" w:dirty=\"true\"/></w:r>"
                              "<w:r><w:instrText xml:space=\"preserve\"> TOC \\o \"" + levels +
                              "\" \\h \\z \\u </w:instrText></w:r><w:r><w:fldChar w:fldCharType=\"separate\"/></w:r>";
    const std::string end = "<w:r><w:fldChar w:fldCharType=\"end\"/></w:r>";
    std::string s = "<w:sdt><w:sdtPr><w:docPartObj><w:docPartGallery w:val=\"Table of Contents\"/><w:docPartUnique/>"
                    "</w:docPartObj></w:sdtPr><w:sdtContent>";
    if (!c.title.empty()) s += paragraph(run(c.title, ""), "TOCHeading");
    if (entries.empty()) s += paragraph(begin + end, "");
    for (std::size_t k = 0; k < entries.size(); ++k) {
      const Heading& h = *entries[k].heading;
      const std::string indent = std::to_string(std::lround(std::max(0, h.level - 2) * 5 * twips_per_mm));
      const std::string text = linked(run(entries[k].number + " " + h.text, "Hyperlink"), h.anchor, "");
      s += paragraph((k == 0 ? begin : "") + text + (k + 1 == entries.size() ? end : ""), "",
                     "<w:spacing w:before=\"0\" w:after=\"40\"/><w:ind w:left=\"" + indent + "\"/>");
    }
    return s + "</w:sdtContent></w:sdt>";
  }
  std::string block(const RawHtml& r) {
    const std::string text = strip_tags(r.html);
    return text.empty() ? "" : paragraph(run(text, ""), "BodyText");
  }
};

const char* kNamespaces =
    " xmlns:w=\"http://schemas.openxmlformats.org/wordprocessingml/2006/main\""
    " xmlns:r=\"http://schemas.openxmlformats.org/officeDocument/2006/relationships\""
    " xmlns:wp=\"http://schemas.openxmlformats.org/drawingml/2006/wordprocessingDrawing\""
    " xmlns:a=\"http://schemas.openxmlformats.org/drawingml/2006/main\""
    " xmlns:pic=\"http://schemas.openxmlformats.org/drawingml/2006/picture\"";

// The bulleted list (a bullet, then an en dash one level down), as pandoc's was.
std::string bullet_definition() {
  std::string s = std::string("<w:abstractNum w:abstractNumId=\"") + bullet_abstract_id +
                  "\"><w:nsid w:val=\"A5E55991\"/><w:multiLevelType w:val=\"multilevel\"/>";
  for (int k = 0; k < 9; ++k)
    s += "<w:lvl w:ilvl=\"" + std::to_string(k) + "\"><w:numFmt w:val=\"bullet\"/><w:lvlText w:val=\"" +
         (k % 2 ? "\xE2\x80\x93" : "\xE2\x80\xA2") + "\"/><w:lvlJc w:val=\"left\"/><w:pPr><w:ind w:left=\"" +
         std::to_string(480 * (k + 1)) + "\" w:hanging=\"360\"/></w:pPr></w:lvl>";
  return s + "</w:abstractNum>";
}

}  // namespace

std::string docx_bytes(const Document& d, const std::string& what) {
  Reference ref = read_reference(d, what);
  Writer w(d, what, ref.text_width_mm);
  std::string body;
  body += paragraph(run(d.title, ""), "Title");
  if (!d.subtitle.empty()) body += paragraph(run(d.subtitle, ""), "Subtitle");
  body += w.blocks(d.blocks);

  std::string& types = ref.part("[Content_Types].xml", what);
  types = insert_before(types, "</Types>",
                        "<Default Extension=\"png\" ContentType=\"image/png\"/>"
                        "<Default Extension=\"svg\" ContentType=\"image/svg+xml\"/>");
  std::string rels;
  for (std::size_t k = 1; k <= w.pictures.size(); ++k) {
    const std::string n = std::to_string(k);
    for (const char* ext : {"Png", "Svg"})
      rels += std::string("<Relationship Id=\"rId") + ext + n +
              "\" Type=\"http://schemas.openxmlformats.org/officeDocument/2006/relationships/image\" Target=\"media/figure" +
              n + (ext[0] == 'P' ? ".png" : ".svg") + "\"/>";
  }
  std::string& doc_rels = ref.part("word/_rels/document.xml.rels", what);
  doc_rels = insert_before(doc_rels, "</Relationships>", rels);
  std::string& numbering = ref.part("word/numbering.xml", what);
  // Every abstract definition before the first instance (ECMA-376 Part 1, §17.9.16).
  numbering = insert_before(numbering, "<w:num ", bullet_definition());
  numbering = insert_before(numbering, "</w:numbering>",
                            std::string("<w:num w:numId=\"") + bullet_num_id + "\"><w:abstractNumId w:val=\"" +
                                bullet_abstract_id + "\"/></w:num>");
  std::string& settings = ref.part("word/settings.xml", what);
  // Word updates the fields (the contents) on opening; in the schema's order, before w:rsids.
  settings = insert_before(settings, "<w:rsids", "<w:updateFields w:val=\"true\"/>");
  ref.part("docProps/core.xml", what) =
      "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n<cp:coreProperties "
      "xmlns:cp=\"http://schemas.openxmlformats.org/package/2006/metadata/core-properties\" "
      "xmlns:dc=\"http://purl.org/dc/elements/1.1/\"><dc:title>" + xml_escape(d.title) + "</dc:title><dc:language>" +
      xml_escape(d.lang) + "</dc:language></cp:coreProperties>";
  ref.part("word/document.xml", what) = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n<w:document" +
                                        std::string(kNamespaces) + "><w:body>" + body + ref.section +
                                        "</w:body></w:document>";
  for (std::size_t k = 0; k < w.pictures.size(); ++k) {
    const std::string n = std::to_string(k + 1);
    ref.parts.push_back({"word/media/figure" + n + ".png", std::move(w.pictures[k].png), false});
    ref.parts.push_back({"word/media/figure" + n + ".svg", std::move(w.pictures[k].svg), true});
  }
  // The content types first, as every writer puts them.
  std::stable_partition(ref.parts.begin(), ref.parts.end(),
                        [](const detail::ZipEntry& e) { return e.name == "[Content_Types].xml"; });
  return detail::write_zip(ref.parts, what);
}

void write_docx(const Document& d, const std::string& path, const std::string& shown) {
  write_output_file(path, docx_bytes(d, shown.empty() ? "--docx " + path : shown), "--docx");
}

}  // namespace assess
