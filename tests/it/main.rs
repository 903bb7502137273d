//! The integration tests of the library and the command line, one module per
//! subject, in one test binary (one link of the library instead of one per
//! file). Tests that need a process of their own stay beside it:
//! `alloc_free` (a counting global allocator), `adversarial` and
//! `html_report` (a browser).

#[path = "../common/mod.rs"]
mod common;

mod analysis;
mod calibration;
mod calibration_delimiters;
mod calibration_files;
mod calibration_identify;
mod calibration_joint;
mod calibration_report;
mod calibration_sd;
mod cli_analysis;
mod cli_contact;
mod cli_flags;
mod cli_output;
mod cli_run_dynamic;
mod cli_start_failures;
mod cli_study_intervals;
mod cli_thermal;
mod cli_validate_hertz;
mod concept_sweep;
mod contact_friction;
mod contact_laws;
mod coupling_shapes;
mod directions;
mod dynamic;
mod fe_exact_gap;
mod fe_validation;
mod fingerprints;
mod fresh_contact;
mod friction_limit;
mod friction_readings;
mod general_hertz;
mod geometry;
mod lanes;
mod materials;
mod mu_distribution;
mod optimize;
mod optimize_shards;
mod path_control;
mod preloads;
mod quasistatic;
mod scene_errors;
mod scenes;
mod seating_path;
mod sobol;
mod study_intervals;
mod study_nominal;
mod study_plot;
mod study_runs;
mod study_sampling;
mod study_scatter;
mod study_stats;
mod study_stream;
mod support_compliance;
mod support_tensor;
mod sweep_cli;
mod sweep_goals;
mod sweep_laws;
mod tables;
mod thermal;
mod unit_calibrate;
mod unit_contact;
mod unit_explore;
mod unit_fe;
mod unit_misc;
mod unit_study;
