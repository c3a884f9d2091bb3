//! The workbench's JSON API (docs/workbench.md, "API"): each endpoint
//! takes one JSON object and answers one, calling the library crates as
//! the commands do — `postc_lsp::compile_checked` for diagnostics,
//! `postc_lsp::analysis` for hover and quick fixes, the runtime with a
//! trace sink for the program and its trace, `postc_verify::plot` for the
//! findings and the backplot, `postc_backends` for conversion, and
//! [`super::super::outputs::write_whole`] for saving. Positions in the
//! editor's text are UTF-16 offsets (what the browser's editor counts).

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::rc::Rc;

use postc_ir::{Diagnostic, Dialect, EventSource, Severity, SourceMap, Span};
use postc_reader_synthetic::{PATTERNS, Synthetic};
use postc_runtime::{Finished, Output};

use crate::cli::stored;
use postc_verify::{Controller, Settings};
use serde::Deserialize;
use serde_json::{Value, json};

use super::roots::Access;
use super::{Reply, State};

/// Most moves a generated toolpath may have in the workbench.
pub const MAX_PATTERN_MOVES: u64 = 2_000_000;
/// Most NC lines whose trace is sent with a program.
pub const TRACE_LINES: usize = 1_000_000;
/// The largest file `/api/open` sends (a post, or a toolpath to show its lines).
const OPEN_LIMIT: u64 = 16 << 20;
/// Most files each corpus picker lists.
const MAX_LISTED: usize = 2000;

/// Answers one API request.
pub fn handle(state: &State, endpoint: &str, body: Value) -> Reply {
    let result = match endpoint {
        "post" => parse(body).and_then(|r| post(state, r)),
        "check" => parse(body).and_then(|r| check(state, r)),
        "hover" => parse(body).and_then(hover),
        "fixes" => parse(body).and_then(fixes),
        "convert" => parse(body).and_then(|r| convert(state, r)),
        "toolpaths" => Ok(toolpaths(state)),
        "posts" => Ok(posts(state)),
        "open" => parse(body).and_then(|r| open(state, r)),
        "save" => parse(body).and_then(|r| save(state, r)),
        "drop" => parse(body).and_then(|r| drop_file(state, r)),
        _ => Err(Reply::error(404, format!("there is no API endpoint `/api/{endpoint}`"))),
    };
    match result {
        Ok(v) => Reply::json(200, &v),
        Err(r) => r,
    }
}

fn parse<T: serde::de::DeserializeOwned>(body: Value) -> Result<T, Reply> {
    serde_json::from_value(body).map_err(|e| Reply::error(400, format!("bad request: {e}")))
}

fn forbidden(why: String) -> Reply {
    Reply::error(403, why)
}

/// A post as the editor holds it.
#[derive(Deserialize)]
struct PostText {
    /// The post's file: its extension gives the dialect, its folder the
    /// files it includes (a Vectric `POST_BASE`).
    path: PathBuf,
    /// The editor's text (lines end with `\n`).
    text: String,
    /// How the file's characters are stored (`utf-8`, `latin-1`), as `/api/open` said.
    #[serde(default)]
    encoding: Option<String>,
}

impl PostText {
    /// The bytes a frontend reads: the text in the file's encoding.
    fn bytes(&self) -> Vec<u8> {
        match self.encoding.as_deref() {
            Some("latin-1") => self.text.chars().map(|c| u8::try_from(u32::from(c)).unwrap_or(b'?')).collect(),
            _ => self.text.as_bytes().to_vec(),
        }
    }

    fn dialect(&self) -> Option<Dialect> {
        postc_driver::post_dialect(&self.path, self.text.as_bytes())
    }

    fn confined(&self, state: &State) -> Result<PathBuf, Reply> {
        state.roots.confine(&self.path, Access::Read).map_err(forbidden)
    }
}

/// Which toolpath to post.
#[derive(Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
enum Choice {
    /// A toolpath file (the corpus's, the one given at start, or a dropped one).
    File { path: PathBuf },
    /// A generated toolpath (`postc toolpath gen`).
    Pattern { name: String, moves: u64 },
}

