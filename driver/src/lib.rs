//! postc's driver: finds the dialect of a post or the format of a toolpath,
//! hands the file to the crate that reads it, validates what comes back,
//! picks the script host a post's scripts need, and opens toolpaths (read
//! ahead on a thread of their own, [`ReadAhead`]).
//!
//! - `postc-front-vectric` (`frontends/vectric`): Vectric `.pp` posts;
//! - `postc-front-cimco` (`frontends/cimco`): CIMCO CNC-Calc JavaScript posts,
//!   whose script functions run in `postc-cimco-host` (`hosts/cimco`);
//! - `postc-front-vcpost` (`frontends/vcpost`): Vericut VcPost posts;
//! - `postc-reader-apt` (`readers/apt`): APT CL toolpaths;
//! - `postc-reader-native` (`readers/native`): the native toolpath stream, RON or JSON Lines;
//! - posts written directly as IR in RON (`.ron`), read here.
//!
//! A post's dialect comes from its extension (`.pp`, `.js`, `.VcPost`,
//! `.ron`, any case) or, failing that, from its content; a toolpath's format
//! from its extension (`.apt`, `.cl`, `.cls`, `.ncl`, `.clt`, `cl.tap` for
//! APT CL; `.ron`, `.jsonl` for the native stream) or its content.

pub mod library;
mod read_ahead;
mod ron_locate;
pub mod settings;

pub use read_ahead::ReadAhead;

use postc_reader_native as native;

use postc_ir::codes;
use std::path::Path;

use postc_ir::{Diagnostic, Dialect, EventSource, FileId, Post, SourceLoader, SourceMap, Span};

/// A compiled post and everything its frontend had to say.
pub struct Compiled {
    /// The post, unless the file could not be read at all.
    pub post: Option<Post>,
    pub diagnostics: Vec<Diagnostic>,
}

impl Compiled {
    fn failed(d: Diagnostic) -> Compiled {
        Compiled { post: None, diagnostics: vec![d] }
    }

    /// Whether any diagnostic is an error.
    pub fn has_errors(&self) -> bool {
        postc_ir::diagnostic::has_errors(&self.diagnostics)
    }
}

/// The dialect a post's extension names (`.pp`, `.js`, `.cps`, `.vcpost`,
/// `.ron`, in any case); `None` for any other extension.
pub fn dialect_of_extension(path: &Path) -> Option<Dialect> {
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    Some(match ext.as_deref()? {
        "pp" => Dialect::Vectric,
        "js" => Dialect::Cimco,
        "cps" => Dialect::Fusion,
        "vcpost" => Dialect::VcPost,
        "ron" => Dialect::Ron,
        _ => return None,
    })
}

/// The dialect a post is written in, from its extension or its content.
pub fn post_dialect(path: &Path, bytes: &[u8]) -> Option<Dialect> {
    if let Some(dialect) = dialect_of_extension(path) {
        return Some(dialect);
    }
    let text = String::from_utf8_lossy(&bytes[..bytes.len().min(1 << 16)]);
    let lower = text.to_ascii_lowercase();
    if lower.contains("function onlinear") || lower.contains("createformat(") || lower.contains("createvariable(") {
        Some(Dialect::Cimco)
    } else if postc_front_vcpost::looks_like_vcpost(bytes) {
        Some(Dialect::VcPost)
    } else if postc_front_vectric::looks_like_vectric(bytes) {
        Some(Dialect::Vectric)
    } else if lower.trim_start().starts_with("(") && lower.contains("handlers") {
        Some(Dialect::Ron)
    } else {
        None
    }
}

/// The host that runs a compiled post's scripts, chosen by the scripts'
/// language, never by the post's dialect: Rhai scripts (what CIMCO
/// functions that do not lower to native IR become) run in the CNC-Calc
/// host, `postc-cimco-host`. `None` when the post has no script postc
/// runs (none, or only Lua, which is kept and not run). Everything that
/// runs a post passes this in [`postc_runtime::RunOptions::script_host`].
pub fn script_host(post: &Post) -> Option<postc_runtime::script_host::ScriptHostFactory> {
    if post.scripts.iter().any(|s| s.language == postc_ir::ScriptLanguage::Rhai)
        || (post.info.dialect == Dialect::Cimco && calls_host(post))
    {
        Some(postc_cimco_host::compile)
    } else {
        None
    }
}

