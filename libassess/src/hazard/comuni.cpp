// comuni.cpp: comune lookup by name (see comuni.hpp).
#include "assess/hazard/comuni.hpp"

#include "assess/hazard/hazard.hpp"
#include "assess/support/error.hpp"
#include "assess/support/input_file.hpp"
#include "assess/support/json_input.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <mutex>
#include <sstream>

namespace assess {

namespace {

/// Lower case ASCII letters and digits only; the accented Latin letters of
/// Italian, German, French, Slovenian and Ladin names lose their accent
/// (UTF-8 two-byte sequences of U+00C0..U+017F); blanks and the punctuation
/// of names (' - . / ,) are dropped. Any other character (an emoji, another
/// script, a control character) becomes '?', so that "L'Aquila😀" matches no
/// comune instead of L'Aquila (issue 31).
std::string fold(const std::string& s) {
  static const char* latin1 =  // U+00C0 .. U+00FF
      "aaaaaaaceeeeiiiidnooooo/ouuuuypsaaaaaaaceeeeiiiidnooooo/ouuuuypy";
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = s[i];
    if (c < 0x80) {
      if (std::isalnum(c)) out += char(std::tolower(c));
      else if (!(c == ' ' || c == '\'' || c == '-' || c == '.' || c == '/' || c == ',' || c == '`')) out += '?';
      continue;
    }
    if ((c == 0xC3 || c == 0xC4 || c == 0xC5) && i + 1 < s.size()) {
      const unsigned cp = ((c & 0x1F) << 6) | (static_cast<unsigned char>(s[i + 1]) & 0x3F);
      ++i;
      if (cp >= 0xC0 && cp <= 0xFF) {
        const char b = latin1[cp - 0xC0];
        if (std::isalpha(static_cast<unsigned char>(b))) out += b;
        else out += '?';  // multiplication and division signs
      } else if (cp >= 0x100 && cp <= 0x17F) {
        // Latin Extended-A: pairs of upper/lower case of a base letter.
        static const char* ext =
            "aaaaaaccccccccddddeeeeeeeeeegggggggghhhhiiiiiiiiiiiijjkkkllllllllllnnnnnnnnnoooooooorrrrrrssssssssttttttuuuuuuuuuuuuwwyyyzzzzzzs";
        const std::size_t k = cp - 0x100;
        if (k < 128) out += ext[k];
      }
      continue;
    }
    // Other characters (other scripts, symbols, emoji): no comune's name.
    // The typographic apostrophe U+2019 (E2 80 99) of "L’Aquila" is dropped like '.
    const bool apostrophe = c == 0xE2 && i + 2 < s.size() && static_cast<unsigned char>(s[i + 1]) == 0x80 &&
                            static_cast<unsigned char>(s[i + 2]) == 0x99;
    if (!apostrophe) out += '?';
    while (i + 1 < s.size() && (static_cast<unsigned char>(s[i + 1]) & 0xC0) == 0x80) ++i;
  }
  return out;
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') cur += '"', ++i;
      else if (c == '"') quoted = false;
      else cur += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.push_back(cur), cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

/// The parts of a bilingual name: "Duino Aurisina-Devin Nabrežina" and
/// "Bolzano/Bozen" split at '/' and at '-' between two multi-letter words.
std::vector<std::string> name_parts(const std::string& name) {
  std::vector<std::string> parts;
  std::string cur;
  for (char c : name) {
    if (c == '/' || c == '-') {
      parts.push_back(cur), cur.clear();
    } else {
      cur += c;
    }
  }
  parts.push_back(cur);
  if (parts.size() < 2) return {};
  return parts;
}

}  // namespace

std::string Comune::describe() const { return name + " (" + province + "), ISTAT " + istat_code; }

std::string comune_note() {
  return "municipal seat used (ISTAT list, Wikidata coordinates): give the building's lat/lon for the final check";
}

ComuneTable ComuneTable::load(const std::string& path) {
  std::istringstream in(read_input_file(path, input_kinds::comuni_table));
  ComuneTable t;
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (n == 1 || line.empty()) continue;
    const std::vector<std::string> f = split_csv(line);
    if (f.size() < 6)
      throw InputError(path + ": line " + std::to_string(n) + ": expected istat_code,name,province,region,lat,lon[,alt_names]");
    Comune c;
    c.istat_code = f[0];
    c.name = f[1];
    c.province = f[2];
    c.region = f[3];
    try {
      c.lat = std::stod(f[4]);
      c.lon = std::stod(f[5]);
    } catch (const std::exception&) {
      throw InputError(path + ": line " + std::to_string(n) + ": lat and lon must be decimal degrees");
    }
    if (f.size() > 6 && !f[6].empty()) {
      std::stringstream ss(f[6]);
      std::string a;
      while (std::getline(ss, a, ';'))
        if (!a.empty()) c.alt_names.push_back(a);
    }
    t.comuni_.push_back(std::move(c));
  }
  if (t.comuni_.empty()) throw InputError(path + ": no comune in the file");
  return t;
}

