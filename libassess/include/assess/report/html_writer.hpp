// html_writer.hpp: the HTML writer of the document model (issue 28): a
// self-contained, printable HTML5 page (inline CSS: A4, fixed type sizes,
// full-width tables that wrap instead of shrinking, headings kept with what
// follows; no scripts, no external resources; one <figure> per figure with
// its SVG inline). Sections are numbered here ("3.2"), so the HTML, the
// Word document and the text agree; the contents list them with the page
// of each heading when the PDF printer has given it (pdf.hpp).
#pragma once

#include "assess/report/document.hpp"

#include <map>
#include <string>

namespace assess {

struct HtmlOptions {
  /// Page of each heading's anchor in the printed PDF (from a first print);
  /// a heading without one has an empty page cell of the same width (the same layout).
  std::map<std::string, int> pages;
  /// Show the contents' page column (a printed edition).
  bool page_column = false;
  /// The contents' page numbers alone: the document up to the end of its
  /// contents, every other mark invisible but laid out the same, no page
  /// footer. Printed and laid over the first pages of the full print
  /// (report_files.cpp), it puts the page numbers in place without printing
  /// the whole document a second time.
  bool contents_overlay = false;
  /// A hidden link to every heading (a print whose bookmarks are added
  /// afterwards): Chromium then writes each heading's named destination,
  /// which gives its page and its bookmark (report/pdf_bookmarks.hpp).
  bool heading_destinations = false;
  /// The file of each other document a link may point into (Span::doc ->
  /// "casa-tabulati.html", relative to this page; issue 36). A link into a
  /// document not listed is printed as its text alone (a PDF: its links
  /// would name the printer's temporary folder).
  std::map<std::string, std::string> documents;
};

std::string to_html(const Document& d, const HtmlOptions& options = {});

}  // namespace assess
