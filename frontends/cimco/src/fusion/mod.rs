//! Autodesk Fusion / HSM `.cps` posts: the same JavaScript front end as
//! CNC-Calc's (lexer, parser, the general lowering, JavaScript's values),
//! with Fusion's host API in place of CNC-Calc's.
//!
//! The host API is JavaScript ([`HOST`], `host.js`): the constants,
//! settings, formats, output variables, sections, tools and vectors
//! Autodesk's engine gives a post, and the engine functions that call the
//! post's entry points. [`compile`] reads it as a second source file,
//! puts its statements before the post's and lowers the two as one
//! program; a function the post declares replaces the host's of that
//! name, as a post's declaration shadows a global in Fusion. A file the
//! post includes at its top level (`include("common.js")`) is read
//! through the source map's loader and its statements take the call's
//! place.

pub mod api;

use std::collections::HashSet;
use std::path::Path;

use postc_ir::{Diagnostic, Dialect, Post, SourceMap, Span, codes};

use crate::ast::{ExprKind, Program, StmtKind};

/// postc's Fusion host API, in JavaScript.
pub const HOST: &str = include_str!("host.js");

/// The name the host's source has in diagnostics.
pub const HOST_NAME: &str = "<postc fusion host>";

/// What postc's host does with a name of Fusion's host API.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Support {
    /// The host defines it: a function, or a variable with the source text
    /// of its starting value (`1`, `"\r\n"`), when it has one.
    Runs { value: Option<String> },
    /// The host has it only to stop the post with a message naming it
    /// (`JS110`: postc does not run it yet).
    Stub,
    /// The host does not define it (`JS109` when a post uses it).
    Missing,
}

/// The host's top-level names and what it does with each, read once.
static SUPPORT: std::sync::LazyLock<std::collections::HashMap<String, Support>> = std::sync::LazyLock::new(|| {
    let (host, _) = crate::parse_as(HOST, postc_ir::FileId(0), crate::Syntax::Fusion);
    let stubs = stubs(&host);
    let mut names = std::collections::HashMap::new();
    for s in &host.body {
        match &s.kind {
            StmtKind::Function(f) => {
                if let Some(n) = &f.name {
                    let support = if stubs.contains(&n.name) { Support::Stub } else { Support::Runs { value: None } };
                    names.insert(n.name.clone(), support);
                }
            }
            StmtKind::Var(declarators) => {
                for d in declarators {
                    let value = d.init.as_ref().and_then(|e| HOST.get(e.span.start..e.span.end));
                    names.insert(d.name.name.clone(), Support::Runs { value: value.map(str::to_string) });
                }
            }
            _ => {}
        }
    }
    names
});

/// What postc's host does with `name` (a name of Fusion's host API).
pub fn support(name: &str) -> Support {
    SUPPORT.get(name).cloned().unwrap_or(Support::Missing)
}

/// Compiles a Fusion post: the IR and every diagnostic, sorted by position.
pub fn compile(path: &Path, bytes: &[u8], sources: &mut SourceMap) -> (Post, Vec<Diagnostic>) {
    let text = String::from_utf8_lossy(bytes).into_owned();
    // The file as written, for a conversion to its own dialect; a file that
    // is not UTF-8 is read with replacement characters, which are not it.
    let written = std::str::from_utf8(bytes).map_or_else(|_| String::new(), str::to_string);
    let file = sources.add(path.display().to_string(), text);
    let host_file = sources.add(HOST_NAME.to_string(), HOST.to_string());
    let text = sources.text(file).unwrap_or_default().to_string();
    let (mut program, mut diagnostics) = crate::parse_as(&text, file, crate::Syntax::Fusion);
    // `include("file")` at the top level: the file's statements in its
    // place (docs/fusion.md, choice 30).
    let folder = path.parent().unwrap_or(Path::new("")).to_path_buf();
    program.body = included(std::mem::take(&mut program.body), &folder, sources, &mut diagnostics, 0);
    // Fusion's engine reads `let` and `const` (CNC-Calc's does not); postc
    // reads them as `var` (docs/fusion.md, "Language").
    diagnostics.retain(|d| d.code != codes::JS018.code);
    let (mut host, host_diagnostics) = crate::parse_as(HOST, host_file, crate::Syntax::Fusion);
    diagnostics.extend(host_diagnostics);
    // `getConfigurationPath()` is the post's own file, as postc was given
    // it (docs/fusion.md, choice 28).
    set_host_text(&mut host, CONFIGURATION_PATH, &path.display().to_string());
    let mut post = Post::default();
    post.info.dialect = Dialect::Fusion;
    post.info.host_file = Some(host_file);
    post.info.source = path.display().to_string();
    post.info.name = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    post.info.file_extension = "nc".into();
    post.info.written = written;
    // What the post says of itself: its name as Fusion's post library shows
    // it (`description`) and its files' extension. The host gives both a
    // default, so in the merged program neither is a constant: they are
    // read from the post's own statements.
    if let Some(description) = own_text(&program, "description").filter(|d| !d.trim().is_empty()) {
        post.info.name = description.trim().to_string();
    }
    if let Some(extension) = own_text(&program, "extension").filter(|e| !e.trim().is_empty()) {
        post.info.file_extension = extension.trim().trim_start_matches('.').to_string();
    }
    // A post that reads `unit` writes for the units it is handed
    // (docs/fusion.md, choice 4).
    post.info.reads_units = reads_unit(&program);
    // `setCodePage("ansi")`: the program is written in Windows-1252
    // (docs/fusion.md, choice 38).
    if code_pages(&program).is_some_and(|pages| pages.iter().all(|p| p.eq_ignore_ascii_case("ansi"))) {
        post.info.text_encoding = postc_ir::post::TextEncoding::Windows1252;
        post.options.windows_1252_output = true;
    }
    if !postc_ir::diagnostic::has_errors(&diagnostics) {
        let stubs = stubs(&host);
        let merged = merge(host, program);
        crate::lower::fusion::lower(&merged, Span::new(file, 0, text.len()), &stubs, &mut post, &mut diagnostics);
    }
    diagnostics.sort_by_key(|d| d.primary_span().map(|s| (s.start, s.end)));
    (post, diagnostics)
}

