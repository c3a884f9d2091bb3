//! `--warn`, `--deny`, `--allow` and `postc.toml` change the severity of
//! warnings per code, prefix or `all` on `postc check` and `postc post`;
//! `postc explain CODE` prints a code's documentation.

use std::path::Path;
use std::process::{Command, Output};

/// A post that compiles with one warning: PP027, no UNITS statement.
const WARNS: &str = "POST_NAME = \"warns\"\nFILE_EXTENSION = \"tap\"\n\
VAR X_POSITION = [X|A|X|1.3]\nVAR Y_POSITION = [Y|A|Y|1.3]\nVAR Z_POSITION = [Z|A|Z|1.3]\n\
VAR FEED_RATE = [F|C|F|1.0]\nbegin HEADER\n\"G90\"\nbegin RAPID_MOVE\n\"G0 [X] [Y] [Z]\"\n\
begin FEED_MOVE\n\"G1 [X] [Y] [Z] [F]\"\nbegin FOOTER\n\"M30\"\n";

fn postc(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_postc")).current_dir(dir).args(args).output().unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A folder `post/` holding the warning post, inside a temporary folder.
fn setup() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("post")).unwrap();
    std::fs::write(dir.path().join("post/w.pp"), WARNS).unwrap();
    dir
}

fn toolpath() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus/toolpaths/arcs_mm.ron").display().to_string()
}

#[test]
fn check_warns_by_default_and_deny_makes_it_fail() {
    let dir = setup();
    let plain = postc(dir.path(), &["check", "post/w.pp"]);
    assert!(plain.status.success(), "{}", stderr(&plain));
    assert!(stderr(&plain).contains("warning[PP027]"));

    for selector in ["PP027", "PP", "all", "pp027"] {
        let denied = postc(dir.path(), &["check", "--deny", selector, "post/w.pp"]);
        assert_eq!(denied.status.code(), Some(1), "--deny {selector}: {}", stderr(&denied));
        assert!(stderr(&denied).contains("error[PP027]"), "{}", stderr(&denied));
    }
    // A more specific rule wins over a broader one.
    let warned = postc(dir.path(), &["check", "--deny", "all", "--warn", "PP027", "post/w.pp"]);
    assert!(warned.status.success(), "{}", stderr(&warned));
    assert!(stderr(&warned).contains("warning[PP027]"));
}

#[test]
fn allow_hides_a_warning() {
    let dir = setup();
    let allowed = postc(dir.path(), &["check", "--allow", "PP027", "post/w.pp"]);
    assert!(allowed.status.success());
    assert!(!stderr(&allowed).contains("PP027"), "{}", stderr(&allowed));
    let json = postc(dir.path(), &["check", "--allow", "PP", "--format", "json", "post/w.pp"]);
    assert_eq!(String::from_utf8_lossy(&json.stdout).trim(), "[]");
}

#[test]
fn an_unknown_code_is_a_bad_command_line() {
    let dir = setup();
    let bad = postc(dir.path(), &["check", "--deny", "PP999", "post/w.pp"]);
    assert_eq!(bad.status.code(), Some(1));
    assert!(stderr(&bad).contains("`PP999` is not a diagnostic code"), "{}", stderr(&bad));
}

#[test]
fn post_writes_nothing_when_a_warning_is_denied() {
    let dir = setup();
    let tp = toolpath();
    let ok = postc(dir.path(), &["post", "post/w.pp", &tp, "-o", "out.tap"]);
    assert!(ok.status.success(), "{}", stderr(&ok));
    assert!(dir.path().join("out.tap").exists());
    std::fs::remove_file(dir.path().join("out.tap")).unwrap();

    let denied = postc(dir.path(), &["post", "--deny", "PP027", "post/w.pp", &tp, "-o", "out.tap"]);
    assert_eq!(denied.status.code(), Some(1), "{}", stderr(&denied));
    assert!(stderr(&denied).contains("error[PP027]"));
    assert!(!dir.path().join("out.tap").exists());

    let to_stdout = postc(dir.path(), &["post", "--deny", "PP027", "post/w.pp", &tp]);
    assert_eq!(to_stdout.status.code(), Some(1));
    assert!(to_stdout.stdout.is_empty());

    let allowed = postc(dir.path(), &["post", "--allow", "PP027", "post/w.pp", &tp]);
    assert!(allowed.status.success());
    assert!(!stderr(&allowed).contains("PP027"));
    assert!(!allowed.stdout.is_empty());
}

