// relazione_context.cpp: the relazione's shared formatting (issue 28): one way
// to print a number, a unit, a clause, a D/C and a verdict.
#include "report/relazione_context.hpp"

#include "report/number_text.hpp"
#include "report/text_format.hpp"
#include "assess/report/note_text.hpp"

#include <cctype>
#include <cmath>

namespace assess::relazione {

namespace {

bool digit(char ch) { return ch >= '0' && ch <= '9'; }

}  // namespace

std::string decimal_comma(const std::string& s) {
  std::string out = s;
  const std::size_t n = s.size();
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (s[i] != '.' || !digit(s[i - 1]) || !digit(s[i + 1])) continue;
    // The integer part and what precedes it.
    std::size_t b = i;
    while (b > 0 && digit(s[b - 1])) --b;
    if (b > 0) {
      const char p = s[b - 1];
      // A clause or section number: "C8.7", "§3.2", "A.4", "8A.4.11", "v0.1".
      if (std::isalpha(static_cast<unsigned char>(p)) || p == '.' || p == '_' || p == '/' ||
          (static_cast<unsigned char>(p) & 0x80))  // "§" and other UTF-8
        continue;
    }
    // The fraction and what follows: a second dot with a digit or a letter ("3.2.10", "3.2.II") is a reference.
    std::size_t e = i + 1;
    while (e < n && digit(s[e])) ++e;
    if (e + 1 < n && s[e] == '.' && (digit(s[e + 1]) || std::isupper(static_cast<unsigned char>(s[e + 1])))) continue;
    // "Tab. 3.2" or "Eq. 1.3": a reference after an abbreviation.
    if (b >= 2 && s[b - 1] == ' ' && s[b - 2] == '.') continue;
    out[i] = ',';
  }
  return out;
}

namespace {

// Greek letters, roots and powers of the engine's ASCII formulas typeset
// ("Se(T1) psi gamma / q" -> "Se(T1) ψ γ / q"), whole words only.
std::string typeset(const std::string& text) {
  static const std::vector<std::pair<std::string, std::string>> words{
      {"psi", "ψ"}, {"gamma", "γ"}, {"xi", "ξ"}, {"eta", "η"}, {"sqrt", "√"}, {"pi", "π"}, {"eps_ud", "ε_ud"},
      {"eps_uk", "ε_uk"}, {"alpha0", "α0"}, {"alpha", "α"}, {"theta_u", "θu"}, {"theta", "θ"}};
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    bool hit = false;
    const bool start = i == 0 || !std::isalpha(static_cast<unsigned char>(text[i - 1]));
    for (const auto& [w, g] : words) {
      if (!start || text.compare(i, w.size(), w) != 0) continue;
      const std::size_t e = i + w.size();
      if (e < text.size() && std::isalpha(static_cast<unsigned char>(text[e]))) continue;
      out += g;
      i = e;
      hit = true;
      break;
    }
    if (hit) continue;
    if (text.compare(i, 2, "^2") == 0) {
      out += "²";
      i += 2;
      continue;
    }
    if (text.compare(i, 4, "ug''") == 0 || text.compare(i, 4, "ur''") == 0) {
      out += text[i + 1] == 'g' ? "üg" : "ür";
      i += 4;
      continue;
    }
    out += text[i++];
  }
  return out;
}

}  // namespace

int dc_decimals(double dc, bool satisfied) {
  int prec = 3;
  // A small D/C keeps two significant digits (issue 36: "0,000" read as a value never computed).
  if (std::isfinite(dc) && dc > 0.0 && dc < 0.01) {
    while (prec < 9 && dc * std::pow(10.0, prec) < 10.0) ++prec;
    return prec;
  }
  if (satisfied || !std::isfinite(dc) || !(dc > 1.0)) return prec;
  while (prec < 9 && std::round(dc * std::pow(10.0, prec)) <= std::pow(10.0, prec)) ++prec;
  return prec;
}

std::string Ctx::loc(const std::string& text) const {
  if (L == Lang::en) return typeset(text);
  return decimal_comma(typeset(localise(L, text)));
}

std::string Ctx::note(const Note& n) const {
  const std::string s = typeset(note_text(L, n));
  return L == Lang::en ? s : decimal_comma(s);
}

std::string Ctx::note(const NoteText& n) const {
  const std::string s = typeset(note_text(L, n));
  return L == Lang::en ? s : decimal_comma(s);
}

std::string Ctx::n(double v, int prec) const {
  const std::string s = detail::number_text(v, ("%." + std::to_string(prec) + "f").c_str());
  if (L == Lang::en) return s;
  std::string out = s;
  for (char& ch : out)
    if (ch == '.') ch = ',';
  return out;
}

std::string Ctx::e(double v, int prec) const {
  std::string s = detail::number_text(v, ("%." + std::to_string(prec) + "e").c_str());
  if (L == Lang::it)
    for (char& ch : s)
      if (ch == '.') ch = ',';
  return s;
}

std::string Ctx::g(double v, int digits) const {
  const std::string s = detail::number_text(v, ("%." + std::to_string(digits) + "g").c_str());
  if (L == Lang::en) return s;
  std::string out = s;
  for (char& ch : out)
    if (ch == '.') ch = ',';
  return out;
}

std::string Ctx::unit(const std::string& u) const {
  if (u == "m/s2") return "m/s²";
  if (u == "m2") return "m²";
  if (u == "m3") return "m³";
  if (u == "kN/m3") return "kN/m³";
  if (u == "-") return "–";
  return u;
}

