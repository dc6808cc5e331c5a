// verdict_style.hpp: the words and the colour of a verdict in three states
// (issue 41): one place per language, read by every writer (relazione, its
// text edition, the terminal summary). "No verdict" has its own words and no
// colour: it is never printed as "not satisfied".
#pragma once

#include "assess/kinematic/outcome.hpp"
#include "assess/report/document.hpp"
#include "assess/report/messages.hpp"

#include <string>

namespace assess {

/// A check's verdict: "verificato", "non verificato", "senza esito" (English: satisfied, not satisfied, no verdict).
const std::string& verdict_word(Lang lang, Outcome o);
/// A conclusion's: "VERIFICATO", "NON VERIFICATO", "SENZA ESITO".
const std::string& verdict_title(Lang lang, Outcome o);
/// Its colour: ok (green), fail (red), plain (no verdict).
constexpr Tone verdict_tone(Outcome o) {
  return o == Outcome::satisfied ? Tone::ok : o == Outcome::not_satisfied ? Tone::fail : Tone::plain;
}

}  // namespace assess
