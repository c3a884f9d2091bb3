//! `postc posts`: the post library, listed; and the library a name given
//! as `postc post --post NAME` is looked up in (docs/posts.md). The library
//! is the embedded posts, then the post folders: those named on the command
//! line, the `[posts] dirs` of the nearest `postc.toml` (from the current
//! folder up), then `POSTC_POSTS` (a path list, as PATH is). Each post is
//! compiled once to read what it says about itself
//! ([`postc_driver::library`]); a post with errors is listed with its first
//! error, not refused.

use std::path::{Path, PathBuf};

use postc_driver::library::{self, Described, Lookup};
use postc_ir::{Diagnostic, codes};

use super::report;
use super::{Failed, fail};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Post folders to list besides the embedded posts, `[posts] dirs` of postc.toml and POSTC_POSTS.
    #[arg(value_name = "DIR")]
    dirs: Vec<PathBuf>,
    /// How to print the list.
    #[arg(long, value_enum, default_value = "human")]
    format: ListFormat,
}

/// How `postc posts` prints the library.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ListFormat {
    /// A table for people: name, dialect, units, extension, path; a post with errors is followed by its first error.
    Human,
    /// One JSON array of {name, dialect, units, extension, path, embedded, error}; null where a post with errors says nothing.
    Json,
}

/// Where a post of the library is.
#[derive(Debug, Clone)]
pub enum Origin {
    /// In the binary: an index of [`crate::library::EMBEDDED`].
    Embedded(usize),
    File(PathBuf),
}

/// One post of the library.
#[derive(Debug, Clone)]
pub struct Entry {
    pub origin: Origin,
    /// What it says about itself; `None` when it does not compile.
    pub described: Option<Described>,
    /// Its first error, as `CODE: message`, when it does not compile.
    pub error: Option<String>,
}

impl Entry {
    /// The path as listed: `<embedded>/FILE` or the file's path.
    pub fn path(&self) -> String {
        match &self.origin {
            Origin::Embedded(i) => crate::library::EMBEDDED[*i].name.to_string(),
            Origin::File(p) => p.display().to_string(),
        }
    }

    /// The name it is selected by: its own, or its file's stem when it
    /// does not compile.
    pub fn name(&self) -> String {
        match &self.described {
            Some(d) => d.name.clone(),
            None => {
                let path = self.path();
                Path::new(&path).file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or(path)
            }
        }
    }
}

/// Describes one post from its bytes (a Vectric `POST_BASE` is read
/// beside it, as `postc post` reads it).
fn describe(path: &Path, bytes: &[u8]) -> (Option<Described>, Option<String>) {
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post_bytes(path, bytes, None, &mut sources);
    match compiled.post {
        Some(post) if !compiled.has_errors() => (Some(Described::of_file(&post, path, bytes)), None),
        _ => {
            let errors: Vec<&Diagnostic> = compiled.diagnostics.iter().filter(|d| d.is_error()).collect();
            let first = errors.first().map_or_else(
                || "the post does not compile".to_string(),
                |d| {
                    let at = d
                        .primary_span()
                        .and_then(|s| sources.line_column(s.file, s.start))
                        .map_or(String::new(), |(l, c)| format!(" at {l}:{c}"));
                    format!("{}{at}: {}", d.code, d.message)
                },
            );
            let more =
                if errors.len() > 1 { format!(" (and {} more errors)", errors.len() - 1) } else { String::new() };
            (None, Some(format!("{first}{more}")))
        }
    }
}

/// The user's post folders, in order: `extra` (the command line's), the
/// `[posts] dirs` of the nearest `postc.toml`, `POSTC_POSTS`.
fn folders(extra: &[PathBuf]) -> Result<Vec<PathBuf>, Diagnostic> {
    let mut dirs = extra.to_vec();
    if let Ok(cwd) = std::env::current_dir() {
        dirs.extend(postc_lint::config::post_dirs(&postc_report::FsLoader, &cwd.join("postc.toml"))?);
    }
    if let Some(list) = std::env::var_os("POSTC_POSTS") {
        dirs.extend(std::env::split_paths(&list).filter(|p| !p.as_os_str().is_empty()));
    }
    // A folder named twice is listed once, where it first comes.
    let mut seen: Vec<PathBuf> = Vec::new();
    dirs.retain(|d| {
        let key = std::fs::canonicalize(d).unwrap_or_else(|_| d.clone());
        let new = !seen.contains(&key);
        seen.push(key);
        new
    });
    Ok(dirs)
}

/// The posts of one folder, by file name: the files whose extension or
/// content is a post's (toolpaths in RON are left out).
fn folder_posts(dir: &Path) -> Result<Vec<Entry>, Diagnostic> {
    let entries = std::fs::read_dir(dir).map_err(|e| {
        let why = if e.kind() == std::io::ErrorKind::NotFound { "does not exist".to_string() } else { e.to_string() };
        Diagnostic::error(codes::IO001, format!("the post folder `{}` cannot be read: {why}", dir.display()))
            .help("correct `[posts] dirs` in postc.toml, POSTC_POSTS or the folder given")
    })?;
    let mut files: Vec<PathBuf> = entries.flatten().map(|e| e.path()).filter(|p| p.is_file()).collect();
    files.sort();
    let mut posts = Vec::new();
    for path in files {
        let known = postc_driver::dialect_of_extension(&path).is_some();
        if !known || postc_driver::is_toolpath(&path, &postc_report::FsLoader) {
            continue;
        }
        let (described, error) = match std::fs::read(&path) {
            Ok(bytes) => describe(&path, &bytes),
            Err(e) => (None, Some(format!("{}: cannot be read: {e}", codes::IO001.code))),
        };
        posts.push(Entry { origin: Origin::File(path), described, error });
    }
    Ok(posts)
}