/// Whether the post's native code calls its host's API (`Expr::Host`:
/// CNC-Calc's drilling data and compensation side).
fn calls_host(post: &Post) -> bool {
    struct Finds(bool);
    impl postc_ir::visit::Visit for Finds {
        fn visit_expr(&mut self, expr: &postc_ir::Expr) {
            if matches!(expr, postc_ir::Expr::Host { .. }) {
                self.0 = true;
            }
            postc_ir::visit::walk_expr(self, expr);
        }
    }
    let mut f = Finds(false);
    postc_ir::visit::walk_post(&mut f, post);
    f.0
}

/// The options of a run of `post` with nothing overridden: the defaults,
/// and the post's script host ([`script_host`]).
pub fn run_options(post: &Post) -> postc_runtime::RunOptions {
    postc_runtime::RunOptions { script_host: script_host(post), ..postc_runtime::RunOptions::default() }
}

/// The post to run over Sub calls (`postc_runtime::calls::run_calls`):
/// a VcPost post's functions whose values come from the calls' lists
/// (`getNthLength1`, ...) read tables of globals the lists fill
/// ([`postc_front_vcpost::call_tables`]). Every other post is run as it is.
pub fn for_calls(post: &Post) -> std::borrow::Cow<'_, Post> {
    match post.info.dialect {
        Dialect::VcPost => match postc_front_vcpost::call_tables::lower(post) {
            Some(lowered) => std::borrow::Cow::Owned(lowered),
            None => std::borrow::Cow::Borrowed(post),
        },
        _ => std::borrow::Cow::Borrowed(post),
    }
}

/// Reads (through the source map's loader) and compiles a post file.
pub fn compile_post(path: &Path, dialect: Option<Dialect>, sources: &mut SourceMap) -> Compiled {
    match sources.loader().read(path) {
        Ok(bytes) => compile_post_bytes(path, &bytes, dialect, sources),
        Err(e) => {
            Compiled::failed(Diagnostic::error(codes::IO001, format!("cannot read post `{}`: {e}", path.display())))
        }
    }
}

/// Compiles a post from its bytes (the embedded default post, tests).
pub fn compile_post_bytes(path: &Path, bytes: &[u8], dialect: Option<Dialect>, sources: &mut SourceMap) -> Compiled {
    let Some(dialect) = dialect.or_else(|| post_dialect(path, bytes)) else {
        return Compiled::failed(
            Diagnostic::error(codes::IO004, format!("cannot tell which dialect `{}` is written in", path.display()))
                .help("name it .pp (Vectric), .js (CIMCO), .cps (Fusion), .VcPost (Vericut) or .ron (postc IR), or pass --dialect"),
        );
    };
    let mut compiled = match dialect {
        Dialect::Vectric => {
            let (post, diagnostics) = postc_front_vectric::compile(path, bytes, sources);
            Compiled { post: Some(post), diagnostics }
        }
        Dialect::VcPost => {
            let (post, diagnostics) = postc_front_vcpost::compile(path, bytes, sources);
            Compiled { post: Some(post), diagnostics }
        }
        Dialect::Cimco => {
            let (post, diagnostics) = postc_front_cimco::compile(path, bytes, sources);
            Compiled { post: Some(post), diagnostics }
        }
        Dialect::Fusion => {
            let (post, diagnostics) = postc_front_cimco::fusion::compile(path, bytes, sources);
            Compiled { post: Some(post), diagnostics }
        }
        Dialect::Ron => return compile_ron(path, bytes, sources),
    };
    validated(&mut compiled, None, sources);
    compiled
}

