// content_hash.cpp: FNV-1a 64 (content_hash.hpp).
#include "assess/support/content_hash.hpp"

#include "assess/support/error.hpp"

#include <cstdio>

namespace assess {

std::uint64_t content_hash(const void* data, std::size_t size, std::uint64_t h) {
  const unsigned char* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    h ^= p[i];
    h *= 1099511628211ull;
  }
  return h;
}

std::uint64_t content_hash(const std::string& bytes) { return content_hash(bytes.data(), bytes.size()); }

std::string hash_hex(std::uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::uint64_t file_content_hash(const std::string& path, const InputKind& kind) {
  return content_hash(read_input_file(path, kind));
}

}  // namespace assess
