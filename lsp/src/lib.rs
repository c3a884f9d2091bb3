//! `postc lsp`: a Language Server Protocol server on stdio for Vectric
//! `.pp`, CIMCO `.js` and Vericut `.VcPost` posts (`docs/editors.md`).
//!
//! - Diagnostics on open and on every change: the document's text is
//!   compiled by `postc_driver::compile_post_bytes` with the dialect of
//!   its extension; every diagnostic of the document itself becomes an LSP
//!   diagnostic with its code and `source: "postc"`. Those of other files
//!   (a Vectric `POST_BASE`) are shown at the top of the document, named.
//! - Hover, definition, completion and code actions come from scanners
//!   over the text ([`analysis`]) and the tables of [`vocab`].
//!
//! Synchronous (rust-analyzer's `lsp-server`): one request at a time, full
//! text sync.

pub mod analysis;
pub mod text;
pub mod vocab;

use std::collections::HashMap;
use std::error::Error;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use lsp_server::{Connection, ExtractError, Message, Notification, Request, RequestId, Response};
use lsp_types::notification::{
    DidChangeTextDocument, DidCloseTextDocument, DidOpenTextDocument, Notification as _, PublishDiagnostics,
};
use lsp_types::request::{CodeActionRequest, Completion, GotoDefinition, HoverRequest, Request as _};
use lsp_types::{
    CodeAction, CodeActionKind, CodeActionOrCommand, CodeActionParams, CodeActionProviderCapability, CompletionItem,
    CompletionItemKind, CompletionOptions, CompletionParams, CompletionResponse, Diagnostic, DiagnosticSeverity,
    DidChangeTextDocumentParams, DidCloseTextDocumentParams, DidOpenTextDocumentParams, GotoDefinitionParams,
    GotoDefinitionResponse, Hover, HoverContents, HoverProviderCapability, Location, MarkupContent, MarkupKind,
    NumberOrString, OneOf, Position, PublishDiagnosticsParams, Range, ServerCapabilities, ServerInfo,
    TextDocumentSyncCapability, TextDocumentSyncKind, TextEdit, Uri, WorkspaceEdit,
};
use postc_ir::{Dialect, Severity, SourceLoader, SourceMap};

use crate::analysis::CompletionKind;

type BoxError = Box<dyn Error + Send + Sync>;

/// An open document.
struct Document {
    text: String,
    dialect: Option<Dialect>,
}

/// The server's capabilities.
pub fn capabilities() -> ServerCapabilities {
    ServerCapabilities {
        text_document_sync: Some(TextDocumentSyncCapability::Kind(TextDocumentSyncKind::FULL)),
        hover_provider: Some(HoverProviderCapability::Simple(true)),
        definition_provider: Some(OneOf::Left(true)),
        completion_provider: Some(CompletionOptions {
            trigger_characters: Some(vec!["[".into(), "<".into(), ".".into(), " ".into()]),
            ..CompletionOptions::default()
        }),
        code_action_provider: Some(CodeActionProviderCapability::Simple(true)),
        ..ServerCapabilities::default()
    }
}

/// Serves one client over a connection (the command line opens it on
/// stdin/stdout): the handshake, then messages until `shutdown` and `exit`.
/// `loader` reads the files a document names (a Vectric post's
/// `POST_BASE`): the command line gives the file system, tests can give
/// files in memory.
pub fn serve(connection: &Connection, loader: Arc<dyn SourceLoader>) -> Result<(), BoxError> {
    let (id, _params) = connection.initialize_start()?;
    let result = serde_json::json!({
        "capabilities": capabilities(),
        "serverInfo": ServerInfo { name: "postc".into(), version: Some(env!("CARGO_PKG_VERSION").into()) },
    });
    connection.initialize_finish(id, result)?;
    let mut docs: HashMap<String, Document> = HashMap::new();
    for msg in &connection.receiver {
        match msg {
            Message::Request(req) => {
                if connection.handle_shutdown(&req)? {
                    return Ok(());
                }
                let response = handle_request(&docs, req);
                connection.sender.send(Message::Response(response))?;
            }
            Message::Notification(not) => {
                if let Some(uri) = handle_notification(&mut docs, not) {
                    let diagnostics = docs.get(uri.as_str()).map_or_else(Vec::new, |d| diagnose(&uri, d, &loader));
                    let params = PublishDiagnosticsParams { uri, diagnostics, version: None };
                    let not = Notification::new(PublishDiagnostics::METHOD.into(), params);
                    connection.sender.send(Message::Notification(not))?;
                }
            }
            Message::Response(_) => {}
        }
    }
    Ok(())
}

