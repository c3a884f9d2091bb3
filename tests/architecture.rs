//! The invariants of `docs/architecture.md`: which crate may use which,
//! read from each crate's `Cargo.toml`, so a new dependency that breaks the
//! architecture fails here; what crates' sources may touch; and its code
//! map, which names every module of every crate.

use std::collections::BTreeMap;
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

/// The backends print from the IR with each dialect's vocabulary; the
/// CIMCO backend also builds the CIMCO frontend's syntax tree to print
/// functions with its printer, and compiles what it printed to check it
/// (docs/convert.md).
#[test]
fn backends_depend_on_the_ir_and_the_dialect_vocabularies() {
    assert_eq!(
        postc_crates("backends"),
        ["postc-ir", "postc-front-vectric", "postc-front-cimco", "postc-front-vcpost"]
    );
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
    assert_eq!(entries, ["cli", "lib.rs", "library.rs", "main.rs"]);
}

/// The Rust sources under a folder, with their text.
fn sources(folder: &str) -> Vec<(String, String)> {
    fn walk(dir: &Path, out: &mut Vec<(String, String)>) {
        let Ok(entries) = std::fs::read_dir(dir) else { return };
        for e in entries.flatten() {
            let path = e.path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|x| x == "rs") {
                out.push((path.display().to_string(), std::fs::read_to_string(&path).unwrap_or_default()));
            }
        }
    }
    let mut out = Vec::new();
    walk(&Path::new(env!("CARGO_MANIFEST_DIR")).join(folder), &mut out);
    assert!(!out.is_empty(), "no sources in {folder}");
    out
}

/// Lines of `folder`'s sources that contain any of
/// `needles`, as `file: line`.
fn uses(folder: &str, needles: &[&str]) -> Vec<String> {
    let mut found = Vec::new();
    for (path, text) in sources(folder) {
        for line in text.lines() {
            let code = line.trim_start();
            if code.starts_with("//") {
                continue;
            }
            if needles.iter().any(|n| code.contains(n)) {
                found.push(format!("{path}: {}", line.trim()));
            }
        }
    }
    found
}

/// The IR opens no file and renders nothing: the source map reads through
/// the loader its caller gives it, and `postc-report` renders.
#[test]
fn the_ir_opens_no_file_and_renders_nothing() {
    assert_eq!(uses("ir/src", &["std::fs", "File::", "codespan", "stdout()", "stderr()"]), Vec::<String>::new());
    assert!(
        !dependencies("ir").iter().any(|d| d == "codespan-reporting" || d == "tempfile"),
        "{:?}",
        dependencies("ir")
    );
}

/// The IR says what a post means, not how the runtime runs it fast: the
/// output-buffer operations of the fast path (`Emit`, `Mark`, `MoveBack`,
/// `Truncate`, `Blocks`, `Written`) are the runtime's (`runtime/src/exec.rs`,
/// made by `runtime/src/prepare/`), and no frontend makes them.
#[test]
fn the_ir_holds_no_execution_strategy() {
    let needles = ["Emit(", "Mark(", "MoveBack", "Truncate(", "Blocks(", "Written(", "__postc_text"];
    for folder in ["ir/src", "frontends/cimco/src", "frontends/vcpost/src", "frontends/vectric/src", "backends/src"] {
        assert_eq!(uses(folder, &needles), Vec::<String>::new(), "{folder}");
    }
    assert!(!uses("runtime/src", &needles).is_empty(), "the runtime's fast path is gone: update this test");
}

/// The runtime writes through sinks and takes "now" as an input: it opens
/// no file, reads no clock and writes no terminal.
#[test]
fn the_runtime_touches_no_file_clock_or_terminal() {
    let found =
        uses("runtime/src", &["std::fs", "File::", "tempfile", "SystemTime", "Instant::now", "stdout()", "stderr()"]);
    assert_eq!(found, Vec::<String>::new());
    assert!(!dependencies("runtime").iter().any(|d| d == "tempfile" || d == "codespan-reporting"));
}

/// Post frontends read what they are given and ask the source map's loader
/// for the rest (`POST_BASE`).
#[test]
fn the_vectric_frontend_reads_post_base_through_the_loader() {
    assert_eq!(uses("frontends/vectric/src", &["std::fs", "File::"]), Vec::<String>::new());
}

