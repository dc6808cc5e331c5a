// pdf_bookmarks.cpp: named destinations read with pdfinfo, bookmarks
// written as a qpdf JSON update (pdf_bookmarks.hpp).
#include "report/pdf_bookmarks.hpp"

#include "report/external_tool.hpp"

#include "assess/support/error.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>

namespace assess::detail {

namespace {

// qpdf's JSON of one object of `pdf` ("trailer" or "N 0 R"): the array under
// the key "qpdf" (its header first, then the object).
nlohmann::json qpdf_object(const std::filesystem::path& pdf, const std::string& object, const std::filesystem::path& dir,
                           int* status) {
  const std::filesystem::path log = dir / "qpdf-json.log";
  *status = run_program({"qpdf", "--no-warn", "--json=2", "--json-key=qpdf", "--json-object=" + object, pdf.string()}, log);
  if (*status != 0) return nullptr;
  return nlohmann::json::parse(read_file(log), nullptr, false);
}

// A PDF name in qpdf's JSON: "/" and the name, every byte outside the
// regular characters written #xx (PDF 1.7 §7.3.5).
std::string pdf_name(const std::string& s) {
  std::string out = "/";
  char hex[4];
  for (unsigned char c : s) {
    if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.') {
      out += char(c);
    } else {
      std::snprintf(hex, sizeof hex, "#%02X", c);
      out += hex;
    }
  }
  return out;
}

std::string ref(long n) { return std::to_string(n) + " 0 R"; }

}  // namespace

std::map<std::string, int> pdf_destinations(const std::filesystem::path& pdf, const std::filesystem::path& dir) {
  std::map<std::string, int> pages;
  const std::filesystem::path log = dir / "dests.txt";
  if (run_program({"pdfinfo", "-dests", pdf.string()}, log) != 0) return pages;
  // "   3 [ XYZ    0  724 null      ] "premessa"": the page, the destination, the quoted name.
  std::istringstream in(read_file(log));
  for (std::string line; std::getline(in, line);) {
    const std::size_t open = line.find('"'), close = line.rfind('"');
    if (open == std::string::npos || close <= open) continue;
    int page = 0;
    if (std::sscanf(line.c_str(), "%d", &page) != 1 || page < 1) continue;
    pages.emplace(line.substr(open + 1, close - open - 1), page);
  }
  return pages;
}

bool write_bookmarks_update(const std::filesystem::path& pdf, const std::vector<Bookmark>& bookmarks,
                            const std::filesystem::path& update, const std::filesystem::path& dir) {
  using nlohmann::json;
  int status = 0;
  const json trailer = qpdf_object(pdf, "trailer", dir, &status);
  if (status == program_not_found) return false;
  auto unreadable = [&] {
    return InputError("--pdf: qpdf could not read the printed PDF's catalog (exit " + std::to_string(status) + ")");
  };
  if (!trailer.is_object() || !trailer.contains("qpdf") || trailer["qpdf"].size() < 2) throw unreadable();
  const long max_id = trailer["qpdf"][0].value("maxobjectid", 0L);
  const std::string root = trailer["qpdf"][1]["trailer"]["value"].value("/Root", "");
  const json catalog_json = qpdf_object(pdf, root, dir, &status);
  if (max_id < 1 || root.empty() || !catalog_json.is_object() || !catalog_json.contains("qpdf") ||
      catalog_json["qpdf"].size() < 2)
    throw unreadable();
  json catalog = catalog_json["qpdf"][1]["obj:" + root]["value"];
  if (!catalog.is_object()) throw unreadable();

  // The tree: each bookmark's parent is the nearest earlier one of a lower level.
  const long top = max_id + 1;  // the outline dictionary; bookmark i is object top + 1 + i
  const long n = long(bookmarks.size());
  std::vector<long> parent(bookmarks.size(), top), first(bookmarks.size(), 0), last(bookmarks.size(), 0),
      prev(bookmarks.size(), 0), next(bookmarks.size(), 0), count(bookmarks.size(), 0);
  long top_first = 0, top_last = 0;
  std::vector<long> stack;  // open ancestors (indices)
  for (long i = 0; i < n; ++i) {
    while (!stack.empty() && bookmarks[std::size_t(stack.back())].level >= bookmarks[std::size_t(i)].level) stack.pop_back();
    const long up = stack.empty() ? -1 : stack.back();
    long& f = up < 0 ? top_first : first[std::size_t(up)];
    long& l = up < 0 ? top_last : last[std::size_t(up)];
    const long obj = top + 1 + i;
    if (f == 0) f = obj;
    else {
      prev[std::size_t(i)] = l;
      next[std::size_t(l - top - 1)] = obj;
    }
    l = obj;
    parent[std::size_t(i)] = up < 0 ? top : top + 1 + up;
    for (long a : stack) ++count[std::size_t(a)];  // every item open: its count is its descendants'
    stack.push_back(i);
  }
  json objects = json::object();
  catalog["/Outlines"] = ref(top);
  catalog["/PageMode"] = "/UseOutlines";
  objects["obj:" + root] = {{"value", catalog}};
  json outline = {{"/Type", "/Outlines"}, {"/Count", n}};
  if (top_first) {
    outline["/First"] = ref(top_first);
    outline["/Last"] = ref(top_last);
  }
  objects["obj:" + ref(top)] = {{"value", outline}};
  for (long i = 0; i < n; ++i) {
    const Bookmark& b = bookmarks[std::size_t(i)];
    json item = {{"/Title", "u:" + b.title}, {"/Parent", ref(parent[std::size_t(i)])}, {"/Dest", pdf_name(b.destination)}};
    if (prev[std::size_t(i)]) item["/Prev"] = ref(prev[std::size_t(i)]);
    if (next[std::size_t(i)]) item["/Next"] = ref(next[std::size_t(i)]);
    if (first[std::size_t(i)]) {
      item["/First"] = ref(first[std::size_t(i)]);
      item["/Last"] = ref(last[std::size_t(i)]);
      item["/Count"] = count[std::size_t(i)];
    }
    objects["obj:" + ref(top + 1 + i)] = {{"value", item}};
  }
  const json header = {{"jsonversion", 2},
                       {"pushedinheritedpageresources", false},
                       {"calledgetallpages", false},
                       {"maxobjectid", max_id}};
  write_file(update, json({{"qpdf", json::array({header, objects})}}).dump(), "--pdf");
  return true;
}

}  // namespace assess::detail
