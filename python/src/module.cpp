// module.cpp: the extension module assess._assess, the private layer under the
// Python package assess (python/assess/__init__.py). Each function is a thin
// layer over the library: it converts its arguments, calls the same library
// functions as the command line's subcommand (apps/cmd_*.cpp) with the GIL
// released, and converts the result; the JSON documents are the library's
// (report/*_report.hpp, risk/run_report.hpp), so that every dict equals what
// `assess ... --json` prints. Errors: assess::InputError becomes
// assess.InputError (a ValueError, with the message and its file and JSON
// path), assess::SystemError an OSError (docs/user/python.md).
#include "json_convert.hpp"

#include <assess/assessment/building_assessment.hpp>
#include <assess/assessment/building_case.hpp>
#include <assess/assessment/case_file.hpp>
#include <assess/assessment/facade_assessment.hpp>
#include <assess/assessment/site_block.hpp>
#include <assess/campaign/campaign.hpp>
#include <assess/campaign/campaign_report.hpp>
#include <assess/campaign/campaign_runner.hpp>
#include <assess/dynamics/rocking_request.hpp>
#include <assess/hazard/hazard.hpp>
#include <assess/records/record_catalogue.hpp>
#include <assess/records/record_io.hpp>
#include <assess/records/record_library.hpp>
#include <assess/report/building_report.hpp>
#include <assess/report/records_report.hpp>
#include <assess/report/rocking_report.hpp>
#include <assess/report/spectrum_report.hpp>
#include <assess/risk/fragility_case.hpp>
#include <assess/risk/fragility_job.hpp>
#include <assess/risk/fragility_report.hpp>
#include <assess/risk/fragility_result.hpp>
#include <assess/risk/run_report.hpp>
#include <assess/support/error.hpp>
#include <assess/support/json_input.hpp>
#include <assess/support/number_rules.hpp>
#include <assess/support/units.hpp>
#include <assess/support/version.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <cmath>
#include <functional>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <future>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace assess::python {
namespace {

PyObject* g_input_error = nullptr;  // assess.InputError (module attribute, lives with the module)

// "FILE: /json/path: what" -> FILE and /json/path; none when the message does
// not name a JSON path (a record file's "FILE:LINE: what", an option's "--k ...").
std::pair<py::object, py::object> location(const std::string& m) {
  const std::size_t at = m.find(": /");
  if (at == std::string::npos || at == 0) return {py::none(), py::none()};
  const std::size_t end = m.find(": ", at + 2);
  const std::string path = m.substr(at + 2, end == std::string::npos ? std::string::npos : end - at - 2);
  if (path.find(' ') != std::string::npos) return {py::none(), py::none()};
  return {py::str(m.substr(0, at)), py::str(path)};
}

void raise_input_error(const std::string& what) {
  const std::string message = plain_numbers(what);
  py::object type = py::reinterpret_borrow<py::object>(g_input_error);
  py::object e = type(message);
  const auto [file, path] = location(message);
  e.attr("message") = message;
  e.attr("file") = file;
  e.attr("path") = path;
  PyErr_SetObject(g_input_error, e.ptr());
}

// A path (str or os.PathLike) or None.
std::optional<std::string> as_path(py::handle v) {
  if (v.is_none()) return std::nullopt;
  if (PyUnicode_Check(v.ptr())) return v.cast<std::string>();
  if (py::hasattr(v, "__fspath__")) {
    py::object p = v.attr("__fspath__")();
    if (PyUnicode_Check(p.ptr())) return p.cast<std::string>();
  }
  return std::nullopt;
}

// A case, a site or a campaign: a path read with the bounded reader, or a
// dict converted (named `label` in messages, its relative paths taken from
// the working directory).
struct Document {
  nlohmann::json doc;
  std::string file;
  bool from_file = false;
};

Document document(py::handle v, const char* label, const InputKind& kind) {
  Document d;
  if (const auto path = as_path(v)) {
    d.file = *path;
    d.from_file = true;
    py::gil_scoped_release nogil;
    d.doc = read_json_file(*path, kind);
  } else {
    d.file = label;
    d.doc = to_json(v, label);
  }
  return d;
}

py::list warning_list(const std::vector<std::string>& ws) {
  py::list l;
  for (const std::string& w : ws) l.append(plain_numbers(w));
  return l;
}

// A vector as a numpy array that owns it (no copy).
py::array_t<double> array_of(std::vector<double>&& v) {
  auto* owned = new std::vector<double>(std::move(v));
  py::capsule free_it(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>(static_cast<py::ssize_t>(owned->size()), owned->data(), free_it);
}

// Runs `work` (without the GIL) on a thread of its own while this thread
// checks every 0.1 s for a signal (Ctrl-C): then `cancel` is set, the work
// stops at its next group of analyses and KeyboardInterrupt is raised.
template <class R>
R interruptible(std::atomic<bool>& cancel, std::function<R()> work) {
  std::future<R> f;
  bool interrupted = false;
  {
    py::gil_scoped_release nogil;
    f = std::async(std::launch::async, std::move(work));
    while (f.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready) {
      if (interrupted) continue;
      py::gil_scoped_acquire gil;
      if (PyErr_CheckSignals() != 0) {
        PyErr_Clear();
        cancel = true;
        interrupted = true;
      }
    }
  }
  R r = f.get();  // rethrows the work's exception
  if (interrupted) {
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  return r;
}

// ---- run, kinematic ------------------------------------------------------

py::tuple run(py::handle kase, bool keep_going, py::handle fragility) {
  const Document d = document(kase, "case", input_kinds::case_file);
  const std::string frag_dir = as_path(fragility).value_or("");
  nlohmann::json j;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release nogil;
    FacadeOptions opt;
    opt.keep_going = keep_going;
    if (is_building_document(d.doc)) {  // `assess run BUILDING --json` (apps/cmd_run.cpp, run_building)
      if (!frag_dir.empty())
        throw InputError(d.file + ": fragility applies to a single-mechanism case (`assess fragility " + d.file +
                         " --mechanism ID` studies one mechanism of a building)");
      const BuildingAssessment res = assess_building(parse_building(d.doc, d.file), opt);
      warnings = res.warnings;
      j = building_json(res);
    } else {  // `assess run CASE --json` (apps/cmd_run.cpp, run_single)
      const FacadeAssessment res = assess_facade(parse_case(d.doc, d.file), opt);
      const std::optional<TieInterventionResult> ties = assess_ties(res);
      warnings = res.warnings;
      // The fragility result of the case: the given directory, else CASE.fragility of a case file.
      std::optional<RunFragility> frag;
      if (!frag_dir.empty() || d.from_file) frag = run_fragility(d.file, frag_dir);
      j = facade_run_json(res, ties, frag);
    }
    stamp_version(j);
  }
  return py::make_tuple(to_python(j), warning_list(warnings));
}

py::tuple kinematic(py::handle kase) {
  const Document d = document(kase, "case", input_kinds::case_file);
  nlohmann::json j;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release nogil;
    if (is_building_document(d.doc))
      throw InputError(d.file + ": a building case (key \"walls\"): assess.run analyses and checks its mechanisms; "
                       "assess.kinematic takes a single-mechanism case (docs/user/building.md)");
    const CaseFile c = parse_case(d.doc, d.file);
    const KinematicCaseResult out = run_kinematic_case(c);
    warnings = out.warnings;
    const std::optional<TieInterventionResult> ties = kinematic_ties(c, warnings);
    j = kinematic_run_json(c, out, ties);
    stamp_version(j);
  }
  return py::make_tuple(to_python(j), warning_list(warnings));
}

// ---- spectrum --------------------------------------------------------------

py::tuple spectrum(py::handle site, py::handle limit_state, std::optional<std::vector<double>> periods,
                   std::optional<double> tr, double damping, std::optional<double> q) {
  const nlohmann::json doc = to_json(site, "site");
  std::vector<LimitState> states(all_limit_states.begin(), all_limit_states.end());
  const bool named = !limit_state.is_none();
  if (named) {
    if (!PyUnicode_Check(limit_state.ptr())) throw InputError("limit_state: expected SLO, SLD, SLV, SLC or None");
    try {
      states = {parse_limit_state(limit_state.cast<std::string>())};
    } catch (const InputError& e) {
      throw InputError(std::string("limit_state: ") + e.what());
    }
  }
  if (named && tr) throw InputError("give either limit_state or tr, not both");
  nlohmann::json j;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release nogil;
    // The number rules of the command line's options (cmd_spectrum.cpp).
    auto check = [](const char* name, double v, const NumberRule& rule) {
      const std::string bad = number_rule_violation(v, rule);
      if (!bad.empty()) throw InputError(std::string(name) + ": " + bad);
    };
    if (tr) check("tr", *tr, rules::return_period_years);
    check("damping", damping, rules::damping_or_zero_pct);
    if (q) check("q", *q, rules::behaviour_factor);
    if (q && !(*q >= 1.0)) throw InputError("q: expected a behaviour factor q >= 1");
    const std::vector<double> T = periods ? *periods : default_spectrum_periods();
    for (double t : T)
      if (!(std::isfinite(t) && t >= 0.0)) throw InputError("periods: expected periods >= 0 s, got " + number_for_message(t));
    const Site s(parse_site_block(doc, "site"));
    const std::vector<SpectrumColumn> cols = spectrum_columns(s, states, named, tr);
    warnings = spectrum_warnings(cols);
    j = spectrum_json(s, cols, damping, T, q);
    stamp_version(j);
  }
  return py::make_tuple(to_python(j), warning_list(warnings));
}