/// Rendering diagnostics is the edge's job.
#[test]
fn only_the_edge_renders_diagnostics() {
    for krate in [
        "ir",
        "runtime",
        "driver",
        "frontends/vectric",
        "frontends/cimco",
        "frontends/vcpost",
        "readers/apt",
        "readers/native",
        "readers/synthetic",
        "hosts/cimco",
        "postp",
        "verify",
        "backends",
        "lsp",
        "lint",
    ] {
        assert!(
            !dependencies(krate).iter().any(|d| d == "codespan-reporting"),
            "{krate} depends on codespan-reporting"
        );
    }
}

/// Only the edge touches the file system, the clock and the terminal: the
/// command line (`src/`) and `postc-report` (rendering, the file-system
/// loader). Every library crate reads through the loader it is given,
/// writes through the sink it is given and takes "now" as an input.
#[test]
fn only_the_edge_touches_files_the_clock_and_the_terminal() {
    let needles = [
        "std::fs",
        "File::",
        "tempfile",
        "SystemTime",
        "Instant::now",
        "stdout()",
        "stderr()",
        "stdin()",
        "Connection::stdio",
        "println!",
        "eprintln!",
        "print!(",
        "eprint!(",
    ];
    let mut found = Vec::new();
    for folder in [
        "ir/src",
        "runtime/src",
        "driver/src",
        "frontends/vectric/src",
        "frontends/cimco/src",
        "frontends/vcpost/src",
        "readers/apt/src",
        "readers/native/src",
        "readers/synthetic/src",
        "hosts/cimco/src",
        "postp/src",
        "verify/src",
        "backends/src",
        "lsp/src",
        "lint/src",
    ] {
        found.extend(uses(folder, &needles));
    }
    assert_eq!(found, Vec::<String>::new());
}

/// `postp` reads its CL file once, through the reader's events: no second
/// handle on the file (the events keep FEDRAT units, COOLNT placement and
/// tool loads as written).
#[test]
fn postp_reads_its_cl_file_through_events_only() {
    assert_eq!(uses("postp/src", &["ClText", ".open(", "read_at("]), Vec::<String>::new());
}

/// The runtime's whole dependency tree (what `cargo tree -p postc-runtime`
/// lists) holds no frontend, no script host and no script engine: it
/// reads IR only, and the host of a post's scripts is handed in.
#[test]
fn the_runtime_depends_on_no_frontend_at_any_depth() {
    let direct = dependencies("runtime");
    for name in &direct {
        assert!(
            !name.starts_with("postc-front") && name != "postc-driver" && name != "postc-cimco-host",
            "postc-runtime depends on {name}"
        );
    }
    // Every postc crate the runtime uses, recursively: only the IR.
    assert_eq!(postc_crates("runtime"), ["postc-ir"]);
    assert_eq!(postc_crates("ir"), Vec::<String>::new());
    assert!(!direct.iter().any(|d| d == "rhai"), "postc-runtime depends on rhai");
}

/// A script host (`hosts/`) runs what a dialect's frontend compiled to
/// script, for the runtime: it uses the runtime and its dialect's frontend,
/// not the other way round.
#[test]
fn the_cimco_script_host_uses_the_runtime_and_the_frontends_names() {
    assert_eq!(postc_crates("hosts/cimco"), ["postc-ir", "postc-runtime", "postc-front-cimco"]);
    assert!(!postc_crates("frontends/cimco").iter().any(|d| d == "postc-runtime"));
}

/// The folders at the repository's root, sorted (hidden ones and `target`
/// left out).
fn root_folders() -> Vec<String> {
    let mut folders: Vec<String> = std::fs::read_dir(env!("CARGO_MANIFEST_DIR"))
        .unwrap()
        .flatten()
        .filter(|e| e.path().is_dir())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|name| !name.starts_with('.') && name != "target")
        .collect();
    folders.sort();
    folders
}

/// The workspace's crate folders (`ir`, `frontends/cimco`): every root
/// folder with a `Cargo.toml`, and every crate of a layer folder
/// (`frontends/`, `readers/`, `hosts/`).
fn crate_folders() -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut crates = Vec::new();
    for name in root_folders() {
        if root.join(&name).join("Cargo.toml").is_file() {
            crates.push(name);
        } else {
            for sub in std::fs::read_dir(root.join(&name)).unwrap().flatten() {
                if sub.path().join("Cargo.toml").is_file() {
                    crates.push(format!("{name}/{}", sub.file_name().to_string_lossy()));
                }
            }
        }
    }
    crates.sort();
    crates
}

