//! The built `postc` keeps the files it is given and the files it writes
//! safe (docs/outputs.md): an output that is an input is refused before
//! anything is read or written; outputs get the mode the shell gives a new
//! file under the same umask, or keep the mode of the file they replace;
//! a signal leaves no temporary file; a command that fails writes none of
//! its outputs. Bad input is reported as a professional tool reports it:
//! a bounded number of diagnostics per file, long lines cut, control
//! characters escaped, messages that say what is wrong with this input.
//! Dates and times follow the README's reproducibility rule.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn postc() -> Command {
    Command::new(env!("CARGO_BIN_EXE_postc"))
}

fn corpus(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus").join(path)
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// A folder with a post (`job.pp`) and a toolpath (`job.ron`) in it.
fn job_dir() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(corpus("posts/vectric/gcode_mm.pp"), dir.path().join("job.pp")).unwrap();
    std::fs::copy(corpus("toolpaths/standard.ron"), dir.path().join("job.ron")).unwrap();
    dir
}

/// The names in a folder, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    names
}

#[test]
fn an_output_that_is_an_input_is_refused_and_nothing_changes() {
    let dir = job_dir();
    let d = dir.path();
    #[cfg(unix)]
    std::os::unix::fs::symlink("job.pp", d.join("link.nc")).unwrap();
    let before: Vec<Vec<u8>> = ["job.pp", "job.ron"].iter().map(|f| std::fs::read(d.join(f)).unwrap()).collect();
    let listing = names(d);
    let cases: &[&[&str]] = &[
        &["post", "job.pp", "job.ron", "-o", "job.ron"],
        &["post", "job.pp", "job.ron", "-o", "job.pp"],
        &["post", "job.pp", "job.ron", "-o", "./job.pp"],
        &["post", "job.pp", "job.ron", "-o", "out.nc", "--trace", "job.pp"],
        &["post", "job.pp", "job.ron", "-o", "out.nc", "--trace", "out.nc"],
        &["convert", "job.pp", "--to", "cimco", "-o", "job.pp"],
        #[cfg(unix)]
        &["post", "job.pp", "job.ron", "-o", "link.nc"],
    ];
    for args in cases {
        let out = postc().current_dir(d).args(*args).output().unwrap();
        assert_eq!(out.status.code(), Some(1), "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains("IO012"), "{args:?}: {}", stderr(&out));
        let after: Vec<Vec<u8>> = ["job.pp", "job.ron"].iter().map(|f| std::fs::read(d.join(f)).unwrap()).collect();
        assert!(after == before, "{args:?} changed an input");
        assert_eq!(names(d), listing, "{args:?} left a file");
    }
}

/// The mode `sh` gives a new file under `umask` (the outside reference),
/// and the mode of `file`.
#[cfg(unix)]
fn mode(file: &Path) -> u32 {
    use std::os::unix::fs::PermissionsExt;
    std::fs::metadata(file).unwrap().permissions().mode() & 0o7777
}

#[cfg(unix)]
fn under_umask(umask: &str, dir: &Path, args: &[&str]) -> Output {
    let mut script = format!("umask {umask}; exec \"$0\"");
    for i in 1..=args.len() {
        script.push_str(&format!(" \"${i}\""));
    }
    Command::new("sh")
        .current_dir(dir)
        .arg("-c")
        .arg(script)
        .arg(env!("CARGO_BIN_EXE_postc"))
        .args(args)
        .output()
        .unwrap()
}

#[cfg(unix)]
#[test]
fn outputs_get_the_umask_mode_or_keep_the_replaced_files_mode() {
    use std::os::unix::fs::PermissionsExt;
    let dir = job_dir();
    let d = dir.path();
    for umask in ["022", "027"] {
        let probe = d.join(format!("probe-{umask}"));
        let made =
            Command::new("sh").current_dir(d).arg("-c").arg(format!("umask {umask}; : > probe-{umask}")).status();
        assert!(made.unwrap().success());
        let expected = mode(&probe);
        let runs: &[&[&str]] = &[
            &["post", "job.pp", "job.ron", "-o", "new.nc", "--trace", "new.jsonl"],
            &["convert", "job.pp", "--to", "cimco", "--postc-extension", "-o", "new.js"],
            &["toolpath", "gen", "--moves", "10", "-o", "new.ron"],
        ];
        for args in runs {
            let out = under_umask(umask, d, args);
            assert!(out.status.success(), "{args:?}: {}", stderr(&out));
        }
        for file in ["new.nc", "new.jsonl", "new.js", "new.ron"] {
            assert_eq!(mode(&d.join(file)), expected, "{file} under umask {umask}");
            std::fs::remove_file(d.join(file)).unwrap();
        }
    }
    // A file that is replaced keeps its mode, whatever the umask.
    let old = d.join("old.nc");
    std::fs::write(&old, "old").unwrap();
    std::fs::set_permissions(&old, std::fs::Permissions::from_mode(0o604)).unwrap();
    let out = under_umask("077", d, &["post", "job.pp", "job.ron", "-o", "old.nc"]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(mode(&old), 0o604);
    assert_ne!(std::fs::read(&old).unwrap(), b"old");
}

#[test]
fn a_failed_trace_writes_no_program() {
    let dir = job_dir();
    let d = dir.path();
    let out = postc()
        .current_dir(d)
        .args(["post", "job.pp", "job.ron", "-o", "tr.nc", "--trace", "no/such/t.jsonl"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(stderr(&out).contains("no/such"), "{}", stderr(&out));
    assert_eq!(names(d), ["job.pp", "job.ron"]);
    // Both outputs appear together when the run succeeds.
    let out = postc()
        .current_dir(d)
        .args(["post", "job.pp", "job.ron", "-o", "tr.nc", "--trace", "tr.jsonl"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(names(d), ["job.pp", "job.ron", "tr.jsonl", "tr.nc"]);
}

/// Waits until a `.postc-*.part` file is in `dir`, or the child ends.
#[cfg(unix)]
fn wait_for_part(dir: &Path, child: &mut std::process::Child) -> bool {
    let start = std::time::Instant::now();
    while start.elapsed() < std::time::Duration::from_secs(120) {
        if names(dir).iter().any(|n| n.starts_with(".postc-") && n.ends_with(".part")) {
            return true;
        }
        if child.try_wait().unwrap().is_some() {
            return false;
        }
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    false
}

#[cfg(unix)]
fn signal(child: &std::process::Child, name: &str) {
    let sent = Command::new("kill").arg(format!("-{name}")).arg(child.id().to_string()).status().unwrap();
    assert!(sent.success());
}

#[cfg(unix)]
#[test]
fn a_signal_removes_the_temporary_files() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // `toolpath gen` of many moves, ended by SIGTERM.
    let mut child =
        postc().current_dir(d).args(["toolpath", "gen", "--moves", "50000000", "-o", "big.ron"]).spawn().unwrap();
    assert!(wait_for_part(d, &mut child), "no temporary file appeared");
    signal(&child, "TERM");
    assert_eq!(child.wait().unwrap().code(), Some(143));
    assert!(names(d).is_empty(), "{:?}", names(d));
    // `post -o` of a long toolpath, ended by SIGINT.
    let made = postc().current_dir(d).args(["toolpath", "gen", "--moves", "400000", "-o", "long.jsonl"]).output();
    assert!(made.unwrap().status.success());
    let post = corpus("posts/vectric/gcode_mm.pp");
    let mut child = postc()
        .current_dir(d)
        .arg("post")
        .arg(&post)
        .args(["long.jsonl", "-o", "long.nc", "--trace", "long.trace.jsonl"])
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    assert!(wait_for_part(d, &mut child), "no temporary file appeared");
    signal(&child, "INT");
    assert_eq!(child.wait().unwrap().code(), Some(130));
    assert_eq!(names(d), ["long.jsonl"]);
}

#[test]
fn impossible_sizes_are_refused_up_front() {
    let dir = tempfile::tempdir().unwrap();
    let mut child = postc()
        .current_dir(dir.path())
        .args(["toolpath", "gen", "--moves", "18446744073709551615", "-o", "huge.ron"])
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > std::time::Duration::from_secs(10) {
            child.kill().unwrap();
            child.wait().unwrap();
            panic!("`toolpath gen --moves 18446744073709551615` was still running after 10 s");
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    };
    let mut text = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut text).unwrap();
    assert!(!status.success());
    assert!(text.contains("10000000000"), "{text}");
    assert!(names(dir.path()).is_empty());
}

/// A Vectric post with `n` lines naming sections that do not exist.
fn flood_post(n: usize) -> String {
    let mut text = String::from("POST_NAME = \"flood\"\nUNITS = \"MM\"\n");
    for i in 0..n {
        text.push_str(&format!("BEGIN NOSUCH{i}\n"));
    }
    text
}

fn json_count(out: &Output) -> usize {
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    v.as_array().unwrap().len()
}

#[test]
fn human_output_stops_after_the_limit_and_json_keeps_every_diagnostic() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("flood.pp"), flood_post(10_000)).unwrap();
    let human = postc().current_dir(d).args(["check", "flood.pp"]).output().unwrap();
    let text = stderr(&human);
    assert_eq!(text.matches("[PP017]").count(), 50, "the default is 50 per file");
    assert!(text.contains("9950 more diagnostic(s) about `flood.pp` not shown"), "{}", &text[text.len() - 400..]);
    assert!(text.len() < 40_000, "{} bytes", text.len());
    let more = postc().current_dir(d).args(["check", "flood.pp", "--max-diagnostics", "3"]).output().unwrap();
    assert_eq!(stderr(&more).matches("[PP017]").count(), 3);
    let all = postc().current_dir(d).args(["check", "flood.pp", "--max-diagnostics", "0"]).output().unwrap();
    assert_eq!(stderr(&all).matches("[PP017]").count(), 10_000);
    let json = postc().current_dir(d).args(["check", "flood.pp", "--format", "json"]).output().unwrap();
    assert_eq!(json_count(&json), 10_000);
}

#[test]
fn vcpost_counts_agree() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mut text = String::new();
    for i in 0..2000 {
        text.push_str(&format!("Sub S{i}\n  Out \"<X\"\nEnd Sub\n"));
    }
    std::fs::write(d.join("flood.VcPost"), text).unwrap();
    let json = postc().current_dir(d).args(["check", "flood.VcPost", "--format", "json"]).output().unwrap();
    let listed = json_count(&json);
    assert_eq!(listed, 2000, "one problem per Sub");
    let human = postc().current_dir(d).args(["check", "flood.VcPost"]).output().unwrap();
    let text = stderr(&human);
    assert!(text.contains(&format!("{listed} error(s)")), "{}", &text[text.len() - 400..]);
    assert!(text.contains(&format!("{} more diagnostic(s)", listed - 50)), "{}", &text[text.len() - 400..]);
}

#[test]
fn long_lines_are_cut_and_control_characters_escaped() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // One 5 MB line whose diagnostic spans all of it.
    std::fs::write(d.join("long.js"), format!("var x = \"{}\n", "a".repeat(5_000_000))).unwrap();
    let out = postc().current_dir(d).args(["check", "long.js"]).output().unwrap();
    let text = stderr(&out);
    assert!(text.contains("JS002") && text.contains('…'), "{text}");
    assert!(text.len() < 2_000, "{} bytes", text.len());
    // Bytes of every value, ESC and BEL among them, as a CIMCO post.
    let mut bytes = Vec::new();
    let mut x: u32 = 12345;
    for _ in 0..100_000 {
        x = x.wrapping_mul(1_103_515_245).wrapping_add(12_345);
        bytes.push((x >> 16) as u8);
    }
    bytes.extend_from_slice(b"\x1b[2J\x07");
    std::fs::write(d.join("noise.js"), &bytes).unwrap();
    let out = postc().current_dir(d).args(["check", "noise.js"]).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(!out.stderr.iter().any(|&b| b < 0x20 && b != b'\n'), "raw control bytes on stderr");
    assert!(out.stderr.len() < 100_000, "{} bytes", out.stderr.len());
    assert!(stderr(&out).contains('␛'), "ESC shown as its control picture");
}

#[test]
fn messages_say_what_is_wrong_with_this_input() {
    let dir = job_dir();
    let d = dir.path();
    // A CL file with a NaN coordinate is CL data with a bad value, not a part program.
    std::fs::write(d.join("nan.apt"), "PARTNO/NAN\nUNITS/MM\nGOTO/NaN,5,0\nFINI\n").unwrap();
    let out = postc().current_dir(d).args(["check", "nan.apt"]).output().unwrap();
    let text = stderr(&out);
    assert!(text.contains("`NaN` is not a number") && !text.contains("part program"), "{text}");
    // The two arguments of `post` swapped.
    let out = postc().current_dir(d).args(["post", "job.ron", "job.pp"]).output().unwrap();
    let text = stderr(&out);
    assert!(text.contains("the post comes first") && text.contains("postc post job.pp job.ron"), "{text}");
    let out = postc().current_dir(d).args(["inspect", "job.ron"]).output().unwrap();
    assert!(stderr(&out).contains("is a toolpath (postc's native events), not a post"), "{}", stderr(&out));
    // A loop of symbolic links.
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink("b.pp", d.join("a.pp")).unwrap();
        std::os::unix::fs::symlink("a.pp", d.join("b.pp")).unwrap();
        let out = postc().current_dir(d).args(["check", "a.pp"]).output().unwrap();
        assert!(stderr(&out).contains("loop of symbolic links"), "{}", stderr(&out));
        std::os::unix::fs::symlink("gone.pp", d.join("dangling.pp")).unwrap();
        let out = postc().current_dir(d).args(["check", "dangling.pp"]).output().unwrap();
        assert!(stderr(&out).contains("a symbolic link to `gone.pp`, which does not exist"), "{}", stderr(&out));
    }
}