/// How deep `include`s may nest (an included file that includes
/// another, ...): past it, or in a loop, an include is refused.
const INCLUDE_DEPTH: usize = 8;

/// The statements with each top-level `include("name")` replaced by the
/// statements of the file `name` beside the post, as Fusion's engine runs
/// the included file where the call is (its functions and variables are
/// the post's globals). A file that cannot be read is an error at the call
/// (JS111) naming it; an `include` of a name made when the post runs is
/// left to the host, which stops there.
fn included(
    body: Vec<crate::ast::Stmt>,
    folder: &Path,
    sources: &mut SourceMap,
    diagnostics: &mut Vec<Diagnostic>,
    depth: usize,
) -> Vec<crate::ast::Stmt> {
    let mut out = Vec::with_capacity(body.len());
    for s in body {
        let name = match &s.kind {
            StmtKind::Expr(e) => match &e.kind {
                ExprKind::Call { callee, args } if matches!(&callee.kind, ExprKind::Ident(n) if n == "include") => {
                    match args.as_slice() {
                        [crate::ast::Expr { kind: ExprKind::String(name), .. }] => Some(name.clone()),
                        _ => None,
                    }
                }
                _ => None,
            },
            _ => None,
        };
        let Some(name) = name else {
            out.push(s);
            continue;
        };
        let path = folder.join(&name);
        if depth >= INCLUDE_DEPTH {
            diagnostics.push(
                Diagnostic::error(
                    codes::JS111,
                    format!("the post includes `{name}` more than {INCLUDE_DEPTH} files deep"),
                )
                .at(s.span, "this include")
                .note("an included file that includes itself, directly or through others, never ends"),
            );
            continue;
        }
        match sources.loader().read(&path) {
            Ok(bytes) => {
                let text = String::from_utf8_lossy(&bytes).into_owned();
                let id = sources.add(path.display().to_string(), text);
                let text = sources.text(id).unwrap_or_default().to_string();
                let (program, found) = crate::parse_as(&text, id, crate::Syntax::Fusion);
                diagnostics.extend(found.into_iter().filter(|d| d.code != codes::JS018.code));
                let inner = path.parent().unwrap_or(folder).to_path_buf();
                out.extend(included(program.body, &inner, sources, diagnostics, depth + 1));
            }
            Err(e) => diagnostics.push(
                Diagnostic::error(codes::JS111, format!("the post includes `{name}`, which cannot be read: {e}"))
                    .at(s.span, "this include")
                    .note(format!("Fusion reads it from the post's folder: `{}`", path.display()))
                    .note("no program is written"),
            ),
        }
    }
    out
}

/// The host's variable that holds the post's own path.
pub const CONFIGURATION_PATH: &str = "__configurationPath";

/// Gives the host's top-level `var NAME = "..."` the text `value`.
fn set_host_text(host: &mut Program, name: &str, value: &str) {
    for s in &mut host.body {
        if let StmtKind::Var(ds) = &mut s.kind {
            for d in ds.iter_mut().filter(|d| d.name.name == name) {
                if let Some(init) = &mut d.init {
                    init.kind = ExprKind::String(value.to_string());
                }
            }
        }
    }
}

/// The host's functions that only stop the post (`__unsupported(...)`):
/// host API postc does not run yet.
fn stubs(host: &Program) -> HashSet<String> {
    host.body
        .iter()
        .filter_map(|s| match &s.kind {
            StmtKind::Function(f) => match f.body.as_slice() {
                [only] => match &only.kind {
                    StmtKind::Expr(e) => match &e.kind {
                        ExprKind::Call { callee, .. }
                            if matches!(&callee.kind, ExprKind::Ident(n) if n == "__unsupported") =>
                        {
                            f.name.as_ref().map(|n| n.name.clone())
                        }
                        _ => None,
                    },
                    _ => None,
                },
                _ => None,
            },
            _ => None,
        })
        .collect()
}