/// Runs [`postc_ir::validate`] on a compiled post: what the runtime and the
/// backends trust. A RON post's problems point at the item of the text
/// that holds them; a frontend's would be a postc bug, reported at the
/// handler or function when it has a span.
fn validated(compiled: &mut Compiled, ron_file: Option<FileId>, sources: &SourceMap) {
    let Some(post) = &compiled.post else { return };
    let problems = postc_ir::validate::validate(post);
    if problems.is_empty() {
        regexes_run(post, ron_file, sources, &mut compiled.diagnostics);
        return;
    }
    for p in problems {
        let (field, index) = p.at.field();
        let place = match index {
            Some(i) => format!("{field}[{i}]"),
            None => field.to_string(),
        };
        let mut d = Diagnostic::error(codes::IR002, format!("{place}: {}", p.message))
            .help("a post's ids must name formats, variables, functions, globals and scripts it has");
        let span = match ron_file {
            Some(file) => sources
                .text(file)
                .and_then(|text| ron_locate::item(text, field, index))
                .map(|(start, end)| Span::new(file, start, end)),
            None => match p.at {
                postc_ir::validate::Item::Handler(i) => post.handlers.get(i).and_then(|h| h.span),
                postc_ir::validate::Item::Function(i) => post.functions.get(i).and_then(|f| f.span),
                _ => None,
            },
        };
        if let Some(span) = span {
            d = d.at(span, "here");
        }
        compiled.diagnostics.push(d);
    }
}

/// Compiles every regular expression of a valid post as the runtime will
/// (`postc_runtime::regex`): a pattern it cannot run (one that does not
/// read, a backreference, lookaround) is refused now, with JS108 at the
/// literal (in a RON post, which keeps no spans, at the item that holds
/// it), rather than when the post reaches it.
fn regexes_run(post: &Post, ron_file: Option<FileId>, sources: &SourceMap, diagnostics: &mut Vec<Diagnostic>) {
    use postc_ir::validate::Item;
    struct Regexes(Vec<(String, Option<Span>)>);
    impl postc_ir::visit::Visit for Regexes {
        fn visit_expr(&mut self, expr: &postc_ir::Expr) {
            if let postc_ir::Expr::Regex { pattern, flags, span } = expr
                && let Err(why) = postc_runtime::regex::Regex::new(pattern, flags)
            {
                self.0.push((format!("postc cannot run the regular expression /{pattern}/{flags}: {why}"), *span));
            }
            postc_ir::visit::walk_expr(self, expr);
        }
    }
    use postc_ir::visit::Visit as _;
    let mut items: Vec<(Item, Vec<&postc_ir::Stmt>, Option<&postc_ir::Expr>)> = Vec::new();
    items.extend(post.globals.iter().enumerate().map(|(i, g)| (Item::Global(i), Vec::new(), Some(&g.initial))));
    items.push((Item::Init, post.init.iter().collect(), None));
    items.extend(post.handlers.iter().enumerate().map(|(i, h)| (Item::Handler(i), h.body.iter().collect(), None)));
    for (i, f) in post.functions.iter().enumerate() {
        if let postc_ir::Body::Native(body) = &f.body {
            items.push((Item::Function(i), body.iter().collect(), None));
        }
    }
    for (item, body, initial) in items {
        let mut found = Regexes(Vec::new());
        body.into_iter().for_each(|s| found.visit_stmt(s));
        initial.into_iter().for_each(|e| found.visit_expr(e));
        for (message, span) in found.0 {
            let mut d = Diagnostic::error(codes::JS108, message)
                .help("postc matches in time linear in the text: a pattern without backreferences and lookaround runs");
            let (field, index) = item.field();
            let span = span.or_else(|| {
                let file = ron_file?;
                let (start, end) = ron_locate::item(sources.text(file)?, field, index)?;
                Some(Span::new(file, start, end))
            });
            if let Some(s) = span {
                d = d.at(s, "this regular expression");
            }
            diagnostics.push(d);
        }
    }
}

/// How deeply a RON post's items may nest.
const RON_DEPTH: usize = 4096;
/// The stack a RON post is read on: room for [`RON_DEPTH`] levels of the
/// reader's recursion in a debug build.
const RON_STACK: usize = 512 << 20;

