//! A post converted to its own dialect: what a person would notice, and
//! whether its settings still work (issue "Convert for real", item 3).
//!
//! - Every corpus post of CIMCO (`corpus/posts/cimco/`,
//!   `corpus/posts/cimco-styles/`), Vectric (`corpus/posts/vectric/`) and
//!   VcPost (`corpus/posts/vcpost/`, the `postp` controllers of
//!   `corpus/posts/postp/`) is converted to its own dialect, and the lines that changed are
//!   counted (a line diff of source and converted post). The counts are
//!   the table of docs/convert.md ("A post converted to its own dialect"),
//!   which this test checks (`POSTC_BLESS=1` rewrites the table).
//! - The settings test: every top-level setting of a CIMCO corpus post
//!   written `var name = number;`, `var name = true|false;` or `var name =
//!   "text";` is changed (a text gets one more character),
//!   in the source and in the post `convert` printed, the same way; both
//!   post the corpus toolpath, and the programs must be the same bytes.
//!   The source is the reference: a setting that changes the source's
//!   program and not the converted post's (a value folded into the IR)
//!   fails. The same again for the post printed from the IR alone (a RON
//!   post without the source's text), where the settings read when the
//!   post is compiled are listed with why.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use crate::support::{self, blessing, corpus, files, stem};
use postc_backends::Target;

/// Where docs/convert.md's table starts and ends.
const TABLE_START: &str = "<!-- own-dialect table: tests/convert_own_dialect.rs -->";
const TABLE_END: &str = "<!-- end of the own-dialect table -->";

fn posts() -> Vec<(PathBuf, Target)> {
    let mut out = Vec::new();
    for dir in ["posts/cimco", "posts/cimco-styles"] {
        out.extend(files(&corpus().join(dir), "js").into_iter().map(|p| (p, Target::Cimco)));
    }
    out.extend(files(&corpus().join("posts/vectric"), "pp").into_iter().map(|p| (p, Target::Vectric)));
    for dir in ["posts/vcpost", "posts/postp"] {
        out.extend(files(&corpus().join(dir), "VcPost").into_iter().map(|p| (p, Target::VcPost)));
    }
    out
}

/// The lines of `a` and `b` that a line diff shows as removed or added.
fn changed_lines(a: &str, b: &str) -> usize {
    similar::TextDiff::from_lines(a, b).iter_all_changes().filter(|c| c.tag() != similar::ChangeTag::Equal).count()
}

fn converted(path: &Path, target: Target) -> String {
    let post = support::compile_file(path);
    let bytes = postc_backends::convert(&post, target).unwrap_or_else(|e| panic!("{}: {e:?}", path.display()));
    String::from_utf8(bytes).expect("a post is text")
}

#[test]
fn a_post_converted_to_its_own_dialect_changes_the_lines_docs_convert_md_lists() {
    let mut table = String::new();
    table.push_str("| post | lines | lines changed | what changed |\n|---|---|---|---|\n");
    for (path, target) in posts() {
        let source = std::fs::read_to_string(&path).expect("a corpus post");
        let printed = converted(&path, target);
        let changed = changed_lines(&source, &printed);
        let folder = path.parent().and_then(|p| p.file_name()).map(|f| f.to_string_lossy().into_owned());
        let what = match changed {
            1 => "the conversion note added",
            _ if source.contains("POST_BASE") => "printed whole from the IR (`POST_BASE`), in the guides' layout",
            _ => "printed from the IR",
        };
        table.push_str(&format!(
            "| `{}/{}` | {} | {} | {} |\n",
            folder.unwrap_or_default(),
            path.file_name().unwrap_or_default().to_string_lossy(),
            source.lines().count(),
            changed,
            what
        ));
    }
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/convert.md");
    let text = std::fs::read_to_string(&docs).expect("docs/convert.md");
    let (Some(start), Some(end)) = (text.find(TABLE_START), text.find(TABLE_END)) else {
        panic!("docs/convert.md has no own-dialect table between `{TABLE_START}` and `{TABLE_END}`");
    };
    let written = &text[start + TABLE_START.len()..end];
    let want = format!("\n{table}");
    if written != want {
        if blessing() {
            let new = format!("{}{}{}{}", &text[..start], TABLE_START, want, &text[end..]);
            std::fs::write(&docs, new).expect("write docs/convert.md");
            return;
        }
        panic!(
            "docs/convert.md's own-dialect table is not what converting the corpus posts gives:\n{}\n{}",
            support::diff(written.as_bytes(), want.as_bytes()),
            support::bless_hint("convert_own_dialect")
        );
    }
}

