// relazione_context.hpp (private to the report layer): what every section of
// the relazione shares (issue 28): the assessment, the options, the language,
// the document being built, and the one way each section prints a number, a
// unit, a clause, a D/C and a verdict. A section is a function that adds
// blocks to the document (relazione_*.cpp); nothing else knows the layout.
#pragma once

#include "assess/assessment/facade_assessment.hpp"
#include "assess/support/note.hpp"
#include "assess/report/relazione.hpp"
#include "assess/assessment/tie_intervention.hpp"
#include "assess/report/document.hpp"
#include "assess/report/facade_report.hpp"
#include "assess/report/messages.hpp"
#include "assess/report/plot.hpp"
#include "assess/report/verdict_style.hpp"

#include <set>
#include <string>
#include <vector>

namespace assess::relazione {

/// The sections' shared state. `readings` collects the readings the document
/// relies on (clauses tagged [R] or [I] in the engine): the body cites the
/// clause only, the appendix "Ipotesi e letture adottate" lists each reading
/// with its basis (issue 28, item 6).
struct Ctx {
  const FacadeAssessment& a;
  const ReportOptions& o;
  Lang L;
  DocumentBuilder& d;
  std::set<std::string>* readings;
  /// Issue 36: the relazione is written with its tabulati di calcolo: the
  /// body refers to them and they to it (not in the terminal's summary).
  bool tabulati = false;
  /// A building's mechanism: the modelling choices are summarised in the
  /// building's own section, each mechanism's in full in the tabulati.
  bool building = false;

  const std::string& t(const std::string& key) const { return msg(L, key); }
  /// A text generated in English by the analysis, in the report's language (decimal comma in Italian).
  std::string loc(const std::string& text) const;
  /// A note of the assessment (assessment/note.hpp) in the report's language, typeset as loc() does.
  std::string note(const Note& n) const;
  std::string note(const NoteText& n) const;
  /// A number with `prec` decimals in the report's convention ("0,991" in Italian; "∞", "—").
  std::string n(double v, int prec) const;
  /// A number in scientific notation with `prec` decimals ("1,234e-04" in Italian).
  std::string e(double v, int prec) const;
  /// A number with %g-like precision (`digits` significant digits).
  std::string g(double v, int digits = 4) const;
  /// A plot in the report's convention (decimal comma in Italian).
  Plot plot() const {
    Plot p;
    p.decimal_comma = L == Lang::it;
    return p;
  }
  /// A unit as typeset ("m/s2" -> "m/s²").
  std::string unit(const std::string& u) const;
  /// A clause as the body cites it: the engine's certainty tags removed and remembered for the appendix.
  std::string clause(const std::string& text) const;
  /// The name of an input of a demand, typeset in the language ("psi(Z) (-)" -> "ψ(Z) (-)", "N (storeys)" -> "N (piani)").
  std::string input_name(const std::string& name) const;

  /// An anchor of this document in the current prefix ("M3-" + "checks"): the
  /// body and the tabulati name their sections alike, so each can point to the other's.
  std::string here(const std::string& local) const { return d.id_prefix() + local; }
  const CandidateResult& candidate(std::size_t i) const { return a.kinematic.candidates[i]; }
  const CandidateResult& gc() const { return candidate(a.kinematic.governing); }

