// zip_archive.hpp (private to the report layer): a zip archive read from and
// written to memory with libzip (Debian package libzip4, loaded when first
// used: native_library.hpp). The Word writer reads its reference document
// (docx_reference, build_info.hpp) and writes the .docx with it.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace assess::detail {

/// One member of an archive: its name ("word/document.xml") and content.
struct ZipEntry {
  std::string name;
  std::string data;
  bool deflate = true;  ///< false: stored (a PNG, already compressed)
};

/// The members of the archive `bytes`, in its order. InputError naming
/// `what` when libzip is missing or the archive cannot be read.
std::vector<ZipEntry> read_zip(std::string_view bytes, const std::string& what);

/// The archive of `entries`, in their order, every member dated 2024-01-01
/// (the same document gives the same bytes). InputError naming `what` when
/// libzip is missing or fails.
std::string write_zip(const std::vector<ZipEntry>& entries, const std::string& what);

}  // namespace assess::detail