std::string Ctx::clause(const std::string& text) const {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == '[') {
      const std::size_t close = text.find(']', i);
      if (close != std::string::npos) {
        const std::string tag = text.substr(i + 1, close - i - 1);
        if (tag == "R" || tag == "I" || tag == "V-T" || tag == "V-S" || tag == "V" || tag == "V-p" || tag == "D") {
          if ((tag == "R" || tag == "I") && readings) {
            // The clause the tag qualifies: what precedes it in this item (after the last ", " or ";").
            std::size_t from = out.find_last_of(",;");
            from = from == std::string::npos ? 0 : from + 1;
            std::string what = out.substr(from);
            while (!what.empty() && what.front() == ' ') what.erase(0, 1);
            while (!what.empty() && what.back() == ' ') what.pop_back();
            readings->insert(what + " [" + tag + "]");
          }
          i = close + 1;
          while (!out.empty() && out.back() == ' ' && i < text.size() && (text[i] == ',' || text[i] == ';' || text[i] == ' '))
            out.pop_back();
          continue;
        }
      }
    }
    out += text[i++];
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == ',')) out.pop_back();
  // A reference to the engine's own theory notes ("docs/theory/mechanisms.md
  // §2.2") is named as such in the report's language, not as a file path.
  static const std::pair<const char*, const char*> theory[] = {
      {"building", "edificio"}, {"chain-dynamics", "dinamica delle catene"}, {"facade", "facciata"},
      {"fragility", "fragilità"}, {"kinematic", "analisi cinematica"}, {"mechanisms", "meccanismi"},
      {"record-selection", "selezione degli accelerogrammi"}, {"rocking", "dinamica del blocco"},
      {"spectra", "spettri"}, {"ties", "catene"}};
  for (const auto& [file, it] : theory) {
    const std::string path = std::string("docs/theory/") + file + ".md";
    for (std::size_t at = out.find(path); at != std::string::npos; at = out.find(path, at + 1))
      out.replace(at, path.size(), L == Lang::it ? std::string("note teoriche di assess, ") + it
                                                  : std::string("assess theory notes, ") + file);
  }
  return loc(out);
}

std::string Ctx::input_name(const std::string& name) const {
  static const std::vector<std::pair<std::string, std::string>> greek{
      {"psi(Z)", "ψ(Z)"}, {"gamma", "γ"}, {"xi", "ξ"}, {"eta", "η"}, {"m/s2", "m/s²"}};
  std::string s = name;
  for (const auto& [from, to] : greek) {
    const std::size_t p = s.find(from);
    if (p != std::string::npos && (p == 0 || s[p - 1] == ' ' || s[p - 1] == '(')) s.replace(p, from.size(), to);
  }
  const std::size_t u = s.find("m/s2");
  if (u != std::string::npos) s.replace(u, 4, "m/s²");
  if (L == Lang::it) {
    const std::size_t st = s.find("(storeys)");
    if (st != std::string::npos) s.replace(st, 9, "(piani)");
  }
  return s;
}

Cell Ctx::outcome_cell(Outcome o) const {
  Cell c(verdict_word(o));
  c.tone = verdict_tone(o);
  return c;
}

Cell Ctx::dc_cell(double dc, Outcome o) const {
  // The number printed carries the verdict: a failing D/C just above 1 gets the
  // decimals that show it ("1,0004", never "1,000" beside "non verificato").
  Cell c(o == Outcome::no_verdict ? "—" : n(dc, dc_decimals(dc, o == Outcome::satisfied)));
  c.numeric = true;
  c.tone = verdict_tone(o);
  c.strong = o != Outcome::no_verdict;
  return c;
}

std::string Ctx::collapse_text(const CheckRow& r) const {
  if (r.analyses == 0 || std::isfinite(r.dc)) return "";
  std::string s = r.collapsed > 0 ? msgf(L, "dc.collapse", r.collapsed, r.analyses)
                                  : msgf(L, "dc.failed", r.failed, r.analyses);
  if (std::isfinite(r.dc_survivors)) s += "; " + msgf(L, "dc.survivors", n(r.dc_survivors, 3));
  return s;
}

Cell Ctx::verdict_cell(const CheckRow& r) const {
  Cell c = outcome_cell(r.outcome());
  c.note = collapse_text(r);
  if (r.kind == "dynamic" && r.analyses > 0 && r.dc == 0.0) c.note = t("dyn.no_uplift");  // D/C 0: the wall never lifted
  return c;
}

Cell Ctx::num(double v, int prec) const {
  Cell c(n(v, prec));
  c.numeric = true;
  return c;
}

std::size_t candidate_of(const FacadeAssessment& a, const std::string& label) {
  for (std::size_t i = 0; i < a.kinematic.candidates.size(); ++i)
    if (a.kinematic.candidates[i].label == label) return i;
  return a.kinematic.governing;
}

std::vector<std::size_t> developed_candidates(const FacadeAssessment& a) {
  std::vector<std::size_t> out;
  auto add = [&](std::size_t i) {
    for (std::size_t j : out)
      if (j == i) return;
    out.push_back(i);
  };
  const Verdict& v = a.verdict;
  std::vector<const MethodVerdict*> order;
  if (const MethodVerdict* m = v.conclusion()) order.push_back(m);
  for (const std::string& code : {std::string("NTC2018"), std::string("NTC2008")})
    for (const MethodVerdict& m : v.methods)
      if (m.code == code) order.push_back(&m);
  for (const MethodVerdict* m : order)
    if (m->governing >= 0) add(candidate_of(a, v.rows[std::size_t(m->governing)].candidate));
  if (out.empty()) add(a.kinematic.governing);
  return out;
}

}  // namespace assess::relazione
