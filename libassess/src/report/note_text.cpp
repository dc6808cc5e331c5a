// note_text.cpp: a note of the assessment rendered from the message catalogue.
#include "assess/report/note_text.hpp"

#include "report/number_text.hpp"

#include <stdexcept>

namespace assess {

namespace {

std::string arg_text(Lang lang, const NoteArg& a) {
  switch (a.kind) {
    case NoteArg::Kind::text: return a.text;
    case NoteArg::Kind::generated: return localise(lang, a.text);
    case NoteArg::Kind::count: return std::to_string(static_cast<long long>(a.value));
    case NoteArg::Kind::number: break;
  }
  const std::string f = a.decimals < 0 ? "%." + std::to_string(-a.decimals) + "g" : "%." + std::to_string(a.decimals) + "f";
  std::string s = detail::number_text(a.value, f.c_str());
  if (lang == Lang::it)
    for (char& c : s)
      if (c == '.') c = ',';
  return a.unit.empty() ? s : s + " " + a.unit;
}

}  // namespace

std::string note_text(Lang lang, const Note& n) {
  const std::string& t = msg(lang, "note." + n.id);
  std::string out;
  std::size_t k = 0, i = 0;
  for (std::size_t p = t.find("{}"); p != std::string::npos; i = p + 2, p = t.find("{}", i)) {
    if (k == n.args.size()) throw std::logic_error("note '" + n.id + "': fewer arguments than placeholders");
    out += t.substr(i, p - i) + arg_text(lang, n.args[k++]);
  }
  if (k != n.args.size()) throw std::logic_error("note '" + n.id + "': more arguments than placeholders");
  return out + t.substr(i);
}

std::string note_text(Lang lang, const NoteText& parts) {
  std::string out;
  for (const Note& n : parts) out += note_text(lang, n);
  return out;
}

}  // namespace assess
