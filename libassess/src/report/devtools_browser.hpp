// devtools_browser.hpp (private to the report layer): one headless Chromium
// for every PDF of a run, driven through its DevTools protocol on a pipe
// (`--remote-debugging-pipe`: the browser reads commands on its descriptor 3
// and answers on 4, each message a JSON text ended by a NUL byte). Each print
// is a tab of its own, so that several pages print side by side from several
// threads while the browser starts once (a start costs about 1.7 CPU-seconds,
// issue 36 item 7). Knows nothing of reports: a page file in, PDF bytes out.
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

namespace assess::detail {

/// The file:// URL of `page` (made absolute), every byte outside the
/// unreserved characters and '/' percent-encoded: a TMPDIR may hold spaces,
/// '#' or '%'.
std::string file_url(const std::filesystem::path& page);

/// The program started but does not speak the protocol on the pipe (it
/// exited or never answered): the caller prints without it.
struct DevtoolsUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class DevtoolsBrowser {
 public:
  /// Starts `program` (a Chromium: headless, no sandbox, its profile and
  /// TMPDIR in `dir`) and waits for its first answer, at most `timeout_s`
  /// seconds. @throws InputError naming the program when it is not found on
  /// PATH or cannot start; DevtoolsUnavailable when it does not answer.
  DevtoolsBrowser(const std::string& program, const std::filesystem::path& dir, int timeout_s = 60);
  /// Closes the browser (Browser.close; its process group killed after 10 s).
  ~DevtoolsBrowser();
  DevtoolsBrowser(const DevtoolsBrowser&) = delete;
  DevtoolsBrowser& operator=(const DevtoolsBrowser&) = delete;

  /// The bytes of the PDF of the HTML file `page`, printed in a new tab as
  /// `chromium --print-to-pdf` prints it: the page size of its @page rule,
  /// backgrounds, no header or footer line and, with `bookmarks`, a tagged
  /// PDF with bookmarks from the headings (without: a quarter less work, for
  /// a print laid over another). Safe to call from several threads at once.
  /// @throws InputError naming the program when the browser fails, ends or
  /// takes more than `timeout_s` seconds.
  std::string print(const std::filesystem::path& page, bool bookmarks = true, int timeout_s = 180);

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace assess::detail
