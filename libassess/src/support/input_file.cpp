// input_file.cpp: the bounded reader of every input file (input_file.hpp).
#include "assess/support/input_file.hpp"

#include "assess/support/error.hpp"
#include "assess/support/output_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace assess {
namespace {

std::string type_of(mode_t m) {
  if (S_ISREG(m)) return "";
  if (S_ISDIR(m)) return "a directory";
  if (S_ISCHR(m)) return "a character device";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISFIFO(m)) return "a FIFO (named pipe)";
  if (S_ISSOCK(m)) return "a socket";
  return "not a regular file";
}

std::string megabytes(std::size_t bytes) {
  char b[32];
  if (bytes >= (std::size_t{1} << 20))
    std::snprintf(b, sizeof b, "%.0f MB", static_cast<double>(bytes) / (1 << 20));
  else
    std::snprintf(b, sizeof b, "%zu bytes", bytes);
  return b;
}

// Errors of the machine (an I/O error, no memory, no file descriptor left)
// are SystemError; the rest are the user's choice of file (InputError).
[[noreturn]] void fail_errno(const std::string& path, const std::string& doing, int err) {
  const std::string msg = path + ": " + doing + ": " + std::strerror(err);
  if (err == EIO || err == ENOMEM || err == EMFILE || err == ENFILE || err == ENOBUFS) throw SystemError(msg);
  throw InputError(msg);
}

struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

// Opens `path` for reading without blocking (a FIFO with no writer would
// block a plain open) and checks what it is.
void open_checked(const std::string& path, const InputKind& kind, Fd& f, struct stat& st) {
  if (path.empty()) throw InputError(std::string("empty file name, expected a ") + kind.what);
  f.fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (f.fd < 0) {
    const int err = errno;
    // A directory opens read-only on Linux; other failures name the reason.
    fail_errno(path, std::string("cannot open the ") + kind.what, err);
  }
  if (::fstat(f.fd, &st) != 0) fail_errno(path, std::string("cannot read the ") + kind.what, errno);
  const std::string t = type_of(st.st_mode);
  if (!t.empty()) throw InputError(path + ": is " + t + ", expected a " + kind.what + " (a regular file)");
  if (static_cast<unsigned long long>(st.st_size) > kind.max_bytes)
    throw InputError(path + ": " + megabytes(static_cast<std::size_t>(st.st_size)) + " is more than the limit of " +
                     megabytes(kind.max_bytes) + " for a " + kind.what);
}

}  // namespace

std::string non_regular_file_type(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return "";
  return type_of(st.st_mode);
}

void check_input_file(const std::string& path, const InputKind& kind) {
  Fd f;
  struct stat st {};
  open_checked(path, kind, f, st);
}

std::string read_input_file(const std::string& path, const InputKind& kind) {
  Fd f;
  struct stat st {};
  open_checked(path, kind, f, st);
  if (kind.protect) protect_input(path);
  // A regular file: no longer blocking reads matter, but its size may change
  // (or be 0 under /proc): read until end of file, never past the limit.
  std::string out;
  try {
    out.reserve(static_cast<std::size_t>(st.st_size));
    char buf[1 << 16];
    while (true) {
      const ssize_t n = ::read(f.fd, buf, sizeof buf);
      if (n < 0) {
        if (errno == EINTR || errno == EAGAIN) continue;
        fail_errno(path, std::string("cannot read the ") + kind.what, errno);
      }
      if (n == 0) break;
      if (out.size() + static_cast<std::size_t>(n) > kind.max_bytes)
        throw InputError(path + ": more than the limit of " + megabytes(kind.max_bytes) + " for a " + kind.what);
      out.append(buf, static_cast<std::size_t>(n));
    }
  } catch (const std::bad_alloc&) {
    throw SystemError(path + ": out of memory while reading the " + std::string(kind.what) + " (" +
                      megabytes(static_cast<std::size_t>(st.st_size)) + ")");
  }
  return out;
}

}  // namespace assess
