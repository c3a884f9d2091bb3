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

/// The runtime's whole dependency tree (what `cargo tree -p postc-runtime`
/// lists) holds no frontend, no script host and no script engine: it
/// reads IR only, and the host of a post's scripts is handed in.
#[test]
fn the_runtime_depends_on_no_frontend_at_any_depth() {
    let direct = dependencies("runtime");
    for name in &direct {
        assert!(
            !name.starts_with("postc-front") && name != "postc-frontends" && name != "postc-cimco-host",
            "postc-runtime depends on {name}"
        );
    }
    // Every postc crate the runtime uses, recursively: only the IR.
    assert_eq!(postc_crates("runtime"), ["postc-ir"]);
    assert_eq!(postc_crates("ir"), Vec::<String>::new());
    assert!(!direct.iter().any(|d| d == "rhai"), "postc-runtime depends on rhai");
}

/// The script host sits beside the CIMCO frontend and uses the runtime,
/// not the other way round.
#[test]
fn the_cimco_script_host_uses_the_runtime_and_the_frontends_names() {
    assert_eq!(postc_crates("frontends/cimco/host"), ["postc-ir", "postc-runtime", "postc-front-cimco"]);
    assert!(!postc_crates("frontends/cimco").iter().any(|d| d == "postc-runtime"));
}

/// The runtime never names a dialect: outside comments, no line of
/// `runtime/src` says `Dialect::`, CIMCO or VcPost (the check of
/// `docs/architecture.md`, `grep -rnE 'Dialect::|cimco|vcpost|Cimco|VcPost' runtime/src`).
#[test]
fn the_runtime_names_no_dialect() {
    let mut found = Vec::new();
    let mut stack = vec![Path::new(env!("CARGO_MANIFEST_DIR")).join("runtime/src")];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            let text = std::fs::read_to_string(&path).unwrap();
            for (i, line) in text.lines().enumerate() {
                let code = line.trim_start();
                if code.starts_with("//") {
                    continue;
                }
                // Drop a trailing comment (no string of the runtime holds `//`
                // before a dialect's name).
                let code = code.split("//").next().unwrap_or("");
                let lower = code.to_ascii_lowercase();
                if code.contains("Dialect::") || lower.contains("cimco") || lower.contains("vcpost") {
                    found.push(format!("{}:{}: {line}", path.display(), i + 1));
                }
            }
        }
    }
    assert!(found.is_empty(), "the runtime names a dialect:\n{}", found.join("\n"));
}