/// The folders at the root are the architecture's layers
/// (docs/architecture.md draws them): dialect frontends, toolpath readers,
/// the driver, the runtime, script hosts, backends, lint, verify, the
/// language server, report, the command line (`src/`), the Python package
/// (`python/`), the workbench's front end (`web/`), and beside them the
/// fuzzer, benches, corpus, docs and tests.
#[test]
fn the_root_folders_are_the_layers() {
    assert_eq!(
        root_folders(),
        [
            "backends",
            "benches",
            "corpus",
            "docs",
            "driver",
            "frontends",
            "fuzz",
            "hosts",
            "ir",
            "lint",
            "lsp",
            "postp",
            "python",
            "readers",
            "report",
            "runtime",
            "src",
            "tests",
            "verify",
            "web"
        ]
    );
}

/// The crates of a layer folder (`frontends`, `readers`, `hosts`): its
/// subfolders with a `Cargo.toml`.
fn layer(folder: &str) -> Vec<String> {
    let crates: Vec<String> = crate_folders().into_iter().filter(|c| c.starts_with(&format!("{folder}/"))).collect();
    assert!(!crates.is_empty(), "no crate in {folder}/");
    assert!(!Path::new(env!("CARGO_MANIFEST_DIR")).join(folder).join("Cargo.toml").exists(), "{folder}/ is a crate");
    crates
}

/// A dialect frontend reads a post's text into IR, and a toolpath reader a
/// toolpath into events: each uses the IR alone.
#[test]
fn frontends_and_readers_use_the_ir_alone() {
    for krate in layer("frontends").into_iter().chain(layer("readers")) {
        assert_eq!(postc_crates(&krate), ["postc-ir"], "{krate}");
    }
}

