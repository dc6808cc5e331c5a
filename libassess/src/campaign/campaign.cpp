// campaign.cpp: the campaign spec, its flat index, the random multipliers of
// the records and the evaluation of one group of analyses (seed paper
// Lipo & de Felice 2017, §3.2).
//
// Notation (code name -> symbol):
//   b_m, h_m       half-thickness b and half-height h of the wall (seed §3.2: (b, h))
//   time_mult      multiplier of the time axis, ~ N(1, time_cov)       (seed §3.2)
//   amp_mult       multiplier of the acceleration axis, ~ N(1, amplitude_cov)
//   scale          scale factor of the record amplitude (seed: 0.2 .. 2.0)
//   pga_m_s2       PGA of the applied record (scale * amp_mult * record)
//   dc_strength    PGA / (2 a0*)        seed Eq. 8 (Eq. 6 with S = 1, q = 2)
//   dc_displacement SDe(Ts) / du*       seed Eq. 8 (Eq. 7), SDe at 5 % damping
//   dc_energy      energy demand / capacity of the rocking analysis (seed Fig. 3)
#include "assess/campaign/campaign.hpp"

#include "assess/dynamics/analysis_limits.hpp"
#include "assess/support/error.hpp"
#include "assess/support/json_input.hpp"
#include "assess/hazard/hazard.hpp"
#include "assess/records/record_catalogue.hpp"
#include "assess/records/record_io.hpp"
#include "assess/records/response_spectrum.hpp"
#include "assess/support/units.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace assess {