/// The `( made by ... on DATE TIME )` line gcode_mm.pp writes.
fn made_line(d: &Path, extra: &[&str], epoch: Option<&str>) -> String {
    let mut cmd = postc();
    cmd.current_dir(d).args(["post", "job.pp", "nodate.ron"]).args(extra).env_remove("SOURCE_DATE_EPOCH");
    if let Some(e) = epoch {
        cmd.env("SOURCE_DATE_EPOCH", e);
    }
    let out = cmd.output().unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    String::from_utf8_lossy(&out.stdout).lines().find(|l| l.contains("made by")).unwrap().to_string()
}

#[test]
fn date_and_time_follow_the_reproducibility_rule() {
    let dir = job_dir();
    let d = dir.path();
    // The standard job without its date and time.
    let text = std::fs::read_to_string(d.join("job.ron")).unwrap();
    let text = text.replace("date:\"2026-01-01\",time:\"12:00:00\",", "");
    assert!(!text.contains("time:\""));
    std::fs::write(d.join("nodate.ron"), text).unwrap();
    // --set date alone: the time is the start of that day, not the clock's.
    assert!(made_line(d, &["--set", "date=2026-01-01"], None).ends_with("on 2026-01-01 00:00 )"));
    assert!(
        made_line(d, &["--set", "date=2026-01-01", "--set", "time=07:30"], None).ends_with("on 2026-01-01 07:30 )")
    );
    // SOURCE_DATE_EPOCH (1767323096 is 2026-01-02 03:04:56 UTC, by `date -u -d @1767323096`).
    // A Vectric post prints a date it is not given in VCarve's long form
    // (docs/vectric.md, decision 44).
    assert!(made_line(d, &[], Some("1767323096")).ends_with("on Friday, January 2, 2026 03:04 )"));
    // A job's date without a time: the same.
    let dated = std::fs::read_to_string(d.join("job.ron")).unwrap().replace("time:\"12:00:00\",", "");
    std::fs::write(d.join("nodate.ron"), dated).unwrap();
    assert!(made_line(d, &[], None).ends_with("on 2026-01-01 00:00 )"));
    // --set wins over the job and over SOURCE_DATE_EPOCH.
    assert!(made_line(d, &["--set", "date=2027-05-06"], Some("1767323096")).ends_with("on 2027-05-06 00:00 )"));
}