/// Fusion posts of `../shared/corpus/fusion/` that convert to Fusion with
/// only the note added, at least (212 posts; the others do not compile:
/// JavaScript postc does not read, or host API it does not run).
const FUSION_AS_WRITTEN_AT_LEAST: usize = 201;

/// Every Fusion post of the corpus that postc compiles converts to `.cps`
/// as its file is written, with the conversion note as its one changed
/// line (a byte order mark stays first), and converting the result again
/// gives the same text (every tenth post, for the test's time: each
/// conversion compiles the post twice).
#[test]
fn fusion_corpus_posts_convert_to_fusion_with_only_the_note_added() {
    let dir = crate::fusion_corpus::shared();
    if !dir.is_dir() {
        support::referee_missing("convert_own_dialect", "../shared/corpus/fusion");
        return;
    }
    let posts = crate::fusion_corpus::posts(&dir);
    let numbered: Vec<(usize, &PathBuf)> = posts.iter().enumerate().collect();
    // Every tenth is converted a second time too.
    let results: Vec<Result<bool, String>> =
        support::in_workers(&numbered, |(i, path)| vec![fusion_as_written(path, i % 10 == 0)]);
    let failures: Vec<String> = results.iter().filter_map(|r| r.as_ref().err().cloned()).collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    let as_written = results.iter().filter(|r| matches!(r, Ok(true))).count();
    assert!(
        as_written >= FUSION_AS_WRITTEN_AT_LEAST,
        "{as_written} Fusion corpus posts convert as written, fewer than {FUSION_AS_WRITTEN_AT_LEAST}"
    );
}

/// A Fusion post converted to Fusion: `Ok(true)` as written, with the
/// note its one changed line (and, `again`, the same text when converted
/// again); `Ok(false)` when postc does not compile the post.
fn fusion_as_written(path: &Path, again: bool) -> Result<bool, String> {
    let Ok(post) = support::compile_warned(path) else { return Ok(false) };
    let source = std::fs::read(path).expect("a corpus post");
    let printed = postc_backends::convert(&post, Target::Fusion).map_err(|e| format!("{}: {e:?}", path.display()))?;
    let (source, printed) = (String::from_utf8_lossy(&source), String::from_utf8_lossy(&printed));
    let changed = changed_lines(&source, &printed);
    let bom_first = !source.starts_with('\u{feff}') || printed.starts_with('\u{feff}');
    if changed != 1 || !bom_first {
        return Err(format!("{}: {changed} lines changed", path.display()));
    }
    if !again {
        return Ok(true);
    }
    // Read back under the source's path, where the files it includes are.
    let mut sources = postc_report::source_map();
    let (again, _) = postc_front_cimco::fusion::compile(path, printed.as_bytes(), &mut sources);
    let twice =
        postc_backends::convert(&again, Target::Fusion).map_err(|e| format!("{}: again: {e:?}", path.display()))?;
    if String::from_utf8_lossy(&twice) != printed {
        return Err(format!("{}: converting the converted post again changes it", path.display()));
    }
    Ok(true)
}

/// `var name = 10;`, `var name = true;` at the top level: the setting's
/// line, its name and its changed value.
fn settings(source: &str) -> Vec<(String, String, String)> {
    let mut out = Vec::new();
    for line in source.lines() {
        let Some(rest) = line.strip_prefix("var ") else { continue };
        let Some((name, value)) = rest.split_once(" = ") else { continue };
        let Some(value) = value.strip_suffix(';') else { continue };
        if !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
            continue;
        }
        let changed = match value {
            "true" => "false".to_string(),
            "false" => "true".to_string(),
            // Text: one more character at its end.
            v if v.len() >= 2 && v.starts_with('"') && v.ends_with('"') && !v[1..v.len() - 1].contains('"') => {
                format!("{}~\"", &v[..v.len() - 1])
            }
            v => match v.parse::<f64>() {
                // A different value of the same kind: 10 -> 7, 0.01 -> 0.02.
                Ok(n) if n.fract() == 0.0 => format!("{}", if n == 0.0 { 1.0 } else { n - 3.0 }),
                Ok(n) => format!("{}", n * 2.0),
                Err(_) => continue,
            },
        };
        out.push((line.to_string(), name.to_string(), format!("var {name} = {changed};")));
    }
    out
}

