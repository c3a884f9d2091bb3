//! The one test binary of the `postc` package: every file in `tests/` is a
//! module of it, so the whole product links once for its tests (one link of
//! the CLI and every crate, not one per file). `cargo test --test suite NAME`
//! runs the tests whose path holds NAME, for example
//! `cargo test --test suite vcarve_real`.

mod cli_manual;
mod many_errors;
mod modules;
mod support;

mod apt_corpus;
mod architecture;
mod check_scaling;
mod cimco_differential;
mod cimco_fidelity;
mod cimco_goldens;
mod cimco_inspect;
mod cimco_native;
mod cimco_node;
mod cimco_runtime;
mod cimco_styles;
mod convert;
mod convert_apt_cimco;
mod convert_fusion;
mod convert_native;
mod convert_own_dialect;
mod corpus_goldens;
mod diagnostic_codes;
mod diagnostic_levels;
mod docs;
mod exact_arcs;
mod fusion_corpus;
mod fusion_node;
mod fusion_real;
mod fuzz;
mod jsonl_fidelity;
mod lint_corpus;
mod lsp;
mod plot;
mod post_budgets;
mod post_library;
mod postp_machines;
mod postp_robustness;
mod postp_words;
mod prepare;
mod real_posts;
mod robustness;
mod rs274;
mod safe_output;
mod safe_programs;
mod serve;
mod toolpath_limits;
mod trace;
mod units;
mod vcarve_real;
mod vcpost_apps;
mod vcpost_corpus;
mod vcpost_rs274;
mod vectric_fidelity;
mod vectric_vendor;
mod verify_cli;
mod verify_corpus;
mod verify_families;
mod verify_faults;
mod verify_postp;
