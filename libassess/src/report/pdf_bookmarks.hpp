// pdf_bookmarks.hpp (private to the report layer): the pages of a printed
// PDF's named destinations, and its bookmarks written afterwards. Chromium
// prints an untagged PDF a quarter faster (and qpdf reads it four times
// faster) but without an outline (issue 36, item 7): each heading a link
// points to is a named destination of the PDF (the print links every
// heading, HtmlOptions::heading_destinations), read back with pdfinfo
// (poppler-utils); the bookmarks are the headings, nested by level, each
// pointing at its destination, added by qpdf with --update-from-json (qpdf
// JSON v2).
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace assess::detail {

/// The page of each named destination of `pdf` (anchor -> page, from 1);
/// empty when pdfinfo is missing or fails. `dir`: a private folder.
std::map<std::string, int> pdf_destinations(const std::filesystem::path& pdf, const std::filesystem::path& dir);

/// One bookmark: its title, its level (1 the top) and the named destination it opens.
struct Bookmark {
  std::string title;
  int level = 1;
  std::string destination;
};

/// Writes to `update` the qpdf JSON (v2) that adds `bookmarks` to `pdf` as
/// its outline (open, shown when the file opens), reading the PDF's catalog
/// and its highest object number with qpdf. False when qpdf is missing;
/// InputError naming --pdf when qpdf cannot read the PDF.
bool write_bookmarks_update(const std::filesystem::path& pdf, const std::vector<Bookmark>& bookmarks,
                            const std::filesystem::path& update, const std::filesystem::path& dir);

}  // namespace assess::detail
