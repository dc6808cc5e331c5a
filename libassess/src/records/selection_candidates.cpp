// selection_candidates.cpp: candidate records with their response spectra at
// the check periods, computed once (selection_candidates.hpp).
#include "assess/records/selection_candidates.hpp"

#include "assess/records/response_spectrum.hpp"
#include "assess/support/error.hpp"
#include "support/parallel_for.hpp"

#include <sstream>

namespace assess {

namespace {

std::vector<CandidateInfo> own_groups(std::size_t n) {
  std::vector<CandidateInfo> info(n);
  for (std::size_t i = 0; i < n; ++i) info[i].event = info[i].station = "#" + std::to_string(i);
  return info;
}

std::string num(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

}  // namespace

SelectionCandidates::SelectionCandidates(const std::vector<Record>& records, const SelectionOptions& opts)
    : SelectionCandidates(records, own_groups(records.size()), opts) {}

SelectionCandidates::SelectionCandidates(const std::vector<Record>& records, const std::vector<CandidateInfo>& info,
                                         const SelectionOptions& opts) {
  opts.validate();
  if (records.empty()) throw InputError("select_records: no candidate records");
  if (info.size() != records.size()) throw InputError("select_records: one CandidateInfo per candidate");
  range_ = opts.range;
  n_periods_ = opts.n_periods;
  damping_ratio_ = opts.damping_ratio;
  periods_ = log_spaced_periods(range_.T_min, range_.T_max, n_periods_);
  candidates_.resize(records.size());
  std::vector<std::size_t> to_compute;
  for (std::size_t i = 0; i < records.size(); ++i) {
    Candidate& c = candidates_[i];
    c.name = records[i].name;
    c.pga = records[i].pga();
    c.info = info[i];
    // A record is used only up to its longest usable period 1/f_low
    // (docs/theory/record-selection.md §2): no spectrum beyond it.
    c.usable = !(info[i].max_usable_period_s < range_.T_max);
    if (c.usable) to_compute.push_back(i);
  }
  // 5 %-damped (opts.damping_ratio) linear oscillator, response_spectrum.hpp.
  const ResponseOptions ro{damping_ratio_, ResponseOptions{}.min_steps_per_period};
  detail::parallel_for(to_compute.size(), [&](std::size_t k) {
    const std::size_t i = to_compute[k];
    const ResponseSpectrum rs = response_spectrum(records[i], periods_, ro);
    std::vector<double>& psa = candidates_[i].psa;
    psa.resize(rs.ordinates.size());
    for (std::size_t j = 0; j < psa.size(); ++j) psa[j] = rs.ordinates[j].PSA;
  });
}

SelectionCandidates::SelectionCandidates(const LibrarySpectra& spectra, const std::vector<std::size_t>& rows,
                                         const std::vector<std::string>& names, const std::vector<CandidateInfo>& info,
                                         const SelectionOptions& opts) {
  opts.validate();
  if (rows.empty()) throw InputError("select_records: no candidate records");
  if (names.size() != rows.size() || info.size() != rows.size())
    throw InputError("select_records: one name and one CandidateInfo per candidate");
  const long d = spectra.find_damping(opts.damping_ratio);
  if (d < 0) throw InputError("select_records: the precomputed spectra have no damping " + num(opts.damping_ratio));
  if (opts.range.T_max > spectra.periods.back())
    throw InputError("select_records: the precomputed spectra end at " + num(spectra.periods.back()) + " s < T_max = " +
                     num(opts.range.T_max) + " s");
  range_ = opts.range;
  n_periods_ = opts.n_periods;
  damping_ratio_ = opts.damping_ratio;
  interpolated_ = true;
  periods_ = log_spaced_periods(range_.T_min, range_.T_max, n_periods_);
  candidates_.resize(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i] >= spectra.ids.size()) throw InputError("select_records: no precomputed spectrum row " + std::to_string(rows[i]));
    Candidate& c = candidates_[i];
    const double* row = spectra.row(rows[i], std::size_t(d));
    c.name = names[i];
    c.pga = row[0];  // T = 0: the rigid oscillator, PSA = PGA
    c.info = info[i];
    c.usable = !(info[i].max_usable_period_s < range_.T_max);
    if (!c.usable) continue;
    c.psa.resize(periods_.size());
    for (std::size_t j = 0; j < periods_.size(); ++j) c.psa[j] = spectra.interpolate(row, periods_[j]);
  }
}

SelectionCandidates SelectionCandidates::subset(const std::vector<std::size_t>& which) const {
  SelectionCandidates out;
  out.range_ = range_;
  out.n_periods_ = n_periods_;
  out.damping_ratio_ = damping_ratio_;
  out.interpolated_ = interpolated_;
  out.periods_ = periods_;
  out.candidates_.reserve(which.size());
  for (std::size_t i : which) out.candidates_.push_back(candidates_.at(i));
  return out;
}

void SelectionCandidates::check_compatible(const SelectionOptions& opts) const {
  if (opts.range.T_min != range_.T_min || opts.range.T_max != range_.T_max || opts.n_periods != n_periods_ ||
      opts.damping_ratio != damping_ratio_)
    throw InputError("select_records: the candidates' spectra were computed for periods " + num(range_.T_min) + "-" +
                     num(range_.T_max) + " s (" + std::to_string(n_periods_) + " periods, damping " +
                     num(damping_ratio_) + "); the selection asks for " + num(opts.range.T_min) + "-" +
                     num(opts.range.T_max) + " s (" + std::to_string(opts.n_periods) + " periods, damping " +
                     num(opts.damping_ratio) + ")");
}

}  // namespace assess
