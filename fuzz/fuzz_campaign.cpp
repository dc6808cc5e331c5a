// libFuzzer harness: the campaign reader (JSON text -> CampaignSpec), its
// normalised form and its flat index (decompose/compose round trip on the
// first, middle and last ids). Record files are resolved against
// tests/data/campaign of the source tree (ASSESS_DATA_DIR) but not read, so
// that each run stays fast. Any exception but InputError, any crash, leak or
// undefined behaviour is a finding.
#include <assess/campaign/campaign.hpp>
#include <assess/support/error.hpp>
#include <assess/support/json_input.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {
std::string base_dir() {
  const char* d = std::getenv("ASSESS_DATA_DIR");
  return std::string(d ? d : ".") + "/tests/data/campaign";
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string dir = base_dir();
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const nlohmann::json doc = assess::parse_json_text(text, "fuzz.json");
    const assess::CampaignSpec s = assess::parse_campaign(doc, dir);
    (void)assess::to_json(s).dump();
    const std::uint64_t n = s.size();
    if (n == 0) std::abort();  // a valid campaign has analyses
    for (std::uint64_t id : {std::uint64_t{0}, n / 2, n - 1})
      if (assess::compose(s, assess::decompose(s, id)) != id) std::abort();
  } catch (const assess::InputError&) {
  }
  return 0;
}
