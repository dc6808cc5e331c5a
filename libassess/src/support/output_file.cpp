// output_file.cpp: the atomic, guarded writer of every output (output_file.hpp).
#include "assess/support/output_file.hpp"

#include "assess/support/error.hpp"
#include "assess/support/termination.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace assess {
namespace fs = std::filesystem;
namespace {

std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
std::set<std::pair<dev_t, ino_t>>& registry() {
  static std::set<std::pair<dev_t, ino_t>> r;
  return r;
}

// A failure of the machine (exit status 1) or of the user's choice (2).
bool machine_failure(int err) {
  return err == ENOSPC || err == EDQUOT || err == EIO || err == ENOMEM || err == EFBIG || err == EMFILE ||
         err == ENFILE || err == ENOBUFS;
}
[[noreturn]] void fail(const std::string& what, const std::string& path, const std::string& doing, int err) {
  const std::string msg = what + ": " + path + ": " + doing + ": " + std::strerror(err);
  if (machine_failure(err)) throw SystemError(msg);
  throw InputError(msg);
}

// Writes all of `content` to `fd`; returns 0 or the errno of the failure.
int write_all(int fd, const std::string& content) {
  const char* p = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return 0;
}

std::string file_type(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISSOCK(m)) return "a socket";
  return "not a regular file";
}

bool inside(const fs::path& p, const fs::path& folder) {
  auto f = folder.begin(), q = p.begin();
  for (; f != folder.end(); ++f, ++q)
    if (q == p.end() || *f != *q) return false;
  return true;
}

}  // namespace

void protect_input(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return;
  std::lock_guard<std::mutex> lock(registry_mutex());
  registry().insert({st.st_dev, st.st_ino});
}

bool is_protected_input(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return false;
  std::lock_guard<std::mutex> lock(registry_mutex());
  return registry().count({st.st_dev, st.st_ino}) > 0;
}

void make_output_folder(const std::string& dir, const std::string& what) {
  if (dir.empty()) throw InputError(what + ": empty folder name");
  struct stat st {};
  if (::stat(dir.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) return;
    throw InputError(what + ": " + dir + ": is " + (S_ISREG(st.st_mode) ? std::string("a regular file") : file_type(st.st_mode)) +
                     ", expected a folder (give a new or an existing folder)");
  }
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    const int err = ec.value();
    fail(what, dir, "cannot create the folder", err);
  }
}

namespace {

// The file an output goes to: `path`, or the target of a link that stays in
// the asked folder. Refuses a link out of it, a directory, a protected input.
// `device`: the target is a character device or a FIFO (written in place).
std::string resolve_output(const std::string& path, const std::string& what, const std::string& folder,
                           struct stat& st, bool& exists, bool& device) {
  if (path.empty()) throw InputError(what + ": empty file name");
  std::string target = path;
  struct stat lst {};
  if (::lstat(path.c_str(), &lst) == 0 && S_ISLNK(lst.st_mode)) {
    // A link: followed only when it leads to a file inside the asked folder
    // (followed by hand: weakly_canonical stops at a dangling link).
    std::error_code ec;
    fs::path to = fs::path(path);
    for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(to, ec)); ++hops) {
      const fs::path next = fs::read_symlink(to, ec);
      if (ec) break;
      to = next.is_absolute() ? next : to.parent_path() / next;
    }
    to = fs::weakly_canonical(to, ec);
    fs::path parent = folder.empty() ? fs::path(path).parent_path() : fs::path(folder);
    if (parent.empty()) parent = ".";
    const fs::path in = fs::weakly_canonical(parent, ec);
    if (ec || to.empty() || !inside(to, in))
      throw InputError(what + ": " + path + " is a symbolic link to " + (to.empty() ? std::string("?") : to.string()) +
                       ", outside " + parent.string() + ": refusing to write through it (remove the link or "
                       "choose another name)");
    target = to.string();
  }
  exists = ::stat(target.c_str(), &st) == 0;
  device = exists && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode));
  if (exists && !S_ISREG(st.st_mode) && !device)
    throw InputError(what + ": " + path + ": is " + file_type(st.st_mode) + ", expected a file name");
  if (exists && !device) {
    std::lock_guard<std::mutex> lock(registry_mutex());
    if (registry().count({st.st_dev, st.st_ino}))
      throw InputError(what + ": " + path + " is an input of this run: refusing to replace it with an output "
                       "(choose another name)");
  }
  if (!exists) {
    const fs::path t(target);
    const std::string dir = t.has_parent_path() ? t.parent_path().string() : ".";
    struct stat dst {};
    if (::stat(dir.c_str(), &dst) != 0 || !S_ISDIR(dst.st_mode))
      throw InputError(what + ": " + path + ": no folder '" + dir + "' to write it in");
  }
  return target;
}

}  // namespace

