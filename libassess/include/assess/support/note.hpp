// note.hpp: a note of the analysis as data, not as an English sentence
// (issue 41): the id of its text in the message catalogue (report/
// messages.cpp, key "note.<id>", a "{}" per argument, in Italian and English)
// and its arguments: numbers kept as numbers with their decimals and unit, so
// that the renderer (report/note_text.hpp) writes them with the language's
// decimal separator. A note made of several parts is a NoteText, its parts
// rendered one after the other.
#pragma once

#include <string>
#include <vector>

namespace assess {

/// One argument of a note.
struct NoteArg {
  enum class Kind {
    text,       ///< a name, a class, a list of labels: printed as it is
    generated,  ///< a text of another layer in English (a record's near-fault reason, a selection
                ///< message): rendered through the report's localise()
    number,     ///< `value` with `decimals` decimals and its `unit`
    count,      ///< a whole number
  };
  Kind kind = Kind::text;
  std::string text;
  double value = 0.0;
  int decimals = 3;  ///< decimals ("%.Nf"); a negative N: -N significant digits ("%.Ng", 5 for 5.0)
  std::string unit;  ///< printed after the number, after a space ("s", "km", "m/s"; "" none)
};

struct Note {
  std::string id;  ///< catalogue key "note.<id>"
  std::vector<NoteArg> args;
};

/// A note of several parts (optional clauses of one sentence), in order.
using NoteText = std::vector<Note>;

inline NoteArg text_arg(std::string s) { return {NoteArg::Kind::text, std::move(s), 0.0, 0, ""}; }
inline NoteArg generated_arg(std::string s) { return {NoteArg::Kind::generated, std::move(s), 0.0, 0, ""}; }
inline NoteArg number_arg(double v, int decimals, std::string unit = "") {
  return {NoteArg::Kind::number, "", v, decimals, std::move(unit)};
}
inline NoteArg count_arg(std::size_t n) { return {NoteArg::Kind::count, "", double(n), 0, ""}; }

/// Every note id the library writes (the catalogue test checks each has
/// its text in both languages, with one "{}" per argument).
const std::vector<std::pair<std::string, std::size_t>>& note_ids();

}  // namespace assess
