//! The command line's conventions: `postc completions bash` loads in bash
//! and completes the subcommands; `postc man DIR` writes a page for the
//! command and each subcommand, and `man` renders every one (under
//! `CI=true` a missing `bash` or `man` fails; `.ci/run` installs man-db);
//! a command that writes files says what it wrote in one line, and `-q`
//! keeps it quiet; long work shows a progress bar on a terminal only (run
//! under `script`'s pseudo-terminal); `-v` says what each step did.

use std::process::Command;

use crate::support::{postc, said};

/// Whether `tool` runs here; under `CI=true` its absence fails the test.
fn have(tool: &str, test: &str) -> bool {
    let found =
        Command::new("sh").args(["-c", &format!("command -v {tool}")]).output().is_ok_and(|o| o.status.success());
    if !found {
        crate::support::referee_missing(test, tool);
    }
    found
}

#[test]
fn bash_completions_load_and_complete_the_subcommands() {
    let o = postc(&["completions", "bash"]);
    assert!(o.status.success(), "{}", said(&o));
    for shell in ["zsh", "fish", "elvish", "powershell"] {
        let other = postc(&["completions", shell]);
        assert!(other.status.success() && !other.stdout.is_empty(), "{shell}: {}", said(&other));
    }
    if !have("bash", "bash_completions_load_and_complete_the_subcommands") {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("postc.bash");
    std::fs::write(&script, &o.stdout).unwrap();
    // Source the script, then ask its function what `postc ve<TAB>` completes to.
    let probe = format!(
        "source '{}' && complete -p postc && COMP_WORDS=(postc ve) COMP_CWORD=1 COMP_LINE='postc ve' COMP_POINT=8 && _postc postc ve postc && printf '%s\\n' \"${{COMPREPLY[@]}}\"",
        script.display()
    );
    let run = Command::new("bash").args(["--norc", "--noprofile", "-c", &probe]).output().unwrap();
    let out = String::from_utf8_lossy(&run.stdout);
    assert!(run.status.success(), "bash could not load the completions: {}{out}", String::from_utf8_lossy(&run.stderr));
    assert!(out.contains("-F _postc postc"), "no completion registered for postc: {out}");
    assert!(out.lines().any(|l| l == "verify"), "`postc ve` does not complete to verify: {out}");
}

#[test]
fn man_pages_render_for_every_subcommand() {
    let dir = tempfile::tempdir().unwrap();
    let o = postc(&["man", &dir.path().display().to_string()]);
    assert!(o.status.success(), "{}", said(&o));
    let mut pages: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    pages.sort();
    for name in [
        "postc.1",
        "postc-post.1",
        "postc-posts.1",
        "postc-check.1",
        "postc-verify.1",
        "postc-toolpath-gen.1",
        "postc-completions.1",
    ] {
        assert!(pages.iter().any(|p| p == name), "no {name} among {pages:?}");
    }
    if !have("man", "man_pages_render_for_every_subcommand") {
        return;
    }
    for page in &pages {
        let path = dir.path().join(page);
        let run =
            Command::new("man").arg("-l").arg(&path).env("MANPAGER", "cat").env("MANWIDTH", "80").output().unwrap();
        let text = String::from_utf8_lossy(&run.stdout);
        let stem = page.trim_end_matches(".1");
        assert!(
            run.status.success() && text.contains("NAME") && text.contains(stem),
            "{page} does not render: {text}{}",
            String::from_utf8_lossy(&run.stderr)
        );
    }
}

#[test]
fn writes_say_what_they_wrote_unless_quiet() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("job.nc");
    let out = out.display().to_string();
    let o = postc(&["post", "corpus/toolpaths/seed_job.ron", "-o", &out]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success() && err.starts_with(&format!("postc: wrote {out} (")), "{}", said(&o));
    assert!(err.contains("blocks") && err.contains("toolpath events"), "{err}");
    let generated = dir.path().join("g.jsonl").display().to_string();
    let o = postc(&["toolpath", "gen", "--pattern", "zigzag", "--moves", "100", "-o", &generated]);
    assert!(String::from_utf8_lossy(&o.stderr).contains("100 zigzag moves"), "{}", said(&o));
    let js = dir.path().join("c.js").display().to_string();
    let o = postc(&["convert", "corpus/posts/vectric/gcode_mm.pp", "--to", "cimco", "--postc-extension", "-o", &js]);
    assert!(String::from_utf8_lossy(&o.stderr).contains("a cimco post"), "{}", said(&o));
    for args in [
        vec!["-q", "post", "corpus/toolpaths/seed_job.ron", "-o", &out],
        vec!["post", "corpus/toolpaths/seed_job.ron", "-o", &out, "--quiet"],
        vec!["toolpath", "gen", "--pattern", "zigzag", "--moves", "100", "-o", &generated, "-q"],
    ] {
        let o = postc(&args);
        assert!(o.status.success() && o.stderr.is_empty(), "{args:?}: {}", said(&o));
    }
}