/// Applies a notification; returns the document whose diagnostics changed.
fn handle_notification(docs: &mut HashMap<String, Document>, not: Notification) -> Option<Uri> {
    match not.method.as_str() {
        DidOpenTextDocument::METHOD => {
            let p: DidOpenTextDocumentParams = serde_json::from_value(not.params).ok()?;
            let dialect = dialect_of(p.text_document.uri.as_str());
            docs.insert(p.text_document.uri.as_str().to_owned(), Document { text: p.text_document.text, dialect });
            Some(p.text_document.uri)
        }
        DidChangeTextDocument::METHOD => {
            let p: DidChangeTextDocumentParams = serde_json::from_value(not.params).ok()?;
            let doc = docs.get_mut(p.text_document.uri.as_str())?;
            // Full sync: the last change holds the whole text. A ranged
            // change (a client ignoring our sync kind) is applied in place.
            for change in p.content_changes {
                match change.range {
                    None => doc.text = change.text,
                    Some(r) => {
                        let start = text::offset(&doc.text, r.start);
                        let end = text::offset(&doc.text, r.end).max(start);
                        doc.text.replace_range(start..end, &change.text);
                    }
                }
            }
            Some(p.text_document.uri)
        }
        DidCloseTextDocument::METHOD => {
            let p: DidCloseTextDocumentParams = serde_json::from_value(not.params).ok()?;
            docs.remove(p.text_document.uri.as_str());
            // Clear what the editor shows for the closed file.
            Some(p.text_document.uri)
        }
        _ => None,
    }
}

fn handle_request(docs: &HashMap<String, Document>, req: Request) -> Response {
    let id = req.id.clone();
    let known = [HoverRequest::METHOD, GotoDefinition::METHOD, Completion::METHOD, CodeActionRequest::METHOD];
    if !known.contains(&req.method.as_str()) {
        let message = format!("postc lsp does not handle `{}`", req.method);
        return Response::new_err(id, lsp_server::ErrorCode::MethodNotFound as i32, message);
    }
    match dispatch(docs, req) {
        Ok(value) => Response { id, result: Some(value), error: None },
        Err(message) => Response::new_err(id, lsp_server::ErrorCode::InvalidParams as i32, message),
    }
}

fn params<R: lsp_types::request::Request>(req: Request) -> Result<(RequestId, R::Params), String> {
    req.extract(R::METHOD).map_err(|e| match e {
        ExtractError::JsonError { method, error } => format!("bad parameters for {method}: {error}"),
        ExtractError::MethodMismatch(r) => format!("unexpected method {}", r.method),
    })
}

