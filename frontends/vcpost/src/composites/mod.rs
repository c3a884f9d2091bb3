//! Composites event files: the routine calls Vericut Composites (VCP) makes
//! to a post, one per line, with the variables of each, read into the Sub
//! calls the runtime makes.
//!
//! A file is RON or JSON Lines, read one line at a time (memory stays flat
//! whatever its length). Its first line says which of Vericut's post-processor notes' two
//! sequences it follows:
//!
//! ```text
//! VcpFile(kind: Laying)                 {"VcpFile":{"kind":"Laying"}}
//! VcpFile(kind: Laying, primers: ["S3_Vertical"])
//! Modals(AccDecDist: 50, ...)           {"Modals":{"AccDecDist":50, ...}}
//! GoTo(AddCutA: "0011", ..., X: 1.5)    {"GoTo":{"AddCutA":"0011", ..., "X":1.5}}
//! CamHeader                             "CamHeader"
//! Option(name: "OpMessage", OptString1: "Check tows")
//! ```
//!
//! Blank lines and lines starting with `//` or `#` are skipped. [`calls`]
//! has one type per routine (its fields are the seed's variables),
//! [`grammar`] the sequences. Each line is checked as it is read: it must
//! parse as a call of the file's kind, carry every variable the seed lists
//! for it, and fit the sequence; values are checked where the seed bounds
//! them. Option and probe calls name their Sub, which the post must have.
//!
//! What the runtime is given: for each call, the Sub of the routine's name
//! (or the named option/probe Sub) and the call's variables. A post may
//! leave out the routines the seed calls optional (the Cam, Pullout,
//! Traverse and Restart routines, OffForm, OnForm, Extent, Length): those
//! calls are skipped silently; without TraverseHeader no TraverseTo or
//! TraverseTrailer is called, without RestartHeader no RestartBuffer or
//! RestartTrailer (the seed: "provided TraverseHeader routine is present").
//! The #Primer Subs the header names run first (VCP's Post card), then
//! those named with `--primer`, before the first call.
//!
//! Its diagnostic codes are declared in the registry `postc_ir::codes`
//! (rendered as docs/diagnostics.md; `postc explain CODE`).

pub mod calls;
pub mod check;
pub mod grammar;

use postc_ir::codes;
use std::collections::{HashMap, VecDeque};
use std::io::{BufRead, BufReader, Read};
use std::path::Path;

use postc_ir::source::SourceReader;
use postc_ir::{CallSource, Diagnostic, FileId, MissingSub, Post, SourceLoader, SourceMap, Span, SubCall};

use crate::ast::SubKeyword;
use calls::{Application, Call, HeaderLine, LayingCall, ProbingCall};
use grammar::{State, Step};

/// Whether a path names a composites event file: `.vcp.ron`, `.vcp.jsonl`
/// or `.vcp.json` (any case), or a file whose first line is the header
/// (read through `loader`).
pub fn is_composites_file(path: &Path, loader: &dyn SourceLoader) -> bool {
    let name = path.file_name().map(|n| n.to_string_lossy().to_ascii_lowercase()).unwrap_or_default();
    if [".vcp.ron", ".vcp.jsonl", ".vcp.json"].iter().any(|e| name.ends_with(e)) {
        return true;
    }
    let mut head = Vec::new();
    if let Ok(f) = loader.open(path) {
        let _ = f.take(4096).read_to_end(&mut head);
    }
    looks_like_composites(&head)
}

/// Whether the first meaningful line of a file is the `VcpFile` header.
pub fn looks_like_composites(head: &[u8]) -> bool {
    let text = String::from_utf8_lossy(head);
    let first = text.lines().map(str::trim).find(|l| !l.is_empty() && !l.starts_with("//") && !l.starts_with('#'));
    first.is_some_and(|l| l.starts_with("VcpFile") || l.replace(' ', "").starts_with("{\"VcpFile\""))
}

/// Line syntaxes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Syntax {
    Ron,
    JsonLines,
}

/// What the reader knows of the post.
struct PostFacts {
    /// Upper-case Sub name to its keyword (None when it has none).
    subs: HashMap<String, Option<SubKeyword>>,
}

impl PostFacts {
    fn new(post: &Post) -> PostFacts {
        let mut subs: HashMap<String, Option<SubKeyword>> =
            post.functions.iter().filter(|f| f.span.is_some()).map(|f| (f.name.to_ascii_uppercase(), None)).collect();
        for sig in crate::signatures::from_post(post) {
            subs.insert(sig.name.to_ascii_uppercase(), sig.keyword);
        }
        PostFacts { subs }
    }

    fn has(&self, name: &str) -> bool {
        self.subs.contains_key(&name.to_ascii_uppercase())
    }

