// json_input.cpp: path-tracking JSON reader (input errors name file, JSON
// path, expected type or range, and unit).
#include "assess/support/json_input.hpp"

#include "assess/support/error.hpp"
#include "assess/support/input_file.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace assess {
namespace {
std::string num(double v) { return number_for_message(v); }
const char* type_name(const nlohmann::json& j) { return j.type_name(); }
}  // namespace

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

namespace {

// A SAX handler that only tracks the JSON pointer of the value being read, so
// that a parse error (a number that overflows a double, a syntax error) names
// where it happened. Used on the error path only (a second, DOM-less pass).
class PathTracker final : public nlohmann::json_sax<nlohmann::json> {
 public:
  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    value();
    frames_.push_back({false, "", -1});
    return true;
  }
  bool key(string_t& k) override {
    frames_.back().key = k;
    return true;
  }
  bool end_object() override {
    frames_.pop_back();
    return true;
  }
  bool start_array(std::size_t) override {
    value();
    frames_.push_back({true, "", -1});
    return true;
  }
  bool end_array() override {
    frames_.pop_back();
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    // The failing value has not been counted yet.
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    error_path_ = pointer();
    error_ = e.what();
    return false;
  }
  const std::string& error_path() const { return error_path_; }
  const std::string& error() const { return error_; }

 private:
  struct Frame {
    bool array;
    std::string key;
    long index;
  };
  bool value() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return true;
  }
  std::string pointer() const {
    std::string out;
    for (const Frame& f : frames_) {
      out += '/';
      if (f.array) {
        out += std::to_string(f.index < 0 ? 0 : f.index);
        continue;
      }
      for (char c : f.key) out += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
    }
    return out.empty() ? "/" : out;
  }
  std::vector<Frame> frames_;
  std::string error_path_ = "/", error_;
};

}  // namespace

namespace {

// The deepest nesting of arrays and objects in `text` (strings skipped), and
// the offset of the bracket that first went past `limit` (a cheap pass over
// the text before any tree is built: a DOM 100 000 levels deep is copied,
// compared, merged and printed by recursive functions).
std::size_t deepest(const std::string& text, std::size_t limit, std::size_t& where) {
  std::size_t depth = 0, max = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max) max = depth;
      if (depth > limit) {
        where = i;
        return depth;
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return max;
}

// Line and column (1-based) of a byte offset.
std::string line_column(const std::string& text, std::size_t offset) {
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(col);
}

}  // namespace

nlohmann::json parse_json_text(const std::string& text, const std::string& file) {
  std::size_t where = 0;
  if (deepest(text, json_max_depth, where) > json_max_depth) {
    // The path of the first values (not 100 000 levels of it).
    PathTracker tracker;
    nlohmann::json::sax_parse(text.substr(0, where), &tracker);
    std::string path = tracker.error_path();
    if (path.size() > 80) path = path.substr(0, 80) + "...";
    throw InputError(file + ": " + path + ": arrays and objects nested more than " + std::to_string(json_max_depth) +
                     " levels deep (at " + line_column(text, where) +
                     "); a case, building or campaign file nests about ten levels");
  }
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    // A number beyond the range of a double (1e400) is reported by
    // nlohmann::json as out_of_range.406, other malformed text as
    // parse_error: both name the file and the JSON path of the value.
    PathTracker tracker;
    nlohmann::json::sax_parse(text, &tracker);
    const bool overflow = e.id == 406;
    throw InputError(file + ": " + tracker.error_path() + ": " +
                     (overflow ? std::string("number out of the range of a double (|x| < 1.8e308): ") + e.what()
                               : std::string("not valid JSON: ") + e.what()));
  } catch (const std::bad_alloc&) {
    throw SystemError(file + ": out of memory while reading the JSON text (" + std::to_string(text.size()) +
                      " bytes)");
  }
}