// ---- rocking ---------------------------------------------------------------

// The library's share of the last assess.rocking call on this thread (s of
// this thread's CPU time, as Python's time.thread_time counts it): the time
// of prepare_rocking, run_rocking and rocking_json and of freeing the record,
// measured around them; the rest of the call is Python's (bench/bench_python.py).
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

thread_local double g_last_library_seconds = 0.0;

double last_library_seconds() { return g_last_library_seconds; }


std::optional<std::string> restitution_text(py::handle r) {
  if (r.is_none()) return std::string();
  if (PyUnicode_Check(r.ptr())) return r.cast<std::string>();
  if (PyFloat_Check(r.ptr()) || PyLong_Check(r.ptr()) || py::hasattr(r, "__float__"))
    return std::string(py::repr(py::float_(py::reinterpret_borrow<py::object>(r))));  // shortest text that reads back as the same double
  return std::nullopt;
}

RockingRequest rocking_request(const std::string& model, double thickness, double height, double unit_weight,
                               std::optional<double> k, py::handle restitution, bool one_sided) {
  RockingRequest q;
  q.model = model;
  q.thickness = thickness;
  q.height = height;
  q.unit_weight_kN = unit_weight;
  q.k_kN = k;
  const auto e = restitution_text(restitution);
  if (!e) throw InputError("--restitution expects a number in [-1, 1], 'housner', 'one-sided-theory' or 'none'");
  q.restitution = *e;
  q.one_sided = one_sided;
  return q;
}