/// A post that stops while it handles an event says which record of the
/// toolpath it stopped at, beside the post's own line: a Fusion post's
/// "Spindle speed out of range." over a CL file that gives no SPINDL left
/// the user to find the record.
#[test]
fn a_post_that_stops_names_the_toolpath_record_it_stopped_at() {
    let dir = tempfile::tempdir().unwrap();
    let post = dir.path().join("stops.js");
    std::fs::write(
        &post,
        "function onLinear(x, y, z, movement) {\n    if (z < 0) { throw new Error(\"too deep\"); }\n    return \"\";\n}\n",
    )
    .unwrap();
    let toolpath = dir.path().join("job.ron");
    std::fs::write(
        &toolpath,
        "Job(units: Mm)\nTool(number: 1, diameter: 6)\nToolpathStart(name: \"Pocket\")\nRapid(x: 0, y: 0, z: 5)\nFeed(x: 0, y: 0, z: -1, feed: 100)\nEnd\n",
    )
    .unwrap();
    let out = postc().arg("post").arg(&post).arg(&toolpath).arg("-o").arg(dir.path().join("job.nc")).output().unwrap();
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("too deep") && err.contains("stops.js:2:"), "{err}");
    assert!(err.contains("job.ron:5:1") && err.contains("while posting this toolpath record"), "{err}");
}

