// termination.cpp: temporaries and child processes cleaned when the process
// is stopped (termination.hpp).
#include "assess/support/termination.hpp"

#include "assess/support/error.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>
#include <thread>

#include <fcntl.h>
#include <pthread.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace assess {
namespace {

// What a signal cleans. Never destroyed: the watcher thread may use it while
// the process exits.
struct Registry {
  std::mutex mutex;
  std::set<std::string> temporaries;
  std::set<pid_t> groups;  // process group ids (= the child's pid)
  std::atomic<bool>* interrupt = nullptr;
  bool interrupted = false;
  bool terminating = false;
};
Registry& registry() {
  static Registry* r = new Registry;
  return *r;
}

const int handled_signals[] = {SIGINT, SIGTERM, SIGHUP};

// Stops every registered process group (SIGTERM, then SIGKILL after 2 s) and
// removes every registered temporary. Called with the registry locked.
void clean_up(Registry& r) {
  for (pid_t g : r.groups) ::kill(-g, SIGTERM);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  for (bool alive = true; alive && std::chrono::steady_clock::now() < deadline;) {
    alive = false;
    for (pid_t g : r.groups) alive = alive || ::kill(-g, 0) == 0;
    if (alive) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  for (pid_t g : r.groups) ::kill(-g, SIGKILL);
  for (const std::string& p : r.temporaries) {
    std::error_code ec;
    std::filesystem::remove_all(p, ec);
  }
}

void watch(sigset_t set) {
  for (;;) {
    int sig = 0;
    if (::sigwait(&set, &sig) != 0) continue;
    Registry& r = registry();
    {
      std::lock_guard<std::mutex> lock(r.mutex);
      if (r.interrupt && !r.interrupted && (sig == SIGINT || sig == SIGTERM)) {
        r.interrupt->store(true);  // the campaign stops after the groups under way
        r.interrupted = true;
        continue;
      }
      // Held to the end: no temporary or child is registered after the clean-up.
      r.terminating = true;
      clean_up(r);
      // End with the signal's own status (a shell reports 130 for SIGINT, 143 for SIGTERM).
      std::signal(sig, SIG_DFL);
      sigset_t one;
      sigemptyset(&one);
      sigaddset(&one, sig);
      ::pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
      ::raise(sig);
      ::_exit(128 + sig);
    }
  }
}

}  // namespace

void install_termination_handling() {
  static std::once_flag once;
  std::call_once(once, []() noexcept {
    // A write beyond `ulimit -f` then fails with EFBIG (output_file.cpp: a
    // full disk), instead of SIGXFSZ killing the process mid-write.
    std::signal(SIGXFSZ, SIG_IGN);
    // A signal ignored when the tool started stays ignored (`nohup assess ...`:
    // SIGHUP; a background job of a non-interactive shell: SIGINT).
    sigset_t set;
    sigemptyset(&set);
    for (int s : handled_signals) {
      struct sigaction old {};
      if (::sigaction(s, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
      sigaddset(&set, s);
    }
    ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
    try {
      std::thread(watch, set).detach();
    } catch (...) {
      // No thread to take them: the signals keep their default action.
      ::pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
    }
  });
}

void set_interrupt_flag(std::atomic<bool>* flag) {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.interrupt = flag;
  r.interrupted = false;
}

std::string make_temporary_folder(const std::string& stem) {
  const char* env = std::getenv("TMPDIR");
  const bool from_env = env && *env;
  const std::string dir = from_env ? env : "/tmp";
  std::string tmpl = dir + "/" + stem + "XXXXXX";
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  if (!::mkdtemp(tmpl.data())) {
    const int err = errno;
    const std::string msg = "cannot create a temporary folder in " + (from_env ? "TMPDIR=" + dir : dir) + ": " +
                            std::strerror(err) + (from_env ? " (set TMPDIR to a writable folder)" : "");
    if (err == ENOSPC || err == EDQUOT || err == EIO || err == ENOMEM) throw SystemError(msg);
    throw InputError(msg);
  }
  r.temporaries.insert(tmpl);
  return tmpl;
}

int make_temporary_file(std::string& path_template) {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  const int fd = ::mkstemp(path_template.data());
  if (fd >= 0) r.temporaries.insert(path_template);
  return fd;
}

void release_temporary(const std::string& path) {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.temporaries.erase(path);
}

StartedProgram start_program(const std::vector<std::string>& argv, const std::string& log_path,
                             const std::string& tmpdir, const std::vector<std::pair<int, int>>& fds) {
  StartedProgram started;
  ProgramResult& res = started.result;
  if (argv.empty()) return started;
  posix_spawn_file_actions_t fa;
  posix_spawnattr_t at;
  ::posix_spawn_file_actions_init(&fa);
  ::posix_spawnattr_init(&at);
  ::posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  ::posix_spawn_file_actions_addopen(&fa, 1, log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  ::posix_spawn_file_actions_adddup2(&fa, 1, 2);
  // Descriptors the program inherits at the numbers it expects (Chromium's
  // --remote-debugging-pipe: 3 and 4); ours are close-on-exec and above 4.
  for (const auto& [child, ours] : fds) ::posix_spawn_file_actions_adddup2(&fa, ours, child);
  // Its own process group (stopped as a whole), no signal blocked, the
  // default action for the signals this process handles or ignores.
  ::posix_spawnattr_setflags(&at, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  ::posix_spawnattr_setpgroup(&at, 0);
  sigset_t none, defaults;
  sigemptyset(&none);
  ::posix_spawnattr_setsigmask(&at, &none);
  sigemptyset(&defaults);
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGXFSZ, SIGPIPE}) sigaddset(&defaults, s);
  ::posix_spawnattr_setsigdefault(&at, &defaults);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  // The environment, TMPDIR replaced when asked.
  const std::string tmpdir_entry = "TMPDIR=" + tmpdir;
  std::vector<char*> env;
  for (char** e = environ; e && *e; ++e)
    if (tmpdir.empty() || std::strncmp(*e, "TMPDIR=", 7) != 0) env.push_back(*e);
  if (!tmpdir.empty()) env.push_back(const_cast<char*>(tmpdir_entry.c_str()));
  env.push_back(nullptr);
  pid_t pid = -1;
  Registry& r = registry();
  {
    std::lock_guard<std::mutex> lock(r.mutex);
    // Started and registered together: a signal stops it, or it never starts.
    const int err = r.terminating ? EINTR : ::posix_spawnp(&pid, argv[0].c_str(), &fa, &at, args.data(), env.data());
    if (err == 0) r.groups.insert(pid);
    res.start_error = err;
  }
  ::posix_spawn_file_actions_destroy(&fa);
  ::posix_spawnattr_destroy(&at);
  if (res.start_error) return started;
  res.started = true;
  started.pid = pid;
  return started;
}

ProgramResult wait_program(StartedProgram& started, int timeout_s) {
  ProgramResult res = started.result;
  if (!res.started || started.pid <= 0) return res;
  const pid_t pid = started.pid;
  started.pid = -1;
  Registry& r = registry();
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_s);
  int status = 0;
  for (auto pause = std::chrono::milliseconds(1);; pause = std::min(pause * 2, std::chrono::milliseconds(20))) {
    const pid_t w = ::waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) break;
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(-pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      res.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(pause);
  }
  {
    std::lock_guard<std::mutex> lock(r.mutex);
    ::kill(-pid, SIGKILL);  // what it left running in its group
    r.groups.erase(pid);
  }
  if (!res.timed_out) {
    if (WIFEXITED(status)) res.exit_status = WEXITSTATUS(status);
    else if (WIFSIGNALED(status)) res.signal = WTERMSIG(status);
  }
  return res;
}

ProgramResult run_program(const std::vector<std::string>& argv, const std::string& log_path, int timeout_s,
                          const std::string& tmpdir) {
  StartedProgram p = start_program(argv, log_path, tmpdir);
  return wait_program(p, timeout_s);
}

}  // namespace assess
