// kinematic_report.hpp: text and JSON reports of a kinematic case and of
// check rows (report layer: formatting only, no physics).
#pragma once

#include "assess/assessment/case_file.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace assess {

/// "verificato / satisfied" or "non verificato / not satisfied".
const char* verdict(bool satisfied);

/// A check row as JSON: code, limit_state, kind, location, demand, capacity,
/// unit, dc, satisfied (null without a verdict), clause, formula, inputs and
/// its safety index ("index", below).
nlohmann::json to_json(const CheckRow& r);
/// A check's safety index as JSON: defined, zeta_E, ag_capacity_g, ag_demand_g
/// (g on rock), TR_capacity_years, TR_demand_years, TR_ratio, extrapolated,
/// bound ("below" | "above" | null), non_monotonic (+ other_crossing_TR_years),
/// shape_held, note.
nlohmann::json to_json(const CheckIndex& x);
/// The kinematic result as JSON (keys alpha0, M_star (t), e_star, a0_star
/// (m/s2), d0_star, du_star (m), Ts (s), d_SLV, d_SLC (m), T_SLV, T_SLC (s),
/// capacity_curve [{d_star, a_star}], checks [...], loads, candidates).
nlohmann::json kinematic_json(const CaseFile& c, const KinematicCaseResult& res);
/// Width of the terminal reports: tables fit 120 columns (the formula and
/// clause of a check on a second line, long lines wrapped), or one line per
/// row however long (--wide).
enum class TextWidth { columns120, wide };

/// The readable kinematic report: every intermediate quantity with its clause,
/// the capacity curve and the checks table.
std::string kinematic_text(const CaseFile& c, const KinematicCaseResult& res, TextWidth width = TextWidth::columns120);
/// The checks table alone.
std::string checks_text(const std::vector<CheckRow>& checks, TextWidth width = TextWidth::columns120);
/// `text` wrapped at blanks to lines of at most `width` columns (UTF-8
/// characters counted once), continuation lines indented by `indent` blanks.
std::string wrap_text(const std::string& text, std::size_t indent, std::size_t width = 120);

/// The JSON of a verdict's state (issue 41): `satisfied` true, false, or null
/// for no verdict (never false); add_outcome also sets "outcome" ("satisfied",
/// "not satisfied", "no verdict").
nlohmann::json satisfied_json(Outcome o);
void add_outcome(nlohmann::json& j, Outcome o);
/// A summary row as JSON: {code, approach, limit_state, location, dc,
/// satisfied (null without a verdict), clause, candidate, note, checks, failing}.
nlohmann::json to_json(const VerdictRow& r);
/// The summary as JSON: {"by_approach": [rows], "overall": [{code, satisfied, checks, failing, no_verdict, max_dc}]}.
nlohmann::json to_json(const Verdict& v);
/// The summary by approach and the overall verdict per code, as text.
std::string verdict_text(const Verdict& v, TextWidth width = TextWidth::columns120);
/// "verificato / satisfied", "non verificato / not satisfied" or "no verdict" for a summary row;
/// a "seed" energy row reads "overturned ..." when any analysis overturned.
std::string verdict_word(const VerdictRow& r);

}  // namespace assess
