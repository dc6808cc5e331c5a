// output_lock.hpp: one writer per campaign output directory (issue 10,
// defect 9). A run plus a concurrent --resume on the same --out interleaved
// their rows (NUL bytes, duplicate ids); two --resume runs both exited 0.
//
// The lock is flock(2) on lock files inside the directory, so it is released
// by the kernel when the process ends, even by kill -9, and never goes stale:
//   parts == 1 (one process):  exclusive lock on DIR/.assess-lock
//   parts  > 1 (MPI ranks):    shared lock on DIR/.assess-lock (the ranks of
//                              one job coexist) and an exclusive lock on
//                              DIR/.assess-lock.part<p>of<n> (one rank per part)
// A second single-process run, or a second MPI job, on the same directory is
// refused with an InputError naming the directory.
#pragma once

#include <string>

namespace assess {

class CampaignOutputLock {
 public:
  /// Creates out_dir if needed and locks it for part `part` of `parts`.
  /// @throws InputError if another process holds a conflicting lock, or if
  ///   the lock file cannot be created
  CampaignOutputLock(const std::string& out_dir, int part = 0, int parts = 1);
  ~CampaignOutputLock();
  CampaignOutputLock(const CampaignOutputLock&) = delete;
  CampaignOutputLock& operator=(const CampaignOutputLock&) = delete;

 private:
  int dir_fd_ = -1;
  int part_fd_ = -1;
};

}  // namespace assess