py::tuple rocking(const std::string& model, double thickness, double height, double unit_weight, py::handle record,
                  std::optional<double> dt, const std::string& unit, std::optional<double> k, py::handle restitution,
                  bool one_sided, double scale, bool reverse, bool history, const std::string& overturn_at,
                  const std::string& stepper, std::optional<double> rtol, std::optional<double> atol,
                  std::optional<double> tail, const std::string& name) {
  RockingRequest q = rocking_request(model, thickness, height, unit_weight, k, restitution, one_sided);
  py::object values;
  if (const auto path = as_path(record)) {
    q.record = *path;
  } else {
    // Samples in memory: a one-dimensional array of numbers (copied once, as doubles).
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(record);
    if (!a) throw InputError("record: expected a file path or a one-dimensional array of accelerations");
    if (a.ndim() != 1)
      throw InputError("record: expected a one-dimensional array of accelerations, got " + std::to_string(a.ndim()) +
                       " dimensions");
    q.values = RockingRequest::Values{a.data(), static_cast<std::size_t>(a.size())};
    q.record = name;
    values = a;  // alive until prepare_rocking has copied them
  }
  q.dt = dt;
  q.unit = unit;
  q.scale = scale;
  q.reverse = reverse;
  q.history = history;
  q.overturn_at = overturn_at;
  q.stepper = stepper;
  if (rtol) q.rtol = *rtol;
  if (atol) q.atol = *atol;
  if (tail) q.tail = *tail;
  nlohmann::json j;
  RockingResult r;
  const double t0 = thread_cpu_seconds();
  // The array's samples are copied into the record with the GIL held (no
  // other thread can change them meanwhile); a file is read without it.
  std::optional<RockingSetup> setup;
  if (q.values) setup.emplace(prepare_rocking(q));
  {
    py::gil_scoped_release nogil;
    if (!setup) setup.emplace(prepare_rocking(q));
    r = run_rocking(*setup);
    j = rocking_json(r, setup->record, q.scale, q.reverse);
    stamp_version(j);
    setup.reset();  // the record freed here, as the command line frees it: the library's share
    g_last_library_seconds = thread_cpu_seconds() - t0;
  }
  py::object h = py::none();
  if (history)
    h = py::make_tuple(array_of(std::move(r.history.t)), array_of(std::move(r.history.theta)),
                       array_of(std::move(r.history.omega)));
  return py::make_tuple(to_python(j), h);
}

