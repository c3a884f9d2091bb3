//! Printing diagnostics: rendered for people on standard error, or as one
//! JSON array for tools.

use std::io::IsTerminal;
use std::sync::{Mutex, MutexGuard};

use postc_ir::{Diagnostic, SourceMap};
use postc_report::Render;

/// How `check` prints diagnostics.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// Rendered for people on standard error, with the source lines.
    Human,
    /// One JSON array on standard output: code, severity, message, file, line, column, end.
    Json,
}

/// Diagnostics shown for people per file unless `--max-diagnostics` says
/// otherwise (docs/diagnostics.md); JSON output keeps every one.
pub const DEFAULT_MAX_DIAGNOSTICS: usize = 50;

/// Diagnostics shown and held back per file, over the whole command.
struct Limit {
    max: usize,
    /// File name, diagnostics shown, diagnostics held back; in the order
    /// the files first came.
    files: Vec<(String, usize, usize)>,
}

static LIMIT: Mutex<Limit> = Mutex::new(Limit { max: DEFAULT_MAX_DIAGNOSTICS, files: Vec::new() });

fn limit() -> MutexGuard<'static, Limit> {
    LIMIT.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// How much a command says besides its diagnostics: `-q` (nothing), the
/// default (a summary line after writing files, progress on a terminal),
/// `-v` (also what each step did and how long it took).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Verbosity {
    Quiet = 0,
    Normal = 1,
    Verbose = 2,
}

static VERBOSITY: std::sync::atomic::AtomicU8 = std::sync::atomic::AtomicU8::new(Verbosity::Normal as u8);

/// Sets `-q/--quiet` or `-v/--verbose`.
pub fn set_verbosity(verbosity: Verbosity) {
    VERBOSITY.store(verbosity as u8, std::sync::atomic::Ordering::Relaxed);
}

fn verbosity() -> Verbosity {
    match VERBOSITY.load(std::sync::atomic::Ordering::Relaxed) {
        0 => Verbosity::Quiet,
        1 => Verbosity::Normal,
        _ => Verbosity::Verbose,
    }
}

/// A spinner on standard error that turns on its own (a tick every
/// 120 ms) while a long run goes on, saying `message` until told more;
/// the caller clears it when the run ends. Only when standard error is a
/// terminal and not `-q`.
pub fn spinner(message: &'static str) -> Option<indicatif::ProgressBar> {
    if verbosity() == Verbosity::Quiet || !std::io::stderr().is_terminal() {
        return None;
    }
    let bar = indicatif::ProgressBar::new_spinner();
    bar.set_message(message);
    bar.enable_steady_tick(std::time::Duration::from_millis(120));
    Some(bar)
}

/// What a [`progress`] bar counts.
#[derive(Clone, Copy, Debug)]
pub enum Unit {
    /// Bytes of a file read or written.
    Bytes,
    /// Toolpath moves.
    Moves,
    /// Toolpath events posted.
    Events,
}

/// A progress bar on standard error for work of `total` units, saying
/// `message`: only when standard error is a terminal and not `-q`, so
/// logs and pipes never see one. The caller moves it (`inc`, or
/// `wrap_read` on a reader) and clears it when the work ends.
pub fn progress(total: u64, unit: Unit, message: &'static str) -> Option<indicatif::ProgressBar> {
    if verbosity() == Verbosity::Quiet || !std::io::stderr().is_terminal() {
        return None;
    }
    let counts = match unit {
        Unit::Bytes => "{bytes}/{total_bytes}",
        Unit::Moves => "{human_pos}/{human_len} moves",
        Unit::Events => "{human_pos}/{human_len} events, {per_sec}",
    };
    let template = format!("{{spinner}} {{msg}} [{{bar:30}}] {counts} ({{eta}} left)");
    let style = indicatif::ProgressStyle::with_template(&template)
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
        .progress_chars("=> ");
    let bar = indicatif::ProgressBar::new(total).with_style(style).with_message(message);
    bar.enable_steady_tick(std::time::Duration::from_millis(120));
    Some(bar)
}

/// Prints the one-line summary of what a command wrote (`postc: wrote
/// ...`) on standard error, unless `-q`.
pub fn wrote(what: std::fmt::Arguments) {
    if verbosity() >= Verbosity::Normal {
        eprintln!("postc: wrote {what}");
    }
}

/// Prints a one-line summary of a command that wrote nothing (`postc:
/// checked ...`) on standard error, unless `-q`.
pub fn summary(what: std::fmt::Arguments) {
    if verbosity() >= Verbosity::Normal {
        eprintln!("postc: {what}");
    }
}

/// Says what a step did and how long it took since `started`, under `-v`
/// only.
pub fn step(started: std::time::Instant, what: std::fmt::Arguments) {
    if verbosity() == Verbosity::Verbose {
        eprintln!("postc: {what} ({:.3} s)", started.elapsed().as_secs_f64());
    }
}

/// Sets how many diagnostics are shown per file (`--max-diagnostics`; 0
/// shows all).
pub fn set_max_diagnostics(max: usize) {
    limit().max = if max == 0 { usize::MAX } else { max };
}

/// Prints diagnostics for people on standard error: at most the
/// `--max-diagnostics` number per file (the file of the diagnostic's
/// primary label) over the whole command; [`summarize_held_back`] says how
/// many more there were.
pub fn eprint(sources: &mut SourceMap, diagnostics: &[Diagnostic]) {
    if diagnostics.is_empty() {
        return;
    }
    let shown: Vec<Diagnostic> = {
        let mut limit = limit();
        let max = limit.max;
        diagnostics
            .iter()
            .filter(|d| {
                let file = d.primary_span().map_or("", |s| sources.name(s.file));
                let i = match limit.files.iter().position(|(f, _, _)| f == file) {
                    Some(i) => i,
                    None => {
                        limit.files.push((file.to_string(), 0, 0));
                        limit.files.len() - 1
                    }
                };
                let entry = &mut limit.files[i];
                if entry.1 < max {
                    entry.1 += 1;
                    true
                } else {
                    entry.2 += 1;
                    false
                }
            })
            .cloned()
            .collect()
    };
    if shown.is_empty() {
        return;
    }
    let color = std::io::stderr().is_terminal() && std::env::var_os("NO_COLOR").is_none();
    eprint!("{}", sources.render(&shown, color));
}

/// Says, once, how many diagnostics per file were held back.
pub fn summarize_held_back() {
    let mut limit = limit();
    let max = limit.max;
    for (file, _, held) in &mut limit.files {
        if *held > 0 {
            let of = if file.is_empty() { String::new() } else { format!(" about `{file}`") };
            eprintln!(
                "postc: {held} more diagnostic(s){of} not shown (the first {max} were); `--max-diagnostics 0` shows all"
            );
            *held = 0;
        }
    }
}

/// The JSON array of `check --format json`.
pub fn json(sources: &SourceMap, diagnostics: &[(String, Diagnostic)]) -> String {
    let items: Vec<_> = diagnostics.iter().map(|(file, d)| sources.to_json(d, file)).collect();
    serde_json::to_string_pretty(&items).unwrap_or_else(|_| "[]".into())
}

/// Writes to standard output; a reader that went away (`| head`) ends the
/// output quietly instead of a panic.
pub fn out(text: &str) {
    use std::io::Write;
    let mut stdout = std::io::stdout().lock();
    let _ = stdout.write_all(text.as_bytes()).and_then(|()| stdout.flush());
}
