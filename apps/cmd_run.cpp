// cmd_run.cpp: `assess run CASE.json [--json] [--html FILE] [--keep-going] [--fragility DIR]`:
// the façade assessment — site, kinematic checks of both editions and the
// dynamic rocking analysis — side by side. Parses, calls, prints.
#include "commands.hpp"

#include <assess/assessment/building_assessment.hpp>
#include <assess/assessment/case_file.hpp>
#include <assess/report/building_report.hpp>
#include <assess/support/json_input.hpp>
#include <assess/support/error.hpp>
#include <assess/support/input_file.hpp>
#include <assess/support/output_file.hpp>
#include <assess/assessment/facade_assessment.hpp>
#include <assess/report/facade_report.hpp>
#include <assess/report/kinematic_report.hpp>
#include <assess/assessment/tie_intervention.hpp>
#include <assess/report/tie_report.hpp>
#include <assess/risk/fragility_report.hpp>
#include <assess/risk/run_report.hpp>

#include <filesystem>
#include <assess/report/report_files.hpp>
#include <assess/report/messages.hpp>
#include <assess/report/text_writer.hpp>

#include <fstream>
#include <functional>
#include <iterator>
#include <iostream>
#include <memory>
#include <optional>

namespace assess::cli {
namespace {

struct RunArgs {
  std::string file, html, pdf, docx, txt, lang = "it", fragility, mechanism, expand;
  bool json = false, keep_going = false, wide = false;
  bool wants_report() const { return !html.empty() || !pdf.empty() || !docx.empty() || !txt.empty(); }
};

// The terminal summary's width: 120 columns, or one line per table row (--wide).
std::size_t text_width(const RunArgs& a) { return a.wide ? std::size_t(100000) : std::size_t(120); }


// The files the run wrote, one line each, in the summary's language: the
// relazione's and, beside each, its tabulati di calcolo (issue 36).
std::string files_written(const RunArgs& a) {
  const Lang L = parse_lang(a.lang);
  std::string s;
  for (const auto& [file, key] : {std::pair{a.html, "out.html"}, {a.pdf, "out.pdf"}, {a.docx, "out.docx"}, {a.txt, "out.txt"}})
    if (!file.empty())
      s += (s.empty() ? "\n" : "") + msg(L, key) + ": " + file + "; " + msg(L, "out.tabulati") + ": " + tabulati_path(file) + "\n";
  return s;
}

// Rewrites a message of the case (for a building's mechanism: the building's
// paths and the mechanism's id, building_path_message); identity otherwise.
using MessageMap = std::function<std::string(const std::string&)>;

void run_single(const RunArgs& a, PdfPrinter& printer, const CaseFile& c, const std::string& case_text,
                const MessageMap& map = {});

// The case file's text for the report's appendix (the bounded reader: the
// file already read once, so the same checks).
std::string read_text(const std::string& path) { return read_input_file(path, input_kinds::case_file); }

// Refuses the outputs before a long run rather than after it: an --html,
// --pdf, --docx or --txt that names an input of the run (the case file
// itself), a directory, a link out of its folder, or another output of the
// run, the expanded cases included (output_file.hpp: by file identity;
// written the same way at the end).
ReportFiles report_files(const RunArgs& a) { return {a.html, a.pdf, a.docx, a.txt}; }

// Then, with --pdf, the PDFs' browser starts: its start-up runs beside the
// assessment (issue 36, item 7).
void check_outputs(const RunArgs& a, PdfPrinter& printer, const std::vector<OutputTarget>& more = {}) {
  std::vector<OutputTarget> all = report_files(a).outputs();
  all.insert(all.end(), more.begin(), more.end());
  check_output_files(all);
  if (!a.pdf.empty()) printer.start();
}

// The expanded cases of --expand DIR (DIR created if needed), as outputs.
std::vector<OutputTarget> expanded_outputs(const RunArgs& a, const std::vector<const BuildingMechanism*>& ms) {
  make_output_folder(a.expand, "--expand");
  std::vector<OutputTarget> out;
  for (const BuildingMechanism* m : ms) out.push_back({a.expand + "/" + m->id + ".json", "--expand " + a.expand, a.expand});
  return out;
}

// --expand DIR: each expanded case as DIR/<id>.json, written whole through
// write_output_file: never over the building file or another input of the
// run, never through a link out of DIR.
void write_expanded(const RunArgs& a, const BuildingCase& b, const std::vector<const BuildingMechanism*>& ms) {
  for (const BuildingMechanism* m : ms)
    write_output_file(a.expand + "/" + m->id + ".json", standalone_case(b, *m).dump(2) + "\n", "--expand " + a.expand,
                      a.expand);
}

// A building case (issue 22; docs/user/building.md): every mechanism, the
// summary and the relazione; --mechanism ID runs one mechanism as a single case.
void run_building(const RunArgs& a, PdfPrinter& printer, const nlohmann::json& doc) {
  const Lang lang = parse_lang(a.lang);
  BuildingCase bc = parse_building(doc, a.file);
  if (!a.mechanism.empty()) {
    const BuildingMechanism& m = find_mechanism(bc, a.mechanism);
    // --expand with --mechanism: that mechanism's expanded case only.
    if (!a.expand.empty()) {
      check_outputs(a, printer, expanded_outputs(a, {&m}));
      write_expanded(a, bc, {&m});
    } else {
      check_outputs(a, printer);
    }
    // Its errors and warnings name the building file's paths and the mechanism.
    const MessageMap map = [&](const std::string& text) { return building_path_message(bc, m, text); };
    try {
      run_single(a, printer, m.kase, standalone_case(bc, m).dump(2) + "\n", map);
    } catch (const InputError& e) {
      throw InputError(map(e.what()));
    }
    if (!a.expand.empty() && !a.json) std::cout << "\nexpanded case written to " << a.expand << "/" << m.id << ".json\n";
    return;
  }
  // Checked before the run, with the expanded cases (one file each), written
  // after it (with the shared selections' ranges).
  if (!a.expand.empty()) {
    std::vector<const BuildingMechanism*> all;
    for (const BuildingMechanism& m : bc.mechanisms) all.push_back(&m);
    check_outputs(a, printer, expanded_outputs(a, all));
  } else {
    check_outputs(a, printer);
  }
  FacadeOptions opt;
  opt.keep_going = a.keep_going;
  opt.histories = a.wants_report();
  // The review (issue 36) is what the summary and the relazione print; --json alone does not need it.
  opt.review = !a.json || a.wants_report();
  opt.review_records = a.wants_report();
  const BuildingAssessment res = assess_building(std::move(bc), opt);
  print_warnings(res.warnings);
  if (!a.expand.empty()) {
    std::vector<const BuildingMechanism*> all;
    for (const BuildingMechanism& m : res.building.mechanisms) all.push_back(&m);
    write_expanded(a, res.building, all);
  }
  if (a.wants_report()) {
    ReportOptions ro;
    ro.lang = lang;
    ro.case_text = read_text(a.file);
    write_report_files(building_relazione(res, ro), report_files(a), &printer);
  }
  if (a.json) {
    nlohmann::json j = building_json(res);
    std::cout << stamp_version(j).dump(2) << "\n";
  } else {
    ReportOptions ro;
    ro.lang = lang;
    std::cout << to_text(building_summary(res, ro), text_width(a), false)
              << (a.expand.empty() ? "" : "\n" + msg(lang, "out.expanded") + ": " + a.expand + "/M*.json\n")
              << files_written(a);
  }
}

void run(const RunArgs& a) {
  PdfPrinter printer;  // started once the outputs are checked (check_outputs)
  const nlohmann::json doc = read_json_file(a.file, input_kinds::case_file);
  // A building's outputs are checked with its expanded cases, once the file is parsed (run_building).
  if (is_building_document(doc)) return run_building(a, printer, doc);
  check_outputs(a, printer);
  if (!a.mechanism.empty() || !a.expand.empty())
    throw InputError(a.file + ": --mechanism and --expand apply to a building case (a file with \"walls\"), "
                     "not to a single-mechanism case");
  run_single(a, printer, parse_case(doc, a.file), read_text(a.file));
}

void run_single(const RunArgs& a, PdfPrinter& printer, const CaseFile& c, const std::string& case_text,
                const MessageMap& map) {
  const Lang lang = parse_lang(a.lang);
  FacadeOptions opt;
  opt.keep_going = a.keep_going;
  opt.histories = a.wants_report();
  opt.review = !a.json || a.wants_report();
  opt.review_records = a.wants_report();
  FacadeAssessment res = assess_facade(c, opt);
  // Issue 23: the tie rods ("ties" or "design"): before/after and their checks;
  // given ties also decide the dynamic check rows.
  const std::optional<TieInterventionResult> ties = assess_ties(res);
  std::vector<std::string> warnings = res.warnings;
  if (map)
    for (std::string& w : warnings) w = map(w);
  print_warnings(warnings);
  // A fragility result of this case: --fragility DIR, or the default output
  // directory of `assess fragility` (CASE.fragility) when it holds this case's.
  const std::optional<RunFragility> frag = run_fragility(a.file, a.fragility);
  if (a.wants_report()) {
    ReportOptions ro;
    ro.lang = lang;
    if (frag) ro.fragility = frag->result;
    if (ties) ro.ties = &*ties;
    ro.case_text = case_text;
    write_report_files(facade_relazione(res, ro), report_files(a), &printer);
  }
  if (a.json) {
    nlohmann::json j = facade_run_json(res, ties, frag);
    std::cout << stamp_version(j).dump(2) << "\n";
  } else {
    ReportOptions ro;
    ro.lang = lang;
    if (frag) ro.fragility = frag->result;
    if (ties) ro.ties = &*ties;
    std::cout << to_text(facade_summary(res, ro), text_width(a), false) << files_written(a);
  }
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand("run", "façade assessment: strength, displacement and dynamic verdicts side by side; "
                                       "a building case (key \"walls\"): every mechanism, safety indices, one relazione");
  cmd->add_option("case", args->file, "case file (JSON, see docs/user/case-file.md)")->required()->check(CLI::ExistingFile);
  cmd->add_flag("--json", args->json, "print the report as JSON");
  cmd->add_option("--html", args->html,
                  "also write the relazione as a self-contained HTML page to this file, and its tabulati di calcolo "
                  "beside it (NAME-tabulati.html)");
  cmd->add_option("--pdf", args->pdf,
                  "also print the relazione to a PDF file (A4, headless Chromium), its tabulati to NAME-tabulati.pdf");
  cmd->add_option("--docx", args->docx,
                  "also write the relazione as an editable Word document, its tabulati to NAME-tabulati.docx");
  cmd->add_option("--txt", args->txt,
                  "also write the relazione as plain text (120 columns), its tabulati to NAME-tabulati.txt");
  cmd->add_option("--lang", args->lang,
                  "language of the terminal summary and of the report: it (default: the relazione is filed in Italy) or en")
;
  cmd->add_flag("--wide", args->wide, "one line per table row however long (default: tables within 120 columns)");
  cmd->add_flag("--keep-going", args->keep_going, "continue with the readable records when some cannot be read");
  cmd->add_option("--mechanism", args->mechanism,
                  "building case: run one mechanism (id M1, M2, ... or its name) as its single-mechanism case");
  cmd->add_option("--expand", args->expand,
                  "building case: write each mechanism's expanded single-mechanism case to DIR/M<n>.json");
  cmd->add_option("--fragility", args->fragility,
                  "add the fragility result in this directory (of `assess fragility`; default CASE.fragility if present)");
  cmd->callback([args] { run(*args); });
}

}  // namespace assess::cli