/// The text the post's last top-level statement of the form `NAME =
/// "..."` (or `var NAME = "..."`) gives NAME.
fn own_text(program: &Program, name: &str) -> Option<String> {
    let text_of = |e: &crate::ast::Expr| match &e.kind {
        ExprKind::String(t) => Some(t.clone()),
        _ => None,
    };
    program.body.iter().rev().find_map(|s| match &s.kind {
        StmtKind::Expr(e) => match &e.kind {
            ExprKind::Assign { op: crate::ast::AssignOp::Assign, target, value } => {
                matches!(&target.kind, ExprKind::Ident(n) if n == name).then(|| text_of(value)).flatten()
            }
            _ => None,
        },
        StmtKind::Var(ds) => ds.iter().rev().find(|d| d.name.name == name)?.init.as_ref().and_then(text_of),
        _ => None,
    })
}

/// The code pages the post's own code gives `setCodePage`, when it calls
/// it and every call names one as text; `None` otherwise.
fn code_pages(program: &Program) -> Option<Vec<String>> {
    let (mut pages, mut other) = (Vec::new(), false);
    each_expr(program, |e| {
        if let ExprKind::Call { callee, args } = &e.kind
            && matches!(&callee.kind, ExprKind::Ident(n) if n == "setCodePage")
        {
            match args.as_slice() {
                [a] if let ExprKind::String(t) = &a.kind => pages.push(t.clone()),
                _ => other = true,
            }
        }
    });
    (!other && !pages.is_empty()).then_some(pages)
}

/// Whether the post's own code (its file and the files it includes, not
/// the host's) names `unit`, the units Fusion hands it.
fn reads_unit(program: &Program) -> bool {
    let mut reads = false;
    each_expr(program, |e| reads |= matches!(&e.kind, ExprKind::Ident(n) if n == "unit"));
    reads
}

/// Calls `f` on every expression of the program, in its functions and
/// function expressions too.
fn each_expr(program: &Program, f: impl FnMut(&crate::ast::Expr)) {
    use crate::lower::scope::{Visit, walk_stmts};
    struct Each<F>(F);
    impl<'a, F: FnMut(&crate::ast::Expr)> Visit<'a> for Each<F> {
        fn expr(&mut self, e: &'a crate::ast::Expr) -> bool {
            (self.0)(e);
            if let ExprKind::Function(f) = &e.kind {
                walk_stmts(&f.body, self);
            }
            true
        }
        fn function_decl(&mut self, f: &'a crate::ast::Function) {
            walk_stmts(&f.body, self);
        }
    }
    walk_stmts(&program.body, &mut Each(f));
}

/// The host's statements, less the functions (and variables) of names the post declares functions of, then the
/// post's.
fn merge(host: Program, post: Program) -> Program {
    let declared: HashSet<&str> = post
        .body
        .iter()
        .filter_map(|s| match &s.kind {
            StmtKind::Function(f) => f.name.as_ref().map(|n| n.name.as_str()),
            _ => None,
        })
        .collect();
    // A host function the post's top-level code assigns
    // (`setWriteInvocations = true;`, `var isMilling = false;`) is a global variable that starts as
    // that function, as a function declaration is a global JavaScript may
    // assign.
    let assigned: HashSet<&str> = post
        .body
        .iter()
        .filter_map(|s| match &s.kind {
            StmtKind::Expr(e) => match &e.kind {
                ExprKind::Assign { target, .. } => match &target.kind {
                    ExprKind::Ident(n) if !declared.contains(n.as_str()) => Some(vec![n.as_str()]),
                    _ => None,
                },
                _ => None,
            },
            // `var isMilling = false;` assigns the host's `isMilling` too.
            StmtKind::Var(ds) => Some(
                ds.iter()
                    .filter(|d| d.init.is_some() && !declared.contains(d.name.name.as_str()))
                    .map(|d| d.name.name.as_str())
                    .collect(),
            ),
            _ => None,
        })
        .flatten()
        .collect();
    // A host variable of a name the post declares a function of (`var end`
    // and the post's `function end()`) is that function, as a function
    // declaration replaces a global of its name in JavaScript.
    let mut body: Vec<_> = host
        .body
        .into_iter()
        .filter_map(|mut s| match &mut s.kind {
            StmtKind::Function(f) if f.name.as_ref().is_some_and(|n| assigned.contains(n.name.as_str())) => {
                let mut f = f.clone();
                let name = f.name.take().expect("a named function");
                let value = crate::ast::Expr::new(ExprKind::Function(Box::new(f)), s.span);
                let var = crate::ast::VarDeclarator { span: name.span, name, init: Some(value) };
                Some(crate::ast::Stmt::new(StmtKind::Var(vec![var]), s.span))
            }
            StmtKind::Function(f) => f.name.as_ref().is_none_or(|n| !declared.contains(n.name.as_str())).then_some(s),
            StmtKind::Var(ds) => {
                ds.retain(|d| !declared.contains(d.name.name.as_str()));
                (!ds.is_empty()).then_some(s)
            }
            _ => Some(s),
        })
        .collect();
    body.extend(post.body);
    Program { body, span: post.span }
}