/// Runs `postc ARGS` under a pseudo-terminal (`script`), as a person at a
/// terminal would; what the terminal showed.
fn on_a_terminal(args: &[&str]) -> String {
    let line = std::iter::once(env!("CARGO_BIN_EXE_postc"))
        .chain(args.iter().copied())
        .map(|a| format!("'{a}'"))
        .collect::<Vec<_>>()
        .join(" ");
    let o = Command::new("script").args(["-qec", &line, "/dev/null"]).output().unwrap();
    assert!(o.status.success(), "{line}: {}", said(&o));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

#[test]
fn long_work_shows_a_progress_bar_on_a_terminal_only() {
    let dir = tempfile::tempdir().unwrap();
    let toolpath = dir.path().join("z.jsonl").display().to_string();
    let program = dir.path().join("z.ngc").display().to_string();
    let o = postc(&["toolpath", "gen", "--pattern", "zigzag", "--moves", "200000", "-o", &toolpath]);
    assert!(o.status.success() && !said(&o).contains('['), "a bar without a terminal: {}", said(&o));
    let o = postc(&["post", &toolpath, "-o", &program, "--no-verify"]);
    assert!(o.status.success(), "{}", said(&o));
    let verify = ["verify", &program, "--toolpath", &toolpath];
    let piped = postc(&verify);
    assert!(piped.status.success() && !said(&piped).contains("verifying"), "{}", said(&piped));
    if !have("script", "long_work_shows_a_progress_bar_on_a_terminal_only") {
        return;
    }
    let shown = on_a_terminal(&verify);
    assert!(shown.contains("verifying [") && shown.contains("MiB"), "no progress bar on a terminal: {shown}");
    let quiet = on_a_terminal(&["-q", "verify", &program, "--toolpath", &toolpath]);
    assert!(!quiet.contains("verifying ["), "-q shows a bar: {quiet}");
}

#[test]
fn verbose_says_what_each_step_did() {
    let o = postc(&["-v", "check", "corpus/posts/vectric/gcode_mm.pp"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success() && err.contains("checked `corpus/posts/vectric/gcode_mm.pp`: 0 diagnostic(s)"), "{err}");
    let o = postc(&["-v", "post", "corpus/toolpaths/seed_job.ron"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success() && err.contains("compiled `<embedded>/gcode_mm.pp`"), "{err}");
    assert!(err.contains("posted 27 toolpath events"), "{err}");
    let o = postc(&["check", "corpus/posts/vectric/gcode_mm.pp"]);
    assert_eq!(String::from_utf8_lossy(&o.stderr), "postc: checked 1 file(s): no problems\n");
    let o = postc(&["-q", "check", "corpus/posts/vectric/gcode_mm.pp"]);
    assert!(o.status.success() && o.stderr.is_empty(), "{}", said(&o));
    let o = postc(&["-q", "-v", "check", "corpus/posts/vectric/gcode_mm.pp"]);
    assert_eq!(o.status.code(), Some(2), "-q and -v together: {}", said(&o));
}

#[test]
fn every_value_of_every_subcommand_has_a_line_of_help() {
    let top = postc(&["--help"]);
    let text = String::from_utf8_lossy(&top.stdout);
    let subcommands: Vec<&str> = text
        .lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .collect();
    assert!(subcommands.len() > 10, "{text}");
    for sub in subcommands {
        let mut args: Vec<&str> = vec![sub];
        if sub == "toolpath" {
            args.push("gen");
        }
        args.push("--help");
        let o = postc(&args);
        let help = String::from_utf8_lossy(&o.stdout);
        assert!(o.status.success(), "{args:?}: {}", said(&o));
        // clap lists values without help as `[possible values: a, b]`, and
        // values with help one a line (`- a: what it is`).
        assert!(!help.contains("[possible values:"), "`postc {}` has values without help:\n{help}", args.join(" "));
    }
}
