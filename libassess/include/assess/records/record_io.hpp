// record_io.hpp: readers of accelerogram files into Record (SI units).
//
// Formats (spectra/records/README.md §4): PEER AT2 with all its header
// variants and line endings (LF, CRLF, CR CR LF); ESM / ITACA ASCII with the
// variable "DYNA" KEY: value header; GEM / ITACA processed fixed-width
// `.cor.acc`; plain one- or two-column text with a declared time step and
// unit. Every error names the file (and line) and what was expected.
#pragma once

#include "assess/records/record.hpp"
#include "assess/support/number_rules.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace assess {

/// The time step of every record, from a header, a time column, a case file's
/// "dt" or --dt (s): 1 us to 10 s. Strong-motion records are sampled at
/// 0.001-0.04 s; 1e-320 s (a subnormal) passed every check "dt > 0" and gave
/// a record 1e-317 s long (issue 31).
inline constexpr double record_dt_min_s = 1e-6;
inline constexpr double record_dt_max_s = 10.0;
/// The rule of a time step given by the user (--dt, assess.rocking's dt).
inline constexpr NumberRule record_dt_rule{"s", record_dt_min_s, record_dt_max_s, false, false,
                                           "strong-motion records are sampled at 0.001-0.04 s"};

/// Unit of the acceleration values in a file.
enum class AccelerationUnit {
  g,      ///< multiples of standard gravity g_n = 9.80665 m/s^2
  m_s2,   ///< m/s^2
  cm_s2   ///< cm/s^2 (gal)
};

/// Parses "g", "m/s2", "m/s^2", "cm/s2", "cm/s^2", "gal".
/// @throws InputError for anything else
AccelerationUnit parse_acceleration_unit(const std::string& text);
/// Factor converting a value in `unit` to m/s^2.
double to_m_s2(AccelerationUnit unit);

/// Reads an accelerogram, detecting its format from the content (PEER AT2,
/// ESM/ITACA ASCII, GEM .cor.acc). Values are converted to m/s^2.
/// @throws InputError for an unknown format, a truncated record (fewer
///   values than the header declares), a non-numeric value, dt <= 0.
Record read_record(const std::string& path);

/// Reads a plain text record: one value per line, or two columns (time in s,
/// acceleration) whose time spacing must equal dt. Blank lines and lines
/// starting with '#' are skipped.
/// @param dt_s time step (s), > 0
/// @param unit unit of the acceleration values
Record read_plain_record(const std::string& path, double dt_s, AccelerationUnit unit);

/// Reads a plain two-column record (time in s, acceleration in `unit`) whose
/// time step is the spacing of its time column, checked for uniformity as in
/// read_plain_record(path, dt, unit).
Record read_plain_record(const std::string& path, AccelerationUnit unit);
/// The same readers on a file's content (`path` names it in messages): for
/// records held in memory, and for the fuzzers of fuzz/.
Record parse_record_text(const std::string& text, const std::string& path);
Record parse_plain_record_text(const std::string& text, const std::string& path, double dt_s, AccelerationUnit unit);

/// A plain record from values held in memory (the Python module's numpy
/// arrays): `values` in `unit` at time step dt_s (s), with the checks of a
/// plain file: dt in [record_dt_min_s, record_dt_max_s], at least 2 values,
/// every value finite once converted to m/s^2 (InputError naming `name` and
/// the index of a bad value). Converted exactly as read_plain_record converts
/// the same numbers read from a file (value times to_m_s2(unit)).
Record make_plain_record(const double* values, std::size_t n, double dt_s, AccelerationUnit unit,
                         const std::string& name);
inline Record make_plain_record(const std::vector<double>& values, double dt_s, AccelerationUnit unit,
                                const std::string& name) {
  return make_plain_record(values.data(), values.size(), dt_s, unit, name);
}

/// Factor that scales `record` to a peak ground acceleration target_pga_m_s2 (m/s^2, > 0).
double scale_factor_to_pga(const Record& record, double target_pga_m_s2);

}  // namespace assess
