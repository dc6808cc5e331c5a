// output_lock.cpp: flock(2) on lock files in the campaign output directory
// (see output_lock.hpp for the protocol).
#include "assess/campaign/output_lock.hpp"

#include "assess/support/error.hpp"
#include "assess/support/output_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace assess {
namespace {

// Opens (creating) `path` and takes the lock `op` without blocking; returns
// the descriptor. Throws naming the directory when another process holds it.
int lock_file(const std::string& path, int op, const std::string& out_dir) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0)
    throw InputError("cannot create the lock file '" + path + "': " + std::strerror(errno));
  int rc;
  do {
    rc = ::flock(fd, op | LOCK_NB);
  } while (rc != 0 && errno == EINTR);
  if (rc != 0) {
    const int err = errno;
    ::close(fd);
    if (err == EWOULDBLOCK)
      throw InputError("output directory '" + out_dir +
                       "' is in use by another assess campaign (lock '" + path +
                       "' is held): wait for it to finish, or choose another --out");
    throw InputError("cannot lock '" + path + "': " + std::strerror(err));
  }
  return fd;
}

}  // namespace

CampaignOutputLock::CampaignOutputLock(const std::string& out_dir, int part, int parts) {
  // A new or an existing folder; an existing regular file is refused by name.
  make_output_folder(out_dir, "--out");
  const std::string base = out_dir + "/.assess-lock";
  dir_fd_ = lock_file(base, parts > 1 ? LOCK_SH : LOCK_EX, out_dir);
  if (parts > 1) {
    try {
      part_fd_ = lock_file(base + ".part" + std::to_string(part) + "of" + std::to_string(parts), LOCK_EX, out_dir);
    } catch (...) {
      ::close(dir_fd_);
      throw;
    }
  }
}

CampaignOutputLock::~CampaignOutputLock() {
  if (part_fd_ >= 0) ::close(part_fd_);
  if (dir_fd_ >= 0) ::close(dir_fd_);
}

}  // namespace assess
