// build_info.cpp: the build's identity and embedded data (build_info.hpp),
// read from the sources generated at build time (libassess/CMakeLists.txt).
#include "assess/report/build_info.hpp"

#include <cstddef>
#include <sstream>

namespace assess {

namespace generated {
extern const char* const source_revision;
extern const char* const test_counts;
extern const unsigned char verification_json[];
extern const std::size_t verification_json_size;
extern const unsigned char reference_docx_it[];
extern const std::size_t reference_docx_it_size;
extern const unsigned char reference_docx_en[];
extern const std::size_t reference_docx_en_size;
}  // namespace generated

int BuildInfo::total_tests() const {
  int n = 0;
  for (const TestGroup& g : tests) n += g.tests;
  return n;
}

const BuildInfo& build_info() {
  static const BuildInfo info = [] {
    BuildInfo b;
    b.version = ASSESS_VERSION;
    b.revision = generated::source_revision;
    std::istringstream in(generated::test_counts);  // "unit 25;numeric 35;..."
    std::string item;
    while (std::getline(in, item, ';')) {
      const std::size_t sp = item.find(' ');
      if (sp == std::string::npos) continue;
      b.tests.push_back({item.substr(0, sp), std::stoi(item.substr(sp + 1))});
    }
    return b;
  }();
  return info;
}

std::string_view verification_record() {
  return {reinterpret_cast<const char*>(generated::verification_json), generated::verification_json_size};
}

std::string_view docx_reference(Lang lang) {
  return lang == Lang::it
             ? std::string_view{reinterpret_cast<const char*>(generated::reference_docx_it), generated::reference_docx_it_size}
             : std::string_view{reinterpret_cast<const char*>(generated::reference_docx_en), generated::reference_docx_en_size};
}

}  // namespace assess