std::shared_ptr<const ComuneTable> ComuneTable::shipped() {
  static std::mutex m;
  static std::shared_ptr<const ComuneTable> table;
  std::lock_guard<std::mutex> lock(m);
  if (!table) table = std::make_shared<const ComuneTable>(load(data_dir() + "/spectra/comuni.csv"));
  return table;
}

const Comune& ComuneTable::find(const std::string& name, const std::string& province) const {
  const std::string key = fold(name), prov = upper(province);
  if (key.empty()) throw InputError("comune '" + name + "': expected the name of an Italian comune");
  auto matches = [&](bool parts) {
    std::vector<const Comune*> out;
    for (const Comune& c : comuni_) {
      bool hit = false;
      if (!parts) {
        hit = fold(c.name) == key;
        for (const std::string& a : c.alt_names) hit = hit || fold(a) == key;
      } else {
        for (const std::string& p : name_parts(c.name)) hit = hit || fold(p) == key;
      }
      if (hit) out.push_back(&c);
    }
    return out;
  };
  std::vector<const Comune*> found = matches(false);
  // A part of a bilingual or double name ("Vignola" of Vignola-Falesina, TN)
  // matches too: a name that is one comune and part of another's (Vignola,
  // MO) needs the province (issue 31: it was taken as the first).
  for (const Comune* c : matches(true))
    if (std::find(found.begin(), found.end(), c) == found.end()) found.push_back(c);
  if (found.empty()) {
    // "Did you mean": the three closest names by edit distance of the folded forms.
    std::vector<std::pair<std::size_t, const Comune*>> near;
    for (const Comune& c : comuni_) near.push_back({edit_distance(fold(c.name), key), &c});
    std::partial_sort(near.begin(), near.begin() + std::min<std::size_t>(3, near.size()), near.end(),
                      [](const auto& a, const auto& b) { return a.first < b.first; });
    std::string list;
    for (std::size_t i = 0; i < std::min<std::size_t>(3, near.size()); ++i)
      list += (i ? ", " : "") + near[i].second->name + " (" + near[i].second->province + ")";
    throw InputError("comune '" + name + "' is not in the ISTAT list; did you mean " + list + "?");
  }
  if (!prov.empty()) {
    std::vector<const Comune*> in_prov;
    for (const Comune* c : found)
      if (c->province == prov) in_prov.push_back(c);
    if (in_prov.empty()) {
      std::string list;
      for (const Comune* c : found) list += (list.empty() ? "" : ", ") + c->describe();
      throw InputError("comune '" + name + "' is not in province " + prov + "; the list has " + list);
    }
    found = in_prov;
  }
  if (found.size() > 1) {
    std::string list;
    for (const Comune* c : found) list += (list.empty() ? "" : ", ") + c->describe();
    throw InputError("comune '" + name + "' is ambiguous: " + list + "; give the province (sigla)");
  }
  return *found.front();
}

}  // namespace assess
