// input_file.hpp: the one reader of every input file (issue 31).
//
// Every file libassess reads on behalf of a user (a case or building file, a
// record, the hazard grid, the list of comuni, a record catalogue or metadata
// table, a campaign) is read by read_input_file: a regular file only (a
// directory, a character or block device such as /dev/zero, a FIFO or a
// socket is refused by name before a byte is read, so nothing blocks or reads
// until memory runs out), at most the size limit of its kind, read in one
// pass. Every failure is an InputError naming the file, what it was expected
// to be and why (docs/reliability.md, "Hostile input").
#pragma once

#include <cstddef>
#include <string>

namespace assess {

/// What a file is expected to be, and the most bytes it may hold.
struct InputKind {
  const char* what;       ///< "case file", "record file", ... (named in errors)
  std::size_t max_bytes;  ///< size limit (bytes)
  /// No output of this run may replace the file (output_file.hpp); false for
  /// the tool's own result files, read back to resume and then rewritten.
  bool protect = true;
};

namespace input_kinds {
inline constexpr std::size_t MiB = std::size_t{1} << 20;
// A case file is a few kB; a building of building_max_mechanisms (1000)
// mechanisms written out in full is a few MB.
inline constexpr InputKind json_file{"JSON file", 64 * MiB};
inline constexpr InputKind case_file{"case file", 64 * MiB};
inline constexpr InputKind campaign_file{"campaign file", 64 * MiB};
// The longest shipped record is 2.4 MB (16889_H1.cor.acc, 60 000 samples);
// 256 MB holds ten million samples written with 16 digits.
inline constexpr InputKind record_file{"record file", 256 * MiB};
inline constexpr InputKind record_catalogue{"record catalogue", 64 * MiB};
inline constexpr InputKind metadata_table{"record metadata table", 64 * MiB};
// The shipped spectra.bin is 1.8 MB (372 records x 602 periods); 256 MB
// holds 50 000 records at the same grid (issue 39: it was read as a result
// file, up to 4 GB).
inline constexpr InputKind record_spectra{"record spectra file", 256 * MiB};
// The shipped grid is 2.4 MB (10 751 nodes), the islands table 4 kB, the list of comuni 380 kB.
inline constexpr InputKind hazard_grid{"hazard grid file", 64 * MiB};
inline constexpr InputKind islands_table{"islands table", 16 * MiB};
inline constexpr InputKind comuni_table{"list of comuni", 64 * MiB};
/// Files this tool wrote itself and reads back (campaign results, fragility summaries, the resume state).
inline constexpr InputKind own_output{"result file", 4096 * MiB, false};
}  // namespace input_kinds

/// The whole content of `path`, a regular file of at most kind.max_bytes bytes.
/// InputError "<path>: is a directory, expected a record file" (or a character
/// device, a FIFO, ...), "<path>: cannot open the case file: No such file or
/// directory", "<path>: 300 MB is more than the limit of 256 MB for a record file".
std::string read_input_file(const std::string& path, const InputKind& kind);

/// Throws the same errors as read_input_file for anything but an existing,
/// readable regular file of at most kind.max_bytes bytes, without reading it
/// (for readers that stream a large file of the tool's own).
void check_input_file(const std::string& path, const InputKind& kind);

/// "a directory", "a character device", "a FIFO", ... for the file type of an
/// existing path that is not a regular file ("" for a regular file, or when
/// the path does not exist).
std::string non_regular_file_type(const std::string& path);

}  // namespace assess
