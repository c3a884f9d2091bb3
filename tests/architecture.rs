//! The dependency invariants of `docs/architecture.md`: which crate may use
//! which. Read from each crate's `Cargo.toml`, so a new dependency that
//! breaks the architecture fails here.

use std::path::Path;

/// The names in a crate's `[dependencies]` table.
fn dependencies(krate: &str) -> Vec<String> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(krate).join("Cargo.toml");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    let mut inside = false;
    let mut names = Vec::new();
    for line in text.lines() {
        let line = line.trim();
        if line.starts_with('[') {
            inside = line == "[dependencies]";
        } else if inside && !line.is_empty() && !line.starts_with('#') {
            names.push(line.split(['=', '.', ' ']).next().unwrap_or("").to_string());
        }
    }
    names
}

fn postc_crates(krate: &str) -> Vec<String> {
    dependencies(krate).into_iter().filter(|d| d.starts_with("postc")).collect()
}

#[test]
fn the_runtime_depends_on_the_ir_alone() {
    assert_eq!(postc_crates("runtime"), ["postc-ir"]);
}

#[test]
fn backends_depend_on_the_ir_and_the_vectric_vocabulary() {
    assert_eq!(postc_crates("backends"), ["postc-ir", "postc-front-vectric"]);
}

#[test]
fn verify_reads_programs_and_events_only() {
    assert_eq!(postc_crates("verify"), ["postc-ir"]);
}

#[test]
fn the_ir_depends_on_no_postc_crate() {
    assert_eq!(postc_crates("ir"), Vec::<String>::new());
}

/// `src/` holds the command line only: every other module of the binary
/// crate is a library crate that tests and benches use directly.
#[test]
fn the_binary_crate_holds_the_command_line() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut entries: Vec<String> =
        std::fs::read_dir(&src).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    entries.sort();
    assert_eq!(entries, ["cli", "default_post.rs", "lib.rs", "main.rs"]);
}