void check_output_file(const std::string& path, const std::string& what, const std::string& folder) {
  struct stat st {};
  bool exists = false, device = false;
  resolve_output(path, what, folder, st, exists, device);
}

void write_output_file(const std::string& path, const std::string& content, const std::string& what,
                       const std::string& folder) {
  struct stat st {};
  bool exists = false, device = false;
  const std::string target = resolve_output(path, what, folder, st, exists, device);
  if (device) {
    // /dev/null, /dev/stdout, a pipe: written in place (a rename would replace the device node).
    const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) fail(what, path, "cannot open for writing", errno);
    const int err = write_all(fd, content);
    const int cerr = ::close(fd) != 0 ? errno : 0;
    if (err) fail(what, path, "cannot write", err);
    if (cerr && cerr != EINTR) fail(what, path, "cannot write", cerr);
    return;
  }
  // The temporary file beside the target (same file system: rename is atomic).
  const fs::path t(target);
  const std::string dir = t.has_parent_path() ? t.parent_path().string() : ".";
  // Registered while it exists: a SIGINT or SIGTERM removes it (termination.hpp).
  std::string tmp = dir + "/." + t.filename().string() + ".tmp.XXXXXX";
  const int fd = make_temporary_file(tmp);
  if (fd < 0) {
    const int err = errno;
    struct stat dst {};
    if (::stat(dir.c_str(), &dst) != 0) fail(what, path, "no such folder '" + dir + "'", err);
    fail(what, path, "cannot create a file in '" + dir + "'", err);
  }
  // The permissions a new file gets (umask), or those of the file replaced.
  mode_t mode = 0;
  if (exists) {
    mode = st.st_mode & 07777;
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  int err = ::fchmod(fd, mode) != 0 ? errno : 0;
  if (!err) err = write_all(fd, content);
  if (::close(fd) != 0 && !err) err = errno;
  if (err) {
    ::unlink(tmp.c_str());
    release_temporary(tmp);
    fail(what, path, "cannot write", err);
  }
  if (::rename(tmp.c_str(), target.c_str()) != 0) {
    err = errno;
    ::unlink(tmp.c_str());
    release_temporary(tmp);
    fail(what, path, "cannot replace the file", err);
  }
  release_temporary(tmp);
}

void check_output_files(const std::vector<OutputTarget>& outputs) {
  // Each output's file: by device and inode when it exists, else by its
  // folder's device and inode and its name (after following a link that
  // stays in its folder), so that "r.pdf", "./r.pdf", "d/../r.pdf", a hard
  // link and a link to it are one file.
  struct Identity {
    dev_t dev;
    ino_t ino;
    std::string name;
    bool operator<(const Identity& o) const { return std::tie(dev, ino, name) < std::tie(o.dev, o.ino, o.name); }
  };
  std::map<Identity, const OutputTarget*> seen;
  for (const OutputTarget& o : outputs) {
    struct stat st {};
    bool exists = false, device = false;
    const std::string target = resolve_output(o.path, o.what, o.folder, st, exists, device);
    if (device) continue;  // /dev/null, /dev/stdout, a pipe: written in place, nothing replaced
    Identity id{st.st_dev, st.st_ino, ""};
    if (!exists) {
      const fs::path t(target);
      struct stat dst {};
      if (::stat((t.has_parent_path() ? t.parent_path().string() : std::string(".")).c_str(), &dst) != 0) continue;
      id = Identity{dst.st_dev, dst.st_ino, t.filename().string()};
    }
    const auto [it, fresh] = seen.emplace(id, &o);
    if (!fresh)
      throw InputError(it->second->what + " " + it->second->path + " and " + o.what + " " + o.path +
                       " are the same file: one output would replace the other (give each its own file name)");
  }
}

}  // namespace assess