/// A post written directly as IR in RON.
fn compile_ron(path: &Path, bytes: &[u8], sources: &mut SourceMap) -> Compiled {
    let text = String::from_utf8_lossy(bytes).into_owned();
    let file = sources.add(path.display().to_string(), text.clone());
    // The IR of a large post nests deeply (a JavaScript post's `else if`
    // chains and expressions): RON reads it to RON_DEPTH levels, on a
    // stack of its own big enough for them.
    let options = ron::Options::default().with_recursion_limit(RON_DEPTH);
    match stacker::grow(RON_STACK, || options.from_str::<Post>(&text)) {
        Ok(post) => {
            let mut compiled = Compiled { post: Some(post), diagnostics: Vec::new() };
            validated(&mut compiled, Some(file), sources);
            compiled
        }
        Err(e) => {
            if let Some((start, end)) = first_event(&text) {
                return Compiled::failed(
                    Diagnostic::error(
                        codes::IR001,
                        format!("`{}` is a toolpath (postc's native events), not a post", path.display()),
                    )
                    .at(postc_ir::Span::new(file, start, end), "a toolpath event")
                    .help("give the post first and the toolpath second: `postc post POST TOOLPATH`; a post as RON is what `postc convert --to ron` writes"),
                );
            }
            let offset = line_col_offset(&text, e.span.start.line, e.span.start.col);
            Compiled::failed(
                Diagnostic::error(codes::IR001, format!("this IR post does not read: {}", e.code))
                    .at(postc_ir::Span::new(file, offset, (offset + 1).min(text.len())), "here"),
            )
        }
    }
}

/// The byte range of the first line of `text` when it is a toolpath
/// event (a `.ron` toolpath given where a post belongs).
fn first_event(text: &str) -> Option<(usize, usize)> {
    let mut start = 0;
    for line in text.split_inclusive('\n') {
        let trimmed = line.trim();
        if !trimmed.is_empty() && !trimmed.starts_with("//") {
            let options = ron::Options::default().with_default_extension(
                ron::extensions::Extensions::IMPLICIT_SOME | ron::extensions::Extensions::UNWRAP_VARIANT_NEWTYPES,
            );
            options.from_str::<postc_ir::event::Event>(trimmed).ok()?;
            return Some((start, start + line.trim_end().len()));
        }
        start += line.len();
    }
    None
}

fn line_col_offset(text: &str, line: usize, col: usize) -> usize {
    let start: usize = text.split_inclusive('\n').take(line.saturating_sub(1)).map(str::len).sum();
    (start + col.saturating_sub(1)).min(text.len())
}

/// Toolpath file formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ToolpathFormat {
    /// The native event stream.
    Native,
    /// APT CL text.
    Apt,
}

/// The format of a toolpath file, from its name or its first bytes.
pub fn toolpath_format(path: &Path, head: &[u8]) -> Option<ToolpathFormat> {
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("").to_ascii_lowercase();
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    if name == "cl.tap" {
        return Some(ToolpathFormat::Apt);
    }
    match ext.as_deref() {
        Some("ron" | "jsonl" | "json" | "ndjson") => return Some(ToolpathFormat::Native),
        Some("apt" | "cl" | "cls" | "clsf" | "ncl" | "clt" | "aptsource") => return Some(ToolpathFormat::Apt),
        _ => {}
    }
    let text = String::from_utf8_lossy(head);
    let first = text.lines().map(str::trim).find(|l| !l.is_empty() && !l.starts_with("//"));
    match first {
        Some(l) if l.starts_with('{') || l.starts_with("Job(") || l.starts_with("Tool(") => {
            Some(ToolpathFormat::Native)
        }
        _ if postc_reader_apt::looks_like_cl(head) => Some(ToolpathFormat::Apt),
        _ => None,
    }
}

/// Whether a path names a toolpath rather than a post. A `.ron` file is a
/// post when it holds an IR post (it has `handlers`), else a toolpath. The
/// file's head is read through `loader`.
pub fn is_toolpath(path: &Path, loader: &dyn SourceLoader) -> bool {
    let head = read_head(loader, path);
    match dialect_of_extension(path) {
        Some(Dialect::Ron) => !looks_like_ir_post(&head),
        Some(_) => false,
        None => toolpath_format(path, &head).is_some(),
    }
}

fn looks_like_ir_post(head: &[u8]) -> bool {
    let text = String::from_utf8_lossy(head);
    text.contains("handlers") && text.contains("formats")
}