class PyRockingModel {
 public:
  PyRockingModel(const std::string& model, double thickness, double height, double unit_weight,
                 std::optional<double> k, py::handle restitution, bool one_sided)
      : request_(rocking_request(model, thickness, height, unit_weight, k, restitution, one_sided)),
        m_(rocking_model_of(request_)) {}

  double theta_cr() const { return m_.theta_cr(); }
  double theta_u() const { return m_.theta_u(+1); }
  double theta_peak() const { return m_.theta_peak(+1); }
  double peak_moment() const { return m_.peak_moment(+1) / units::kN; }
  double capacity() const { return m_.capacity() / units::kN; }
  double alpha() const { return m_.body().alpha; }
  double weight() const { return m_.body().W / units::kN; }
  double restitution() const { return m_.restitution(); }
  double frequency_parameter() const { return m_.body().p(); }

  py::array_t<double> moment(py::array_t<double, py::array::c_style | py::array::forcecast> theta) const {
    py::array_t<double> out(theta.request().shape);
    const double* src = theta.data();
    double* dst = out.mutable_data();
    for (py::ssize_t i = 0; i < theta.size(); ++i) dst[i] = m_.restoring_moment(src[i]) / units::kN;
    return out;
  }

  py::tuple free(double theta0, double duration, double theta_dot0, std::optional<double> rtol,
                 std::optional<double> atol, bool history) const {
    RockingOptions o;
    if (rtol) o.rel_tol = *rtol;
    if (atol) o.abs_tol = *atol;
    o.record_history = history;
    nlohmann::json j;
    RockingResult r;
    {
      py::gil_scoped_release nogil;
      r = analyse_free(m_, {theta0, theta_dot0}, duration, o);
      if (!succeeded(r))
        throw InputError(std::string("the analysis failed (termination ") + to_string(r.termination) + "): " +
                         r.message + "; no result is reported");
      j = rocking_result_json(r);
    }
    py::object h = py::none();
    if (history)
      h = py::make_tuple(array_of(std::move(r.history.t)), array_of(std::move(r.history.theta)),
                         array_of(std::move(r.history.omega)));
    return py::make_tuple(to_python(j), h);
  }

 private:
  RockingRequest request_;
  RockingModel m_;
};

// ---- records ---------------------------------------------------------------

std::string catalogue_path(py::handle catalogue) {
  const auto p = as_path(catalogue);
  return p ? *p : data_dir() + "/spectra/records/catalogue.json";
}

RecordFilterOptions filter_options(std::optional<double> mw_min, std::optional<double> mw_max,
                                   std::optional<double> r_min, std::optional<double> r_max,
                                   std::vector<std::string> site_classes, std::vector<std::string> countries,
                                   bool relax) {
  RecordFilterOptions o;
  o.mw_min = mw_min, o.mw_max = mw_max, o.r_min = r_min, o.r_max = r_max;
  o.site_classes = std::move(site_classes);
  o.countries = std::move(countries);
  o.relax = relax;
  return o;
}

py::list records_list(py::handle catalogue, std::optional<double> mw_min, std::optional<double> mw_max,
                      std::optional<double> r_min, std::optional<double> r_max, std::vector<std::string> site_classes,
                      std::vector<std::string> countries, bool all) {
  const std::string path = catalogue_path(catalogue);
  const RecordFilterOptions o = filter_options(mw_min, mw_max, r_min, r_max, site_classes, countries, true);
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  {
    py::gil_scoped_release nogil;
    const RecordCatalogue cat = read_catalogue(path);
    for (const CatalogueEntry& e : catalogue_listing(cat, o, all)) j.push_back(catalogue_entry_json(e));
  }
  return to_python(j);
}