#[derive(Deserialize)]
struct PostRequest {
    #[serde(flatten)]
    post: PostText,
    toolpath: Option<Choice>,
}

/// Offsets in the editor's text.
struct Doc<'a> {
    text: &'a str,
    line_starts: Vec<usize>,
    /// The post's dialect, for its quick fixes.
    dialect: Option<Dialect>,
}

impl<'a> Doc<'a> {
    fn new(post: &'a PostText) -> Doc<'a> {
        let text = post.text.as_str();
        let line_starts = std::iter::once(0).chain(text.match_indices('\n').map(|(i, _)| i + 1)).collect();
        Doc { text, line_starts, dialect: post.dialect() }
    }

    /// The UTF-16 offset of a line (from 0) and a column in characters.
    fn utf16(&self, line: usize, column: usize) -> usize {
        let Some(&start) = self.line_starts.get(line) else { return self.text.encode_utf16().count() };
        let end = self.line_starts.get(line + 1).map_or(self.text.len(), |e| e - 1);
        let line_text = &self.text[start..end];
        let byte = line_text.char_indices().nth(column).map_or(line_text.len(), |(i, _)| i);
        self.text[..start + byte].encode_utf16().count()
    }

    /// The quick fixes of the language server within a byte range, with editor offsets.
    fn fixes(&self, start: usize, end: usize) -> Vec<Value> {
        let Some(dialect) = self.dialect else { return Vec::new() };
        postc_lsp::analysis::fixes(dialect, self.text, start, end)
            .into_iter()
            .map(|f| {
                json!({ "title": f.title, "from": self.of_byte(f.start), "to": self.of_byte(f.end), "insert": f.replacement })
            })
            .collect()
    }

    /// The byte offset of a UTF-16 offset.
    fn byte(&self, utf16: usize) -> usize {
        let mut units = 0;
        for (i, c) in self.text.char_indices() {
            if units >= utf16 {
                return i;
            }
            units += c.len_utf16();
        }
        self.text.len()
    }

    /// The UTF-16 offset of a byte offset.
    fn of_byte(&self, byte: usize) -> usize {
        let mut byte = byte.min(self.text.len());
        while !self.text.is_char_boundary(byte) {
            byte -= 1;
        }
        self.text[..byte].encode_utf16().count()
    }
}

/// The line (from 0) and column (in characters) of a byte offset of `basis`.
fn line_column(basis: &str, offset: usize) -> (usize, usize) {
    let mut offset = offset.min(basis.len());
    while !basis.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &basis[..offset];
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (before.matches('\n').count(), before[line_start..].chars().count())
}

fn severity(s: Severity) -> &'static str {
    match s {
        Severity::Error => "error",
        Severity::Warning => "warning",
        Severity::Note => "note",
    }
}

/// Diagnostics as JSON: those of the edited post with editor offsets
/// (`from`, `to`), those of other files with their place (`at`).
fn diagnostics_json(diagnostics: &[Diagnostic], sources: &SourceMap, post_file: &str, doc: &Doc) -> Vec<Value> {
    diagnostics
        .iter()
        .map(|d| {
            let primary = d.labels.iter().find(|l| l.primary).or(d.labels.first());
            let mut v = json!({
                "severity": severity(d.severity),
                "code": d.code,
                "message": d.message,
                "help": d.help,
                "notes": d.notes,
            });
            if let Some(l) = primary {
                v["label"] = json!(l.message);
                if sources.name(l.span.file) == post_file {
                    let basis = sources.text(l.span.file).unwrap_or(doc.text);
                    let (l0, c0) = line_column(basis, l.span.start);
                    let (l1, c1) = line_column(basis, l.span.end);
                    let (from, to) = (doc.utf16(l0, c0), doc.utf16(l1, c1));
                    v["from"] = json!(from);
                    v["to"] = json!(to);
                    v["line"] = json!(l0 + 1);
                    v["fixes"] = json!(doc.fixes(doc.byte(from), doc.byte(to)));
                } else if let Some((line, column)) = sources.line_column(l.span.file, l.span.start) {
                    v["at"] = json!(format!("{}:{line}:{column}", sources.name(l.span.file)));
                }
            }
            v
        })
        .collect()
}

