// docx_writer.hpp: the Word writer of the document model (issue 28, item 10):
// the same relazione as an editable .docx (headings as Word headings, tables
// as tables, figures embedded, a table of contents Word updates), through
// pandoc (Debian package pandoc; figures converted by rsvg-convert, package
// librsvg2-bin) from an HTML rendering without styles.
#pragma once

#include "assess/report/document.hpp"

#include <string>

namespace assess {

/// The HTML that pandoc reads: the document's structure, no CSS; each figure
/// panel an <img> of `figure_file(id, k)` in the same folder.
std::string to_pandoc_html(const Document& d);

/// Writes `d` to `path` as a Word document. `shown` names the output in
/// errors ("--docx relazione.docx"; default "--docx PATH"): the user's file,
/// not a temporary one (issue 39). @throws InputError if pandoc is missing
/// (naming the package) or fails.
void write_docx(const Document& d, const std::string& path, const std::string& shown = "");

}  // namespace assess
