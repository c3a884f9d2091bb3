//! `postc verify` over the `postp` mill controllers (ACORN, FANUC, HAAS,
//! TORMACH) and the APT corpus: each CL file of `../shared/corpus/apt` and
//! `corpus/toolpaths/apt` is posted for each mill controller and the
//! program is verified against the CL file's own moves. Exceptions are
//! listed in `EXCEPTIONS` and in `docs/verify.md`.

use std::collections::BTreeMap;
use std::io::Cursor;
use std::path::{Path, PathBuf};

use postc_postp::controller::{self, Controller as Mill};
use postc_postp::transform::{Machine, Transform};
use postc_postp::{self as postp, Settings as PostpSettings};
use postc_runtime::{Finished, Output};
use postc_verify::{Controller, Settings};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// (CL file name or "*", finding code, why).
const EXCEPTIONS: &[(&str, &str, &str)] = &[
    (
        "*",
        "VF004",
        "postp writes PPRINT text and tool-holder notes (`[HOLDER=...] 6MM CRB ...`) as bare lines, not comments",
    ),
    (
        "*",
        "VF038",
        "postp's M06 relies on the machine's tool-change macro to raise Z; the CL files go to the tool change without a retract",
    ),
    (
        "Haas_Machine__mworks.ncl",
        "VF030",
        "an inch CL file (UNITS/INCHES); postp's program has no G20, so it reads as millimetres",
    ),
    (
        "sketched-tools-inch__mworks.ncl",
        "VF030",
        "an inch CL file (UNITS/INCHES); postp's program has no G20, so it reads as millimetres",
    ),
];

/// CL files larger than this are skipped to keep the test's time reasonable in debug builds.
const MAX_BYTES: u64 = 400 << 10;

fn cl_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            cl_files(&path, out);
        } else if postc_driver::is_toolpath(&path, &postc_report::FsLoader)
            && path.metadata().is_ok_and(|m| m.len() <= MAX_BYTES)
        {
            out.push(path);
        }
    }
}

#[test]
fn postp_mill_programs_verify_against_their_cl_files() {
    let mut files = Vec::new();
    cl_files(&root().join("corpus/toolpaths/apt"), &mut files);
    cl_files(&root().join("../shared/corpus/apt"), &mut files);
    files.sort();
    let mills = [Mill::AcornM, Mill::FanucM, Mill::HaasM, Mill::TormM];
    let (mut pairs, mut not_posted) = (0, 0);
    let mut failures = Vec::new();
    let mut by_code: BTreeMap<&str, usize> = BTreeMap::new();
    for file in &files {
        let name = file.file_name().unwrap().to_string_lossy().into_owned();
        for machine in mills {
            let mut sources = postc_report::source_map();
            let settings = PostpSettings { options: None, machine: Some(machine), ..PostpSettings::default() };
            let Ok(report) = postp::post(file, &settings, Output::memory(), &mut sources) else {
                not_posted += 1;
                continue;
            };
            let Finished::Memory(parts) = report.output else { unreachable!() };
            let program = parts.concat();
            let Ok(head) = postp::head(file, Some(machine), &mut sources) else { continue };
            let Ok(options) = postp::load_options(machine, None, &mut sources) else { continue };
            let Ok(post) = postp::compile(&head, &options, &mut sources) else { continue };
            let controller = match machine {
                Mill::FanucM => Controller::Fanuc,
                Mill::HaasM => Controller::Haas,
                _ => Controller::LinuxCnc,
            };
            let file_id = sources.add("program", String::from_utf8_lossy(&program).into_owned());
            // The events postp posts from: the CL reader's, through postp's transform.
            let reader = postc_driver::open_toolpath(file, &mut sources).unwrap();
            let machine_data = Machine {
                kind: machine.kind(),
                name: machine.name(),
                axes: controller::rotary_axes(head.axis_type),
                retractz: options.retractz,
            };
            let mut source = Transform::new(reader, machine_data);
            let verdict = postc_verify::verify(
                &mut Cursor::new(&program),
                file_id,
                &mut source,
                &Settings::from_post(&post, controller, 0.01),
            );
            pairs += 1;
            for d in verdict.findings.iter().filter(|d| d.is_error()) {
                if EXCEPTIONS.iter().any(|(f, c, _)| (*f == "*" || *f == name) && *c == d.code) {
                    continue;
                }
                *by_code.entry(d.code).or_insert(0) += 1;
                let line = d.primary_span().and_then(|s| sources.line_column(s.file, s.start)).map_or(0, |p| p.0);
                let key = format!("{name} {}", d.code);
                if !failures.iter().any(|f: &String| f.starts_with(&key)) {
                    failures.push(format!("{key} for {} at line {line}: {}", machine.name(), d.message));
                }
            }
        }
    }
    println!(
        "verify postp: {} CL files, {pairs} CL file x controller pairs verified, {not_posted} not posted; findings by code {by_code:?}",
        files.len()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