fn dispatch(docs: &HashMap<String, Document>, req: Request) -> Result<serde_json::Value, String> {
    let json = |v: Result<serde_json::Value, serde_json::Error>| v.map_err(|e| e.to_string());
    let doc_of = |uri: &Uri| docs.get(uri.as_str()).and_then(|d| Some((d, d.dialect?)));
    match req.method.as_str() {
        HoverRequest::METHOD => {
            let (_, p) = params::<HoverRequest>(req)?;
            let tdp = p.text_document_position_params;
            let Some((doc, dialect)) = doc_of(&tdp.text_document.uri) else { return Ok(serde_json::Value::Null) };
            let at = text::offset(&doc.text, tdp.position);
            let hover = analysis::hover(dialect, &doc.text, at).map(|h| Hover {
                contents: HoverContents::Markup(MarkupContent { kind: MarkupKind::Markdown, value: h.markdown }),
                range: Some(text::range(&doc.text, h.start, h.end)),
            });
            json(serde_json::to_value(hover))
        }
        GotoDefinition::METHOD => {
            let (_, p) = params::<GotoDefinition>(req)?;
            let tdp: GotoDefinitionParams = p;
            let pos = tdp.text_document_position_params;
            let uri = pos.text_document.uri;
            let Some((doc, dialect)) = doc_of(&uri) else { return Ok(serde_json::Value::Null) };
            let at = text::offset(&doc.text, pos.position);
            let def = analysis::definition(dialect, &doc.text, at)
                .map(|(s, e)| GotoDefinitionResponse::Scalar(Location::new(uri.clone(), text::range(&doc.text, s, e))));
            json(serde_json::to_value(def))
        }
        Completion::METHOD => {
            let (_, p) = params::<Completion>(req)?;
            let p: CompletionParams = p;
            let pos = p.text_document_position;
            let Some((doc, dialect)) = doc_of(&pos.text_document.uri) else { return Ok(serde_json::Value::Null) };
            let at = text::offset(&doc.text, pos.position);
            let after_space = p.context.is_some_and(|c| c.trigger_character.as_deref() == Some(" "));
            let items = analysis::completion(dialect, &doc.text, at, after_space)
                .into_iter()
                .map(|c| CompletionItem {
                    label: c.label,
                    kind: Some(match c.kind {
                        CompletionKind::Section => CompletionItemKind::MODULE,
                        CompletionKind::Variable => CompletionItemKind::VARIABLE,
                        CompletionKind::Function => CompletionItemKind::FUNCTION,
                        CompletionKind::Constant => CompletionItemKind::CONSTANT,
                        CompletionKind::Keyword => CompletionItemKind::KEYWORD,
                        CompletionKind::Property => CompletionItemKind::PROPERTY,
                    }),
                    detail: Some(c.detail),
                    ..CompletionItem::default()
                })
                .collect();
            json(serde_json::to_value(CompletionResponse::Array(items)))
        }
        CodeActionRequest::METHOD => {
            let (_, p) = params::<CodeActionRequest>(req)?;
            let p: CodeActionParams = p;
            let uri = p.text_document.uri;
            let Some((doc, dialect)) = doc_of(&uri) else { return Ok(serde_json::Value::Null) };
            let start = text::offset(&doc.text, p.range.start);
            let end = text::offset(&doc.text, p.range.end);
            let actions: Vec<CodeActionOrCommand> = analysis::fixes(dialect, &doc.text, start, end)
                .into_iter()
                .map(|f| {
                    let range = text::range(&doc.text, f.start, f.end);
                    let edit = TextEdit::new(range, f.replacement);
                    #[allow(clippy::mutable_key_type)] // Uri's hash is its text
                    let changes = HashMap::from([(uri.clone(), vec![edit])]);
                    let diagnostics: Vec<Diagnostic> =
                        p.context.diagnostics.iter().filter(|d| overlaps(d.range, range)).cloned().collect();
                    CodeActionOrCommand::CodeAction(CodeAction {
                        title: f.title,
                        kind: Some(CodeActionKind::QUICKFIX),
                        diagnostics: (!diagnostics.is_empty()).then_some(diagnostics),
                        edit: Some(WorkspaceEdit { changes: Some(changes), ..WorkspaceEdit::default() }),
                        is_preferred: Some(true),
                        ..CodeAction::default()
                    })
                })
                .collect();
            json(serde_json::to_value(actions))
        }
        other => Err(format!("postc lsp does not handle `{other}`")),
    }
}

fn overlaps(a: Range, b: Range) -> bool {
    a.start <= b.end && b.start <= a.end
}

/// The dialect a document's extension names.
#[doc(hidden)]
pub fn dialect_of(uri: &str) -> Option<Dialect> {
    let path = uri.split(['?', '#']).next().unwrap_or(uri);
    postc_driver::dialect_of_extension(std::path::Path::new(path))
}

/// The file path of a `file:` URI (percent-decoded); another scheme gives
/// its text as a name.
pub fn path_of(uri: &str) -> PathBuf {
    let Some(rest) = uri.strip_prefix("file://") else { return PathBuf::from(uri) };
    let rest = rest.strip_prefix("localhost").unwrap_or(rest);
    let bytes = rest.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        let hex = |b: u8| (b as char).to_digit(16);
        if bytes[i] == b'%'
            && i + 2 < bytes.len()
            && let (Some(h), Some(l)) = (hex(bytes[i + 1]), hex(bytes[i + 2]))
        {
            out.push((h * 16 + l) as u8);
            i += 3;
            continue;
        }
        out.push(bytes[i]);
        i += 1;
    }
    let mut s = String::from_utf8_lossy(&out).into_owned();
    // file:///C:/x on Windows.
    if s.len() > 2 && s.as_bytes()[0] == b'/' && s.as_bytes()[2] == b':' {
        s.remove(0);
    }
    PathBuf::from(s)
}

