// relazione_choices.cpp: the modelling choices that move a result (issue 36,
// item 3): one table ("scelte di modellazione") with each choice, where it
// acts, the value adopted and the alternative, the adopted method's D/C with
// each and whether the verdict changes — the alternatives computed by the
// assessment (assessment/modelling_choices.hpp), none here — the defaults the
// case did not give (issue 41) in the same table; the notes that state each
// choice where it acts; and the judgement's words (assessment/judgement.hpp).
#include "report/relazione_context.hpp"
#include "report/text_format.hpp"

#include "report/report_heading.hpp"

#include <algorithm>
#include <cmath>

namespace assess::relazione {

std::string choice_name(Lang L, const std::string& key) { return msg(L, "choice." + key + ".name"); }
std::string choice_where(Lang L, const std::string& key) { return msg(L, "choice." + key + ".where"); }

std::string choice_value(const Ctx& c, const ModellingChoice& x, bool alt) {
  const double v = alt ? x.alternative : x.adopted;
  const std::string& label = alt ? x.alternative_label : x.adopted_label;
  if (x.key == "FC") return (label.empty() ? "" : label + ", ") + "FC = " + c.n(v, 2);
  if (x.key == "lumped_masses") return msgf(c.L, alt ? "choice.lumped" : "choice.distributed", c.n(v, 4));
  if (x.key == "displacement_bound") return msgf(c.L, alt ? "choice.unbounded" : "choice.bounded", c.n(v, 4));
  if (x.key == "height_demand") return alt ? c.t("choice.ground") : msgf(c.L, "choice.height", c.n(v, 2));
  if (x.key == "friction_activation") return "κ = " + c.n(v, 2);
  if (x.key == "seat_friction") return "μ = " + c.n(v, 2);
  if (x.key == "dSLV_over_d0" || x.key == "dSLC_over_d0") return c.n(v, 2) + " d0*";
  if (x.key == "xi_SLV_pct" || x.key == "xi_SLC_pct") return "ξ = " + c.n(v, 0) + " %";
  if (x.key == "selection_window") {
    const double mw0 = alt ? x.alternative_b : x.adopted_b, r0 = alt ? x.alternative_c : x.adopted_c,
                 r1 = alt ? x.alternative_d : x.adopted_d;
    return "Mw " + c.n(mw0, 1) + "–" + c.n(v, 1) + ", R " + c.n(r0, 0) + "–" + c.n(r1, 0) + " km";
  }
  return c.g(v, 4);
}

std::string default_value_text(Lang L, const CaseDefault& d) {
  // The engine's words for a value the case did not give, in the report's
  // language (issue 36, item 5: no code tokens in the Italian body).
  const bool it = L == Lang::it;
  const std::string& v = d.value;
  if (d.path == "/method" && (v == "linear" || v == "nonlinear" || v == "dynamic")) return msg(L, "method." + v);
  if (v == "false") return it ? "no" : "no";
  if (v == "true") return it ? "sì" : "yes";
  if (v == "one-sided") return msg(L, "dyn.one_sided");
  if (v == "two-sided") return msg(L, "dyn.two_sided");
  if (v == "smooth") return msg(L, "dyn.smooth");
  if (v == "normal") return it ? "normale" : "normal";
  if (v == "exclude") return it ? "esclusi" : "excluded";
  if (v == "= /site/soil") return it ? "quella del sito" : "the site's";
  return it ? decimal_comma(localise(L, v)) : v;
}

std::vector<Cell> choice_head(const Ctx& c) {
  return {Cell(c.t("choice.col_choice")), Cell(c.t("choice.col_where")), Cell(c.t("choice.col_adopted")),
          Cell(c.t("choice.col_alternative")), numeric_cell(c.t("choice.col_dc")), numeric_cell(c.t("choice.col_dc_alt")),
          Cell(c.t("choice.col_outcome"))};
}

std::vector<std::vector<Cell>> choice_rows(const Ctx& c, const std::vector<ModellingChoice>& choices) {
  std::vector<std::vector<Cell>> rows;
  for (const ModellingChoice& x : choices) {
    Cell name(choice_name(c.L, x.key), x.case_key.empty() ? c.t("choice.engine_reading") : msgf(c.L, "choice.case_key", x.case_key));
    Cell dc = c.dc_cell(x.dc, x.outcome);
    dc.note = c.t("method." + x.method);
    Cell dc_alt = x.computed() ? c.dc_cell(x.dc_alternative, x.outcome_alternative) : numeric_cell("—");
    // A dynamic D/C of zero is computed: the wall never lifted (issue 36, item 5: said why).
    if (x.method == "dynamic" && x.dc == 0.0) dc.note = c.t("dyn.no_uplift");
    if (x.computed() && x.method == "dynamic" && x.dc_alternative == 0.0) dc_alt.note = c.t("dyn.no_uplift");
    // An infinite dynamic D/C is an overturning: said in words beside "∞".
    if (x.method == "dynamic" && std::isinf(x.dc)) dc.note = c.t("dyn.overturning");
    if (x.computed() && x.method == "dynamic" && std::isinf(x.dc_alternative)) dc_alt.note = c.t("dyn.overturning");
    Cell out = x.computed() ? c.outcome_cell(x.outcome_alternative) : Cell(c.t("choice.not_computed." + x.not_computed));
    if (x.computed()) out.note = c.t(x.flips() ? "choice.changes" : "choice.same");
    rows.push_back({name, Cell(choice_where(c.L, x.key)), Cell(choice_value(c, x, false)), Cell(choice_value(c, x, true)), dc,
                    dc_alt, out});
  }
  return rows;
}

std::string choice_flip_text(const Ctx& c, const ModellingChoice& x) {
  return choice_name(c.L, x.key) + " (" + choice_value(c, x, true) + "): D/C " + c.n(x.dc, 3) + " → " +
         c.n(x.dc_alternative, 3) + ", " + verdict_word(c.L, x.outcome_alternative);
}

void add_choice_notes(Ctx& c, const std::vector<std::string>& keys) {
  // One item per choice (issue 36: length): the adopted value and the
  // method's D/C with it said once, then each alternative with its D/C.
  std::vector<std::string> order;  // the choices' own order
  for (const ModellingChoice& x : c.a.choices)
    if (std::find(keys.begin(), keys.end(), x.key) != keys.end() &&
        std::find(order.begin(), order.end(), x.key) == order.end())
      order.push_back(x.key);
  // The method and its D/C with the adopted values, said once when every
  // computed alternative of the note refers to the same.
  const ModellingChoice* base = nullptr;
  bool shared = true;
  for (const ModellingChoice& x : c.a.choices) {
    if (std::find(order.begin(), order.end(), x.key) == order.end() || !x.computed()) continue;
    if (!base) base = &x;
    else if (x.method != base->method || x.dc != base->dc) shared = false;
  }
  auto with_dc = [&](const ModellingChoice& x) {
    const bool fell = x.method == "dynamic" && std::isinf(x.dc);
    return " (" + c.t("method." + x.method) + ", D/C " + c.n(x.dc, 3) + (fell ? ", " + c.t("dyn.overturning") : "") + ")";
  };
  std::vector<Inline> items;
  for (const std::string& key : order) {
    std::string s;
    const auto n = std::count_if(c.a.choices.begin(), c.a.choices.end(), [&](const ModellingChoice& x) { return x.key == key; });
    for (const ModellingChoice& x : c.a.choices) {
      if (x.key != key) continue;
      if (s.empty())
        s = choice_name(c.L, x.key) + ": " + choice_value(c, x, false) + (x.computed() && !shared ? with_dc(x) : "") +
            "; " + c.t(n > 1 ? "choice.alternatives" : "choice.alternative") + " ";
      else
        s += ", ";
      s += choice_value(c, x, true);
      if (x.computed()) {
        s += " → " + c.n(x.dc_alternative, 3);
        if (x.method == "dynamic" && std::isinf(x.dc_alternative)) s += " (" + c.t("dyn.overturning") + ")";
        if (x.flips()) s += " (" + verdict_word(c.L, x.outcome_alternative) + ")";
      }
    }
    if (!s.empty()) items.push_back({Span{s}});
  }
  if (items.empty()) return;
  Inline head{Span{c.t("choice.acting")}};
  if (c.tabulati) {
    head.push_back(Span{" "});
    head.push_back(c.building ? reference(c.t("choice.see_tab"), c.here("choices"), tabulati_key)
                              : reference(c.t("choice.see_body"), c.here("choices")));
  }
  if (base && shared)
    head.push_back(Span{msgf(c.L, "choice.acting_dc", c.t("method." + base->method), c.n(base->dc, 3))});
  // One note paragraph (issue 36: the body's length), the alternatives separated by ";".
  head.push_back(Span{": "});
  for (std::size_t i = 0; i < items.size(); ++i) {
    for (Span& x : items[i]) head.push_back(std::move(x));
    head.push_back(Span{i + 1 < items.size() ? "; " : "."});
  }
  c.d.add_paragraph(head, "note");
}

void add_choices(Ctx& c) {
  c.d.add_heading(c.t("choice.heading"), 2, true, true, "choices");
  c.d.add_paragraph(c.t("choice.intro"));
  std::vector<std::vector<Cell>> rows = choice_rows(c, c.a.choices);
  // The values the case did not give (issue 41), each in the same table: with
  // its computed alternative where the choice has one, else as it is.
  std::vector<std::vector<Cell>> defaults;
  for (const CaseDefault& d : assessment_defaults(c.a)) {
    bool covered = false;
    for (std::size_t i = 0; i < c.a.choices.size(); ++i)
      if (!c.a.choices[i].case_key.empty() && c.a.choices[i].case_key == d.path) {
        rows[i][2].note = c.t("choice.default");
        covered = true;
      }
    if (covered) continue;
    defaults.push_back({Cell(c.t(d.effect)), Cell(d.path), Cell(default_value_text(c.L, d))});
  }
  if (rows.empty() && defaults.empty()) {
    c.d.add_paragraph(c.t("choice.none"));
    return;
  }
  if (!rows.empty()) c.d.add_cell_table(choice_head(c), rows, c.t("choice.cap"), "choices");
  // The values assumed without an alternative, in a table of their own (issue 36: one line each).
  if (!defaults.empty())
    c.d.add_cell_table({Cell(c.t("choice.col_default")), Cell(c.t("choice.col_key")), Cell(c.t("choice.col_value"))}, defaults,
                       c.t("choice.defaults_cap"), "defaults");
}

void add_tab_choices(Ctx& c) {
  if (c.a.choices.empty()) return;
  c.d.add_heading(c.t("choice.heading_mech"), 3, false, true, "choices");
  c.d.add_cell_table(choice_head(c), choice_rows(c, c.a.choices), c.t("choice.cap"), "choices");
}

std::string judgement_qualifier(const Ctx& c, const Judgement& j) {
  if (j.robust || j.outcome == Outcome::no_verdict) return "";
  std::vector<std::string> why;
  if (j.thin) why.push_back(c.t("eval.why_thin"));
  if (!j.disagree.empty()) why.push_back(c.t("eval.why_disagree"));
  if (!j.flips.empty()) {
    std::string list;
    for (std::size_t i : j.flips) list += (list.empty() ? "" : ", ") + choice_name(c.L, c.a.choices[i].key) + " (" +
                                          choice_value(c, c.a.choices[i], true) + ")";
    why.push_back(msgf(c.L, "eval.why_flips", list));
  }
  if (j.outcome == Outcome::satisfied && j.collapses_count()) why.push_back(c.t("eval.why_collapses"));
  for (const std::string& k : j.implausible) why.push_back(c.t("eval.why_" + k));
  std::string s;
  for (const std::string& w : why) s += (s.empty() ? "" : "; ") + w;
  return s;
}

std::string judgement_text(const Ctx& c, const Judgement& j) {
  if (j.outcome == Outcome::no_verdict) return c.t("eval.undecided_judgement");
  if (j.robust) return c.t(j.outcome == Outcome::satisfied ? "eval.robust_ok" : "eval.robust_fail");
  return msgf(c.L, j.outcome == Outcome::satisfied ? "eval.fragile_ok" : "eval.fragile_fail", judgement_qualifier(c, j));
}

}  // namespace assess::relazione