py::object records_select(py::handle site, const std::string& limit_state, py::handle catalogue, int count,
                          double t_min, double t_max, double max_scale, double max_mean_scale, double max_pga_ratio,
                          double max_misfit, int per_event, int per_station, const std::string& near_fault,
                          double near_fault_km, std::optional<double> mw_min, std::optional<double> mw_max,
                          std::optional<double> r_min, std::optional<double> r_max,
                          std::vector<std::string> site_classes, std::vector<std::string> countries, bool relax) {
  const nlohmann::json doc = to_json(site, "site");
  const std::string path = catalogue_path(catalogue);
  LibrarySelectionRules rules;
  rules.filters = catalogue_filters(filter_options(mw_min, mw_max, r_min, r_max, site_classes, countries, relax));
  rules.include_near_fault = parse_near_fault_option(near_fault);
  rules.near_fault_km = near_fault_km;
  SelectionOptions so;
  so.n_records = count;
  so.range = PeriodRange{t_min, t_max};
  so.max_scale = max_scale;
  so.max_mean_scale = max_mean_scale;
  so.max_pga_ratio = max_pga_ratio;
  so.max_per_event = per_event;
  so.max_per_station = per_station;
  so.max_misfit = max_misfit;
  nlohmann::ordered_json j;
  {
    py::gil_scoped_release nogil;
    LimitState ls = LimitState::SLV;
    try {
      ls = parse_limit_state(limit_state);
    } catch (const InputError& e) {
      throw InputError(std::string("limit_state: ") + e.what());
    }
    const Site s(parse_site_block(doc, "site"));
    const std::shared_ptr<const RecordLibrary> lib = RecordLibrary::open(path);
    j = site_selection_json(select_for_site(s, ls, *lib, rules, so));
  }
  return to_python(j);
}

py::dict records_read(py::handle path_or_none, std::optional<double> dt, const std::string& unit) {
  const auto path = as_path(path_or_none);
  if (!path) throw InputError("path: expected the path of a record file");
  Record r;
  {
    py::gil_scoped_release nogil;
    if (dt) r = read_plain_record(*path, *dt, parse_acceleration_unit(unit.empty() ? "g" : unit));
    else if (!unit.empty()) r = read_plain_record(*path, parse_acceleration_unit(unit));
    else r = read_record(*path);
  }
  py::dict d;
  d["name"] = r.name;
  d["format"] = r.format;
  d["source"] = r.source;
  d["event"] = r.event;
  d["station"] = r.station;
  d["component"] = r.component;
  d["dt"] = r.dt;
  d["npts"] = r.size();
  d["pga_g"] = r.pga() / units::g_n;
  d["acc"] = array_of(std::move(r.acc));
  return d;
}

// ---- campaign, fragility -----------------------------------------------------

std::string campaign(py::handle spec, const std::string& out, unsigned threads, bool resume, std::uint64_t limit,
                     bool plots) {
  const Document d = document(spec, "campaign", input_kinds::campaign_file);
  std::atomic<bool> cancel{false};
  std::function<std::string()> work = [&]() -> std::string {
    CampaignSpec cs;
    if (d.from_file) {
      cs = read_campaign(d.file);
    } else {
      try {
        cs = parse_campaign(d.doc, ".");
      } catch (const InputError& e) {
        throw InputError(std::string("campaign: ") + e.what());
      }
    }
    const Campaign c(std::move(cs));
    CampaignRunOptions o;
    o.threads = threads;
    o.resume = resume;
    o.limit = limit;
    o.cancel = &cancel;
    const CampaignRunSummary s = run_campaign(c, out, o);
    if (!s.interrupted) write_campaign_report(c, out, plots);
    return campaign_part_path(out, 0, 1);
  };
  return interruptible(cancel, work);
}

py::object fragility(py::handle kase, const std::string& mechanism, std::optional<std::vector<double>> stripes,
                     bool ida, std::optional<std::vector<double>> ida_levels_g, int records, int bootstrap,
                     std::uint64_t seed, py::handle out_dir, unsigned threads, bool resume, bool plots) {
  const Document d = document(kase, "case", input_kinds::case_file);
  FragilityOptions fo;
  fo.method = ida ? FragilityMethod::ida : FragilityMethod::stripes;
  if (stripes) {
    if (ida) throw InputError("--stripes: not with --ida (IDA levels are given by --ida-levels)");
    fo.return_periods = *stripes;
  }
  if (ida_levels_g) {
    if (!ida) throw InputError("--ida-levels: only with --ida");
    for (double g : *ida_levels_g) fo.ida_levels.push_back(g * units::g);
  }
  fo.records = records;
  fo.bootstrap = bootstrap;
  fo.seed = seed;
  const std::optional<std::string> out_given = as_path(out_dir);
  std::atomic<bool> cancel{false};
  std::function<nlohmann::json()> work = [&]() -> nlohmann::json {
    const FragilityCase fc = fragility_case(d.doc, d.file, mechanism);
    const FragilityStudy study = prepare_case_fragility(fc, fo);
    const FragilityJob job(study);
    const std::string out = out_given.value_or(fc.default_out);
    CampaignRunOptions o;
    o.threads = threads;
    o.resume = resume;
    o.cancel = &cancel;
    const CampaignRunSummary s = run_campaign_job(job, out, o);
    if (s.interrupted) return nullptr;
    const FragilityResult result = fit_fragility(study, read_fragility_csv(campaign_part_path(out, 0, 1)));
    write_fragility_report(study, result, out, plots);
    return fragility_to_json(study, result);
  };
  return to_python(interruptible(cancel, work));
}

}  // namespace
}  // namespace assess::python