#[test]
fn postc_toml_above_the_post_sets_levels_and_flags_win() {
    let dir = setup();
    let tp = toolpath();
    std::fs::write(dir.path().join("postc.toml"), "[diagnostics]\ndeny = [\"PP027\"]\n").unwrap();
    let checked = postc(dir.path(), &["check", "post/w.pp"]);
    assert_eq!(checked.status.code(), Some(1), "{}", stderr(&checked));
    assert!(stderr(&checked).contains("error[PP027]"));
    let posted = postc(dir.path(), &["post", "post/w.pp", &tp, "-o", "out.tap"]);
    assert_eq!(posted.status.code(), Some(1));
    assert!(!dir.path().join("out.tap").exists());

    // The command line wins over the file.
    let warned = postc(dir.path(), &["check", "--warn", "PP027", "post/w.pp"]);
    assert!(warned.status.success(), "{}", stderr(&warned));
    let allowed = postc(dir.path(), &["check", "--allow", "PP027", "post/w.pp"]);
    assert!(allowed.status.success());
    assert!(!stderr(&allowed).contains("PP027"));

    // The nearest file wins: one in the post's own folder.
    std::fs::write(dir.path().join("post/postc.toml"), "[diagnostics]\nallow = [\"all\"]\n").unwrap();
    let nearest = postc(dir.path(), &["check", "post/w.pp"]);
    assert!(nearest.status.success(), "{}", stderr(&nearest));
    assert!(!stderr(&nearest).contains("PP027"));

    // A file that does not read, or names an unknown code, is an error.
    std::fs::write(dir.path().join("post/postc.toml"), "[diagnostics]\ndeny = [\"PP999\"]\n").unwrap();
    let bad = postc(dir.path(), &["check", "post/w.pp"]);
    assert_eq!(bad.status.code(), Some(1));
    assert!(stderr(&bad).contains("PP999"), "{}", stderr(&bad));
}

#[test]
fn explain_prints_a_code_and_refuses_an_unknown_one() {
    let dir = setup();
    let known = postc(dir.path(), &["explain", "PP027"]);
    assert!(known.status.success());
    let text = String::from_utf8_lossy(&known.stdout);
    assert!(text.starts_with("PP027: no `UNITS` statement"), "{text}");
    assert!(text.contains("severity: warning"), "{text}");

    let unknown = postc(dir.path(), &["explain", "PQ027"]);
    assert_eq!(unknown.status.code(), Some(1));
    assert!(stderr(&unknown).contains("did you mean PP027?"), "{}", stderr(&unknown));
    let not_a_code = postc(dir.path(), &["explain", "hello"]);
    assert_eq!(not_a_code.status.code(), Some(1));
    assert!(stderr(&not_a_code).contains("is not a diagnostic code"));
}

#[test]
fn a_denied_runtime_warning_writes_no_program() {
    let dir = setup();
    // The post has no DWELL_MOVE section: drilling with dwells warns RT010 while posting.
    let tp = Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus/toolpaths/drill_mm.ron").display().to_string();
    let warned = postc(dir.path(), &["post", "--allow", "PP027", "post/w.pp", &tp, "-o", "out.tap"]);
    assert!(warned.status.success(), "{}", stderr(&warned));
    assert!(stderr(&warned).contains("warning[RT010]"), "{}", stderr(&warned));
    assert!(dir.path().join("out.tap").exists());

    // The denied run writes nothing: the file there before is left as it was.
    std::fs::write(dir.path().join("out.tap"), "before").unwrap();
    let denied = postc(dir.path(), &["post", "--allow", "PP027", "--deny", "RT", "post/w.pp", &tp, "-o", "out.tap"]);
    assert_eq!(denied.status.code(), Some(1), "{}", stderr(&denied));
    assert!(stderr(&denied).contains("error[RT010]"), "{}", stderr(&denied));
    assert_eq!(std::fs::read(dir.path().join("out.tap")).unwrap(), b"before");
    std::fs::remove_file(dir.path().join("out.tap")).unwrap();
    let denied = postc(dir.path(), &["post", "--allow", "PP027", "--deny", "RT", "post/w.pp", &tp, "-o", "out.tap"]);
    assert_eq!(denied.status.code(), Some(1), "{}", stderr(&denied));
    assert!(!dir.path().join("out.tap").exists());
}
