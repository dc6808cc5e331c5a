// text_writer.hpp: the plain-text writer of the document model (issue 28,
// item 12): the same relazione as the HTML, PDF and Word files, for a
// terminal or a text file, within a width (120 columns by default):
// numbered headings, paragraphs and lists wrapped, tables in columns (a table
// wider than the width is written row by row, "header: value"), a figure by
// its caption, boxes indented with a bar.
#pragma once

#include "assess/report/document.hpp"

#include <cstddef>
#include <string>

namespace assess {

/// `figures` false leaves the figures out (the terminal's summary), true writes each by its caption.
std::string to_text(const Document& d, std::size_t width = 120, bool figures = true);

}  // namespace assess
