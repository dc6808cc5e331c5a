// campaign.hpp: a parametric campaign of rocking analyses (seed paper
// Lipo & de Felice 2017, §3.2): walls x records x scale factors x
// realisations of random time/amplitude multipliers x restitution values x
// models, as a flat, deterministic index of analyses, each compared with the
// code's demand/capacity ratios (seed Eq. 8).
#pragma once

#include "assess/kinematic/free_wall_capacity.hpp"
#include "assess/records/record.hpp"
#include "assess/dynamics/rocking_analysis.hpp"
#include "assess/dynamics/rocking_model.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace assess {

/// A free-standing rectangular wall of the campaign. b and h are the
/// HALF-thickness and HALF-height (the seed's notation: a 2b x 2h block).
struct CampaignWall {
  std::string name;
  double b_m = 0.0;               ///< half-thickness b (m)
  double h_m = 0.0;               ///< half-height h (m)
  double unit_weight_N_m3 = 0.0;  ///< unit weight gamma (N/m^3)
  double k_N_m3 = 0.0;            ///< Winkler modulus of the smooth model (N/m^3)
};

/// A record of the campaign: a display name and the resolved file path.
struct CampaignRecord {
  std::string name;
  std::string path;
  /// Plain text record: the unit of its values ("" = format detected from the
  /// content) and its time step (s; 0 = a two-column file gives it).
  std::string unit;
  double dt = 0.0;
};

/// The two models of the seed: the smooth block on a Winkler bed and the rigid
/// Housner block.
enum class CampaignModel { smooth, rigid };
const char* to_string(CampaignModel m);

/// A restitution value as written in the campaign ("housner",
/// "one_sided_theory", "none" or a number in [-1, 1]).
struct CampaignRestitution {
  std::string label;  ///< as written (numbers in shortest round-trip form)
  Restitution value;
};

/// The campaign as read from its JSON file (see docs/user/campaign.md).
struct CampaignSpec {
  std::string name;                          ///< free text
  std::vector<CampaignWall> walls;           ///< >= 1
  std::vector<CampaignRecord> records;       ///< >= 1
  std::vector<double> scale_factors;         ///< amplitude factors (-), each > 0
  std::vector<CampaignRestitution> restitutions;  ///< >= 1 (default: housner)
  std::vector<CampaignModel> models;         ///< default: smooth, rigid
  int realisations = 50;                     ///< N >= 1; realisation 0 is the unperturbed record
  double time_cov = 0.03;                    ///< coefficient of variation of the time-axis multiplier (-)
  double amplitude_cov = 0.03;               ///< coefficient of variation of the amplitude multiplier (-)
  std::uint64_t seed = 1;                    ///< seed of the multipliers
  bool one_sided = false;                    ///< one-sided rocking (default two-sided)
  double FC = 1.0;                           ///< confidence factor of the code check (seed §3.2: 1)
  RockingOptions rocking;                    ///< integrator options (scale/reverse must stay default)

  /// Number of analyses: walls x records x scales x realisations x restitutions x models.
  std::uint64_t size() const;
  /// Analyses per group (restitutions x models): a group shares the wall,
  /// the record, the scale factor and the realisation (the same perturbed record).
  std::uint64_t group_size() const;
};

/// Reads a campaign JSON object. Relative record paths are resolved against
/// `base_dir` first, then data_dir(). @throws InputError naming the JSON path
/// (e.g. "records[2].file") of the offending value.
CampaignSpec parse_campaign(const nlohmann::json& j, const std::string& base_dir);
/// Reads a campaign JSON file (records relative to the file's directory).
CampaignSpec read_campaign(const std::string& path);
/// The normalised campaign (every resolved value), used to check that a
/// resumed campaign is the same one.
nlohmann::json to_json(const CampaignSpec& spec);

/// Position of an analysis in the cartesian product. The flat id is
/// id = ((((wall*NR + record)*NS + scale)*NN + realisation)*NE + restitution)*NM + model.
struct AnalysisIndex {
  std::size_t wall = 0, record = 0, scale = 0, realisation = 0, restitution = 0, model = 0;
};
AnalysisIndex decompose(const CampaignSpec& spec, std::uint64_t id);
std::uint64_t compose(const CampaignSpec& spec, const AnalysisIndex& ix);

/// Random multipliers of one realisation of one record.
struct Perturbation {
  double time = 1.0;       ///< multiplier of the time axis (dt) (-)
  double amplitude = 1.0;  ///< multiplier of the accelerations (-)
};

/// The multipliers of (record, realisation): normal, mean 1, coefficients of
/// variation time_cov and amplitude_cov, from a counter-based generator
/// (SplitMix64 of seed, record and realisation, then Box-Muller), so they do
/// not depend on the order of evaluation, the thread or the MPI rank.
/// Realisation 0 is the unperturbed record (1, 1).
Perturbation perturbation(std::uint64_t seed, std::size_t record, std::size_t realisation, double time_cov,
                          double amplitude_cov);

/// Every input and output of one analysis (one row of results.csv).
struct AnalysisRow {
  std::uint64_t id = 0;
  std::string wall;
  double b_m = 0, h_m = 0, unit_weight_kN_m3 = 0;
  std::optional<double> k_kN_m3;  ///< smooth model only
  std::string record;
  double scale = 0;
  int realisation = 0;
  double time_mult = 1, amp_mult = 1;
  std::string restitution;  ///< label
  std::string model;        ///< "smooth" | "rigid"
  // code check (seed Eq. 2-8), with the perturbed and scaled record
  bool has_code = false;  ///< the fields below up to dc_displacement are set
  double pga_m_s2 = 0, a0_star_m_s2 = 0, du_star_m = 0, Ts_s = 0, SDe_Ts_m = 0;
  double dc_strength = 0, dc_displacement = 0;
  // dynamics
  bool has_dynamics = false;  ///< the fields below up to termination are set
  std::optional<double> e;  ///< restitution coefficient used
  double theta_u_rad = 0, theta_max_rad = 0, theta_ratio = 0, t_theta_max_s = 0;
  bool overturned = false;
  long impacts = 0;
  double dc_energy = 0;
  std::string termination;
  bool ok = true;      ///< false: the analysis failed, outputs are not set
  std::string reason;  ///< why it failed
};

/// A campaign ready to run: the spec with its records read and its models built.
class Campaign {
 public:
  /// Reads every record and builds every model. A record file that exists but
  /// cannot be read does not throw: its analyses fail with the reader's message.
  /// @throws InputError for an invalid model (e.g. k too small), naming the wall.
  explicit Campaign(CampaignSpec spec);

  const CampaignSpec& spec() const { return spec_; }
  std::uint64_t size() const { return spec_.size(); }

  /// Evaluates the analyses with ids in [first, end), which must lie in one
  /// group (same wall, record, scale, realisation). Never throws for a failing
  /// analysis: the row says why.
  std::vector<AnalysisRow> evaluate(std::uint64_t first, std::uint64_t end) const;
  /// One analysis.
  AnalysisRow evaluate(std::uint64_t id) const { return evaluate(id, id + 1).front(); }

  /// The model of (wall, restitution, model) indices.
  const RockingModel& model(std::size_t wall, std::size_t restitution, std::size_t model) const;
  /// The record of index r, after the perturbation of realisation n and the scale factor s.
  Record applied_record(std::size_t r, std::size_t n, double scale) const;

 private:
  CampaignSpec spec_;
  std::vector<std::optional<Record>> records_;
  std::vector<std::string> record_errors_;
  std::vector<RockingModel> models_;  // [wall][restitution][model]
  std::vector<FreeWallCapacity> capacities_;
};

}  // namespace assess