/// The LSP diagnostics of a document: its text compiled as its dialect.
fn diagnose(uri: &Uri, doc: &Document, loader: &Arc<dyn SourceLoader>) -> Vec<Diagnostic> {
    let path = path_of(uri.as_str());
    let mut sources = SourceMap::with_loader(Arc::clone(loader));
    match compile_checked(&path, doc.text.as_bytes(), doc.dialect, &mut sources) {
        Some(compiled) => convert(&path, &doc.text, &sources, &compiled.diagnostics),
        None => vec![Diagnostic {
            range: Range::default(),
            severity: Some(DiagnosticSeverity::ERROR),
            source: Some("postc".into()),
            message: "postc failed while checking this post (a postc bug: please report it with the post)".into(),
            ..Diagnostic::default()
        }],
    }
}

/// A post's text compiled as its dialect, as an editor shows it: the
/// frontend's diagnostics, the lints `postc check` runs on a post that
/// compiles, and the severities of the project's postc.toml (read through
/// the source map's loader). What the language server and the workbench
/// (`postc serve`) both show. `None` when postc panicked on the text (a
/// frontend bug must not take the editor's server down with it).
pub fn compile_checked(
    path: &Path,
    bytes: &[u8],
    dialect: Option<Dialect>,
    sources: &mut SourceMap,
) -> Option<postc_driver::Compiled> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let mut compiled = postc_driver::compile_post_bytes(path, bytes, dialect, sources);
        // The lints, as `postc check` runs them, on a post that compiles.
        if let Some(post) = &compiled.post
            && !postc_ir::diagnostic::has_errors(&compiled.diagnostics)
        {
            compiled.diagnostics.extend(postc_lint::lint(post, &postc_lint::Options::default()));
        }
        // The severities the project's postc.toml chooses, as on the command line.
        match postc_lint::config::rules_for(sources.loader(), path) {
            Ok(rules) => rules.apply(&mut compiled.diagnostics),
            Err(d) => compiled.diagnostics.push(d),
        }
        compiled
    }))
    .ok()
}

/// Converts postc diagnostics into LSP ones for the document at `path`.
pub fn convert(path: &Path, text: &str, sources: &SourceMap, diagnostics: &[postc_ir::Diagnostic]) -> Vec<Diagnostic> {
    let name = path.display().to_string();
    let mut out = Vec::new();
    for d in diagnostics {
        let primary = d.labels.iter().find(|l| l.primary).or(d.labels.first());
        let mut message = d.message.clone();
        let range = match primary {
            Some(l) if sources.name(l.span.file) == name => {
                // Spans index the text the frontend decoded, which is the
                // document's own text (a BOM aside): use it for positions.
                let basis = sources.text(l.span.file).unwrap_or(text);
                if !l.message.is_empty() {
                    message.push_str(&format!(" ({})", l.message));
                }
                text::range(basis, l.span.start, l.span.end)
            }
            Some(l) => {
                // Another file (POST_BASE): keep the problem visible at the
                // top of this document, saying where it is.
                let other = sources.name(l.span.file);
                let at = match sources.line_column(l.span.file, l.span.start) {
                    Some((line, col)) => format!("{other}:{line}:{col}"),
                    None => other.to_owned(),
                };
                message = format!("in {at}: {message}");
                Range::new(Position::new(0, 0), Position::new(0, 0))
            }
            None => Range::new(Position::new(0, 0), Position::new(0, 0)),
        };
        if let Some(help) = &d.help {
            message.push_str(&format!("\nhelp: {help}"));
        }
        for note in &d.notes {
            message.push_str(&format!("\nnote: {note}"));
        }
        out.push(Diagnostic {
            range,
            severity: Some(match d.severity {
                Severity::Error => DiagnosticSeverity::ERROR,
                Severity::Warning => DiagnosticSeverity::WARNING,
                Severity::Note => DiagnosticSeverity::INFORMATION,
            }),
            code: Some(NumberOrString::String(d.code.to_owned())),
            source: Some("postc".into()),
            message,
            ..Diagnostic::default()
        });
    }
    out
}

/// What the tests of this crate's modules (`tests/modules/`) reach that is
/// not its interface: nothing else uses these.
#[doc(hidden)]
pub mod testing {
    pub use crate::dialect_of;
}