/// `-o` naming a pipe (a FIFO a sender reads from) writes the program
/// into the pipe and leaves the pipe a pipe; it was replaced by a regular
/// file holding the program, which the reader never saw.
#[cfg(unix)]
#[test]
fn a_program_written_to_a_pipe_goes_through_it_and_the_pipe_stays() {
    use std::os::unix::fs::FileTypeExt;
    let dir = job_dir();
    let fifo = dir.path().join("sender.fifo");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let (sent, got) = std::sync::mpsc::channel();
    let reading = fifo.clone();
    std::thread::spawn(move || {
        let _ = sent.send(std::fs::read(&reading));
    });
    let out =
        postc().current_dir(dir.path()).args(["post", "job.pp", "job.ron", "-o", "sender.fifo"]).output().unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(std::fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo(), "the pipe was replaced by a file");
    let read = got.recv_timeout(std::time::Duration::from_secs(20)).expect("nothing was written into the pipe");
    std::fs::create_dir(dir.path().join("plain")).unwrap();
    let plain = postc()
        .current_dir(dir.path())
        .args(["post", "job.pp", "job.ron", "-o", "plain/sender.fifo"])
        .output()
        .unwrap();
    assert!(plain.status.success(), "{}", stderr(&plain));
    assert_eq!(read.unwrap(), std::fs::read(dir.path().join("plain/sender.fifo")).unwrap());
    assert_eq!(names(dir.path()), ["job.pp", "job.ron", "plain", "sender.fifo"]);
}