/// `/api/check`: the post's diagnostics, as `postc lsp` gives them.
fn check(state: &State, req: PostText) -> Result<Value, Reply> {
    let path = req.confined(state)?;
    let mut sources = postc_report::source_map();
    let doc = Doc::new(&req);
    let compiled = postc_lsp::compile_checked(&path, &req.bytes(), req.dialect(), &mut sources);
    let diagnostics = match &compiled {
        Some(c) => diagnostics_json(&c.diagnostics, &sources, &path.display().to_string(), &doc),
        None => vec![crashed()],
    };
    Ok(json!({ "diagnostics": diagnostics }))
}

/// What the page shows when postc panicked on the post: as the language
/// server says it, without a code (it is no diagnostic of the post's).
fn crashed() -> Value {
    json!({
        "severity": "error",
        "message": "postc failed while checking this post (a postc bug: please report it with the post)",
        "from": 0,
        "to": 0,
    })
}

/// One traced NC line, as the runtime reports it.
struct Traced {
    part: usize,
    line: u64,
    span: Option<Span>,
    event: Option<u64>,
    event_span: Option<Span>,
}

/// `/api/post`: the post's diagnostics and, when it compiles, the program
/// it writes over the toolpath, the trace of every NC line (the post line
/// that wrote it, the toolpath event it came from), verify's findings and
/// the backplot.
fn post(state: &State, req: PostRequest) -> Result<Value, Reply> {
    let started = std::time::Instant::now();
    let path = req.post.confined(state)?;
    let post_name = path.display().to_string();
    let mut sources = postc_report::source_map();
    let doc = Doc::new(&req.post);
    let Some(compiled) = postc_lsp::compile_checked(&path, &req.post.bytes(), req.post.dialect(), &mut sources) else {
        return Ok(json!({ "diagnostics": [crashed()] }));
    };
    let mut out = json!({ "diagnostics": diagnostics_json(&compiled.diagnostics, &sources, &post_name, &doc) });
    let post = match compiled.post {
        Some(post) if !compiled.has_errors() => post,
        _ => {
            out["note"] = json!("the post has errors; nothing was posted");
            return Ok(out);
        }
    };
    let Some(choice) = &req.toolpath else {
        out["note"] = json!("choose a toolpath to post");
        return Ok(out);
    };
    let open = |sources: &mut SourceMap| open_toolpath(state, choice, sources);
    let mut source = open(&mut sources)?;
    let traced: Rc<RefCell<Vec<Traced>>> = Rc::default();
    let sink = Rc::clone(&traced);
    let options = postc_runtime::RunOptions {
        script_host: postc_driver::script_host(&post),
        trace: Some(Box::new(move |t: &postc_runtime::trace::TraceLine<'_>| {
            let mut all = sink.borrow_mut();
            if all.len() < TRACE_LINES {
                all.push(Traced {
                    part: t.part,
                    line: t.line,
                    span: t.span,
                    event: t.event,
                    event_span: t.event_span.filter(|s| *s != Span::default()),
                });
            }
        })),
        ..super::super::clock::run_options()
    };
    let report = match postc_runtime::run(&post, &mut source, Output::memory(), options) {
        Ok(r) => r,
        Err(diagnostics) => {
            out["diagnostics"] = json!(diagnostics_json(&diagnostics, &sources, &post_name, &doc));
            out["note"] = json!("posting failed");
            return Ok(out);
        }
    };
    let parts = match report.output {
        Finished::Memory(parts) => parts,
        _ => Vec::new(),
    };
    let mut part_start = Vec::with_capacity(parts.len());
    let mut lines_so_far = 0u64;
    for p in &parts {
        part_start.push(lines_so_far);
        lines_so_far += p.iter().filter(|&&b| b == b'\n').count() as u64;
    }
    let program: Vec<u8> = parts.concat();
    let warnings = diagnostics_json(&report.warnings, &sources, &post_name, &doc);
    if let Some(list) = out["diagnostics"].as_array_mut() {
        list.extend(warnings);
    }
    // The trace: per NC line (from 1), the post line (0: none), the
    // toolpath event (-1: none) and the toolpath line (0: none).
    let mut trace_post = vec![0u32; lines_so_far.min(TRACE_LINES as u64) as usize];
    let mut trace_event = vec![-1i64; trace_post.len()];
    let mut trace_toolpath = vec![0u32; trace_post.len()];
    for t in traced.borrow().iter() {
        let global = part_start.get(t.part).copied().unwrap_or(0) + t.line;
        let Some(i) = usize::try_from(global).ok().and_then(|g| g.checked_sub(1)).filter(|&i| i < trace_post.len())
        else {
            continue;
        };
        if let Some(span) = t.span
            && sources.name(span.file) == post_name
            && let Some((line, _)) = sources.line_column(span.file, span.start)
        {
            trace_post[i] = line as u32;
        }
        if let Some(e) = t.event {
            trace_event[i] = e as i64;
        }
        if let Some(span) = t.event_span
            && let Some((line, _)) = sources.line_column(span.file, span.start)
        {
            trace_toolpath[i] = line as u32;
        }
    }
    out["program"] = json!(String::from_utf8_lossy(&program));
    out["lines"] = json!(lines_so_far);
    out["events"] = json!(report.events);
    out["parts"] = json!(parts.len());
    out["trace"] = json!({ "post": trace_post, "event": trace_event, "toolpath": trace_toolpath });
    // Verify's findings and the backplot, as `postc plot` draws them.
    let name = format!("program.{}", post.info.file_extension);
    let head = &program[..program.len().min(4096)];
    let refused = postc_verify::post_refusal(&name, &post)
        .or_else(|| postc_verify::refusal(&name, Some(&post), &post.info.file_extension.to_ascii_lowercase(), head));
    match refused {
        Some(d) => out["verify_note"] = json!(d.message),
        None => {
            let file = sources.add(name.clone(), String::from_utf8_lossy(&program).into_owned());
            let mut drawn = open(&mut sources)?;
            let mut again = open(&mut sources)?;
            let settings = Settings::from_post(&post, Controller::Generic, 0.01);
            let (mut plot, verified) =
                postc_verify::plot::draw(&mut &program[..], file, &mut *drawn, &mut *again, &settings, &sources);
            if let Some(why) = postc_verify::not_gcode(&verified) {
                out["verify_note"] = json!(why);
            } else {
                plot.title = format!("{} over {}", file_name(&path), choice_name(choice));
                let findings: Vec<Value> = verified
                    .findings
                    .iter()
                    .zip(&verified.lines)
                    .enumerate()
                    .map(|(i, (d, (line, _)))| {
                        json!({
                            "number": i + 1,
                            "severity": severity(d.severity),
                            "code": d.code,
                            "message": d.message,
                            "line": line,
                        })
                    })
                    .collect();
                out["findings"] = json!(findings);
                out["verify"] = json!({
                    "errors": verified.errors,
                    "warnings": verified.warnings,
                    "moves": verified.stats.motions,
                    "matched": verified.stats.matched,
                    "expected": verified.stats.expected,
                });
                out["svg"] = json!(plot.svg());
            }
        }
    }
    out["elapsed_ms"] = json!(started.elapsed().as_secs_f64() * 1000.0);
    Ok(out)
}

