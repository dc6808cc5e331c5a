// html_report.hpp: a minimal builder for a self-contained, printable HTML5
// report (report layer; no physics). Inline CSS only (A4 print styles, a page
// break before each level-2 section but the first), no scripts, no external
// resources; each plot is an inline SVG inside <figure id=...>.
#pragma once

#include <string>
#include <vector>

namespace assess {

class HtmlReport {
 public:
  /// @param title document title (<title> and the level-1 heading)
  explicit HtmlReport(std::string title);

  /// A heading; level 2 opens a section (new printed page), 3-4 subsections.
  /// @param level 2..4 (level 1 is the document title); InputError otherwise
  void add_heading(const std::string& text, int level = 2);
  /// A paragraph of plain text (escaped).
  void add_paragraph(const std::string& text);
  /// A table of plain-text cells (escaped); rows must have the header's width.
  void add_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
                 const std::string& caption = "");
  /// A figure holding an SVG document (e.g. from render_svg()). The XML
  /// prolog is dropped and every id inside the SVG is prefixed with `id` so
  /// several plots can share the page. @param id unique, [A-Za-z][A-Za-z0-9_-]*
  void add_svg(const std::string& svg, const std::string& caption, const std::string& id);

  std::size_t figure_count() const { return figure_ids_.size(); }
  /// The complete HTML5 document.
  std::string str() const;

 private:
  std::string title_;
  std::string body_;
  std::vector<std::string> figure_ids_;
  bool has_section_ = false;
};

}  // namespace assess