nlohmann::json read_json_file(const std::string& path, const InputKind& kind) {
  return parse_json_text(read_input_file(path, kind), path);
}

JsonNode::JsonNode(const nlohmann::json& value, std::string file, std::string path)
    : value_(&value), file_(std::move(file)), path_(std::move(path)) {}

void JsonNode::fail(const std::string& message) const {
  throw InputError(file_ + ": " + (path_.empty() ? "/" : path_) + ": " + message);
}

void JsonNode::fail_missing(const std::string& key, const std::string& expected) const {
  throw InputError(file_ + ": " + path_ + "/" + key + ": missing: " + expected);
}

bool JsonNode::has(const std::string& key) const { return value_->is_object() && value_->contains(key); }

void JsonNode::allow_only(std::initializer_list<const char*> allowed) const {
  if (!value_->is_object()) fail(std::string("expected an object, got ") + type_name(*value_));
  for (auto it = value_->begin(); it != value_->end(); ++it) {
    const std::string& k = it.key();
    if (std::any_of(allowed.begin(), allowed.end(), [&](const char* a) { return k == a; })) continue;
    std::string best;
    std::size_t dbest = 1000;
    for (const char* a : allowed) {
      const std::size_t d = edit_distance(k, a);
      if (d < dbest) {
        dbest = d;
        best = a;
      }
    }
    std::string msg = "unknown key \"" + k + "\"";
    if (dbest <= std::max<std::size_t>(2, k.size() / 3)) msg += " (did you mean \"" + best + "\"?)";
    std::string list;
    for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    JsonNode(*value_, file_, path_).fail(msg + "; expected one of: " + list);
  }
}

JsonNode JsonNode::at(const std::string& key) const {
  if (!value_->is_object()) fail(std::string("expected an object, got ") + type_name(*value_));
  if (!value_->contains(key)) fail("missing required key \"" + key + "\"");
  return JsonNode((*value_)[key], file_, path_ + "/" + key);
}

JsonNode JsonNode::at(std::size_t i) const {
  return JsonNode((*value_)[i], file_, path_ + "/" + std::to_string(i));
}

std::optional<JsonNode> JsonNode::find(const std::string& key) const {
  if (!has(key) || (*value_)[key].is_null()) return std::nullopt;
  return JsonNode((*value_)[key], file_, path_ + "/" + key);
}

std::vector<JsonNode> JsonNode::array(const std::string& key, std::size_t min_size) const {
  const JsonNode a = at(key);
  if (!a.value_->is_array()) a.fail(std::string("expected an array, got ") + type_name(*a.value_));
  if (a.value_->size() < min_size) a.fail("expected at least " + std::to_string(min_size) + " elements");
  std::vector<JsonNode> out;
  for (std::size_t i = 0; i < a.value_->size(); ++i) out.push_back(a.at(i));
  return out;
}

double JsonNode::as_number(const char* unit, double lo, double hi) const {
  if (!value_->is_number())
    fail(std::string("expected a number (") + unit + "), got " + type_name(*value_));
  const double v = value_->get<double>();
  if (is_subnormal(v))
    fail(number_rule_violation(v, NumberRule{unit, lo, hi, false, false, ""}));
  if (!std::isfinite(v) || v < lo || v > hi) {
    std::string range = lo > -1e300 && hi < 1e300 ? "in [" + num(lo) + ", " + num(hi) + "]"
                        : lo > -1e300            ? ">= " + num(lo)
                                                 : "<= " + num(hi);
    fail("value " + num(v) + " out of range: expected " + range + " " + unit);
  }
  return v;
}

double JsonNode::as_number(const NumberRule& rule) const {
  if (!value_->is_number())
    fail(std::string("expected a number (") + rule.unit + "), got " + type_name(*value_));
  const double v = value_->get<double>();
  const std::string bad = number_rule_violation(v, rule);
  if (!bad.empty()) fail(bad);
  return v;
}

