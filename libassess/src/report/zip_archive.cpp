// zip_archive.cpp: zip archives in memory through libzip, loaded at run time.
#include "report/zip_archive.hpp"

#include "report/native_library.hpp"

#include "assess/support/error.hpp"

#include <zip.h>

#include <ctime>
#include <memory>

namespace assess::detail {

namespace {

// The functions of libzip the writer uses, looked up once (thread-safe static).
struct Libzip {
  NativeLibrary lib{"libzip.so.4", "libzip4"};
  decltype(&::zip_error_init) error_init = ASSESS_NATIVE(lib, zip_error_init);
  decltype(&::zip_error_fini) error_fini = ASSESS_NATIVE(lib, zip_error_fini);
  decltype(&::zip_error_strerror) error_strerror = ASSESS_NATIVE(lib, zip_error_strerror);
  decltype(&::zip_strerror) strerror = ASSESS_NATIVE(lib, zip_strerror);
  decltype(&::zip_source_buffer_create) source_buffer_create = ASSESS_NATIVE(lib, zip_source_buffer_create);
  decltype(&::zip_source_buffer) source_buffer = ASSESS_NATIVE(lib, zip_source_buffer);
  decltype(&::zip_source_keep) source_keep = ASSESS_NATIVE(lib, zip_source_keep);
  decltype(&::zip_source_free) source_free = ASSESS_NATIVE(lib, zip_source_free);
  decltype(&::zip_source_open) source_open = ASSESS_NATIVE(lib, zip_source_open);
  decltype(&::zip_source_read) source_read = ASSESS_NATIVE(lib, zip_source_read);
  decltype(&::zip_source_close) source_close = ASSESS_NATIVE(lib, zip_source_close);
  decltype(&::zip_open_from_source) open_from_source = ASSESS_NATIVE(lib, zip_open_from_source);
  decltype(&::zip_file_add) file_add = ASSESS_NATIVE(lib, zip_file_add);
  decltype(&::zip_set_file_compression) set_file_compression = ASSESS_NATIVE(lib, zip_set_file_compression);
  decltype(&::zip_file_set_mtime) file_set_mtime = ASSESS_NATIVE(lib, zip_file_set_mtime);
  decltype(&::zip_close) close = ASSESS_NATIVE(lib, zip_close);
  decltype(&::zip_discard) discard = ASSESS_NATIVE(lib, zip_discard);
  decltype(&::zip_get_num_entries) get_num_entries = ASSESS_NATIVE(lib, zip_get_num_entries);
  decltype(&::zip_get_name) get_name = ASSESS_NATIVE(lib, zip_get_name);
  decltype(&::zip_stat_init) stat_init = ASSESS_NATIVE(lib, zip_stat_init);
  decltype(&::zip_stat_index) stat_index = ASSESS_NATIVE(lib, zip_stat_index);
  decltype(&::zip_fopen_index) fopen_index = ASSESS_NATIVE(lib, zip_fopen_index);
  decltype(&::zip_fread) fread = ASSESS_NATIVE(lib, zip_fread);
  decltype(&::zip_fclose) fclose = ASSESS_NATIVE(lib, zip_fclose);
};

const Libzip& libzip(const std::string& what) {
  static Libzip z;
  z.lib.require(what);
  return z;
}

// A zip_error_t freed on every path.
struct ZipError {
  const Libzip& z;
  zip_error_t e;
  explicit ZipError(const Libzip& lz) : z(lz) { z.error_init(&e); }
  ~ZipError() { z.error_fini(&e); }
  std::string text() { return z.error_strerror(&e); }
};

// 2024-01-01 00:00 UTC, the date of every member (reproducible bytes).
constexpr std::time_t member_time = 1704067200;

}  // namespace

std::vector<ZipEntry> read_zip(std::string_view bytes, const std::string& what) {
  const Libzip& z = libzip(what);
  ZipError err(z);
  zip_source_t* src = z.source_buffer_create(bytes.data(), bytes.size(), 0, &err.e);
  if (!src) throw InputError(what + ": cannot read the zip archive: " + err.text());
  zip_t* za = z.open_from_source(src, ZIP_RDONLY, &err.e);
  if (!za) {
    z.source_free(src);
    throw InputError(what + ": cannot read the zip archive: " + err.text());
  }
  std::unique_ptr<zip_t, decltype(z.discard)> archive(za, z.discard);  // frees the source too
  std::vector<ZipEntry> out;
  const zip_int64_t n = z.get_num_entries(za, 0);
  for (zip_int64_t i = 0; i < n; ++i) {
    zip_stat_t st;
    z.stat_init(&st);
    const char* name = z.get_name(za, zip_uint64_t(i), 0);
    zip_file_t* f = name && z.stat_index(za, zip_uint64_t(i), 0, &st) == 0 && (st.valid & ZIP_STAT_SIZE)
                        ? z.fopen_index(za, zip_uint64_t(i), 0)
                        : nullptr;
    if (!f) throw InputError(what + ": cannot read member " + std::to_string(i) + " of the zip archive: " + z.strerror(za));
    ZipEntry e{name, std::string(st.size, '\0')};
    const zip_int64_t got = st.size ? z.fread(f, e.data.data(), st.size) : 0;
    z.fclose(f);
    if (got != zip_int64_t(st.size)) throw InputError(what + ": cannot read " + e.name + " of the zip archive");
    out.push_back(std::move(e));
  }
  return out;
}

std::string write_zip(const std::vector<ZipEntry>& entries, const std::string& what) {
  const Libzip& z = libzip(what);
  ZipError err(z);
  zip_source_t* buffer = z.source_buffer_create(nullptr, 0, 0, &err.e);
  if (!buffer) throw InputError(what + ": cannot make the zip archive: " + err.text());
  std::unique_ptr<zip_source_t, decltype(z.source_free)> keep(buffer, z.source_free);
  zip_t* za = z.open_from_source(buffer, ZIP_TRUNCATE, &err.e);
  if (!za) throw InputError(what + ": cannot make the zip archive: " + err.text());
  z.source_keep(buffer);  // the archive's close writes into it; ours to read and free
  auto fail = [&](const std::string& step) {
    const std::string reason = z.strerror(za);
    z.discard(za);
    throw InputError(what + ": cannot make the zip archive (" + step + "): " + reason);
  };
  for (const ZipEntry& e : entries) {
    zip_source_t* s = z.source_buffer(za, e.data.data(), e.data.size(), 0);
    if (!s) fail(e.name);
    const zip_int64_t k = z.file_add(za, e.name.c_str(), s, ZIP_FL_ENC_UTF_8);
    if (k < 0) {
      z.source_free(s);
      fail(e.name);
    }
    if (z.set_file_compression(za, zip_uint64_t(k), e.deflate ? ZIP_CM_DEFLATE : ZIP_CM_STORE, 0) != 0 ||
        z.file_set_mtime(za, zip_uint64_t(k), member_time, 0) != 0)
      fail(e.name);
  }
  if (z.close(za) != 0) fail("close");
  std::string out;
  if (z.source_open(buffer) != 0) throw InputError(what + ": cannot read the zip archive made");
  char chunk[1 << 16];
  for (zip_int64_t n; (n = z.source_read(buffer, chunk, sizeof chunk)) > 0;) out.append(chunk, std::size_t(n));
  z.source_close(buffer);
  return out;
}

}  // namespace assess::detail