/// The driver sits above the dialects, the readers, the hosts and the
/// runtime, and below every application of them (the command line, lint's
/// tests, the language server, `postp`): no crate it uses uses it.
#[test]
fn the_driver_sits_above_frontends_readers_hosts_and_the_runtime() {
    for d in postc_crates("driver") {
        assert!(
            d == "postc-ir"
                || d == "postc-runtime"
                || d.starts_with("postc-front-")
                || d.starts_with("postc-reader-")
                || d.ends_with("-host"),
            "the driver uses {d}"
        );
    }
    let below = ["ir", "runtime", "backends", "verify", "report"].map(String::from);
    for krate in below.into_iter().chain(layer("frontends")).chain(layer("readers")).chain(layer("hosts")) {
        assert!(!postc_crates(&krate).iter().any(|d| d == "postc-driver"), "{krate} uses the driver");
    }
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

/// Toolpath readers and post dialects sit in separate folders and know
/// nothing of each other: a reader depends on no post frontend, a post
/// frontend on no reader.
#[test]
fn readers_and_post_dialects_are_apart() {
    for reader in layer("readers") {
        let deps = dependencies(&reader);
        assert!(!deps.iter().any(|d| d.starts_with("postc-front")), "{reader} depends on a post frontend: {deps:?}");
    }
    for dialect in layer("frontends") {
        let deps = dependencies(&dialect);
        assert!(!deps.iter().any(|d| d.starts_with("postc-reader")), "{dialect} depends on a reader: {deps:?}");
    }
}

/// Comments describe the present: no line of Rust cites an issue number,
/// a seed file by its number or the product brief (the seeds are named by
/// their titles; history lives in git). The check of
/// `grep -rnE 'issue [0-9]+|BRI[E]F|seed 00[0-9]' --include=*.rs .` (written here with `[E]` so that it does not find itself).
#[test]
fn comments_cite_no_issue_seed_number_or_numbered_decision() {
    let brief = concat!("BRI", "EF");
    let mut found = Vec::new();
    // web/ holds the workbench's JavaScript, no Rust.
    for folder in root_folders().into_iter().filter(|f| f != "corpus" && f != "docs" && f != "web") {
        for (path, text) in sources(&folder) {
            for (i, line) in text.lines().enumerate() {
                let cites = |word: &str| {
                    line.match_indices(word)
                        .any(|(j, _)| line[j + word.len()..].chars().next().is_some_and(|c| c.is_ascii_digit()))
                };
                if cites("issue ") || cites("seed 00") || line.contains(brief) {
                    found.push(format!("{path}:{}: {}", i + 1, line.trim()));
                }
            }
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n"));
}

/// The sections of a `Cargo.toml` as (header, lines), in order: the
/// header as written (`[lib]`, `[[test]]`), the lines up to the next one
/// with comments and blank lines left out.
fn manifest_sections(krate: &str) -> Vec<(String, Vec<String>)> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(krate).join("Cargo.toml");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    let mut sections: Vec<(String, Vec<String>)> = vec![(String::new(), Vec::new())];
    for line in text.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with('#')) {
        if line.starts_with('[') {
            sections.push((line.to_string(), Vec::new()));
        } else {
            sections.last_mut().unwrap().1.push(line.replace(' ', ""));
        }
    }
    sections
}

/// No crate links a unit-test binary: each crate's `[lib]` (and each
/// `[[bin]]`) says `test = false`, and no source under a `src/` holds a
/// `#[cfg(test)]` module. The tests of a module of `src/` are in its crate's
/// `tests/modules/` when the crate has a test binary, else in the root's
/// `tests/modules/CRATE/` (the command line's in `tests/modules/cli/`). So
/// the test executables of the workspace are the root's `suite` and each
/// crate's one `tests` binary (`each_crate_links_one_integration_test_binary`).
#[test]
fn no_crate_links_a_unit_test_binary() {
    let mut binaries = Vec::new();
    for krate in std::iter::once(".".to_string()).chain(crate_folders()) {
        let sections = manifest_sections(&krate);
        let targets: Vec<_> = sections.iter().filter(|(h, _)| h == "[lib]" || h == "[[bin]]").collect();
        assert!(targets.iter().any(|(h, _)| h == "[lib]"), "{krate}/Cargo.toml has no [lib] saying test = false");
        for (header, lines) in targets {
            assert!(lines.iter().any(|l| l == "test=false"), "{krate}/Cargo.toml: {header} links a unit-test binary");
        }
        for (header, lines) in &sections {
            if header == "[[test]]" {
                let name = lines.iter().find_map(|l| l.strip_prefix("name=")).unwrap_or("?");
                binaries.push(format!("{krate}: {name}"));
            }
        }
        let src = if krate == "." { "src".to_string() } else { format!("{krate}/src") };
        for (path, text) in sources(&src) {
            assert!(!text.contains("#[cfg(test)]"), "{path} has unit tests: move them to tests/modules/");
        }
    }
    assert!(binaries.len() <= 7, "{} test binaries: {binaries:?}", binaries.len());
}

/// Each crate's integration tests build as one binary (`autotests = false`
/// and one `[[test]]` whose `tests/main.rs` holds every file of `tests/` as
/// a module), so a test build links one binary per crate with tests, not
/// one per file.
#[test]
fn each_crate_links_one_integration_test_binary() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for krate in std::iter::once(".".to_string()).chain(crate_folders()) {
        let dir = root.join(&krate);
        // python/tests holds the Python package's pytest files, no Rust.
        let rust_tests = std::fs::read_dir(dir.join("tests"))
            .is_ok_and(|entries| entries.flatten().any(|e| e.path().extension().is_some_and(|x| x == "rs")));
        if !rust_tests {
            continue;
        }
        let manifest = std::fs::read_to_string(dir.join("Cargo.toml")).unwrap();
        assert!(manifest.contains("autotests = false"), "{krate}: tests/ files would each link a binary");
        assert_eq!(manifest.matches("[[test]]").count(), 1, "{krate}: one integration-test binary");
        let main = std::fs::read_to_string(dir.join("tests/main.rs")).unwrap_or_default();
        for entry in std::fs::read_dir(dir.join("tests")).unwrap().flatten() {
            let name = entry.file_name().to_string_lossy().into_owned();
            let module = name.strip_suffix(".rs").unwrap_or(&name);
            let is_module = name.ends_with(".rs") || entry.path().join("mod.rs").is_file();
            if is_module && name != "main.rs" {
                assert!(
                    main.contains(&format!("mod {module};")),
                    "{krate}/tests/{name} is not a module of tests/main.rs"
                );
            }
        }
    }
}