fn file_name(p: &Path) -> String {
    p.file_name().map_or_else(|| p.display().to_string(), |n| n.to_string_lossy().into_owned())
}

fn choice_name(choice: &Choice) -> String {
    match choice {
        Choice::File { path } => file_name(path),
        Choice::Pattern { name, moves } => format!("{name} ({moves} moves)"),
    }
}

/// The events of the chosen toolpath.
fn open_toolpath(state: &State, choice: &Choice, sources: &mut SourceMap) -> Result<Box<dyn EventSource>, Reply> {
    match choice {
        Choice::File { path } => {
            let path = state.roots.confine(path, Access::Read).map_err(forbidden)?;
            postc_driver::open_toolpath(&path, sources).map_err(|d| Reply::error(422, d.message))
        }
        Choice::Pattern { name, moves } => {
            if *moves > MAX_PATTERN_MOVES {
                return Err(Reply::error(422, format!("at most {MAX_PATTERN_MOVES} moves")));
            }
            match Synthetic::new(name, *moves) {
                Some(s) => Ok(Box::new(s)),
                None => Err(Reply::error(422, format!("there is no pattern `{name}`"))),
            }
        }
    }
}

#[derive(Deserialize)]
struct HoverRequest {
    #[serde(flatten)]
    post: PostText,
    /// Where the pointer is, in UTF-16 units.
    offset: usize,
}

