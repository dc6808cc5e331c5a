// html_report.hpp: a minimal builder for a self-contained, printable HTML5
// report (report layer; no physics). Inline CSS only (A4 print styles, a page
// break before each level-2 section but the first), no scripts, no external
// resources; each plot is an inline SVG inside <figure id=...>.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace assess {

/// A table cell: escaped text, an optional CSS class ("num" right-aligned
/// figures, "dc-ok"/"dc-fail" D/C colours, "ok"/"fail" verdicts) and an
/// optional second line in small type (formula, clause).
struct HtmlCell {
  std::string text;
  std::string cls;
  std::string note;
  HtmlCell(std::string t = "", std::string c = "", std::string n = "")
      : text(std::move(t)), cls(std::move(c)), note(std::move(n)) {}
  HtmlCell(const char* t) : text(t) {}
};

class HtmlReport {
 public:
  /// @param title document title (<title> and the level-1 heading)
  explicit HtmlReport(std::string title);

  /// A heading; level 2 opens a section (a new printed page unless
  /// new_page is false), 3-4 subsections.
  /// @param level 2..4 (level 1 is the document title); InputError otherwise
  void add_heading(const std::string& text, int level = 2, bool new_page = true);
  /// A paragraph of plain text (escaped).
  void add_paragraph(const std::string& text);
  /// A table of plain-text cells (escaped); rows must have the header's width.
  void add_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
                 const std::string& caption = "");
  /// A figure holding an SVG document (e.g. from render_svg()). The XML
  /// prolog is dropped and every id inside the SVG is prefixed with `id` so
  /// several plots can share the page. @param id unique, [A-Za-z][A-Za-z0-9_-]*
  void add_svg(const std::string& svg, const std::string& caption, const std::string& id);

  /// A table of cells with classes (see HtmlCell); `cls` is the table's class.
  void add_cell_table(const std::vector<HtmlCell>& header, const std::vector<std::vector<HtmlCell>>& rows,
                 const std::string& caption, const std::string& cls = "");
  /// Several SVG documents side by side in one figure (small multiples),
  /// each with a short label; ids are prefixed with `id`-<n>.
  void add_svg_grid(const std::vector<std::pair<std::string, std::string>>& svgs_and_labels,
                    const std::string& caption, const std::string& id);
  /// A pre-formatted block (escaped), e.g. the case file echoed in an appendix.
  void add_pre(const std::string& text);
  /// A fragment of HTML built by the caller, inserted as is: the caller
  /// escapes every piece of user text in it (xml_escape).
  void add_raw_html(const std::string& html);
  /// The document's language (<html lang>), "en" by default.
  void set_lang(const std::string& lang) { lang_ = lang; }
  /// A line under the title (escaped).
  void set_subtitle(const std::string& text) { subtitle_ = text; }

  /// A prefix put before every figure id from now on (several reports on one
  /// page, e.g. "M3-": the building's mechanisms); "" by default.
  void set_id_prefix(const std::string& prefix) { id_prefix_ = prefix; }
  /// Headings added from now on go `shift` levels deeper (0 by default; 1
  /// nests a whole report under a level-2 heading: 2 -> h3, 3 -> h4, 4 -> h5).
  void set_heading_shift(int shift) { heading_shift_ = shift; }
  const std::string& id_prefix() const { return id_prefix_; }
  int heading_shift() const { return heading_shift_; }

  /// The body built so far (no title, subtitle or styles): a report nested
  /// in another one is built apart and inserted with add_raw_html.
  const std::string& body() const { return body_; }

  std::size_t figure_count() const { return figure_ids_.size(); }
  /// The complete HTML5 document.
  std::string str() const;

 private:
  std::string svg_body(const std::string& svg, const std::string& id) const;
  std::string title_;
  std::string lang_ = "en";
  std::string subtitle_;
  std::string body_;
  std::vector<std::string> figure_ids_;
  bool has_section_ = false;
  std::string id_prefix_;
  int heading_shift_ = 0;
};

}  // namespace assess