double JsonNode::number(const std::string& key, const NumberRule& rule) const { return at(key).as_number(rule); }

double JsonNode::number_or(const std::string& key, double fallback, const NumberRule& rule) const {
  const auto n = find(key);
  return n ? n->as_number(rule) : fallback;
}

Eigen::Vector2d JsonNode::as_point(const NumberRule& rule) const {
  if (!value_->is_array() || value_->size() != 2) fail(std::string("expected a point [x, z] (") + rule.unit + ")");
  return Eigen::Vector2d(at(std::size_t{0}).as_number(rule), at(std::size_t{1}).as_number(rule));
}

std::string JsonNode::as_string() const {
  if (!value_->is_string()) fail(std::string("expected a string, got ") + type_name(*value_));
  const std::string& s = value_->get_ref<const std::string&>();
  // Names, paths and labels are printed in reports, tables and HTML: no
  // control characters, which broke the text tables and put a NUL byte into
  // the HTML (issue 31; number_rules.hpp).
  const std::string bad = control_character_violation(s);
  if (!bad.empty())
    fail(bad + ": names and file names are printed in the reports; write it without control characters");
  return s;
}

double JsonNode::number(const std::string& key, const char* unit, double lo, double hi) const {
  return at(key).as_number(unit, lo, hi);
}

double JsonNode::number_or(const std::string& key, double fallback, const char* unit, double lo,
                           double hi) const {
  const auto n = find(key);
  return n ? n->as_number(unit, lo, hi) : fallback;
}

double JsonNode::positive(const std::string& key, const char* unit) const {
  const JsonNode n = at(key);
  const double v = n.as_number(unit);
  if (!(v > 0.0)) n.fail("value " + num(v) + " out of range: expected > 0 " + unit);
  return v;
}

int JsonNode::integer(const std::string& key, int lo, int hi) const {
  const JsonNode n = at(key);
  if (!n.value_->is_number_integer()) n.fail(std::string("expected an integer, got ") + type_name(*n.value_));
  if (n.value_->is_number_unsigned() && n.value_->get<unsigned long long>() > static_cast<unsigned long long>(hi))
    n.fail("value " + std::to_string(n.value_->get<unsigned long long>()) + " out of range: expected " +
           std::to_string(lo) + ".." + std::to_string(hi));
  const long long v = n.value_->get<long long>();
  if (v < lo || v > hi)
    n.fail("value " + std::to_string(v) + " out of range: expected " + std::to_string(lo) + ".." + std::to_string(hi));
  return static_cast<int>(v);
}

int JsonNode::integer_or(const std::string& key, int fallback, int lo, int hi) const {
  return find(key) ? integer(key, lo, hi) : fallback;
}

std::string JsonNode::string(const std::string& key) const { return at(key).as_string(); }

std::string JsonNode::choice(const std::string& key, std::initializer_list<const char*> choices) const {
  const JsonNode n = at(key);
  const std::string s = n.as_string();
  std::string list;
  for (const char* c : choices) {
    if (s == c) return s;
    list += (list.empty() ? "\"" : ", \"") + std::string(c) + "\"";
  }
  n.fail("\"" + s + "\": expected one of " + list);
}

bool JsonNode::boolean_or(const std::string& key, bool fallback) const {
  const auto n = find(key);
  if (!n) return fallback;
  if (!n->value_->is_boolean()) n->fail(std::string("expected true or false, got ") + type_name(*n->value_));
  return n->value_->get<bool>();
}

Eigen::Vector2d JsonNode::as_point(const char* unit) const {
  if (!value_->is_array() || value_->size() != 2) fail(std::string("expected a point [x, z] (") + unit + ")");
  return Eigen::Vector2d(at(std::size_t{0}).as_number(unit), at(std::size_t{1}).as_number(unit));
}

Eigen::Vector2d JsonNode::point(const std::string& key) const { return at(key).as_point(rules::coordinate_m); }

}  // namespace assess