fn toolpaths(post: &Path) -> Vec<PathBuf> {
    let cimco = corpus().join("toolpaths/cimco");
    if stem(post).contains("lathe") {
        vec![cimco.join("lathe.ron")]
    } else {
        vec![cimco.join("mill.ron"), cimco.join("drill.ron")]
    }
}

/// The programs `text` (a CIMCO post) writes over `toolpaths`, or its error.
fn programs(name: &str, text: &str, toolpaths: &[PathBuf]) -> Vec<Result<Vec<Vec<u8>>, String>> {
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post_bytes(Path::new(name), text.as_bytes(), None, &mut sources);
    if compiled.has_errors() {
        return vec![Err(format!("does not compile: {:?}", compiled.diagnostics))];
    }
    let Some(post) = compiled.post else { return vec![Err("no post".into())] };
    toolpaths.iter().map(|t| support::post_parts(&post, t)).collect()
}

/// The post printed from its IR alone: its RON without the source's text
/// (`written`), converted back.
fn printed_from_the_ir(path: &Path) -> String {
    let mut post = support::compile_file(path);
    post.drop_written();
    let bytes = postc_backends::convert(&post, Target::Cimco).unwrap_or_else(|e| panic!("{}: {e:?}", path.display()));
    String::from_utf8(bytes).expect("a post is text")
}

#[test]
fn settings_of_a_cimco_post_converted_to_cimco_still_work() {
    let mut failures = Vec::new();
    let mut from_ir: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let (mut tried, mut effective) = (0, 0);
    for dir in ["posts/cimco", "posts/cimco-styles"] {
        for path in files(&corpus().join(dir), "js") {
            let source = std::fs::read_to_string(&path).expect("a corpus post");
            let name = path.file_name().unwrap_or_default().to_string_lossy().into_owned();
            let toolpaths = toolpaths(&path);
            let as_converted = converted(&path, Target::Cimco);
            let from_the_ir = printed_from_the_ir(&path);
            let unchanged = programs(&name, &source, &toolpaths);
            for (line, setting, changed) in settings(&source) {
                tried += 1;
                let want = programs(&name, &source.replacen(&line, &changed, 1), &toolpaths);
                if want != unchanged {
                    effective += 1;
                }
                for (form, text) in [("converted", &as_converted), ("printed from the IR", &from_the_ir)] {
                    // The setting as the converted post writes it.
                    let Some(at) = text.lines().find(|l| l.starts_with(&format!("var {setting} = "))) else {
                        if form == "converted" {
                            failures.push(format!("{name}: the converted post has no `var {setting} = ...;`"));
                        } else {
                            from_ir.entry(name.clone()).or_default().push(format!("{setting} (not printed)"));
                        }
                        continue;
                    };
                    let got = programs(&name, &text.replacen(at, &changed, 1), &toolpaths);
                    if got != want {
                        if form == "converted" {
                            failures.push(format!("{name}: `{changed}` changes the source's program, not the converted post's the same way"));
                        } else {
                            from_ir.entry(name.clone()).or_default().push(setting.clone());
                        }
                    }
                }
            }
        }
    }
    eprintln!("{tried} settings changed, {effective} of them change the source's program");
    eprintln!("settings the post printed from the IR alone does not follow:");
    for (post, names) in &from_ir {
        eprintln!("  {post}: {}", names.join(", "));
    }
    assert!(tried >= 100, "only {tried} settings found in the corpus CIMCO posts");
    // Read when the post is compiled, into `createVariable` prefixes the IR
    // holds as text (docs/convert.md, "A post converted to its own dialect").
    let known: BTreeMap<String, Vec<String>> =
        [("fanuc_mill.js".to_string(), vec!["variableDelimeter".to_string()])].into();
    assert_eq!(from_ir, known, "the settings the post printed from the IR alone does not follow changed");
    assert!(
        failures.is_empty(),
        "{} settings do not work in the converted post:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
