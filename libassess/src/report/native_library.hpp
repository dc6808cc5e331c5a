// native_library.hpp (private to the report layer): a shared library of the
// system loaded when a writer first needs it (dlopen), not linked into the
// executable: the Word writer's zip (libzip), SVG renderer (librsvg, cairo)
// and deflate (zlib) would otherwise be loaded at every command's start-up,
// which loads libc and libm alone (issue 32; README "Speed"). Each function
// is looked up by its name and given the type of its declaration in the
// library's own header (decltype), so a changed signature fails to compile.
#pragma once

#include "assess/support/error.hpp"

#include <dlfcn.h>

#include <string>

namespace assess::detail {

class NativeLibrary {
 public:
  /// Loads `soname` ("libzip.so.4"); `package` is the Debian package that has it.
  NativeLibrary(const char* soname, const char* package) : soname_(soname), package_(package) {
    handle_ = ::dlopen(soname, RTLD_NOW | RTLD_LOCAL);
    if (!handle_) error_ = dlerror_text();
  }
  NativeLibrary(const NativeLibrary&) = delete;
  NativeLibrary& operator=(const NativeLibrary&) = delete;
  // Never unloaded: a library such as librsvg registers types in GLib that
  // outlive it, and the writers may run again in the same process.

  /// The function `name` of the library (or of a library it depends on), or
  /// nullptr, the first failure kept for error().
  template <class F>
  F* symbol(const char* name) {
    if (!handle_) return nullptr;
    void* p = ::dlsym(handle_, name);
    if (!p && error_.empty()) error_ = "it has no function " + std::string(name);
    return reinterpret_cast<F*>(p);
  }

  /// Throws InputError("<what>: cannot load <soname> (<reason>): install the
  /// Debian package <package>") when the library or one of its functions is missing.
  void require(const std::string& what) const {
    if (!error_.empty())
      throw InputError(what + ": cannot load " + soname_ + " (" + error_ + "): install the Debian package " + package_);
  }

 private:
  static std::string dlerror_text() {
    const char* e = ::dlerror();
    return e ? e : "unknown reason";
  }
  std::string soname_, package_, error_;
  void* handle_ = nullptr;
};

}  // namespace assess::detail

/// Looks up the function `name` in `lib` with the type of its declaration.
#define ASSESS_NATIVE(lib, name) (lib).symbol<decltype(::name)>(#name)