/// A device that cannot take the program (`/dev/full`: no space left)
/// fails the command with the reason, and the device stays a device.
#[cfg(target_os = "linux")]
#[test]
fn a_device_that_cannot_take_the_program_fails_the_command() {
    use std::os::unix::fs::FileTypeExt;
    let full = Path::new("/dev/full");
    let is_device = |p: &Path| std::fs::symlink_metadata(p).is_ok_and(|m| m.file_type().is_char_device());
    assert!(is_device(full), "this machine has no /dev/full");
    let dir = job_dir();
    let out = postc().current_dir(dir.path()).args(["post", "job.pp", "job.ron", "-o", "/dev/full"]).output().unwrap();
    assert!(is_device(full), "/dev/full was replaced by a file");
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(stderr(&out).contains("IO003") && stderr(&out).contains("No space left"), "{}", stderr(&out));
    let out = postc().current_dir(dir.path()).args(["post", "job.pp", "job.ron", "-o", "/dev/null"]).output().unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(is_device(Path::new("/dev/null")), "/dev/null was replaced by a file");
}

/// `-o` naming a symbolic link writes the file the link names (a
/// machine's program folder linked into a project) and keeps the link;
/// a link to a file not there yet makes that file.
#[cfg(unix)]
#[test]
fn a_program_written_through_a_link_lands_where_the_link_points() {
    let dir = job_dir();
    std::fs::create_dir(dir.path().join("machine")).unwrap();
    std::fs::write(dir.path().join("machine/prog.nc"), "old\n").unwrap();
    std::os::unix::fs::symlink("machine/prog.nc", dir.path().join("prog.nc")).unwrap();
    std::os::unix::fs::symlink("machine/next.nc", dir.path().join("next.nc")).unwrap();
    for name in ["prog.nc", "next.nc"] {
        let out = postc().current_dir(dir.path()).args(["post", "job.pp", "job.ron", "-o", name]).output().unwrap();
        assert!(out.status.success(), "{}", stderr(&out));
        let link = dir.path().join(name);
        assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "{name}: the link was replaced");
        let written = std::fs::read_to_string(dir.path().join("machine").join(name)).unwrap();
        assert!(written.starts_with("(") && written.contains("G1"), "{name}: {written}");
    }
    assert_eq!(names(&dir.path().join("machine")), ["next.nc", "prog.nc"]);
}

