// fresh_process.hpp (bench only): run a piece of work in a child process
// (fork) and measure its CPU time (user + system, every thread, from
// wait4's rusage) and wall time. A process starts with nothing read: the
// record library, its spectra, the memo of selections and the hazard grid
// are loaded by the work itself, as in one `assess` command. Repeating the
// work in one process would measure the memo instead (issue 32).
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace assess::bench {

struct ProcessTime {
  double cpu_s = 0.0;   ///< user + system time of the child (s)
  double wall_s = 0.0;  ///< s
  bool ok = false;      ///< the child exited with status 0
};

/// Runs work() (returning an exit status) in a child process.
template <typename Work>
ProcessTime in_fresh_process(Work&& work) {
  std::fflush(stdout);
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) std::exit(3);
  if (pid == 0) {
    const int rc = work();
    std::fflush(stdout);
    _exit(rc);
  }
  int status = 0;
  struct rusage ru {};
  wait4(pid, &status, 0, &ru);
  ProcessTime t;
  t.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  t.cpu_s = double(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) + 1e-6 * double(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  t.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  return t;
}

/// The best (least) CPU and wall time of `n` runs of work(i) (i = 0 ... n-1,
/// returning an exit status), each in a fresh process; with `print_runs`,
/// each run's times as "  run i: CPU ... s, wall ... s". ok false (and the
/// runs stop) at the first run that fails.
struct BestTime {
  double cpu_s = 1e300;
  double wall_s = 1e300;
  bool ok = true;
};
template <typename Work>
BestTime best_of_fresh_processes(int n, Work&& work, bool print_runs) {
  BestTime best;
  for (int i = 0; i < n; ++i) {
    const ProcessTime t = in_fresh_process([&] { return work(i); });
    if (!t.ok) {
      best.ok = false;
      return best;
    }
    if (print_runs) std::printf("  run %d: CPU %.3f s, wall %.3f s\n", i + 1, t.cpu_s, t.wall_s);
    best.cpu_s = t.cpu_s < best.cpu_s ? t.cpu_s : best.cpu_s;
    best.wall_s = t.wall_s < best.wall_s ? t.wall_s : best.wall_s;
  }
  return best;
}

}  // namespace assess::bench
