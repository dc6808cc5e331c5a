// find_note.hpp: the part of a note (support/note.hpp) with a given catalogue id,
// for tests that check a note as data (its id and its arguments), not its words.
#pragma once

#include "assess/support/note.hpp"

#include <string>

namespace assess::test {

/// The first part of `text` whose id is `id`; nullptr when there is none.
inline const Note* find_note(const NoteText& text, const std::string& id) {
  for (const Note& n : text)
    if (n.id == id) return &n;
  return nullptr;
}

/// The count (NoteArg::Kind::count) of argument `k` of `n`; -1 when it is not a count.
inline long note_count(const Note& n, std::size_t k) {
  if (k >= n.args.size() || n.args[k].kind != NoteArg::Kind::count) return -1;
  return static_cast<long>(n.args[k].value);
}

}  // namespace assess::test