/// `/api/hover`: what the language server's hover says at an offset.
fn hover(req: HoverRequest) -> Result<Value, Reply> {
    let Some(dialect) = req.post.dialect() else { return Ok(Value::Null) };
    let doc = Doc::new(&req.post);
    let at = doc.byte(req.offset);
    Ok(match postc_lsp::analysis::hover(dialect, &req.post.text, at) {
        Some(h) => json!({ "markdown": h.markdown, "from": doc.of_byte(h.start), "to": doc.of_byte(h.end) }),
        None => Value::Null,
    })
}

#[derive(Deserialize)]
struct FixesRequest {
    #[serde(flatten)]
    post: PostText,
    from: usize,
    to: usize,
}

/// `/api/fixes`: the language server's quick fixes within a range.
fn fixes(req: FixesRequest) -> Result<Value, Reply> {
    let doc = Doc::new(&req.post);
    Ok(json!(doc.fixes(doc.byte(req.from), doc.byte(req.to))))
}

#[derive(Deserialize)]
struct ConvertRequest {
    #[serde(flatten)]
    post: PostText,
    /// vectric, vcpost, cimco, fusion or ron.
    to: String,
}

/// `/api/convert`: the post as another dialect's, as `postc convert` writes it.
fn convert(state: &State, req: ConvertRequest) -> Result<Value, Reply> {
    use postc_backends::Target;
    let target = match req.to.as_str() {
        "vectric" => Target::Vectric,
        "vcpost" => Target::VcPost,
        "cimco" => Target::Cimco,
        "fusion" => Target::Fusion,
        "ron" => Target::Ron,
        other => return Err(Reply::error(400, format!("cannot convert to `{other}`"))),
    };
    let path = req.post.confined(state)?;
    let post_name = path.display().to_string();
    let mut sources = postc_report::source_map();
    let doc = Doc::new(&req.post);
    let mut compiled = postc_driver::compile_post_bytes(&path, &req.post.bytes(), req.post.dialect(), &mut sources);
    let mut rules = postc_ir::codes::LevelRules::default();
    for code in super::super::convert::NOT_READ_WHOLE {
        let _ = rules.add(code, postc_ir::codes::Level::Deny, 2);
    }
    rules.apply(&mut compiled.diagnostics);
    let post = match compiled.post {
        Some(p) if !compiled.has_errors() => p,
        _ => {
            return Ok(json!({
                "diagnostics": diagnostics_json(&compiled.diagnostics, &sources, &post_name, &doc),
                "note": "the post has errors; it was not converted",
            }));
        }
    };
    Ok(match postc_backends::convert_warned(&post, target) {
        Ok((text, warnings)) => json!({
            "text": String::from_utf8_lossy(&text),
            "extension": target.extension(),
            "diagnostics": diagnostics_json(&warnings, &sources, &post_name, &doc),
        }),
        Err(diagnostics) => json!({
            "diagnostics": diagnostics_json(&diagnostics, &sources, &post_name, &doc),
            "note": format!("the post cannot be converted to {}", req.to),
        }),
    })
}

/// Files under `dir` whose names `keep` accepts, sorted, at most [`MAX_LISTED`].
fn listed(dir: &Path, keep: &dyn Fn(&Path) -> bool) -> Vec<String> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else { continue };
        for e in entries.flatten() {
            let p = e.path();
            match e.file_type() {
                Ok(t) if t.is_dir() => stack.push(p),
                Ok(t) if t.is_file() && keep(&p) && out.len() < MAX_LISTED => out.push(p.display().to_string()),
                _ => {}
            }
        }
    }
    out.sort();
    out
}