namespace {

using nlohmann::json;

bool file_exists(const std::string& p) {
  std::error_code ec;
  return std::filesystem::is_regular_file(p, ec);
}

std::string shortest(double v) {
  char buf[32];
  for (int prec = 1; prec <= 17; ++prec) {
    std::snprintf(buf, sizeof buf, "%.*g", prec, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

// The JSON pointer of a path built as "records[1].file" (the notation used
// while parsing): "/records/1/file", as in the case files' messages.
std::string pointer(const std::string& path) {
  std::string out = "/";
  for (char c : path) {
    if (c == '[' || c == '.') out += '/';
    else if (c != ']') out += c;
  }
  return out;
}

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError(pointer(path) + ": " + what);
}

double number(const json& j, const std::string& path) {
  if (!j.is_number()) fail(path, "expected a number, got " + j.dump());
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(path, "expected a finite number");
  return v;
}

double positive(const json& j, const std::string& path, const std::string& unit) {
  const double v = number(j, path);
  if (!(v > 0.0)) fail(path, "expected a positive value (" + unit + "), got " + shortest(v));
  return v;
}

std::string text(const json& j, const std::string& path) {
  if (!j.is_string()) fail(path, "expected a string, got " + j.dump());
  return j.get<std::string>();
}

const json& require(const json& j, const char* key, const std::string& path) {
  if (!j.contains(key)) fail(path, std::string("missing required key '") + key + "'");
  return j.at(key);
}

const json& array_of(const json& j, const std::string& path) {
  if (!j.is_array() || j.empty()) fail(path, "expected a non-empty array");
  return j;
}

std::string child(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

// The record file as an absolute, normalised path (so that a campaign resumed
// from another working directory is recognised as the same one).
std::string resolve_record(const std::string& file, const std::string& base_dir, const std::string& path) {
  namespace fs = std::filesystem;
  auto found = [](const std::string& p) { return fs::absolute(fs::path(p)).lexically_normal().string(); };
  if (!file.empty() && file.front() == '/') {
    if (file_exists(file)) return found(file);
    fail(path, "record file '" + file + "' not found");
  }
  const std::string a = base_dir.empty() ? file : base_dir + "/" + file;
  if (file_exists(a)) return found(a);
  const std::string b = data_dir() + "/" + file;
  if (file_exists(b)) return found(b);
  fail(path, "record file '" + file + "' not found (looked in '" + a + "' and '" + b + "')");
}

// %g: a bound as written in analysis_limits.hpp (100, 1e+09).
std::string g(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// A scale factor in (0, limits::scale_max].
double scale_factor(double v, const std::string& path) {
  if (!(v > 0.0 && v <= limits::scale_max))
    fail(path, "a scale factor must lie in (0, " + g(limits::scale_max) + "] (-), got " + shortest(v));
  return v;
}

std::vector<double> parse_scales(const json& j, const std::string& path) {
  std::vector<double> out;
  constexpr double max_factors = 100000;
  if (j.is_object()) {
    for (const auto& [key, v] : j.items())
      if (key != "from" && key != "to" && key != "step") fail(path + "." + key, "unknown key (expected from, to, step)");
    const double from = scale_factor(positive(require(j, "from", path), path + ".from", "-"), path + ".from");
    const double to = scale_factor(positive(require(j, "to", path), path + ".to", "-"), path + ".to");
    const double step = positive(require(j, "step", path), path + ".step", "-");
    if (to < from) fail(path + ".to", "must be >= from");
    // The count as a double first: (to - from) / step may be far beyond a long.
    const double count = std::round((to - from) / step) + 1.0;
    if (!(count <= max_factors))
      fail(path, "too many scale factors (" + shortest(count) + ", at most " + g(max_factors) + ")");
    const long n = static_cast<long>(count);
    // Printed to 12 significant digits so that from + i*step reads as written
    // (0.6, not 0.6000000000000001) and a small factor never rounds to 0.
    for (long i = 0; i < n; ++i) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.12g", from + double(i) * step);
      out.push_back(scale_factor(std::strtod(buf, nullptr), path + "[" + std::to_string(i) + "]"));
    }
    if (out.empty()) fail(path, "the range gives no scale factor");
  } else {
    const json& a = array_of(j, path);
    for (std::size_t i = 0; i < a.size(); ++i)
      out.push_back(scale_factor(positive(a[i], child(path, i), "-"), child(path, i)));
  }
  return out;
}

CampaignRestitution parse_restitution(const json& j, const std::string& path) {
  if (j.is_number()) {
    const double e = number(j, path);
    if (e < -1.0 || e > 1.0) fail(path, "a restitution coefficient must lie in [-1, 1], got " + shortest(e));
    return {shortest(e), Restitution::given(e)};
  }
  if (!j.is_string()) fail(path, "expected \"housner\", \"one_sided_theory\", \"none\" or a number in [-1, 1]");
  const std::string s = j.get<std::string>();
  if (s == "housner") return {s, Restitution::housner()};
  if (s == "one_sided_theory" || s == "one-sided-theory") return {"one_sided_theory", Restitution::one_sided_theory()};
  if (s == "none") return {s, Restitution::none()};
  fail(path, "unknown restitution '" + s + "' (expected housner, one_sided_theory, none or a number in [-1, 1])");
}

void parse_integrator(const json& j, const std::string& path, RockingOptions& o) {
  if (!j.is_object()) fail(path, "expected an object");
  for (const auto& [key, v] : j.items()) {
    const std::string p = path + "." + key;
    if (key == "stepper") {
      const auto stepper = parse_stepper(v.is_string() ? v.get<std::string>() : "");
      if (!stepper) fail(p, "expected \"rk8pd\", \"rkck\" or \"rkf45\"");
      o.stepper = *stepper;
    } else if (key == "rel_tol") {
      o.rel_tol = positive(v, p, "-");
    } else if (key == "abs_tol") {
      o.abs_tol = positive(v, p, "rad");
    } else if (key == "max_steps") {
      // An integer in [1, 1e9] checked before the cast (1e300 was undefined behaviour).
      const double n = positive(v, p, "steps");
      if (!(n <= limits::max_steps_max) || n != std::floor(n))
        fail(p, "expected an integer number of steps in [1, " + g(limits::max_steps_max) + "], got " + shortest(n));
      o.max_steps = static_cast<long>(n);
    } else if (key == "tail_s") {
      o.tail_s = number(v, p);
    } else if (key == "overturn_at") {
      const std::string s = v.is_string() ? v.get<std::string>() : "";
      if (s == "theta_u") o.overturn = OverturnCriterion::theta_u;
      else if (s == "half_pi") o.overturn = OverturnCriterion::half_pi;
      else fail(p, "expected \"theta_u\" or \"half_pi\"");
    } else {
      fail(p, "unknown key (expected stepper, rel_tol, abs_tol, max_steps, tail_s, overturn_at)");
    }
  }
  try {
    o.validate();
  } catch (const InputError& e) {
    fail(path, e.what());
  }
}

// SplitMix64 (Steele, Lea & Flood 2014): a bijective 64-bit mixer; hashing a
// counter with it gives a counter-based generator.
std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Uniform in (0, 1]: 53 random bits, never 0 (log(0) in Box-Muller).
double unit_open0(std::uint64_t bits) { return (double((bits >> 11) + 1)) * 0x1.0p-53; }

}  // namespace

const char* to_string(CampaignModel m) { return m == CampaignModel::smooth ? "smooth" : "rigid"; }

std::uint64_t CampaignSpec::group_size() const { return std::uint64_t(restitutions.size()) * models.size(); }

std::uint64_t CampaignSpec::size() const {
  return std::uint64_t(walls.size()) * records.size() * scale_factors.size() * std::uint64_t(realisations) *
         group_size();
}

CampaignSpec parse_campaign(const json& j, const std::string& base_dir) {
  if (!j.is_object()) fail("$", "a campaign must be a JSON object");
  static const char* known[] = {"name",         "walls",     "records",        "scale_factors", "restitution",
                                "models",       "realisations", "time_cov",    "amplitude_cov", "seed",
                                "one_sided",    "FC",        "unit_weight_kN_m3", "k_kN_m3",   "integrator",
                                "description"};
  for (const auto& [key, v] : j.items()) {
    bool ok = false;
    for (const char* k : known) ok = ok || key == k;
    if (!ok) fail(key, "unknown key");
  }
  CampaignSpec s;
  s.name = j.contains("name") ? text(j["name"], "name") : "campaign";
  const double gamma_default = j.contains("unit_weight_kN_m3")
                                   ? positive(j["unit_weight_kN_m3"], "unit_weight_kN_m3", "kN/m^3")
                                   : 0.0;
  const double k_default = j.contains("k_kN_m3") ? positive(j["k_kN_m3"], "k_kN_m3", "kN/m^3") : 0.0;

  const json& walls = array_of(require(j, "walls", "$"), "walls");
  for (std::size_t i = 0; i < walls.size(); ++i) {
    const std::string p = child("walls", i);
    const json& w = walls[i];
    if (!w.is_object()) fail(p, "expected an object {\"b\": half-thickness m, \"h\": half-height m}");
    CampaignWall cw;
    cw.b_m = positive(require(w, "b", p), p + ".b", "m, half-thickness");
    cw.h_m = positive(require(w, "h", p), p + ".h", "m, half-height");
    if (!(cw.h_m > cw.b_m)) fail(p + ".h", "the half-height h must exceed the half-thickness b");
    cw.name = w.contains("name") ? text(w["name"], p + ".name") : "b" + shortest(cw.b_m) + "_h" + shortest(cw.h_m);
    const double gamma = w.contains("unit_weight_kN_m3")
                             ? positive(w["unit_weight_kN_m3"], p + ".unit_weight_kN_m3", "kN/m^3")
                             : gamma_default;
    if (!(gamma > 0.0)) fail(p, "no unit weight: give unit_weight_kN_m3 here or at the top level");
    if (gamma > limits::unit_weight_max_N_m3 / units::kN)
      fail(w.contains("unit_weight_kN_m3") ? p + ".unit_weight_kN_m3" : "unit_weight_kN_m3",
           "a unit weight must be <= " + g(limits::unit_weight_max_N_m3 / units::kN) + " kN/m^3, got " +
               shortest(gamma));
    cw.unit_weight_N_m3 = gamma * units::kN;
    const double k = w.contains("k_kN_m3") ? positive(w["k_kN_m3"], p + ".k_kN_m3", "kN/m^3") : k_default;
    if (k > limits::winkler_k_max_N_m3 / units::kN)
      fail(w.contains("k_kN_m3") ? p + ".k_kN_m3" : "k_kN_m3",
           "a Winkler modulus must be <= " + g(limits::winkler_k_max_N_m3 / units::kN) +
               " kN/m^3 (a stiffer base is rigid: use the rigid model), got " + shortest(k));
    cw.k_N_m3 = k * units::kN;
    s.walls.push_back(cw);
  }

  const json& recs = array_of(require(j, "records", "$"), "records");
  std::optional<RecordCatalogue> catalogue;
  for (std::size_t i = 0; i < recs.size(); ++i) {
    const std::string p = child("records", i);
    const json& r = recs[i];
    CampaignRecord cr;
    std::string file;
    if (r.is_object() && r.contains("id")) {
      // A record of the catalogue shipped in data_dir()/spectra/records.
      const std::string id = text(r["id"], p + ".id");
      if (r.contains("file")) fail(p, "give either \"id\" or \"file\", not both");
      if (!catalogue) catalogue = read_catalogue(data_dir() + "/spectra/records/catalogue.json");
      const CatalogueEntry* e = catalogue->find(id);
      if (!e) fail(p + ".id", "'" + id + "' is not in the record catalogue " + catalogue->directory + "/catalogue.json");
      cr.path = resolve_record(catalogue->directory + "/" + e->file, "", p + ".id");
      cr.name = r.contains("name") ? text(r["name"], p + ".name") : e->id;
      s.records.push_back(cr);
      continue;
    }
    if (r.is_string()) {
      file = r.get<std::string>();
    } else if (r.is_object()) {
      file = text(require(r, "file", p), p + ".file");
      if (r.contains("name")) cr.name = text(r["name"], p + ".name");
      // A plain record, as in the case files: {"file", "dt": s, "unit"} for one
      // column, {"file", "unit"} for two (time, acceleration).
      if (r.contains("unit")) {
        cr.unit = text(r["unit"], p + ".unit");
        try {
          parse_acceleration_unit(cr.unit);
        } catch (const InputError&) {
          fail(p + ".unit", "'" + cr.unit + "': expected \"g\", \"m/s^2\" or \"cm/s^2\"");
        }
      }
      if (r.contains("dt")) {
        cr.dt = positive(r["dt"], p + ".dt", "s");
        if (cr.unit.empty()) fail(p, "a plain record with \"dt\" needs \"unit\": \"g\", \"m/s^2\" or \"cm/s^2\"");
      }
    } else {
      fail(p, "expected a file path, {\"name\": ..., \"file\": ...} or {\"id\": catalogue id}");
    }
    cr.path = resolve_record(file, base_dir, r.is_object() ? p + ".file" : p);
    if (cr.name.empty()) {
      const auto slash = file.find_last_of('/');
      cr.name = slash == std::string::npos ? file : file.substr(slash + 1);
    }
    s.records.push_back(cr);
  }

  s.scale_factors = parse_scales(require(j, "scale_factors", "$"), "scale_factors");

  if (j.contains("restitution")) {
    const json& r = j["restitution"];
    if (r.is_array()) {
      array_of(r, "restitution");
      for (std::size_t i = 0; i < r.size(); ++i) s.restitutions.push_back(parse_restitution(r[i], child("restitution", i)));
    } else {
      s.restitutions.push_back(parse_restitution(r, "restitution"));
    }
  } else {
    s.restitutions.push_back({"housner", Restitution::housner()});
  }

  if (j.contains("models")) {
    const json& m = array_of(j["models"], "models");
    for (std::size_t i = 0; i < m.size(); ++i) {
      const std::string v = m[i].is_string() ? m[i].get<std::string>() : "";
      if (v == "smooth") s.models.push_back(CampaignModel::smooth);
      else if (v == "rigid") s.models.push_back(CampaignModel::rigid);
      else fail(child("models", i), "expected \"smooth\" or \"rigid\"");
    }
  } else {
    s.models = {CampaignModel::smooth, CampaignModel::rigid};
  }
  for (std::size_t i = 0; i < s.walls.size(); ++i)
    for (CampaignModel m : s.models)
      if (m == CampaignModel::smooth && !(s.walls[i].k_N_m3 > 0.0))
        fail(child("walls", i), "the smooth model needs k_kN_m3 (here or at the top level)");

  if (j.contains("realisations")) {
    const json& n = j["realisations"];
    if (!n.is_number_integer() || n.get<long long>() < 1 || n.get<long long>() > 100000000)
      fail("realisations", "expected an integer >= 1");
    s.realisations = n.get<int>();
  }
  if (j.contains("time_cov")) s.time_cov = number(j["time_cov"], "time_cov");
  if (j.contains("amplitude_cov")) s.amplitude_cov = number(j["amplitude_cov"], "amplitude_cov");
  // Multipliers must stay positive: at a CoV of 0.2 a non-positive draw is a
  // 5-sigma event, so larger values are refused rather than truncated.
  if (s.time_cov < 0.0 || s.time_cov > 0.2) fail("time_cov", "expected a fraction in [0, 0.2] (0.03 = 3 %)");
  if (s.amplitude_cov < 0.0 || s.amplitude_cov > 0.2)
    fail("amplitude_cov", "expected a fraction in [0, 0.2] (0.03 = 3 %)");
  if (j.contains("seed")) {
    const json& v = j["seed"];
    if (!v.is_number_unsigned()) fail("seed", "expected a non-negative integer");
    s.seed = v.get<std::uint64_t>();
  }
  if (j.contains("one_sided")) {
    if (!j["one_sided"].is_boolean()) fail("one_sided", "expected true or false");
    s.one_sided = j["one_sided"].get<bool>();
  }
  if (j.contains("FC")) {
    s.FC = number(j["FC"], "FC");
    if (s.FC < 1.0) fail("FC", "the confidence factor must be >= 1");
  }
  if (j.contains("integrator")) parse_integrator(j["integrator"], "integrator", s.rocking);
  return s;
}

CampaignSpec read_campaign(const std::string& path) {
  // The bounded reader: a regular file (a directory, a device or a FIFO is named).
  // Errors name the file and the JSON path ("campaign file 'c.json': /walls/0/b: number out of the range ...").
  const json j = parse_json_text(read_input_file(path, input_kinds::campaign_file), "campaign file '" + path + "'");
  const auto slash = path.find_last_of('/');
  try {
    return parse_campaign(j, slash == std::string::npos ? "." : path.substr(0, slash));
  } catch (const InputError& e) {
    throw InputError("campaign file '" + path + "': " + e.what());
  }
}

json to_json(const CampaignSpec& s) {
  json j;
  j["name"] = s.name;
  for (const auto& w : s.walls)
    j["walls"].push_back({{"name", w.name}, {"b_m", w.b_m}, {"h_m", w.h_m},
                          {"unit_weight_N_m3", w.unit_weight_N_m3}, {"k_N_m3", w.k_N_m3}});
  for (const auto& r : s.records) {
    json rj{{"name", r.name}, {"path", r.path}};
    if (!r.unit.empty()) rj["unit"] = r.unit;
    if (r.dt > 0.0) rj["dt"] = r.dt;
    j["records"].push_back(rj);
  }
  j["scale_factors"] = s.scale_factors;
  for (const auto& r : s.restitutions) j["restitution"].push_back(r.label);
  for (auto m : s.models) j["models"].push_back(to_string(m));
  j["realisations"] = s.realisations;
  j["time_cov"] = s.time_cov;
  j["amplitude_cov"] = s.amplitude_cov;
  j["seed"] = s.seed;
  j["one_sided"] = s.one_sided;
  j["FC"] = s.FC;
  const RockingOptions& o = s.rocking;
  j["integrator"] = {{"stepper", int(o.stepper)}, {"rel_tol", o.rel_tol}, {"abs_tol", o.abs_tol},
                     {"max_steps", o.max_steps}, {"tail_s", o.tail_s}, {"overturn", int(o.overturn)}};
  j["analyses"] = s.size();
  return j;
}

AnalysisIndex decompose(const CampaignSpec& s, std::uint64_t id) {
  AnalysisIndex ix;
  ix.model = id % s.models.size();
  id /= s.models.size();
  ix.restitution = id % s.restitutions.size();
  id /= s.restitutions.size();
  ix.realisation = id % std::uint64_t(s.realisations);
  id /= std::uint64_t(s.realisations);
  ix.scale = id % s.scale_factors.size();
  id /= s.scale_factors.size();
  ix.record = id % s.records.size();
  ix.wall = id / s.records.size();
  return ix;
}

std::uint64_t compose(const CampaignSpec& s, const AnalysisIndex& ix) {
  std::uint64_t id = ix.wall;
  id = id * s.records.size() + ix.record;
  id = id * s.scale_factors.size() + ix.scale;
  id = id * std::uint64_t(s.realisations) + ix.realisation;
  id = id * s.restitutions.size() + ix.restitution;
  return id * s.models.size() + ix.model;
}

Perturbation perturbation(std::uint64_t seed, std::size_t record, std::size_t realisation, double time_cov,
                          double amplitude_cov) {
  if (realisation == 0) return {};
  // Counter = (seed, record, realisation): each is mixed in turn, so distinct
  // triples give independent streams.
  const std::uint64_t key = splitmix64(splitmix64(splitmix64(seed) ^ std::uint64_t(record)) ^ std::uint64_t(realisation));
  const double u1 = unit_open0(splitmix64(key ^ 1)), u2 = unit_open0(splitmix64(key ^ 2));
  // Box-Muller (1958): two independent standard normals from two uniforms.
  const double rho = std::sqrt(-2.0 * std::log(u1)), phi = 2.0 * units::pi * u2;
  return {1.0 + time_cov * rho * std::cos(phi), 1.0 + amplitude_cov * rho * std::sin(phi)};
}

Campaign::Campaign(CampaignSpec spec) : spec_(std::move(spec)) {
  for (const auto& r : spec_.records) {
    try {
      if (r.unit.empty())
        records_.emplace_back(read_record(r.path));
      else if (r.dt > 0.0)
        records_.emplace_back(read_plain_record(r.path, r.dt, parse_acceleration_unit(r.unit)));
      else
        records_.emplace_back(read_plain_record(r.path, parse_acceleration_unit(r.unit)));
      record_errors_.emplace_back();
    } catch (const InputError& e) {
      records_.emplace_back();
      record_errors_.emplace_back(e.what());
    }
  }
  const Sidedness side = spec_.one_sided ? Sidedness::one_sided : Sidedness::two_sided;
  for (std::size_t w = 0; w < spec_.walls.size(); ++w) {
    const CampaignWall& wall = spec_.walls[w];
    const std::string p = "/walls/" + std::to_string(w) + " (" + wall.name + ")";
    try {
      capacities_.push_back(free_wall_capacity(wall.b_m, wall.h_m, spec_.FC));
      const RockingBody body = RockingBody::rectangle(2.0 * wall.b_m, 2.0 * wall.h_m, wall.unit_weight_N_m3);
      for (const auto& rest : spec_.restitutions)
        for (CampaignModel m : spec_.models)
          models_.emplace_back(body, m == CampaignModel::smooth ? Foundation::winkler(wall.k_N_m3) : Foundation::rigid(),
                               side, rest.value);
    } catch (const InputError& e) {
      throw InputError(p + ": " + e.what());
    }
  }
}

const RockingModel& Campaign::model(std::size_t wall, std::size_t restitution, std::size_t model) const {
  return models_[(wall * spec_.restitutions.size() + restitution) * spec_.models.size() + model];
}

Record Campaign::applied_record(std::size_t r, std::size_t n, double scale) const {
  if (r >= records_.size()) throw InputError("record index " + std::to_string(r) + " out of range");
  if (!records_[r]) throw InputError(record_errors_[r]);
  const Perturbation p = perturbation(spec_.seed, r, n, spec_.time_cov, spec_.amplitude_cov);
  if (!(p.time > 0.0) || !(p.amplitude > 0.0))
    throw InputError("non-positive random multiplier (time " + shortest(p.time) + ", amplitude " +
                     shortest(p.amplitude) + ")");
  Record rec = records_[r]->scaled(scale * p.amplitude);
  rec.dt *= p.time;
  return rec;
}

std::vector<AnalysisRow> Campaign::evaluate(std::uint64_t first, std::uint64_t end) const {
  const std::uint64_t G = spec_.group_size();
  if (!(first < end && end <= spec_.size() && (end - 1) / G == first / G))
    throw InputError("analyses [" + std::to_string(first) + ", " + std::to_string(end) +
                     ") are not a non-empty range within one group of " + std::to_string(G));
  std::vector<AnalysisRow> rows;
  const AnalysisIndex g = decompose(spec_, first);
  const CampaignWall& wall = spec_.walls[g.wall];
  const FreeWallCapacity& cap = capacities_[g.wall];
  const Perturbation p = perturbation(spec_.seed, g.record, g.realisation, spec_.time_cov, spec_.amplitude_cov);

  AnalysisRow base;
  base.wall = wall.name;
  base.b_m = wall.b_m;
  base.h_m = wall.h_m;
  base.unit_weight_kN_m3 = wall.unit_weight_N_m3 / units::kN;
  base.record = spec_.records[g.record].name;
  base.scale = spec_.scale_factors[g.scale];
  base.realisation = int(g.realisation);
  base.time_mult = p.time;
  base.amp_mult = p.amplitude;
  base.a0_star_m_s2 = cap.a0_star;
  base.du_star_m = cap.du_star;
  base.Ts_s = cap.Ts;

  // The record as applied and its code ratios are shared by the whole group.
  std::optional<Record> rec;
  std::string group_error = record_errors_[g.record];
  if (group_error.empty()) {
    try {
      rec = applied_record(g.record, g.realisation, base.scale);
      base.pga_m_s2 = rec->pga();
      base.SDe_Ts_m = spectral_ordinates(*rec, cap.Ts).SD;  // 5 % damping (ResponseOptions default)
      const CodeRatios cr = code_ratios(cap, base.pga_m_s2, base.SDe_Ts_m);
      base.dc_strength = cr.strength;
      base.dc_displacement = cr.displacement;
      base.has_code = true;
    } catch (const std::exception& e) {
      group_error = e.what();
    }
  }

  for (std::uint64_t id = first; id < end; ++id) {
    const AnalysisIndex ix = decompose(spec_, id);
    AnalysisRow row = base;
    row.id = id;
    row.restitution = spec_.restitutions[ix.restitution].label;
    row.model = to_string(spec_.models[ix.model]);
    if (spec_.models[ix.model] == CampaignModel::smooth) row.k_kN_m3 = wall.k_N_m3 / units::kN;
    if (!group_error.empty()) {
      row.ok = false;
      row.reason = group_error;
      rows.push_back(std::move(row));
      continue;
    }
    try {
      const RockingResult r = analyse(model(ix.wall, ix.restitution, ix.model), *rec, spec_.rocking);
      row.has_dynamics = true;
      row.e = r.restitution;
      row.theta_u_rad = r.theta_u;
      row.theta_max_rad = r.theta_max;
      row.theta_ratio = r.theta_max / r.theta_u;
      row.t_theta_max_s = r.t_theta_max;
      row.overturned = r.overturned;
      row.impacts = r.impacts;
      row.dc_energy = r.dc;
      row.termination = to_string(r.termination);
      if (r.termination != RockingTermination::completed && r.termination != RockingTermination::overturned) {
        row.ok = false;
        row.reason = r.message.empty() ? row.termination : r.message;
      }
    } catch (const std::exception& e) {
      row.ok = false;
      row.reason = e.what();
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace assess
