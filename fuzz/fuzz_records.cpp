// libFuzzer harness: every record reader (PEER AT2, ESM/ITACA ASCII, GEM
// .cor.acc, plain one- or two-column text) on arbitrary bytes. The first byte
// picks the reader and, for plain text, the time step and the unit; the rest
// is the file's content. Any exception but InputError, any crash, leak or
// undefined behaviour (ASan + UBSan) is a finding. On success the record must
// hold finite accelerations and a positive time step.
#include <assess/records/record_io.hpp>
#include <assess/support/error.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t selector = data[0];
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    assess::Record r;
    if (selector % 2 == 0) {
      r = assess::parse_record_text(text, "fuzz.AT2");
    } else {
      const assess::AccelerationUnit units[] = {assess::AccelerationUnit::g, assess::AccelerationUnit::m_s2,
                                                assess::AccelerationUnit::cm_s2};
      const double dts[] = {0.01, 0.005, 1e-300, 1e300};
      r = assess::parse_plain_record_text(text, "fuzz.txt", dts[(selector >> 1) % 4], units[(selector >> 3) % 3]);
    }
    if (!(std::isfinite(r.dt) && r.dt > 0.0)) std::abort();
    for (double a : r.acc)
      if (!std::isfinite(a)) std::abort();
    (void)r.pga();
  } catch (const assess::InputError&) {
    // a named input error: the expected outcome for bad bytes
  }
  return 0;
}