/// `--set tolerance=MM` cuts arcs at that tolerance and verify judges the
/// chords by it: at 0.05 mm verify refused every chord of
/// `gcode_noarcs_mm.pp` (VF014 against its own 0.01 mm). A tolerance no
/// program can print, or one that is no longer the arc's shape, is refused.
#[test]
fn a_set_tolerance_is_the_one_the_chords_are_judged_by() {
    let dir = job_dir();
    std::fs::copy(corpus("posts/vectric/gcode_noarcs_mm.pp"), dir.path().join("noarcs.pp")).unwrap();
    let post = |tolerance: &str, out: &str| {
        let set = format!("tolerance={tolerance}");
        postc()
            .current_dir(dir.path())
            .args(["post", "noarcs.pp", "job.ron", "--set", &set, "-o", out])
            .output()
            .unwrap()
    };
    let lines = |out: &str| std::fs::read_to_string(dir.path().join(out)).unwrap().lines().count();
    let fine = post("0.001", "fine.nc");
    assert!(fine.status.success(), "{}", stderr(&fine));
    for coarse in ["0.05", "1"] {
        let out = post(coarse, "coarse.nc");
        assert!(out.status.success(), "tolerance {coarse}: {}", stderr(&out));
        assert!(!stderr(&out).contains("VF014"), "{}", stderr(&out));
        assert!(lines("coarse.nc") < lines("fine.nc"));
    }
    for refused in ["0", "-1", "0.00001", "1.5", "inf", "NaN", "abc"] {
        let out = post(refused, "refused.nc");
        assert_eq!(out.status.code(), Some(1), "{refused}");
        assert!(stderr(&out).contains("IO007") && stderr(&out).contains("0.0001 to 1"), "{refused}: {}", stderr(&out));
    }
    assert!(!dir.path().join("refused.nc").exists());
}
