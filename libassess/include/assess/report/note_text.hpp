// note_text.hpp: a note of the analysis (support/note.hpp) in words:
// its catalogue text "note.<id>" (messages.cpp) in the report's language with
// each "{}" replaced by its argument: a number with the language's decimal
// separator and its unit, a text as it is, a text of another layer through
// localise().
#pragma once

#include "assess/support/note.hpp"
#include "assess/report/messages.hpp"

#include <string>

namespace assess {

/// The note in `lang`. A note whose arguments do not match its text's
/// placeholders is a programming error: std::logic_error naming it.
std::string note_text(Lang lang, const Note& n);
/// The parts of a note, rendered one after the other.
std::string note_text(Lang lang, const NoteText& parts);

}  // namespace assess
