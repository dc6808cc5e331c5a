// once_value.hpp (private): a value computed once per process and shared by
// every thread that asks for it, or the error its computation gave (issue 39,
// class 1).
//
// std::call_once must not be left by an exception here: with the static
// runtime (ASSESS_STATIC_RUNTIME) an exception unwinding through
// pthread_once's frame aborted the process (SIGABRT, no message: `assess
// records select --mw-min 7 --mw-max 5`, a record file changed since
// `assess records build`). The work runs inside a noexcept function that
// keeps either its value or its exception; the exception is rethrown to
// every caller after call_once has returned, so each caller gets the same
// clear message (InputError: exit 2, SystemError: exit 1).
#pragma once

#include <exception>
#include <memory>
#include <mutex>

namespace assess::detail {

template <typename T>
class OnceValue {
 public:
  /// The value of `work()` (a std::shared_ptr<const T>), computed by the
  /// first caller while the others wait; or the exception it threw,
  /// rethrown here to every caller.
  template <typename Work>
  std::shared_ptr<const T> get(Work&& work) {
    std::call_once(once_, [&]() noexcept {
      try {
        value_ = work();
      } catch (...) {
        error_ = std::current_exception();
      }
    });
    if (error_) std::rethrow_exception(error_);
    return value_;
  }

 private:
  std::once_flag once_;
  std::shared_ptr<const T> value_;
  std::exception_ptr error_;
};

}  // namespace assess::detail