    /// Checks a Sub an option, probe or primer names.
    fn named(&self, name: &str, want: SubKeyword, at: Option<Span>) -> Result<Option<Diagnostic>, Diagnostic> {
        let with = |d: Diagnostic, label: &str| match at {
            Some(s) => d.at(s, label.to_string()),
            None => d,
        };
        match self.subs.get(&name.to_ascii_uppercase()) {
            None => Err(with(
                Diagnostic::error(codes::CP005, format!("the post has no Sub `{name}`")).help(format!(
                    "an {} Sub is declared with `Sub {name}()` and a `' #{}` comment",
                    want.as_str(),
                    want.as_str()
                )),
                "named here",
            )),
            Some(k) if *k != Some(want) => Ok(Some(with(
                Diagnostic::warning(codes::CP007, format!("Sub `{name}` has no `#{}` keyword comment", want.as_str()))
                    .help(format!("add `' #{}` after its Sub line so Vericut offers it", want.as_str())),
                "called here",
            ))),
            Some(_) => Ok(None),
        }
    }
}

/// The calls of the #Primer Subs named on the command line.
pub fn primers(post: &Post, names: &[String], diagnostics: &mut Vec<Diagnostic>) -> Vec<SubCall> {
    let facts = PostFacts::new(post);
    let mut out = Vec::new();
    for name in names {
        match facts.named(name, SubKeyword::Primer, None) {
            Ok(warning) => {
                diagnostics.extend(warning);
                out.push(SubCall {
                    sub: name.clone(),
                    vars: Vec::new(),
                    span: Span::default(),
                    missing: MissingSub::Warn,
                });
            }
            Err(d) => diagnostics.push(d),
        }
    }
    out
}

/// Reads a composites event file as Sub calls.
pub struct CompositesReader<R> {
    input: R,
    file: FileId,
    syntax: Option<Syntax>,
    kind: Option<Application>,
    state: State,
    facts: PostFacts,
    pending: VecDeque<SubCall>,
    line: String,
    offset: usize,
    last: Span,
    done: bool,
    ron: ron::Options,
}

/// Opens an event file for a post; `primers` are the calls to make first.
pub fn open(
    path: &Path,
    sources: &mut SourceMap,
    post: &Post,
    primers: Vec<SubCall>,
) -> Result<CompositesReader<BufReader<SourceReader>>, Diagnostic> {
    let f = sources.loader().open(path).map_err(|e| {
        Diagnostic::error(codes::CP010, format!("cannot open the event file `{}`: {e}", path.display()))
    })?;
    let id = sources.add_streamed(path.display().to_string());
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let syntax = match ext.as_deref() {
        Some("ron") => Some(Syntax::Ron),
        Some("jsonl" | "json") => Some(Syntax::JsonLines),
        _ => None,
    };
    Ok(CompositesReader::new(BufReader::with_capacity(1 << 16, f), syntax, id, post, primers))
}

impl<R: BufRead> CompositesReader<R> {
    pub fn new(
        input: R,
        syntax: Option<Syntax>,
        file: FileId,
        post: &Post,
        primers: Vec<SubCall>,
    ) -> CompositesReader<R> {
        let ron = ron::Options::default().with_default_extension(
            ron::extensions::Extensions::IMPLICIT_SOME | ron::extensions::Extensions::UNWRAP_VARIANT_NEWTYPES,
        );
        CompositesReader {
            input,
            file,
            syntax,
            kind: None,
            state: State::Start,
            facts: PostFacts::new(post),
            pending: primers.into(),
            line: String::new(),
            offset: 0,
            last: Span::new(file, 0, 0),
            done: false,
            ron,
        }
    }

