// build_info.hpp: what the relazione says of the program that wrote it (NTC
// 2018 §10.2, the code's identity and validation; issue 36, item 2) and what
// its Word edition is laid out with, compiled into the library at build time
// (libassess/CMakeLists.txt): the name and version, the source revision
// (`git describe`, "unknown" outside a checkout), the tests of the source
// tree per group, the verification record docs/verification.json (the same
// data as docs/verification.md), and the Word reference documents.
#pragma once

#include "assess/report/messages.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace assess {

struct TestGroup {
  std::string group;  ///< the first part of the tests' names: "unit", "numeric", "cli" ...
  int tests = 0;
};

struct BuildInfo {
  std::string name = "assess";
  std::string version;   ///< the project's version ("0.1.0")
  std::string revision;  ///< the source revision, or "unknown"
  std::vector<TestGroup> tests;  ///< empty when the build has no tests configured
  int total_tests() const;
};

const BuildInfo& build_info();

/// docs/verification.json as it was when the library was built.
std::string_view verification_record();

/// The Word reference document of the relazione in `lang` (tools/docx): A4,
/// margins, page numbers, the verdict colours (docx_writer.hpp).
std::string_view docx_reference(Lang lang);

}  // namespace assess