/// `/api/toolpaths`: what the toolpath picker offers.
fn toolpaths(state: &State) -> Value {
    let corpus =
        state.roots.corpus.as_ref().map_or_else(Vec::new, |c| {
            listed(&c.join("toolpaths"), &|p| postc_driver::toolpath_format(p, b"").is_some())
        });
    json!({
        "start": state.toolpath.as_ref().map(|p| p.display().to_string()),
        "corpus": corpus,
        "patterns": PATTERNS.iter().map(|(name, help)| json!({ "name": name, "help": help })).collect::<Vec<_>>(),
        "max_moves": MAX_PATTERN_MOVES,
    })
}

/// `/api/posts`: what the post picker offers.
fn posts(state: &State) -> Value {
    let is_post = |p: &Path| postc_driver::dialect_of_extension(p).is_some_and(|d| d != Dialect::Ron);
    let corpus = state.roots.corpus.as_ref().map_or_else(Vec::new, |c| listed(&c.join("posts"), &is_post));
    json!({ "start": state.post.as_ref().map(|p| p.display().to_string()), "corpus": corpus })
}

#[derive(Deserialize)]
struct PathRequest {
    path: PathBuf,
}

/// `/api/open`: a file's text (a post, or a toolpath the page shows the
/// lines of), its dialect and how it is stored.
fn open(state: &State, req: PathRequest) -> Result<Value, Reply> {
    let path = state.roots.confine(&req.path, Access::Read).map_err(forbidden)?;
    if std::fs::metadata(&path).is_ok_and(|m| m.len() > OPEN_LIMIT) {
        let why = format!("`{}` is over {} MiB: too large to show", req.path.display(), OPEN_LIMIT >> 20);
        return Err(Reply::error(422, why));
    }
    let bytes =
        std::fs::read(&path).map_err(|e| Reply::error(404, format!("cannot read `{}`: {e}", req.path.display())))?;
    let (text, how) = stored::decode(&bytes);
    let dialect = postc_driver::post_dialect(&path, &bytes).map(postc_driver::library::dialect_name);
    Ok(json!({
        "path": req.path.display().to_string(),
        "text": text,
        "encoding": if how.utf8 { "utf-8" } else { "latin-1" },
        "bom": how.bom,
        "crlf": how.crlf,
        "dialect": dialect,
    }))
}

#[derive(Deserialize)]
struct SaveRequest {
    path: PathBuf,
    text: String,
}

/// `/api/save`: writes the post back to its file, whole or not at all
/// (`outputs::write_whole`), in the encoding, byte-order mark and line
/// endings the file has.
fn save(state: &State, req: SaveRequest) -> Result<Value, Reply> {
    let path = state.roots.confine(&req.path, Access::Write).map_err(forbidden)?;
    let how = match std::fs::read(&path) {
        Ok(bytes) => stored::decode(&bytes).1,
        Err(_) => stored::Stored { utf8: true, bom: false, crlf: false },
    };
    let bytes = stored::encode(&req.text, how).map_err(|e| Reply::error(422, e))?;
    super::super::outputs::write_whole(&path, &bytes, &[], None).map_err(|d| Reply::error(500, d.message))?;
    Ok(json!({ "path": req.path.display().to_string(), "bytes": bytes.len() }))
}

#[derive(Deserialize)]
struct DropRequest {
    /// The dropped file's name (its extension says its format).
    name: String,
    text: String,
}

/// `/api/drop`: keeps a toolpath dropped on the page in the workbench's
/// own folder; its path, to choose it as a file.
fn drop_file(state: &State, req: DropRequest) -> Result<Value, Reply> {
    let name = Path::new(&req.name).file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    if name.is_empty()
        || name.starts_with('.')
        || postc_driver::toolpath_format(Path::new(&name), req.text.as_bytes()).is_none()
    {
        return Err(Reply::error(422, format!("`{}` is not a toolpath (APT CL, .ron or .jsonl)", req.name)));
    }
    let path = state.roots.dropped.join(&name);
    std::fs::write(&path, req.text.as_bytes()).map_err(|e| Reply::error(500, format!("cannot keep `{name}`: {e}")))?;
    Ok(json!({ "path": path.display().to_string() }))
}
