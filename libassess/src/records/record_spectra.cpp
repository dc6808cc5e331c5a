// record_spectra.cpp: the library's precomputed spectra (record_spectra.hpp).
//
// File layout (all integers and doubles little-endian; this library refuses
// a file whose byte order marker does not read back as 1.0):
//   "ASSESS-SPECTRA-1"            16 bytes (magic and version)
//   double 1.0                    byte order marker
//   uint64 catalogue_hash         content_hash of the catalogue.json
//   uint32 n_periods, n_dampings, n_records
//   double periods[n_periods], dampings[n_dampings]
//   n_records x (uint32 length, id bytes)
//   double psa[n_records][n_dampings][n_periods]
//   uint64 content_hash of every byte above
#include "assess/records/record_spectra.hpp"

#include "assess/records/response_spectrum.hpp"
#include "assess/support/content_hash.hpp"
#include "assess/support/error.hpp"
#include "assess/support/input_file.hpp"
#include "assess/support/number_rules.hpp"
#include "assess/support/output_file.hpp"
#include "assess/support/units.hpp"
#include "support/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>

namespace assess {

namespace {

constexpr char magic[17] = "ASSESS-SPECTRA-1";

template <typename T>
void put(std::string& out, const T& v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.append(b, sizeof(T));
}

// Reads the payload, bytes [pos, end) with end = size - 8 (the content hash
// after it is not data): pos never passes end, so no difference underflows
// (issue 39's fuzzer: an id's length read from the hash's bytes moved pos
// past the file, and the next read came from a wild address).
struct Reader {
  const std::string& bytes;
  const std::string& path;
  std::size_t pos = 0;
  std::size_t end() const { return bytes.size() >= 8 ? bytes.size() - 8 : 0; }
  std::size_t left() const { return pos <= end() ? end() - pos : 0; }
  template <typename T>
  T get() {
    if (left() < sizeof(T)) throw InputError("record spectra '" + path + "': truncated file");
    T v;
    std::memcpy(&v, bytes.data() + pos, sizeof(T));
    pos += sizeof(T);
    return v;
  }
};

}  // namespace

std::vector<double> spectra_grid_periods() {
  const int n = int(std::lround(std::log10(spectra_grid_T_max_s / spectra_grid_T_min_s) * spectra_grid_per_decade)) + 1;
  std::vector<double> T = log_spaced_periods(spectra_grid_T_min_s, spectra_grid_T_max_s, n);
  T.insert(T.begin(), 0.0);
  return T;
}

long LibrarySpectra::find(const std::string& id) const {
  const auto it = std::find(ids.begin(), ids.end(), id);
  return it == ids.end() ? -1 : long(it - ids.begin());
}

long LibrarySpectra::find_damping(double xi) const {
  const auto it = std::find(dampings.begin(), dampings.end(), xi);
  return it == dampings.end() ? -1 : long(it - dampings.begin());
}

double LibrarySpectra::interpolate(const double* r, double T) const {
  if (!(T >= 0.0) || T > periods.back())
    throw InputError("record spectra: period " + std::to_string(T) + " s outside the grid 0-" +
                     std::to_string(periods.back()) + " s");
  // First grid period >= T.
  const std::size_t k = std::size_t(std::lower_bound(periods.begin(), periods.end(), T) - periods.begin());
  if (periods[k] == T) return r[k];
  const double T0 = periods[k - 1], T1 = periods[k];
  if (T0 == 0.0) return r[0] + (r[1] - r[0]) * T / T1;  // rigid end: linear from the PGA
  if (!(r[k - 1] > 0.0) || !(r[k] > 0.0)) return r[k - 1] + (r[k] - r[k - 1]) * (T - T0) / (T1 - T0);
  const double w = std::log(T / T0) / std::log(T1 / T0);
  return std::exp(std::log(r[k - 1]) + w * (std::log(r[k]) - std::log(r[k - 1])));
}

LibrarySpectra compute_library_spectra(const RecordCatalogue& cat, const std::vector<double>& dampings) {
  LibrarySpectra s;
  s.periods = spectra_grid_periods();
  s.dampings = dampings;
  s.catalogue_hash = cat.text_hash;
  std::vector<const CatalogueEntry*> todo;
  for (const CatalogueEntry& e : cat.entries)
    if (e.usable_for_design) todo.push_back(&e), s.ids.push_back(e.id);
  const std::size_t np = s.periods.size(), nd = dampings.size();
  s.psa.assign(todo.size() * nd * np, 0.0);
  // One (record, damping) row per task: the record is read in each task of
  // its row (a few ms) rather than held for every row at once.
  detail::parallel_for(todo.size() * nd, [&](std::size_t task) {
    const std::size_t i = task / nd, d = task % nd;
    const Record rec = cat.load(*todo[i]);
    ResponseOptions ro;
    ro.damping_ratio = dampings[d];
    const ResponseSpectrum rs = response_spectrum(rec, s.periods, ro);
    double* out = s.psa.data() + (i * nd + d) * np;
    for (std::size_t j = 0; j < np; ++j) out[j] = rs.ordinates[j].PSA;
  });
  return s;
}

void write_library_spectra(const LibrarySpectra& s, const std::string& path) {
  std::string out(magic, 16);
  put(out, 1.0);
  put(out, s.catalogue_hash);
  put(out, std::uint32_t(s.periods.size()));
  put(out, std::uint32_t(s.dampings.size()));
  put(out, std::uint32_t(s.ids.size()));
  for (double T : s.periods) put(out, T);
  for (double d : s.dampings) put(out, d);
  for (const std::string& id : s.ids) {
    put(out, std::uint32_t(id.size()));
    out += id;
  }
  for (double v : s.psa) put(out, v);
  put(out, content_hash(out));
  write_output_file(path, out, "the record spectra");  // whole or not at all (output_file.hpp)
}

LibrarySpectra read_library_spectra(const std::string& path, const RecordCatalogue& cat) {
  if (!std::filesystem::exists(path)) throw InputError("record spectra '" + path + "' not found");
  // The bounded reader: a regular file within its limit, never a FIFO.
  return parse_library_spectra(read_input_file(path, input_kinds::record_spectra), path, cat);
}

LibrarySpectra parse_library_spectra(const std::string& bytes, const std::string& path, const RecordCatalogue& cat) {
  const std::string where = "record spectra '" + path + "'";
  if (bytes.size() < 16 + 8 + 8 + 12 + 8 || bytes.compare(0, 16, magic) != 0)
    throw InputError(where + ": not a spectra file of this version (" + magic + ")");
  std::uint64_t stored;
  std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
  if (content_hash(bytes.data(), bytes.size() - 8) != stored)
    throw InputError(where + ": content hash mismatch (damaged file)");
  Reader rd{bytes, path, 16};
  if (rd.get<double>() != 1.0) throw InputError(where + ": written with another byte order");
  LibrarySpectra s;
  s.catalogue_hash = rd.get<std::uint64_t>();
  if (s.catalogue_hash != cat.text_hash)
    throw InputError(where + " were computed for another catalogue.json (catalogue hash " +
                     hash_hex(s.catalogue_hash) + ", this one " + hash_hex(cat.text_hash) +
                     "): stale, rebuild them with `assess records build`");
  // The counts, checked against what the file holds in 64-bit arithmetic
  // before anything is allocated (issue 39: the product of three 32-bit
  // counts wrapped, and a 600 kB file asked for 64 GB).
  const std::uint64_t np = rd.get<std::uint32_t>(), nd = rd.get<std::uint32_t>(), nr = rd.get<std::uint32_t>();
  const std::uint64_t left = rd.left();  // < 2^63: a string's size
  const auto sizes = [&] { return where + ": its counts (" + std::to_string(np) + " periods, " + std::to_string(nd) +
                                  " dampings, " + std::to_string(nr) + " records) do not fit the file"; };
  // Each quotient bounds the next product: np + nd <= left/8, nd np <= left/8.
  if (np < 2 || nd < 1 || np > left / 8 || nd > left / 8 - np || nd > left / 8 / np) throw InputError(sizes());
  // Each record takes an id (4 bytes of length at least) and nd np ordinates.
  const std::uint64_t per_record = 4 + 8 * nd * np;
  if (nr > (left - 8 * (np + nd)) / per_record) throw InputError(sizes());
  s.periods.resize(np);
  for (double& T : s.periods) T = rd.get<double>();
  s.dampings.resize(nd);
  for (double& d : s.dampings) d = rd.get<double>();
  s.ids.resize(nr);
  for (std::string& id : s.ids) {
    const std::uint32_t len = rd.get<std::uint32_t>();
    if (len > rd.left()) throw InputError(where + ": truncated file");
    id.assign(bytes, rd.pos, len);
    rd.pos += len;
  }
  const std::uint64_t n = nr * nd * np;
  if (rd.left() != n * 8) throw InputError(sizes());
  s.psa.resize(n);
  if (n) std::memcpy(s.psa.data(), bytes.data() + rd.pos, n * 8);
  // The content, checked after the hash (which only says the file is as it
  // was written; issue 39: NaN, zero, negative or 1e300 ordinates and a NaN
  // or repeated period grid became selections).
  for (std::size_t j = 0; j < s.periods.size(); ++j) {
    const double T = s.periods[j];
    if (!(std::isfinite(T) && (j == 0 ? T == 0.0 : T > s.periods[j - 1])))
      throw InputError(where + ": the period grid must start at 0 s and increase strictly with finite periods "
                       "(period " + std::to_string(j) + " is " + number_for_message(T) + " s)");
  }
  for (std::size_t d = 0; d < s.dampings.size(); ++d)
    if (!(s.dampings[d] > 0.0 && s.dampings[d] < 1.0) ||
        std::find(s.dampings.begin(), s.dampings.begin() + long(d), s.dampings[d]) != s.dampings.begin() + long(d))
      throw InputError(where + ": damping " + number_for_message(s.dampings[d]) +
                       " is not a fraction of critical in (0, 1) distinct from the others");
  // The records: the catalogue's usable ones, in its order (compute_library_spectra).
  std::vector<const CatalogueEntry*> usable;
  for (const CatalogueEntry& e : cat.entries)
    if (e.usable_for_design) usable.push_back(&e);
  if (usable.size() != s.ids.size())
    throw InputError(where + ": " + std::to_string(s.ids.size()) + " records, the catalogue has " +
                     std::to_string(usable.size()) + " usable for design: rebuild them with `assess records build`");
  for (std::size_t i = 0; i < usable.size(); ++i) {
    const CatalogueEntry& e = *usable[i];
    if (s.ids[i] != e.id)
      throw InputError(where + ": record " + std::to_string(i + 1) + " is '" + s.ids[i] + "', the catalogue's is '" +
                       e.id + "': rebuild them with `assess records build`");
    for (std::size_t d = 0; d < s.dampings.size(); ++d) {
      const double* r = s.row(i, d);
      // T = 0: the record's PGA, as the catalogue gives it (6 digits).
      const double pga = e.pga_g * units::g_n;
      if (!(std::fabs(r[0] - pga) <= 1e-5 * pga))
        throw InputError(where + ": record " + e.id + ": PSA(0) = " + number_for_message(r[0]) +
                         " m/s^2 is not its PGA " + number_for_message(pga) + " m/s^2");
      // 0 < PSA(T) <= PGA / (xi sqrt(1 - xi^2)): the oscillator's impulse
      // response h(t) = e^(-xi w t) sin(w_d t) / w_d gives |w^2 u| <= max|a|
      // w^2 / w_d int e^(-xi w t) dt = PGA w / (xi w_d) (docs/theory/record-selection.md §2.6).
      const double xi = s.dampings[d], bound = pga / (xi * std::sqrt(1.0 - xi * xi)) * (1.0 + 1e-9);
      for (std::size_t j = 0; j < s.periods.size(); ++j)
        if (!(r[j] > 0.0 && r[j] <= bound))
          throw InputError(where + ": record " + e.id + ": PSA " + number_for_message(r[j]) + " m/s^2 at T = " +
                           number_for_message(s.periods[j]) + " s, damping " + number_for_message(xi) +
                           ": expected a positive value at most PGA/(xi sqrt(1 - xi^2)) = " + number_for_message(bound) +
                           " m/s^2");
    }
  }
  return s;
}

}  // namespace assess