PYBIND11_MODULE(_assess, m) {
  using namespace assess::python;
  m.doc() = "libassess from Python: the private layer of the package assess (use `import assess`).";
  m.attr("__version__") = assess::version();

  // assess.InputError: bad input, a ValueError with the command line's message.
  static py::exception<assess::InputError> input_error(m, "InputError", PyExc_ValueError);
  input_error.attr("__module__") = "assess";  // tracebacks name assess.InputError
  input_error.attr("__doc__") =
      "Bad input: the command line's message (str(e), e.message); e.file and e.path name the file and the JSON "
      "path when the message has them, else None. A ValueError.";
  g_input_error = input_error.ptr();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const assess::InputError& e) {
      raise_input_error(e.what());
    } catch (const assess::SystemError& e) {
      PyErr_SetString(PyExc_OSError, assess::plain_numbers(e.what()).c_str());
    } catch (const std::filesystem::filesystem_error& e) {
      const std::string where = e.path1().string() + (e.path2().empty() ? "" : " -> " + e.path2().string());
      PyErr_SetString(PyExc_OSError, (where + ": " + e.code().message()).c_str());
    }
  });

  m.def("_run", &run, py::arg("case"), py::arg("keep_going"), py::arg("fragility"));
  m.def("_kinematic", &kinematic, py::arg("case"));
  m.def("_spectrum", &spectrum, py::arg("site"), py::arg("limit_state"), py::arg("periods"), py::arg("tr"),
        py::arg("damping"), py::arg("q"));
  m.def("_rocking", &rocking, py::arg("model"), py::arg("thickness"), py::arg("height"), py::arg("unit_weight"),
        py::arg("record"), py::arg("dt"), py::arg("unit"), py::arg("k"), py::arg("restitution"),
        py::arg("one_sided"), py::arg("scale"), py::arg("reverse"), py::arg("history"), py::arg("overturn_at"),
        py::arg("stepper"), py::arg("rtol"), py::arg("atol"), py::arg("tail"), py::arg("name"));
  m.def("_last_library_seconds", &last_library_seconds);
  m.def("_records_list", &records_list);
  m.def("_records_select", &records_select);
  m.def("_records_read", &records_read);
  m.def("_campaign", &campaign);
  m.def("_fragility", &fragility);

  py::class_<PyRockingModel>(m, "_RockingModel")
      .def(py::init<const std::string&, double, double, double, std::optional<double>, py::handle, bool>(),
           py::arg("model"), py::arg("thickness"), py::arg("height"), py::arg("unit_weight"), py::arg("k"),
           py::arg("restitution"), py::arg("one_sided"))
      .def_property_readonly("theta_cr", &PyRockingModel::theta_cr)
      .def_property_readonly("theta_u", &PyRockingModel::theta_u)
      .def_property_readonly("theta_peak", &PyRockingModel::theta_peak)
      .def_property_readonly("peak_moment", &PyRockingModel::peak_moment)
      .def_property_readonly("capacity", &PyRockingModel::capacity)
      .def_property_readonly("alpha", &PyRockingModel::alpha)
      .def_property_readonly("weight", &PyRockingModel::weight)
      .def_property_readonly("restitution", &PyRockingModel::restitution)
      .def_property_readonly("frequency_parameter", &PyRockingModel::frequency_parameter)
      .def("moment", &PyRockingModel::moment, py::arg("theta"))
      .def("free", &PyRockingModel::free, py::arg("theta0"), py::arg("duration"), py::arg("theta_dot0"),
           py::arg("rtol"), py::arg("atol"), py::arg("history"));
}