  /// The verdict word of a check: "verificato", "non verificato", "senza esito" (verdict_style.hpp).
  std::string verdict_word(Outcome o) const { return assess::verdict_word(L, o); }
  /// The verdict as a cell and as a span: its word (a title: "VERIFICATO") and its colour (verdict_style.hpp).
  Cell outcome_cell(Outcome o) const;
  Span outcome_span(Outcome o) const { return Span{verdict_title(L, o), true, verdict_tone(o)}; }
  /// A D/C cell read from the check's own verdict (the one rule of code_checks.hpp):
  /// its number ("∞" for a collapse or a failed analysis, "—" without a verdict), coloured by the verdict.
  Cell dc_cell(double dc, Outcome o) const;
  Cell dc_cell(const CheckRow& r) const { return dc_cell(r.dc, r.outcome()); }
  /// The outcome cell of a check, with the reason when the D/C alone does not say it.
  Cell verdict_cell(const CheckRow& r) const;
  /// "collasso in 2 su 14 analisi; media sulle analisi senza collasso D/C 0,486".
  std::string collapse_text(const CheckRow& r) const;
  Cell num(double v, int prec) const;
  Cell text(const std::string& s) const { return Cell(s); }
};

// ---------------------------------------------------------------- sections
// Each adds its blocks to c.d; the façade relazione calls them in the order of
// a relazione di calcolo (facade_document.cpp), the building relazione nests
// the mechanism's sections (building_document.cpp). Issue 36: the relazione
// is two documents, the body and the tabulati di calcolo; a section of the
// body adds to the body (c.d), a section of the tabulati ("add_tab_...") is
// called with a context whose c.d is the tabulati's builder. Both builders
// carry the same id prefix (a building's mechanism: "M3-"), so that each
// refers to the other's sections by anchor (Ctx::here, reference()).

void add_front_matter(Ctx& c);           // frontespizio, verdict box, contents
void add_verdict_box(Ctx& c);            // per code and method, the conclusion
void add_premessa(Ctx& c);               // scope, mechanism, adopted procedure, the tabulati
/// The sentence of the premessa that introduces the tabulati di calcolo (both relazioni).
Inline tabulati_sentence(Lang L);
void add_normativa(Ctx& c);
void add_building_description(Ctx& c);   // descrizione, indagini e LC (its source checked), muratura, criteri
/// The survey and knowledge level: the engineer's text, the adopted level and
/// FC, and a flag when the text names another level (issue 36, item 5).
void add_knowledge_level(Ctx& c);
void add_choices(Ctx& c);                // scelte di modellazione: every choice with its alternative computed, the defaults
void add_site(Ctx& c);                   // azione sismica, spectra
void add_formulas(Ctx& c);               // every formula once, with its clause
void add_mechanism(Ctx& c);              // the candidate that decides, developed; the candidates examined
void add_checks(Ctx& c);                 // the checks tables
void add_safety_indices(Ctx& c);         // zetaE and TR_C/TR_D
void add_dynamic(Ctx& c);                // the dynamic analysis in the body: model, records, results
void add_dynamic_summary(Ctx& c);        // its model in one line, records, results per restitution (terminal summary)
/// The records of `x` (table, flags, selection, compatibility figure `id`): a building's shared set, once.
void add_record_set(Ctx& c, const FacadeAssessment& x, const std::string& id);
void add_comparison(Ctx& c);             // D/C by approach: bars and the methods' table
void add_interventions(Ctx& c);          // ties, or what a failing mechanism needs
/// The tie rods' section (relazione_ties.cpp): states, drawing, levels, formulas, checks, dynamics, detailing.
void add_tie_section(Ctx& c, const TieInterventionResult& t);
/// Issue 37: the ties of a wall once (relazione_ties.cpp): each level with the mechanisms it restrains
/// (`members`: a label and the mechanism's tie result), its wedge, its checks in every mechanism, the detailing.
/// `tabulati`: the building relazione's tabulati builder (same id prefix), which
/// then holds the wall's tie formulas and detailing (issue 36); none: all here.
void add_wall_tie_section(Ctx& c, const std::string& wall,
                          const std::vector<std::pair<std::string, const TieInterventionResult*>>& members,
                          DocumentBuilder* tabulati = nullptr);
void add_probabilistic(Ctx& c);
void add_evaluation(Ctx& c);             // valutazione dei risultati: margin, methods, choices, judgement
void add_conclusions(Ctx& c, bool signature = true);
void add_signature(Ctx& c);              // place, date, the engineer
/// The NTC 2018 §10.2 chapter (relazione_code.cpp): the code's identity, its
/// validation, and the checks of acceptability of each mechanism's results
/// (`mechanisms`: label and assessment; one for a façade).
void add_code_chapter(Ctx& c, const std::vector<std::pair<std::string, const FacadeAssessment*>>& mechanisms);
void add_readings_appendix(Ctx& c);      // ipotesi e letture adottate (tabulati)
void add_warnings(Ctx& c);
void add_legend(Ctx& c);
void add_case_file(Ctx& c);              // the case file (tabulati)

// The tabulati di calcolo (issue 36, item 1).
void add_tab_intro(Ctx& c);              // what the tabulati hold, and the relazione they belong to
void add_tab_candidates(Ctx& c);         // every candidate: virtual work, quantities, capacity curve, checks
void add_tab_dynamic(Ctx& c);            // the dynamic analysis: model, records, histories, every candidate
void add_tab_comparison(Ctx& c);         // every row of the comparison by approach
void add_tab_choices(Ctx& c);
void add_tab_ties(Ctx& c);               // a building's mechanism with ties: their formulas, dynamic check, detailing            // the modelling choices of one mechanism in full (a building's)

// Pieces of the mechanism's development shared by the body and the tabulati (relazione_mechanism.cpp).
/// The candidate the body develops: the one whose check governs the adopted method.
std::size_t body_candidate(const FacadeAssessment& a);
/// The data of candidate `ci` (bodies or the mechanism's own quantities), its
/// drawing (figure id `fig`, "" none) and its derivation.
void add_candidate_data(Ctx& c, std::size_t ci, const std::string& fig, int level);
void add_virtual_work(Ctx& c, std::size_t ci);
void add_quantities(Ctx& c, std::size_t ci);
void add_curve_table(Ctx& c, std::size_t ci);
void add_adrs(Ctx& c, std::size_t ci, const std::string& id);

// The modelling choices (relazione_choices.cpp), for both relazioni.
/// Its name ("Fattore di confidenza FC"), where it acts, its adopted and alternative values as text.
std::string choice_name(Lang L, const std::string& key);
std::string choice_where(Lang L, const std::string& key);
std::string choice_value(const Ctx& c, const ModellingChoice& x, bool alternative);
/// A value the case did not give (issue 41's defaults) in the report's words ("nonlinear" -> "analisi cinematica non lineare").
std::string default_value_text(Lang L, const CaseDefault& d);
/// The rows of the choices table of one mechanism (choice, where, adopted, alternative, D/C, outcome).
std::vector<std::vector<Cell>> choice_rows(const Ctx& c, const std::vector<ModellingChoice>& choices);
std::vector<Cell> choice_head(const Ctx& c);
/// "FC = 1,35 (LC1): D/C 0,991 → 1,115, non verificato" — one alternative that changes the verdict.
std::string choice_flip_text(const Ctx& c, const ModellingChoice& x);
/// The notes that state, where each acts, the choices `keys` of the mechanism:
/// each with its alternative and the D/C it gives, and where the choices' table is.
void add_choice_notes(Ctx& c, const std::vector<std::string>& keys);
/// The judgement of the adopted verdict in one sentence (judgement.hpp), "" without one.
std::string judgement_text(const Ctx& c, const Judgement& j);
/// Its qualification beside a verdict ("esito non solido: margine inferiore al 10 %"), "" when robust.
std::string judgement_qualifier(const Ctx& c, const Judgement& j);

/// The rows of a checks table (every input in the second line of the check's
/// cell, D/C and outcome read from the check) and its header.
std::vector<std::vector<Cell>> check_rows(const Ctx& c, const std::vector<CheckRow>& rows, bool with_candidate);
std::vector<Cell> check_head(const Ctx& c, bool with_candidate);

/// The candidates the body develops in full: the one that governs the
/// adopted method first, then those that govern the other methods (NTC 2018,
/// then NTC 2008), each once.
std::vector<std::size_t> developed_candidates(const FacadeAssessment& a);
/// The candidate index of a check's candidate label (kinematic.governing if none matches).
std::size_t candidate_of(const FacadeAssessment& a, const std::string& label);

/// The decimals a D/C is printed with: 3, more when a failing D/C would round
/// to 1.000 (the number printed carries the verdict: "1,0004", issue 28) or
/// when a D/C below 0.01 would lose its digits ("0,00023", issue 36).
int dc_decimals(double dc, bool satisfied);

/// Italian decimal comma in a text generated by the engine: "0.991" ->
/// "0,991", never inside a clause or section number ("C8.7.1.2", "§3.2.3.6",
/// "Tab. 3.2.II", "[3.2.10]") or a version.
std::string decimal_comma(const std::string& text);

}  // namespace assess::relazione
