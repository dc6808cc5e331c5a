// devtools_browser.cpp: the DevTools protocol over Chromium's pipe
// (devtools_browser.hpp). One socket pair stands for the pipe (the browser
// reads its descriptor 3 and writes its 4, both our socket's other end; a
// socket writes with MSG_NOSIGNAL, so a browser that ended gives an error,
// not SIGPIPE). One reader thread files each answer under its id and each
// page's load event under its session; the callers wait for theirs.
#include "report/devtools_browser.hpp"

#include "assess/support/error.hpp"
#include "assess/support/termination.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <map>
#include <mutex>
#include <set>
#include <system_error>
#include <thread>

#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

namespace assess::detail {

namespace {

using Clock = std::chrono::steady_clock;

// RFC 4648 base 64, as the protocol sends binary data (printToPDF's `data`).
std::string base64_decode(const std::string& in) {
  static const auto table = [] {
    std::array<int, 256> t{};
    t.fill(-1);
    const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (int i = 0; i < 64; ++i) t[static_cast<unsigned char>(digits[i])] = i;
    return t;
  }();
  std::string out;
  out.reserve(in.size() / 4 * 3);
  unsigned bits = 0;
  int count = 0;
  for (unsigned char c : in) {
    const int v = table[c];
    if (v < 0) continue;  // '=' padding, line breaks
    bits = (bits << 6) | unsigned(v);
    if ((count += 6) >= 8) {
      count -= 8;
      out += char((bits >> count) & 0xFFu);
    }
  }
  return out;
}

// A descriptor moved above 4 and close-on-exec (the program receives it as 3 and 4 only).
int high_descriptor(int fd) {
  const int moved = ::fcntl(fd, F_DUPFD_CLOEXEC, 10);
  ::close(fd);
  return moved;
}

}  // namespace

std::string file_url(const std::filesystem::path& page) {
  static const char* hex = "0123456789ABCDEF";
  std::string url = "file://";
  for (unsigned char c : std::filesystem::absolute(page).string()) {
    if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') url += char(c);
    else url += std::string("%") + hex[c >> 4] + hex[c & 15];
  }
  return url;
}

struct DevtoolsBrowser::State {
  std::string program;
  int fd = -1;  // our end of the socket pair
  StartedProgram process;
  std::thread reader;
  std::mutex write_mutex;
  std::mutex mutex;  // guards what follows
  std::condition_variable changed;
  std::map<long, nlohmann::json> answers;
  std::set<std::string> loaded;  // sessions whose page fired its load event
  bool ended = false;            // the pipe is closed: the browser ended
  long next_id = 0;

  void read_messages() {
    std::string buffer;
    char chunk[1 << 16];
    for (;;) {
      const ssize_t n = ::recv(fd, chunk, sizeof chunk, 0);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      // A message ends at the first NUL of the new bytes (the ones before had none).
      std::size_t start = 0, from = buffer.size();
      buffer.append(chunk, std::size_t(n));
      for (std::size_t end; (end = buffer.find('\0', from)) != std::string::npos; start = from = end + 1) {
        nlohmann::json m = nlohmann::json::parse(buffer.begin() + long(start), buffer.begin() + long(end), nullptr, false);
        if (!m.is_object()) continue;
        std::lock_guard<std::mutex> lock(mutex);
        if (m.contains("id") && m["id"].is_number_integer()) {
          const long id = m["id"].get<long>();  // before the move (json's operator= takes its argument by value)
          answers[id] = std::move(m);
        } else if (m.contains("method") && m["method"] == "Page.loadEventFired" && m.contains("sessionId") &&
                   m["sessionId"].is_string()) {
          loaded.insert(m["sessionId"].get<std::string>());
        }
        changed.notify_all();
      }
      buffer.erase(0, start);
    }
    std::lock_guard<std::mutex> lock(mutex);
    ended = true;
    changed.notify_all();
  }

  [[noreturn]] void fail(const std::string& why) const { throw InputError("--pdf: " + program + " " + why); }

