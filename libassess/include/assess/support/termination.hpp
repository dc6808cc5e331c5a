// termination.hpp: what a run leaves behind when it is stopped (issue 39,
// class 5): its temporary files and folders, and the programs it started
// (Chromium, pdfinfo, qpdf).
//
// Every temporary file or folder the library creates is registered here while
// it exists, and every child process runs in its own process group, also
// registered. The CLI calls install_termination_handling() first thing: SIGINT,
// SIGTERM and SIGHUP are then taken by one watcher thread (blocked in every
// other thread), which stops the child process groups (SIGTERM, SIGKILL after
// two seconds), removes the temporaries and ends the process with the
// signal's own status. SIGXFSZ (a write beyond `ulimit -f`) is ignored: the
// write fails with EFBIG instead, reported like a full disk (SystemError,
// exit status 1) with no temporary left. docs/reliability.md, "Round five".
#pragma once

#include <atomic>
#include <string>
#include <utility>
#include <vector>

namespace assess {

/// Blocks SIGINT, SIGTERM and SIGHUP in the calling thread (and so in every
/// thread it starts later) and starts the watcher thread described above; a
/// signal ignored when the process started (`nohup`) stays ignored. Ignores
/// SIGXFSZ. Call once, from main, before any other thread starts.
void install_termination_handling();

/// While set (non-null), the first SIGINT or SIGTERM sets `*flag` instead of
/// ending the process (a campaign finishes the groups under way, writes them
/// and stops: --resume continues); a second one ends it as above. nullptr
/// restores the default.
void set_interrupt_flag(std::atomic<bool>* flag);

/// A new private folder <TMPDIR or /tmp>/<stem>XXXXXX (mkdtemp), registered
/// for removal if the process is stopped. InputError naming TMPDIR and the
/// system's reason when it cannot be created ("cannot create a temporary
/// folder in TMPDIR=/nope: No such file or directory"); SystemError for a
/// full disk.
std::string make_temporary_folder(const std::string& stem);

/// mkstemp(`path_template`) (its XXXXXX replaced by the name made), the new
/// file registered for removal if the process is stopped. Returns the file
/// descriptor, or -1 with errno set.
int make_temporary_file(std::string& path_template);

/// The temporary `path` (a file or a folder) is gone or kept: no longer removed on a signal.
void release_temporary(const std::string& path);

/// How a program run by run_program ended.
struct ProgramResult {
  bool started = false;   ///< false: the program could not be started (start_error)
  int start_error = 0;    ///< errno of the start: ENOENT = not found on PATH
  bool timed_out = false; ///< killed after the time limit
  int exit_status = -1;   ///< its exit status when it exited, else -1
  int signal = 0;         ///< the signal that ended it, else 0
};

/// Runs `argv` (a program found on PATH, and its arguments; no shell) with
/// standard input from /dev/null and standard output and error to
/// `log_path`, in its own process group (registered: stopped with this
/// process), at most `timeout_s` seconds (then its group is killed). With
/// `tmpdir`, the program's TMPDIR is that folder (Chromium leaves its
/// org.chromium.* folders there when it is stopped: a temporary of ours
/// holds them).
ProgramResult run_program(const std::vector<std::string>& argv, const std::string& log_path, int timeout_s,
                          const std::string& tmpdir = "");

/// A program started by start_program and not yet waited for.
struct StartedProgram {
  int pid = -1;          ///< its pid and process group (registered: stopped with this process)
  ProgramResult result;  ///< `started` and `start_error` so far
};

/// run_program in two halves, for a program one talks to while it runs
/// (Chromium's DevTools pipe): starts it as run_program does, with the
/// descriptors `fds` (pairs: the number in the program, ours) inherited at
/// the numbers it expects; wait_program waits at most `timeout_s` seconds
/// (then kills its group), stops what it left in its group and forgets it.
StartedProgram start_program(const std::vector<std::string>& argv, const std::string& log_path,
                             const std::string& tmpdir = "", const std::vector<std::pair<int, int>>& fds = {});
ProgramResult wait_program(StartedProgram& program, int timeout_s);

}  // namespace assess
