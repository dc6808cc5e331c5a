// json_input.hpp: a reader over nlohmann::json that tracks the JSON path of
// every value, so that each input error names the file, the path (e.g.
// /mechanism/blocks/2/unit_weight), what was expected and its unit. Unknown
// keys are errors with a "did you mean" suggestion.
#pragma once

#include "assess/support/input_file.hpp"
#include "assess/support/number_rules.hpp"

#include <nlohmann/json.hpp>

#include <Eigen/Core>

#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

namespace assess {

/// A view of one JSON value with its location. Cheap to copy (refers to the
/// document, which must outlive it).
class JsonNode {
 public:
  JsonNode(const nlohmann::json& value, std::string file, std::string path = "");

  const nlohmann::json& value() const { return *value_; }
  const std::string& path() const { return path_; }  ///< "" for the root
  bool is_object() const { return value_->is_object(); }
  bool has(const std::string& key) const;

  /// Throws InputError "<file>: <path>: <message>".
  [[noreturn]] void fail(const std::string& message) const;
  /// A required member that is missing: InputError "<file>: <path>/<key>: missing: <what is expected>".
  [[noreturn]] void fail_missing(const std::string& key, const std::string& expected) const;
  /// Every key must be one of `allowed`, else an error with the closest one.
  void allow_only(std::initializer_list<const char*> allowed) const;

  /// A member (required); error if missing.
  JsonNode at(const std::string& key) const;
  /// An array element.
  JsonNode at(std::size_t i) const;
  std::optional<JsonNode> find(const std::string& key) const;
  /// The elements of a required array member (`min_size` at least).
  std::vector<JsonNode> array(const std::string& key, std::size_t min_size = 0) const;

  /// This value as a number in [lo, hi]; `unit` is named in errors. Every
  /// number read is finite and never subnormal (number_rules.hpp).
  double as_number(const char* unit, double lo = -1e300, double hi = 1e300) const;
  /// This value as a number obeying `rule` (number_rules.hpp: finite, not
  /// subnormal, within the physical range of its quantity, in its unit).
  double as_number(const NumberRule& rule) const;
  /// Required number member obeying `rule`.
  double number(const std::string& key, const NumberRule& rule) const;
  /// Optional number member obeying `rule` (absent or null: `fallback`).
  double number_or(const std::string& key, double fallback, const NumberRule& rule) const;
  /// A point [x, z], each coordinate obeying `rule` (default rules::coordinate_m).
  Eigen::Vector2d as_point(const NumberRule& rule) const;
  std::string as_string() const;
  /// Required number member in [lo, hi] (closed) with its unit.
  double number(const std::string& key, const char* unit, double lo = -1e300, double hi = 1e300) const;
  double number_or(const std::string& key, double fallback, const char* unit, double lo = -1e300,
                   double hi = 1e300) const;
  /// Same, for a number that must be > lo (strictly).
  double positive(const std::string& key, const char* unit) const;
  int integer(const std::string& key, int lo, int hi) const;
  int integer_or(const std::string& key, int fallback, int lo, int hi) const;
  std::string string(const std::string& key) const;
  /// A string that must be one of `choices`.
  std::string choice(const std::string& key, std::initializer_list<const char*> choices) const;
  bool boolean_or(const std::string& key, bool fallback) const;
  /// A point [x, z] (m).
  Eigen::Vector2d point(const std::string& key) const;
  Eigen::Vector2d as_point(const char* unit) const;

 private:
  const nlohmann::json* value_;
  std::string file_;
  std::string path_;
};

/// Levenshtein distance (for suggestions).
std::size_t edit_distance(const std::string& a, const std::string& b);

/// The deepest nesting of arrays and objects any JSON input may have (a case
/// or building file nests about ten levels). Deeper text is refused before a
/// tree is built: copying, merging or printing a tree 100 000 levels deep
/// recurses once per level (issue 31: a building file so nested ended in a
/// segmentation fault).
inline constexpr std::size_t json_max_depth = 64;

/// Parses a JSON file read by read_input_file (a regular file within the
/// limit of `kind`); InputError naming the file, the JSON path (e.g.
/// /mechanism/height for "height": 1e400) and the parse position.
nlohmann::json read_json_file(const std::string& path, const InputKind& kind = input_kinds::json_file);
/// Same, for JSON text read from `file` (named in errors): nested at most
/// json_max_depth levels.
nlohmann::json parse_json_text(const std::string& text, const std::string& file);

}  // namespace assess
