// Notes as data (issue 41, item 6): every note id the assessment writes has
// its text in Italian and English with one "{}" per argument; a note renders
// its numbers with the language's decimal separator and their unit, a text of
// another layer through localise(), and its parts in order.
#include <doctest/doctest.h>

#include "assess/support/note.hpp"
#include "assess/report/messages.hpp"
#include "assess/report/note_text.hpp"

#include <limits>
#include <stdexcept>
#include <string>

using namespace assess;

namespace {
std::size_t placeholders(const std::string& t) {
  std::size_t n = 0;
  for (std::size_t p = t.find("{}"); p != std::string::npos; p = t.find("{}", p + 2)) ++n;
  return n;
}
}  // namespace

TEST_CASE("every note id has its text in both languages, one placeholder per argument") {
  CHECK(note_ids().size() >= 17);
  for (const auto& entry : note_ids()) {
    const std::string id = entry.first;  // not a structured binding: CAPTURE is a lambda (clang 14, C++17)
    const auto args = entry.second;
    CAPTURE(id);
    CHECK(placeholders(msg(Lang::it, "note." + id)) == args);
    CHECK(placeholders(msg(Lang::en, "note." + id)) == args);
  }
}

TEST_CASE("a note renders its numbers with the language's decimal separator and unit") {
  // The default period range of a selection (record-selection.md §2.3): the
  // English text is the one the JSON and the terminal always gave.
  const NoteText range{{"range.default", {number_arg(0.5, 3), number_arg(0.075, 3, "s"), number_arg(1.5, 3),
                                          number_arg(2.25, 3, "s"), number_arg(0.125, 3, "s"), number_arg(1.5, 3, "s")}},
                       {"range.raised", {number_arg(0.1, 3, "s")}}};
  CHECK(note_text(Lang::en, range) ==
        "0.500 x min(Ts, T_SLV) = 0.075 s to 1.500 x max(Ts, T_SLV) = 2.250 s (Ts = 0.125 s, T_SLV = 1.500 s), "
        "raised to 0.100 s");
  CHECK(note_text(Lang::it, range) ==
        "0,500 × min(Ts, T_SLV) = 0,075 s a 1,500 × max(Ts, T_SLV) = 2,250 s (Ts = 0,125 s, T_SLV = 1,500 s), "
        "portato a 0,100 s");
  const Note misfit{"flag.misfit", {number_arg(0.254, 3), number_arg(0.2, 3), count_arg(28)}};
  CHECK(note_text(Lang::en, misfit) == "misfit 0.254 > 0.200 (rank 28)");
  CHECK(note_text(Lang::it, misfit) == "scarto 0,254 > 0,200 (posizione 28)");
  const Note vs30{"flag.class_vs30", {text_arg("B"), number_arg(359.0, 0, "m/s"), text_arg("C")}};
  CHECK(note_text(Lang::en, vs30) == "class B as stated by the source; its Vs30 359 m/s would give C");
  CHECK(note_text(Lang::it, vs30) == "categoria B dichiarata dalla fonte; la sua Vs30 359 m/s darebbe C");
  // Two periods beyond the range's end, and a number that is not finite (never "inf").
  const Note beyond{"range.beyond_two", {text_arg("T_SLV"), number_arg(4.5, 3, "s"), text_arg("T_SLC"),
                                         number_arg(std::numeric_limits<double>::infinity(), 3, "s"),
                                         number_arg(4.0, 3, "s")}};
  CHECK(note_text(Lang::en, beyond) == "; T_SLV = 4.500 s and T_SLC = ∞ s lie beyond its end 4.000 s: the set's "
                                       "mean spectrum is not checked against the target there");
  CHECK(note_text(Lang::it, beyond).rfind("; T_SLV = 4,500 s e T_SLC = ∞ s sono oltre il suo estremo 4,000 s", 0) ==
        0);
}

TEST_CASE("a dynamic check's note and the dynamic model, as data, in both languages") {
  // A dynamic row of two records, one overturning (facade_assessment.cpp dynamic_row): its parts in order.
  const NoteText row{{"check.d0_exceeded", {count_arg(1), count_arg(2), count_arg(1)}},
                     {"check.records", {count_arg(2)}},
                     {"check.rule_few_collapse", {}},
                     {"check.failed", {count_arg(1), count_arg(2)}}};
  CHECK(note_text(Lang::en, row) ==
        "d0 exceeded in 1 of 2 analyses (overturned in 1); 2 records: the most unfavourable result; fewer than 3 "
        "records (NTC 2018 §7.3.5) cannot show the wall safe, but a collapse fails the check whatever their number; "
        "1 of 2 analyses FAILED (not verified; left out of the statistics)");
  CHECK(note_text(Lang::it, row).rfind("d0 superato in 1 su 2 analisi (ribaltamento in 1); 2 accelerogrammi: ", 0) == 0);
  // The floor-motion filter: a damping ratio by its significant digits (5 %, 2.5 %), the rest by decimals.
  const NoteText floor{{"dyn.floor_filter", {number_arg(7.0, 2, "m"), number_arg(0.215, 3, "s"), number_arg(5.0, -3, "%"),
                                             number_arg(1.2, 4)}}};
  CHECK(note_text(Lang::en, floor) ==
        "; base at Z = 7.00 m, floor motions a_Z = ug'' + gamma psi ur'' (first mode: T1 = 0.215 s, xi = 5 %, "
        "gamma psi = 1.2000)");
  CHECK(note_text(Lang::it, NoteText{{"dyn.floor_given", {number_arg(2.5, -3, "m")}}}) ==
        "; base a Z = 2,5 m, moti di piano forniti dall'utente");
}

TEST_CASE("a text of another layer is localised; a note whose arguments do not fit is an error") {
  const Note shared{"shared.each_own", {count_arg(3), number_arg(0.2, 3), number_arg(2.0, 3, "s"),
                                        generated_arg("no candidate of class A")}};
  CHECK(note_text(Lang::en, shared) == "the union of the ranges of the 3 candidates analysed dynamically (0.200-2.000 s) "
                                       "gives no compatible set (no candidate of class A): each candidate selected over "
                                       "its own range");
  CHECK(note_text(Lang::it, shared) == "l'unione degli intervalli dei 3 cinematismi analizzati dinamicamente "
                                       "(0,200-2,000 s) non dà un insieme compatibile (nessun candidato di categoria A): "
                                       "ogni cinematismo ha la propria selezione");
  // A step of the site-class ladder: its parts in order.
  const NoteText step{{"step.classes", {text_arg("C, D")}}, {"step.no_selection", {count_arg(12)}}};
  CHECK(note_text(Lang::en, step) == "class C, D: 12 candidates, no selection");
  CHECK(note_text(Lang::it, step) == "categoria C, D: 12 candidati, nessuna selezione");
  CHECK_THROWS_AS(note_text(Lang::en, Note{"flag.misfit", {number_arg(1.0, 3)}}), std::logic_error);
  CHECK_THROWS_AS(note_text(Lang::en, Note{"flag.not_in_library", {count_arg(1)}}), std::logic_error);
  CHECK_THROWS_AS(note_text(Lang::en, Note{"no.such.note", {}}), std::logic_error);
}