    /// Reads the next meaningful line: its text and span.
    fn next_line(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<(String, Span)> {
        while !self.done {
            self.line.clear();
            let start = self.offset;
            match self.input.read_line(&mut self.line) {
                Ok(0) => self.done = true,
                Ok(n) => {
                    self.offset += n;
                    let lead = self.line.len() - self.line.trim_start().len();
                    let text = self.line.trim();
                    if text.is_empty() || text.starts_with("//") || text.starts_with('#') {
                        continue;
                    }
                    let span = Span::new(self.file, start + lead, start + lead + text.len());
                    self.last = span;
                    return Some((text.to_string(), span));
                }
                Err(e) => {
                    self.done = true;
                    diagnostics.push(
                        Diagnostic::error(codes::CP010, format!("cannot read the event file: {e}"))
                            .at(Span::new(self.file, start, start + 1), "from here on"),
                    );
                }
            }
        }
        None
    }

    fn parse<T: serde::de::DeserializeOwned>(
        &mut self,
        text: &str,
        span: Span,
        code: &'static str,
    ) -> Result<T, Diagnostic> {
        let syntax =
            *self.syntax.get_or_insert(if text.starts_with(['{', '"']) { Syntax::JsonLines } else { Syntax::Ron });
        let (message, col) = match syntax {
            Syntax::Ron => match self.ron.from_str::<T>(text) {
                Ok(v) => return Ok(v),
                Err(e) => (e.code.to_string(), e.span.start.col),
            },
            Syntax::JsonLines => match serde_json::from_str::<T>(text) {
                Ok(v) => return Ok(v),
                Err(e) => (e.to_string(), e.column()),
            },
        };
        let col = col.saturating_sub(1).min(text.len().saturating_sub(1));
        let at = Span::new(self.file, span.start + col, (span.start + col + 1).min(span.end));
        Err(Diagnostic::error(code, format!("this line is not a valid call: {message}"))
            .at(at, "here")
            .also(span, "in this call")
            .help("each call carries every variable Vericut's application notes list for its routine; docs/vcpost.md has the list"))
    }

    /// Checks one call against the sequence and the post, and makes its Sub call.
    fn accept<C: Call + check::Checked>(
        &mut self,
        call: C,
        span: Span,
        diagnostics: &mut Vec<Diagnostic>,
    ) -> Option<SubCall> {
        let step = Step { routine: call.routine(), number: call.number() };
        let probing = self.kind == Some(Application::Probing);
        let next = if probing { grammar::probing(self.state, step) } else { grammar::laying(self.state, step) };
        match next {
            Ok(s) => self.state = s,
            Err(m) => {
                diagnostics.push(
                    Diagnostic::error(codes::CP003, format!("`{}` cannot come here", step.routine))
                        .at(span, format!("expected {}", m.expected))
                        .help("docs/vcpost.md has the sequences Vericut's application notes allow"),
                );
                self.state = if probing { grammar::probing_resync(step) } else { grammar::laying_resync(step) };
            }
        }
        call.check(span, diagnostics);
        let routine = step.routine;
        if let Some(want) = call.named_keyword() {
            match self.facts.named(call.sub(), want, Some(span)) {
                Ok(w) => diagnostics.extend(w),
                Err(d) => {
                    diagnostics.push(d);
                    return None;
                }
            }
        }
        let dropped = (matches!(routine, "TraverseTo" | "TraverseTrailer") && !self.facts.has("TraverseHeader"))
            || (matches!(routine, "RestartBuffer" | "RestartTrailer") && !self.facts.has("RestartHeader"));
        if dropped {
            return None;
        }
        let core = [
            "Modals",
            "PlyHeader",
            "LinkHeader",
            "MoveTo",
            "LinkTrailer",
            "PacketHeader",
            "GoTo",
            "PacketTrailer",
            "PlyTrailer",
            "ProgramHeader",
            "SetAngle",
            "ProgramTrailer",
            "Option",
            "Probe",
        ];
        let missing = if core.contains(&routine) { MissingSub::Warn } else { MissingSub::Skip };
        Some(SubCall { sub: call.sub().to_string(), vars: call.vars(), span, missing })
    }
}

impl<R: BufRead> CallSource for CompositesReader<R> {
    fn next_call(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<SubCall> {
        if self.kind.is_some()
            && let Some(c) = self.pending.pop_front()
        {
            return Some(c);
        }
        while let Some((text, span)) = self.next_line(diagnostics) {
            let Some(kind) = self.kind else {
                match self.parse::<HeaderLine>(&text, span, codes::CP002.code) {
                    Ok(HeaderLine::VcpFile(h)) => {
                        self.kind = Some(h.kind);
                        for name in h.primers.iter().rev() {
                            match self.facts.named(name, SubKeyword::Primer, Some(span)) {
                                Ok(w) => {
                                    diagnostics.extend(w);
                                    let call = SubCall {
                                        sub: name.clone(),
                                        vars: Vec::new(),
                                        span,
                                        missing: MissingSub::Warn,
                                    };
                                    self.pending.push_front(call);
                                }
                                Err(d) => diagnostics.push(d),
                            }
                        }
                        if let Some(c) = self.pending.pop_front() {
                            return Some(c);
                        }
                    }
                    Err(d) => {
                        diagnostics.push(
                            d.note("the first line says which sequence the file follows: VcpFile(kind: Laying) or VcpFile(kind: Probing)"),
                        );
                        self.done = true;
                    }
                }
                continue;
            };
            let call = match kind {
                Application::Laying => {
                    self.parse::<LayingCall>(&text, span, codes::CP001.code).map(|c| self.accept(c, span, diagnostics))
                }
                Application::Probing => {
                    self.parse::<ProbingCall>(&text, span, codes::CP001.code).map(|c| self.accept(c, span, diagnostics))
                }
            };
            match call {
                Ok(Some(c)) => return Some(c),
                Ok(None) => {}
                Err(d) => diagnostics.push(d),
            }
        }
        if self.kind.is_some()
            && let Some(what) = grammar::unfinished(self.state)
        {
            diagnostics.push(Diagnostic::error(codes::CP004, what).at(self.last, "the last call"));
            self.state = State::Done;
        } else if self.kind.is_none() && !postc_ir::diagnostic::has_errors(diagnostics) {
            diagnostics.push(Diagnostic::error(codes::CP002, "the event file is empty: it has no VcpFile header"));
            self.kind = Some(Application::Laying);
            self.state = State::Done;
        }
        None
    }
}