/// The crates of the workspace, each as the code map names it (its folder,
/// `frontends/cimco/`) with the folder of its modules (`frontends/cimco/src`):
/// every root folder with a `Cargo.toml`, every crate of a layer folder
/// (`frontends/`, `readers/`, `hosts/`), and `src/`, the command line
/// (crate `postc`, whose modules are in `src` itself).
fn crate_sources() -> Vec<(String, String)> {
    let mut crates = vec![("src/".to_string(), "src".to_string())];
    crates.extend(crate_folders().into_iter().map(|f| (format!("{f}/"), format!("{f}/src"))));
    crates.sort();
    crates
}

/// The `.rs` files under a crate's source folder, as paths relative to it
/// (`prepare/fuse.rs`).
fn modules(src: &str) -> Vec<String> {
    let base = Path::new(env!("CARGO_MANIFEST_DIR")).join(src);
    let mut found: Vec<String> = sources(src)
        .into_iter()
        .map(|(path, _)| Path::new(&path).strip_prefix(&base).unwrap().to_string_lossy().replace('\\', "/"))
        .collect();
    found.sort();
    found
}

/// The code map of docs/architecture.md: its crates table, and each crate's
/// subsection (`### runtime/`) with the modules its list names. An entry is
/// `` - `a.rs`: what it owns `` or, for a group, `` - `a.rs`, `b.rs`: ... ``.
fn code_map() -> (String, BTreeMap<String, Vec<String>>) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/architecture.md");
    let text = std::fs::read_to_string(&path).unwrap();
    let start = text.find("\n## Code map\n").expect("docs/architecture.md has no \"## Code map\"") + 1;
    let section = &text[start..];
    let section = &section[..section[1..].find("\n## ").map_or(section.len(), |i| i + 1)];
    let mut map: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut current: Option<String> = None;
    for line in section.lines() {
        if let Some(heading) = line.strip_prefix("### ") {
            assert!(map.insert(heading.to_string(), Vec::new()).is_none(), "two subsections `### {heading}`");
            current = Some(heading.to_string());
        } else if let Some(mut rest) = line.strip_prefix("- ") {
            let krate = current.as_ref().unwrap_or_else(|| panic!("a module entry before any crate: {line}"));
            loop {
                let name = rest
                    .strip_prefix('`')
                    .and_then(|r| r.split_once('`'))
                    .unwrap_or_else(|| panic!("### {krate}: an entry that does not start with `module.rs`: {line}"));
                map.get_mut(krate).unwrap().push(name.0.to_string());
                if let Some(more) = name.1.strip_prefix(", ") {
                    rest = more;
                } else if name.1.starts_with(": ") {
                    break;
                } else {
                    panic!("### {krate}: an entry is `a.rs`: ... or `a.rs`, `b.rs`: ...: {line}");
                }
            }
        }
    }
    (section.to_string(), map)
}

/// docs/architecture.md's code map is whole and current: every crate has a
/// row in its table and a subsection, and every `.rs` file under a crate's
/// `src/` has an entry in its crate's subsection; every crate and module
/// the map names exists, each named once.
#[test]
fn the_code_map_names_every_module() {
    let (section, map) = code_map();
    let crates = crate_sources();
    let folders: Vec<&String> = crates.iter().map(|(folder, _)| folder).collect();
    let headings: Vec<&String> = map.keys().collect();
    assert_eq!(headings, folders, "the code map's subsections (`### folder/`) are not the workspace's crates");
    let mut problems = Vec::new();
    for (folder, src) in &crates {
        if !section.contains(&format!("| `{folder}` |")) {
            problems.push(format!("{folder}: no row in the crates table"));
        }
        let actual = modules(src);
        let named = &map[folder];
        for module in &actual {
            if !named.contains(module) {
                problems.push(format!("### {folder}: no entry for `{module}`"));
            }
        }
        for (i, module) in named.iter().enumerate() {
            if !actual.contains(module) {
                problems.push(format!("### {folder}: `{module}` is no module of {src}/"));
            } else if named[..i].contains(module) {
                problems.push(format!("### {folder}: `{module}` has two entries"));
            }
        }
    }
    assert!(problems.is_empty(), "docs/architecture.md's code map:\n{}", problems.join("\n"));
}