/// The whole library: the embedded posts, then each folder's. Folders that
/// cannot be read are returned as diagnostics beside it.
pub fn library(extra: &[PathBuf]) -> Result<(Vec<Entry>, Vec<Diagnostic>), Diagnostic> {
    let mut entries: Vec<Entry> = crate::library::EMBEDDED
        .iter()
        .enumerate()
        .map(|(i, e)| {
            let (described, error) = describe(Path::new(e.name), e.text);
            Entry { origin: Origin::Embedded(i), described, error }
        })
        .collect();
    let mut problems = Vec::new();
    for dir in folders(extra)? {
        match folder_posts(&dir) {
            Ok(posts) => entries.extend(posts),
            Err(d) => problems.push(d),
        }
    }
    Ok((entries, problems))
}

/// The post `--post NAME` names, found in the library; an error with the
/// near names, or with every path when several posts have the name.
pub fn find(wanted: &str) -> Result<Entry, Diagnostic> {
    let (entries, problems) = library(&[])?;
    let names: Vec<String> = entries.iter().map(Entry::name).collect();
    match library::lookup(wanted, &names) {
        Lookup::One(i) => Ok(entries[i].clone()),
        Lookup::Ambiguous(all) => {
            let mut d = Diagnostic::error(codes::IO014, format!("{} posts have the name `{wanted}`", all.len()));
            for i in all {
                d = d.note(format!("`{}`: {}", names[i], entries[i].path()));
            }
            Err(d.help("rename one of them, or give the post's path instead of --post"))
        }
        Lookup::NotFound(near) => {
            let mut d = Diagnostic::error(codes::IO013, format!("no post in the library has the name `{wanted}`"));
            if !near.is_empty() {
                let shown: Vec<String> = near.iter().map(|&i| format!("`{}`", names[i])).collect();
                d = d.help(format!("did you mean {}?", shown.join(" or ")));
            } else {
                d = d.help("`postc posts` lists the library's names");
            }
            for p in problems {
                d = d.note(p.message);
            }
            Err(d)
        }
    }
}

pub fn run(args: Args) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    let (entries, problems) = library(&args.dirs).map_err(|d| fail(&mut sources, d))?;
    match args.format {
        ListFormat::Json => report::out(&json(&entries)),
        ListFormat::Human => report::out(&table(&entries)),
    }
    report::eprint(&mut sources, &problems);
    if problems.is_empty() { Ok(()) } else { Err(Failed) }
}

/// One post as `--format json` gives it, in this order.
#[derive(serde::Serialize)]
struct Row<'a> {
    name: String,
    dialect: Option<&'static str>,
    units: Option<&'static str>,
    extension: Option<&'a str>,
    path: String,
    embedded: bool,
    error: Option<&'a str>,
}

/// The listing as one JSON array.
fn json(entries: &[Entry]) -> String {
    let rows: Vec<Row> = entries
        .iter()
        .map(|e| {
            let d = e.described.as_ref();
            Row {
                name: e.name(),
                dialect: d.map(|d| library::dialect_name(d.dialect)),
                units: d.map(|d| library::units_name(d.units)),
                extension: d.map(|d| d.extension.as_str()),
                path: e.path(),
                embedded: matches!(e.origin, Origin::Embedded(_)),
                error: e.error.as_deref(),
            }
        })
        .collect();
    let mut text = serde_json::to_string_pretty(&rows).unwrap_or_else(|_| "[]".into());
    text.push('\n');
    text
}

/// The listing as a table for people, a post with errors followed by its
/// first error.
fn table(entries: &[Entry]) -> String {
    let rows: Vec<[String; 5]> = entries
        .iter()
        .map(|e| match &e.described {
            Some(d) => [
                e.name(),
                library::dialect_name(d.dialect).to_string(),
                library::units_name(d.units).to_string(),
                if d.extension.is_empty() { "-".to_string() } else { d.extension.clone() },
                e.path(),
            ],
            None => [e.name(), "-".into(), "-".into(), "-".into(), e.path()],
        })
        .collect();
    let header = ["NAME", "DIALECT", "UNITS", "EXT", "PATH"].map(String::from);
    let mut widths = [0usize; 5];
    for row in std::iter::once(&header).chain(&rows) {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let line = |row: &[String; 5]| {
        let cells: Vec<String> = row.iter().zip(widths).map(|(c, w)| format!("{c:<w$}")).collect();
        format!("{}\n", cells.join("  ").trim_end())
    };
    let mut out = line(&header);
    for (row, e) in rows.iter().zip(entries) {
        out.push_str(&line(row));
        if let Some(error) = &e.error {
            out.push_str(&format!("  error: {error}\n"));
        }
    }
    out
}