/// The first 16 KiB of a file (fewer when one read returns fewer), or
/// nothing when it cannot be read.
fn read_head(loader: &dyn SourceLoader, path: &Path) -> Vec<u8> {
    use std::io::Read;
    let mut head = vec![0u8; 1 << 14];
    let n = loader.open(path).and_then(|mut f| f.read(&mut head)).unwrap_or(0);
    head.truncate(n);
    head
}

/// Opens a toolpath as a stream of events, read on a thread of its own
/// ([`ReadAhead`]).
pub fn open_toolpath(path: &Path, sources: &mut SourceMap) -> Result<Box<dyn EventSource>, Diagnostic> {
    if !sources.loader().exists(path) {
        // A path that is there but cannot be followed (a loop of links) says why.
        let message = match sources.loader().len(path) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                format!("cannot open toolpath `{}`: {e}", path.display())
            }
            _ => format!("toolpath `{}` does not exist", path.display()),
        };
        return Err(Diagnostic::error(codes::IO001, message));
    }
    let events = match toolpath_format(path, &read_head(sources.loader(), path)) {
        Some(ToolpathFormat::Native) => ReadAhead::start(native::open(path, sources)?),
        Some(ToolpathFormat::Apt) => ReadAhead::start(postc_reader_apt::open(path, sources)?),
        None if !sources.loader().is_file(path) && sources.loader().read_dir(path).is_ok() => {
            return Err(Diagnostic::error(
                codes::IO001,
                format!("toolpath `{}` is a folder, not a file", path.display()),
            )
            .help("give the toolpath file inside it"));
        }
        None => {
            return Err(Diagnostic::error(
                codes::IO006,
                format!("cannot tell what kind of toolpath `{}` is", path.display()),
            )
            .help("name it .ron or .jsonl (native events) or .apt/.cl/.cls/.ncl (APT CL)"));
        }
    };
    Ok(Box::new(Outlined { events, path: path.to_path_buf(), loader: sources.shared_loader() }))
}

/// A toolpath file's events, and the job's outline read from the file once
/// more when a post that reads ahead asks for it.
struct Outlined {
    events: Box<dyn EventSource>,
    path: std::path::PathBuf,
    loader: Option<std::sync::Arc<dyn postc_ir::source::SourceLoader>>,
}

impl EventSource for Outlined {
    fn next_event(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<(postc_ir::event::Event, Span)> {
        self.events.next_event(diagnostics)
    }

    /// The second reading's diagnostics are the first's: they are dropped.
    fn outline(&mut self) -> Option<postc_ir::outline::JobOutline> {
        let mut sources = SourceMap::with_loader(self.loader.clone()?);
        let mut source: Box<dyn EventSource> =
            match toolpath_format(&self.path, &read_head(sources.loader(), &self.path))? {
                ToolpathFormat::Native => Box::new(native::open(&self.path, &mut sources).ok()?),
                ToolpathFormat::Apt => Box::new(postc_reader_apt::open(&self.path, &mut sources).ok()?),
            };
        let mut dropped = Vec::new();
        Some(postc_ir::outline::JobOutline::of(std::iter::from_fn(|| {
            dropped.clear();
            source.next_event(&mut dropped).map(|(e, _)| e)
        })))
    }
}

/// Reads a whole toolpath and returns every diagnostic (for `postc check`).
pub fn check_toolpath(path: &Path, sources: &mut SourceMap) -> Vec<Diagnostic> {
    if toolpath_format(path, &read_head(sources.loader(), path)) == Some(ToolpathFormat::Apt) {
        return postc_reader_apt::check(path, sources);
    }
    let mut source = match open_toolpath(path, sources) {
        Ok(s) => s,
        Err(d) => return vec![d],
    };
    let mut diagnostics = Vec::new();
    while source.next_event(&mut diagnostics).is_some() {}
    diagnostics
}

/// What the tests of this crate's modules (the root suite's
/// `tests/modules/driver/`) reach that is not its interface: nothing
/// else uses these.
#[doc(hidden)]
pub mod testing {
    pub mod read_ahead {
        pub use crate::read_ahead::BATCH;
    }
    pub mod ron_locate {
        pub use crate::ron_locate::item;
    }
}
