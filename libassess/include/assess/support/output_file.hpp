// output_file.hpp: the one writer of every output file (issue 31).
//
// A report, a JSON document, an expanded case, a history, a campaign or
// fragility summary is written whole or not at all: into a temporary file in
// the target's folder, then renamed onto the target (rename(2) is atomic, so
// a kill during the write leaves the old file or none, never a cut one).
// Before a byte is written it refuses (InputError, exit status 2):
//  - to replace a file this process read as an input (a case, a building
//    file, a record: every file read by read_input_file, compared by device
//    and inode, so a hard link or another spelling of the path is caught);
//  - to write through a symbolic link that leads out of the asked folder;
//  - a target that is a directory.
// A target that is a character device or a FIFO (/dev/null, /dev/stdout, a
// pipe) is written in place. The temporary file is registered for removal
// should a signal stop the process (termination.hpp). A failure of the machine (no space left, an I/O
// error, e.g. writing to /dev/full) is a SystemError (exit status 1), never a
// silent success. docs/reliability.md, "Outputs".
#pragma once

#include <string>
#include <vector>

namespace assess {

/// Writes `content` to `path` as described above. `what` names the output in
/// errors ("--html", "--expand out", "the campaign summary"); `folder` is the
/// folder the user asked for (a link may not lead out of it; "" = the folder
/// of `path`).
void write_output_file(const std::string& path, const std::string& content, const std::string& what,
                       const std::string& folder = "");

/// The checks of write_output_file without writing (a link out of `folder`,
/// a directory, an input of this run, a missing folder), for the command
/// line to refuse an output before a long run rather than after it.
void check_output_file(const std::string& path, const std::string& what, const std::string& folder = "");

/// One output of a run: its file, the option or name that asks for it
/// ("--pdf", "--expand out"), and the folder a link may not lead out of ("" =
/// the file's folder).
struct OutputTarget {
  std::string path, what, folder;
};

/// check_output_file for each output, and no two of them one file (issue 39:
/// `--pdf r.pdf --docx r.pdf` or `--expand D --txt D/M1.json` exited 0, one
/// output replacing the other). Files are compared by identity, as outputs
/// are against inputs: device and inode when the file exists, else its
/// folder's and its name, after following a link; so another spelling of
/// the path ("./r.pdf"), a hard link or a symbolic link is caught. Character
/// devices and FIFOs (/dev/null) are written in place and may be shared.
/// InputError "--pdf r.pdf and --docx ./r.pdf are the same file: ...".
void check_output_files(const std::vector<OutputTarget>& outputs);

/// Records `path` as an input of this run: no output may replace it.
/// read_input_file calls it for every file it reads (but the tool's own
/// result files read back to resume). Thread-safe.
void protect_input(const std::string& path);

/// True when `path` exists and is (by device and inode) a file protected by protect_input.
bool is_protected_input(const std::string& path);

/// Creates the output folder `dir` (and its parents) if needed. InputError
/// when it exists and is not a directory ("--out results.csv: is a regular
/// file, expected a folder"), or when it cannot be created (a read-only file
/// system, no permission).
void make_output_folder(const std::string& dir, const std::string& what);

}  // namespace assess
