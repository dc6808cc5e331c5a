// Umbrella header: every public header of libassess, module by module
// (docs/architecture.md). Prefer the single headers in library code.
#pragma once

// support
#include <assess/support/error.hpp>
#include <assess/support/json_input.hpp>
#include <assess/support/units.hpp>
#include <assess/support/version.hpp>

// hazard
#include <assess/hazard/hazard.hpp>
#include <assess/hazard/hazard_curve.hpp>
#include <assess/hazard/seismic_action.hpp>
#include <assess/hazard/site.hpp>
#include <assess/hazard/spectrum.hpp>

// kinematic
#include <assess/kinematic/chain.hpp>
#include <assess/kinematic/code_checks.hpp>
#include <assess/kinematic/code_rules.hpp>
#include <assess/kinematic/floor_spectrum.hpp>
#include <assess/kinematic/free_wall_capacity.hpp>
#include <assess/kinematic/kinematic_analysis.hpp>
#include <assess/kinematic/friction_overturning.hpp>
#include <assess/kinematic/horizontal_flexure.hpp>
#include <assess/kinematic/mechanism_catalogue.hpp>
#include <assess/kinematic/roof_thrust.hpp>

// records
#include <assess/records/ground_motion.hpp>
#include <assess/records/record.hpp>
#include <assess/records/record_catalogue.hpp>
#include <assess/records/record_io.hpp>
#include <assess/records/record_selection.hpp>
#include <assess/records/response_spectrum.hpp>
#include <assess/records/selection_candidates.hpp>
#include <assess/records/strong_motion.hpp>

// dynamics
#include <assess/dynamics/analysis_limits.hpp>
#include <assess/dynamics/hybrid_ode.hpp>
#include <assess/dynamics/analysis_end.hpp>
#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/dynamics/rocking_body.hpp>
#include <assess/dynamics/rocking_from_chain.hpp>
#include <assess/dynamics/rocking_model.hpp>
#include <assess/dynamics/rocking_request.hpp>

// assessment
#include <assess/assessment/case_file.hpp>
#include <assess/assessment/dynamic_case.hpp>
#include <assess/assessment/facade_assessment.hpp>
#include <assess/assessment/site_block.hpp>
#include <assess/assessment/verdict.hpp>

// report
#include <assess/report/facade_report.hpp>
#include <assess/report/document.hpp>
#include <assess/report/docx_writer.hpp>
#include <assess/report/html_report.hpp>
#include <assess/report/html_writer.hpp>
#include <assess/report/report_files.hpp>
#include <assess/report/text_writer.hpp>
#include <assess/report/kinematic_report.hpp>
#include <assess/report/plot.hpp>
#include <assess/report/plot_layout.hpp>
#include <assess/report/probabilistic_result.hpp>
#include <assess/report/records_report.hpp>
#include <assess/report/rocking_report.hpp>
#include <assess/report/spectrum_report.hpp>

// campaign
#include <assess/campaign/campaign.hpp>
#include <assess/campaign/campaign_report.hpp>
#include <assess/campaign/campaign_runner.hpp>
#include <assess/campaign/output_lock.hpp>

// risk
#include <assess/risk/collapse_rate.hpp>
#include <assess/risk/fragility_case.hpp>
#include <assess/risk/fragility_job.hpp>
#include <assess/risk/fragility_report.hpp>
#include <assess/risk/fragility_result.hpp>
#include <assess/risk/fragility_study.hpp>
#include <assess/risk/lognormal_fragility.hpp>
#include <assess/risk/run_report.hpp>
