// tie_html.cpp: the section of the relazione on the tie rods (issue 23):
// the ties drawn on the mechanism, each level's rod and anchor, the checks
// of the tie with their clauses, the force each check of the mechanism needs,
// and the verdicts before and after side by side. Formatting only. Italian
// and English strings are kept here, in one table, apart from messages.cpp.
#include "assess/report/tie_report.hpp"

#include "assess/report/mechanism_drawing.hpp"
#include "assess/support/units.hpp"
#include "report/text_format.hpp"
#include "report/xml_escape.hpp"

#include <cmath>
#include <map>

namespace assess {
namespace {

using detail::xml_escape;
constexpr double kN = units::kN;

const std::string& tr(Lang lang, const std::string& key) {
  static const std::map<std::string, std::pair<std::string, std::string>> t{
      {"title", {"Intervento: catene (tiranti)", "Intervention: tie rods"}},
      {"intro_design",
       {"Progetto della catena più piccola (barra e piastra commerciali) che soddisfa tutte le verifiche del "
        "meccanismo e della catena (riparazione o intervento locale, NTC 2018 §8.4.1).",
        "Design of the smallest tie (commercial rod and plate) that satisfies every check of the mechanism and of "
        "the tie (repair or local intervention, NTC 2018 §8.4.1)."}},
      {"intro_given",
       {"Verifica del meccanismo con le catene indicate e verifiche delle catene.",
        "Check of the mechanism with the given ties, and checks of the ties."}},
      {"not_found",
       {"Nessuna combinazione degli elenchi soddisfa tutte le verifiche; si riporta la più grande.",
        "No combination of the lists satisfies every check; the largest is shown."}},
      {"level", {"Livello", "Level"}},
      {"rod", {"Barra", "Rod"}},
      {"anchor", {"Capochiave", "Anchor"}},
      {"position", {"Posizione (m)", "Position (m)"}},
      {"spacing", {"Interasse (m)", "Spacing (m)"}},
      {"free_length", {"Lunghezza libera (m)", "Free length (m)"}},
      {"T_Rd", {"Resistenza di progetto T_Rd (kN)", "Design strength T_Rd (kN)"}},
      {"governing", {"governata da", "governed by"}},
      {"checks_title", {"Verifiche della catena", "Checks of the tie"}},
      {"check", {"Verifica", "Check"}},
      {"clause", {"Riferimento", "Clause / source"}},
      {"demand", {"Domanda", "Demand"}},
      {"capacity", {"Capacità", "Capacity"}},
      {"unit", {"Unità", "Unit"}},
      {"outcome", {"Esito", "Outcome"}},
      {"ok", {"verificato", "satisfied"}},
      {"ko", {"non verificato", "not satisfied"}},
      {"required_title",
       {"Forza necessaria per ogni verifica del meccanismo", "Force needed by each check of the mechanism"}},
      {"code", {"Norma", "Code"}},
      {"ls", {"SL", "LS"}},
      {"kind", {"Tipo", "Kind"}},
      {"where", {"Posizione", "Location"}},
      {"per_tie", {"per catena (kN)", "per tie (kN)"}},
      {"per_metre", {"per metro (kN/m)", "per metre (kN/m)"}},
      {"dc_without", {"D/C senza catena", "D/C without the tie"}},
      {"before_after", {"Meccanismo prima e dopo l'intervento", "The mechanism before and after the intervention"}},
      {"before", {"prima", "before"}},
      {"after", {"dopo", "after"}},
      {"all_checks", {"tutte le verifiche", "every check"}},
      {"zeta", {"ζE = PGA capacità / PGA domanda (NTC 2018)", "ζE = PGA capacity / PGA demand (NTC 2018)"}},
      {"N_Ed",
       {"Domanda N_Ed: la massima forza necessaria per catena", "Demand N_Ed: the largest force needed per tie"}},
      {"rod yield", {"snervamento della barra", "rod yield"}},
      {"local compression", {"compressione locale della muratura", "local compression of the masonry"}},
      {"punching", {"punzonamento del cuneo murario", "punching of the masonry wedge"}},
      {"anchor bending", {"flessione del capochiave", "bending of the anchor"}},
      {"rod elongation", {"allungamento della barra", "rod elongation"}},
      {"strength", {"resistenza", "strength"}},
      {"displacement", {"spostamento", "displacement"}},
      {"ground", {"al suolo", "ground"}},
      {"height", {"in quota", "height"}},
      {"bearing", {"compressione locale", "local compression"}},
      {"rodg", {"barra", "rod"}},
      // The clauses of the tie checks (tie_checks.cpp), in the relazione's language.
      {"clause.rod yield", {"NTC 2018 §4.2.4.1.2 [4.2.6] [R]", "NTC 2018 §4.2.4.1.2 [4.2.6] [R]"}},
      {"clause.local compression",
       {"muratura sotto il capochiave, prassi [R]", "masonry under the anchor, practice [R]"}},
      {"clause.punching", {"cuneo murario a 45°, prassi [R]", "45-degree masonry wedge, practice [R]"}},
      {"clause.anchor bending.plate", {"piastra a mensole [I]", "plate as cantilever strips [I]"}},
      {"clause.anchor bending.bar", {"paletto appoggiato [I]", "bar, simply supported [I]"}},
      {"clause.rod elongation", {"eps_ud = 0,9 eps_uk, eps_uk = 7,5 % [I]", "eps_ud = 0.9 eps_uk, eps_uk = 7.5 % [I]"}},
      {"dyn_title",
       {"Verifica dinamica prima e dopo la catena (Circ. 2019 C8.7.1.2.1.9)",
        "Dynamic check before and after the tie (Circ. 2019 C8.7.1.2.1.9)"}},
      {"dyn_intro",
       {"Le analisi dinamiche della facciata (sopra) ripetute con la catena progettata come vincolo monolatero (solo trazione) "
        "elastico-perfettamente plastico nel suo punto.",
        "The façade's dynamic analyses (above) repeated with the designed tie as a one-sided (tension-only) "
        "elastic-perfectly-plastic restraint at its point."}},
      {"dyn_intro_given",
       {"Le analisi dinamiche della facciata (sopra) sono quelle della parete con le sue catene, vincoli monolateri (solo "
        "trazione) elastico-perfettamente plastici nel loro punto; prima: le stesse analisi senza catene.",
        "The façade's dynamic analyses (above) are those of the wall with its ties, one-sided (tension-only) "
        "elastic-perfectly-plastic restraints at their points; before: the same analyses without them."}},
      {"dyn_not",
       {"Analisi dinamica con la catena non eseguita: richiede la sezione dinamica e un moto monolatero "
        "(corpo o catena cinematica).",
        "Dynamic analysis with the tie not done: it needs the dynamic section and one-sided rocking (a body or a "
        "chain)."}},
      {"dyn_e", {"e (restituzione)", "e (restitution)"}},
      {"dyn_N", {"N accelerogrammi", "N records"}},
      {"dyn_over", {"ribaltamenti prima / dopo", "overturned before / after"}},
      {"dyn_d", {"d* domanda prima / dopo (m)", "d* demand before / after (m)"}},
      {"dyn_dslv", {"d_SLV prima / dopo (m)", "d_SLV before / after (m)"}},
      {"dyn_yield", {"catena snervata / rotta", "rod yielded / broken"}},
      {"dyn_verdict", {"esito prima → dopo", "outcome before → after"}},
      {"drawing",
       {"Le catene sul meccanismo (frecce: la resistenza di progetto del livello sulla striscia analizzata).",
        "The ties on the mechanism (arrows: the level's design strength on the strip analysed)."}},
  };
  static const std::string empty;
  const auto it = t.find(key);
  if (it == t.end()) return key;
  return lang == Lang::it ? it->second.first : it->second.second;
}

std::string td(const std::string& s) { return "<td>" + s + "</td>"; }
std::string th(const std::string& s) { return "<th>" + s + "</th>"; }
std::string fnum(double v, const char* f) { return std::isfinite(v) ? format(f, v) : std::string("–"); }
std::string verdict_cell(Lang lang, bool ok) {
  return std::string("<td style=\"color:") + (ok ? "#1a7f37" : "#c62828") + "\">" + tr(lang, ok ? "ok" : "ko") + "</td>";
}

// The governing candidate's chain with each level drawn as a tie arrow of its design strength.
std::string drawing(const TieInterventionResult& t, Lang lang) {
  const CandidateResult& cr = t.after.candidates[t.after.governing];
  const Chain& chain = t.case_after.mechanism.candidates[t.after.governing].chain;
  std::vector<Load> loads;
  for (const Load& l : chain.loads())
    if (l.type != LoadType::SelfWeight) loads.push_back(l);
  for (const TieWork& w : cr.result.ties) {
    Load l;
    l.type = LoadType::Tie;
    l.name = w.tie.name;
    l.block = w.tie.block;
    l.point = w.tie.point;
    l.force = w.tie.capacity * w.tie.direction;
    loads.push_back(l);
  }
  try {
    const Chain drawn(chain.blocks(), chain.constraints(), loads);
    return mechanism_svg(drawn, cr.result, lang);
  } catch (const std::exception&) {
    return mechanism_svg(chain, cr.result, lang);
  }
}

}  // namespace

std::string tie_section_title(Lang lang) { return tr(lang, "title"); }

std::string tie_html_section(const TieInterventionResult& t, Lang lang, const std::string& id_prefix,
                             int heading_level) {
  // Headings at `heading_level`; every id (the section's, the drawing's
  // markers) prefixed, so that several sections share a page (the building).
  const std::string h_open = "<h" + std::to_string(heading_level) + ">";
  const std::string h_close = "</h" + std::to_string(heading_level) + ">";
  auto prefixed = [&](std::string svg) {
    for (const char* key : {"id=\"", "url(#"})
      for (std::size_t at = svg.find(key); !id_prefix.empty() && at != std::string::npos;
           at = svg.find(key, at + std::string(key).size() + id_prefix.size()))
        svg.insert(at + std::string(key).size(), id_prefix);
    return svg;
  };
  std::string h = "<div class=\"ties\" id=\"" + xml_escape(id_prefix) + "ties\">\n";
  h += "<p>" + tr(lang, t.designed ? "intro_design" : "intro_given") + "</p>\n";
  if (t.designed && !t.found) h += "<p style=\"color:#c62828\">" + tr(lang, "not_found") + "</p>\n";
  h += "<figure>" + prefixed(drawing(t, lang)) + "<figcaption>" + tr(lang, "drawing") + "</figcaption></figure>\n";
  // Levels.
  h += "<table class=\"data\"><tr>" + th(tr(lang, "level")) + th(tr(lang, "rod")) + th(tr(lang, "anchor")) +
       th(tr(lang, "position")) + th(tr(lang, "spacing")) + th(tr(lang, "free_length")) + th(tr(lang, "T_Rd")) + "</tr>\n";
  for (const TieLevelResult& L : t.levels) {
    const Tie& x = L.tie;
    const std::string rod = (x.rod.diameter > 0.0 ? format("Ø%.0f mm", x.rod.diameter * 1e3)
                                                  : format("A = %.0f mm²", x.rod.area * 1e6)) +
                            " " + x.rod.grade;
    const std::string anchor =
        x.anchor.type == AnchorType::Plate
            ? format("%.0f × %.0f × %.0f mm ", x.anchor.a * 1e3, x.anchor.b * 1e3, x.anchor.t * 1e3) + x.anchor.grade
            : format("paletto %.0f mm, Ø%.0f mm ", x.anchor.a * 1e3, x.anchor.b * 1e3) + x.anchor.grade;
    const std::string gov = L.resistance.governing == "rod" ? tr(lang, "rodg") : tr(lang, L.resistance.governing);
    h += "<tr>" + td(xml_escape(x.name)) + td(rod) + td(anchor) + td(format("(%.2f, %.2f)", x.point.x(), x.point.y())) +
         td(format("%.2f", x.spacing)) + td(format("%.2f", x.free_length)) +
         td(format("%.1f", L.resistance.design / kN) + " (" + tr(lang, "governing") + " " + gov + ")") + "</tr>\n";
  }
  h += "</table>\n";
  for (const TieLevelResult& L : t.levels) {
    h += h_open + tr(lang, "checks_title") + " — " + xml_escape(L.tie.name) + h_close + "\n";
    h += "<p>" + tr(lang, "N_Ed") + format(" = %.2f kN.", L.N_Ed / kN) + "</p>\n";
    h += "<table class=\"data\"><tr>" + th(tr(lang, "check")) + th(tr(lang, "clause")) + th(tr(lang, "demand")) +
         th(tr(lang, "capacity")) + th(tr(lang, "unit")) + th("D/C") + th(tr(lang, "outcome")) + "</tr>\n";
    for (const TieCheckRow& c : L.checks) {
      const double s = c.unit == "mm" ? 1e3 : 1.0 / kN;
      const std::string ck = c.check == "anchor bending"
                                 ? std::string("clause.anchor bending.") +
                                       (L.tie.anchor.type == AnchorType::Plate ? "plate" : "bar")
                                 : "clause." + c.check;
      h += "<tr>" + td(tr(lang, c.check)) + td(xml_escape(tr(lang, ck))) + td(fnum(c.demand * s, "%.2f")) +
           td(fnum(c.capacity * s, "%.2f")) + td(c.unit) + td(fnum(c.dc, "%.3f")) + verdict_cell(lang, c.satisfied) +
           "</tr>\n";
    }
    h += "</table>\n" + h_open + tr(lang, "required_title") + " — " + xml_escape(L.tie.name) + h_close + "\n";
    h += "<table class=\"data\"><tr>" + th(tr(lang, "code")) + th(tr(lang, "ls")) + th(tr(lang, "kind")) +
         th(tr(lang, "where")) + th(tr(lang, "per_tie")) + th(tr(lang, "per_metre")) + th(tr(lang, "dc_without")) +
         "</tr>\n";
    for (const RequiredTieForce& f : L.required)
      h += "<tr>" + td(f.code) + td(f.limit_state) + td(tr(lang, f.kind)) + td(tr(lang, f.location)) +
           td(fnum(f.per_tie / kN, "%.2f")) + td(fnum(f.per_metre / kN, "%.2f")) + td(fnum(f.dc_without, "%.3f")) +
           "</tr>\n";
    h += "</table>\n";
  }
  // Before / after.
  const CandidateResult& b = t.before.candidates[t.before.governing];
  const CandidateResult& a = t.after.candidates[t.after.governing];
  h += h_open + tr(lang, "before_after") + h_close + "\n<table class=\"data\"><tr>" + th("") + th(tr(lang, "before")) +
       th(tr(lang, "after")) + "</tr>\n";
  h += "<tr>" + td("α0") + td(format("%.4f", b.result.alpha0)) + td(format("%.4f", a.result.alpha0)) + "</tr>\n";
  h += "<tr>" + td("a0* (m/s²)") + td(format("%.4f", b.result.a0_star)) + td(format("%.4f", a.result.a0_star)) + "</tr>\n";
  h += "<tr>" + td("d0* (m)") + td(b.result.curve_complete() ? format("%.4f", b.result.d0_star) : "–") +
       td(a.result.curve_complete() ? format("%.4f", a.result.d0_star) : "–") + "</tr>\n";
  h += "<tr>" + td(tr(lang, "zeta")) + td(fnum(t.zetaE_before, "%.3f")) + td(fnum(t.zetaE_after, "%.3f")) + "</tr>\n";
  h += "<tr>" + td(tr(lang, "all_checks")) + verdict_cell(lang, t.passes_before) + verdict_cell(lang, t.passes_after) +
       "</tr>\n";
  for (const CheckRow& row : b.checks) {
    const CheckRow* r2 = nullptr;
    for (const CheckRow& x : a.checks)
      if (x.code == row.code && x.limit_state == row.limit_state && x.kind == row.kind && x.location == row.location)
        r2 = &x;
    h += "<tr>" + td(row.code + " " + row.limit_state + " " + tr(lang, row.kind) + " " + tr(lang, row.location) + " D/C") +
         td(fnum(row.dc, "%.3f")) + td(r2 ? fnum(r2->dc, "%.3f") : "–") + "</tr>\n";
  }
  h += "</table>\n";
  // Dynamics before / after.
  h += h_open + tr(lang, "dyn_title") + h_close + "\n";
  if (!t.dynamics.applies) {
    h += "<p>" + tr(lang, "dyn_not") + "</p>\n";
  } else {
    h += "<p>" + tr(lang, t.designed ? "dyn_intro" : "dyn_intro_given") + "</p>\n<table class=\"data\"><tr>" + th(tr(lang, "dyn_e")) +
         th(tr(lang, "dyn_N")) + th(tr(lang, "dyn_over")) + th(tr(lang, "dyn_d")) + th(tr(lang, "dyn_dslv")) +
         th(tr(lang, "dyn_yield")) + th(tr(lang, "dyn_verdict")) + "</tr>\n";
    for (const TieDynamicSummary& x : t.dynamics.summaries)
      h += "<tr>" + td(format("%.3f", x.e)) + td(format("%d", x.records)) +
           td(format("%d / %d", x.overturned_before, x.overturned_after)) +
           td(format("%.4f / %.4f", x.d_demand_before, x.d_demand_after)) +
           td(format("%.4f / %.4f", x.d_SLV_before, x.d_SLV_after)) + td(format("%d / %d", x.yielded, x.ruptured)) +
           "<td>" + tr(lang, x.satisfied_before ? "ok" : "ko") + " → " + tr(lang, x.satisfied_after ? "ok" : "ko") +
           "</td></tr>\n";
    h += "</table>\n";
  }
  h += "</div>\n";
  return h;
}

}  // namespace assess