  // Sends one command and waits for its answer's result until `deadline`.
  nlohmann::json call(const std::string& method, nlohmann::json params, const std::string& session,
                      Clock::time_point deadline) {
    long id = 0;
    {
      std::lock_guard<std::mutex> lock(mutex);
      id = ++next_id;
    }
    nlohmann::json m = {{"id", id}, {"method", method}, {"params", std::move(params)}};
    if (!session.empty()) m["sessionId"] = session;
    const std::string text = m.dump() + '\0';
    {
      std::lock_guard<std::mutex> lock(write_mutex);
      for (std::size_t sent = 0; sent < text.size();) {
        const ssize_t n = ::send(fd, text.data() + sent, text.size() - sent, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail("ended before it finished printing");
        sent += std::size_t(n);
      }
    }
    std::unique_lock<std::mutex> lock(mutex);
    if (!changed.wait_until(lock, deadline, [&] { return answers.count(id) || ended; }))
      throw std::system_error(std::make_error_code(std::errc::timed_out));
    if (!answers.count(id)) fail("ended before it finished printing");
    nlohmann::json answer = std::move(answers[id]);
    answers.erase(id);
    lock.unlock();
    if (answer.contains("error")) {
      const nlohmann::json& e = answer["error"];
      fail("refused " + method + ": " +
           (e.is_object() && e.contains("message") && e["message"].is_string() ? e["message"].get<std::string>() : e.dump()));
    }
    const nlohmann::json result = answer.value("result", nlohmann::json::object());
    if (!result.is_object()) fail("answered " + method + " with no result");
    return result;
  }

  // Closes the browser (Browser.close when `polite`; its group killed after
  // 10 s) and ends the reader.
  void stop(bool polite) {
    if (polite) {
      const std::string bye =
          nlohmann::json({{"id", 0}, {"method", "Browser.close"}, {"params", nlohmann::json::object()}}).dump() + '\0';
      (void)!::send(fd, bye.data(), bye.size(), MSG_NOSIGNAL);
    }
    wait_program(process, polite ? 10 : 0);
    ::shutdown(fd, SHUT_RDWR);
    if (reader.joinable()) reader.join();
    ::close(fd);
    fd = -1;
  }

  void wait_loaded(const std::string& session, Clock::time_point deadline) {
    std::unique_lock<std::mutex> lock(mutex);
    if (!changed.wait_until(lock, deadline, [&] { return loaded.count(session) || ended; }))
      throw std::system_error(std::make_error_code(std::errc::timed_out));
    if (!loaded.count(session)) fail("ended before it finished printing");
    loaded.erase(session);
  }
};

DevtoolsBrowser::DevtoolsBrowser(const std::string& program, const std::filesystem::path& dir, int timeout_s)
    : s_(std::make_unique<State>()) {
  s_->program = program;
  int pair[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0)
    throw SystemError("--pdf: cannot make a pipe for " + program + ": " + std::strerror(errno));
  s_->fd = high_descriptor(pair[0]);
  const int theirs = high_descriptor(pair[1]);
  s_->process = start_program({program, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                               "--disable-background-networking", "--disable-component-update", "--disable-sync",
                               "--user-data-dir=" + (dir / "profile").string(), "--remote-debugging-pipe"},
                              (dir / "chromium.log").string(), dir.string(), {{3, theirs}, {4, theirs}});
  ::close(theirs);
  if (!s_->process.result.started) {
    ::close(s_->fd);
    const int err = s_->process.result.start_error;
    if (err == ENOENT)
      throw InputError("--pdf: " + program + " was not found on PATH: install it (Debian: apt-get install chromium)");
    throw InputError("--pdf: cannot start " + program + ": " + std::strerror(err));
  }
  s_->reader = std::thread([s = s_.get()] { s->read_messages(); });
  try {
    s_->call("Browser.getVersion", nlohmann::json::object(), "", Clock::now() + std::chrono::seconds(timeout_s));
  } catch (const std::exception&) {
    // Exited, closed the pipe or never answered: not a DevTools browser.
    s_->stop(false);
    throw DevtoolsUnavailable(program + " does not answer on its DevTools pipe");
  }
}

DevtoolsBrowser::~DevtoolsBrowser() {
  if (s_ && s_->fd >= 0) s_->stop(true);
}

std::string DevtoolsBrowser::print(const std::filesystem::path& page, bool bookmarks, int timeout_s) {
  const auto deadline = Clock::now() + std::chrono::seconds(timeout_s);
  using nlohmann::json;
  try {
    const std::string target = s_->call("Target.createTarget", {{"url", "about:blank"}}, "", deadline).value("targetId", "");
    const std::string session =
        s_->call("Target.attachToTarget", {{"targetId", target}, {"flatten", true}}, "", deadline).value("sessionId", "");
    s_->call("Page.enable", json::object(), session, deadline);
    const json nav = s_->call("Page.navigate", {{"url", file_url(page)}}, session, deadline);
    if (!nav.value("errorText", "").empty()) s_->fail("could not open the page: " + nav.value("errorText", ""));
    s_->wait_loaded(session, deadline);
    // As `--print-to-pdf --no-pdf-header-footer --generate-pdf-document-outline` prints.
    const json pdf = s_->call("Page.printToPDF",
                              {{"printBackground", true},
                               {"preferCSSPageSize", true},
                               {"displayHeaderFooter", false},
                               {"generateTaggedPDF", bookmarks},
                               {"generateDocumentOutline", bookmarks}},
                              session, deadline);
    s_->call("Target.closeTarget", {{"targetId", target}}, "", deadline);
    return base64_decode(pdf.value("data", ""));
  } catch (const std::system_error&) {
    s_->fail("did not finish printing within its time limit (" + std::to_string(timeout_s) + " s)");
  } catch (const nlohmann::json::exception&) {
    s_->fail("sent an answer of an unexpected form");  // a field of the wrong type
  }
}

}  // namespace assess::detail
