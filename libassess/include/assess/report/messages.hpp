// messages.hpp: the message catalogue of the reports (report layer). Every
// sentence, heading, column title and code term printed in the HTML/PDF
// relazione lives in one table (src/report/messages.cpp), in Italian and
// English; the code's own terms are in Italian in both (meccanismo di
// ribaltamento semplice, verifica allo SLV, moltiplicatore alpha0 ...).
#pragma once

#include <string>
#include <vector>

namespace assess {

/// Language of a report. Default Italian (docs/user/run.md: the relazione di
/// calcolo is filed with an Italian authority under NTC 2018).
enum class Lang { it, en };

/// "it" or "en"; InputError naming the accepted values otherwise.
Lang parse_lang(const std::string& s);
std::string to_string(Lang l);  ///< "it", "en"

/// The text of `key` in `lang`. An unknown key is a programming error:
/// std::logic_error naming it (the catalogue test renders every key).
const std::string& msg(Lang lang, const std::string& key);
/// Every key of the catalogue (for the catalogue test).
std::vector<std::string> message_keys();

/// The Italian/English name of a mechanism type ("simple_overturning" ->
/// "ribaltamento semplice" / "simple overturning"); the type itself if unknown.
std::string mechanism_name(Lang lang, const std::string& type);

}  // namespace assess
