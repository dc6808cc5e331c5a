// docx_writer.hpp: the Word writer of the document model (issue 28, item 10;
// issue 36, items 6 and 7): the same relazione as an editable .docx, written
// as WordprocessingML by the library itself: headings as Word headings with
// their bookmarks, tables as tables, figures as pictures (the SVG, with a PNG
// for readers before Word 2016), a table of contents Word updates on opening,
// and the page, styles and footer of the reference document (build_info.hpp).
// The zip goes through libzip, the PNGs through librsvg and zlib, each loaded
// when a Word document is first written (Debian packages libzip4, librsvg2-2).
#pragma once

#include "assess/report/document.hpp"

#include <string>

namespace assess {

/// The bytes of `d` as a Word document. `what` names the output in errors
/// ("--docx relazione.docx"). @throws InputError if libzip or librsvg is
/// missing (naming the package) or a figure cannot be drawn.
std::string docx_bytes(const Document& d, const std::string& what = "--docx");

/// Writes `d` to `path` as a Word document (support/output_file.hpp's guarded
/// writer). `shown` names the output in errors ("--docx relazione.docx";
/// default "--docx PATH"): the user's file, not a temporary one (issue 39).
void write_docx(const Document& d, const std::string& path, const std::string& shown = "");

}  // namespace assess
