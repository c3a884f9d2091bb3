//! The command line's conventions: `postc completions bash` loads in bash
//! and completes the subcommands; `postc man DIR` writes a page for the
//! command and each subcommand, and `man` renders every one (under
//! `CI=true` a missing `bash` or `man` fails; `.ci/run` installs man-db);
//! a command that writes files says what it wrote in one line, and `-q`
//! keeps it quiet.

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
    let o = postc(&["convert", "corpus/posts/vectric/gcode_mm.pp", "--to", "cimco", "-o", &js]);
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
