//! A CIMCO post with code printed as the CNC-Calc JavaScript it is, in the
//! order the CIMCO frontend compiles back to the same IR:
//!
//! 1. a `//` comment naming the source file and dialect;
//! 2. the top-level statements in the source's order (the list
//!    `__postc_init` keeps, `Function::source`): each as written, but where
//!    the IR holds what a statement made, the IR's: a `globals = {...}` or
//!    `PostInfo = {...}` object from its properties (the post's settings:
//!    `linebreak`, `tolerance`, `useRadius`, `PostInfo.title`,
//!    `PostInfo.type`, ...), a constant as `var name = value;` (bare
//!    settings such as `var linebreak = "\n";` among them), a format as
//!    `var name = createFormat({...});` and an output variable as `var
//!    name = createVariable({...}, format);`, with the keys that differ
//!    from CNC-Calc's defaults (no `var` for a global the source did not
//!    declare, `Global::implicit`);
//! 3. every function of the post, in order, under its name: a native one
//!    printed from its IR ([`super::body`]), one whose IR does not say all
//!    of it (a script, a reader of `arguments`, an `onInit` that makes
//!    formats) as written.
//!
//! What postc added is left out, since compiling the post adds it again:
//! `__postc_init` and the bridges to the entry points, `getFeedrate` and
//! its variables when the post has none of its own, the forms of a
//! function for each number of arguments (`writeBlock/5`), the globals of
//! text constants. The handlers are not printed either: the CIMCO frontend
//! derives them from the functions' names ([`super::check`] makes sure the
//! post's are those).
//!
//! Refused: options no CNC-Calc setting sets (`CV004`), formats
//! `createFormat` cannot make (`CV003`), variables `createVariable` cannot
//! make (`CV005`), scripts whose JavaScript was not kept and bodies no
//! CNC-Calc function says (`CV002`).

use std::collections::HashSet;

use postc_front_cimco::ast::{
    AssignOp, Expr as Js, ExprKind, KeyForm, Property, PropertyKey, Stmt as JsStmt, StmtKind, VarDeclarator,
};
use postc_front_cimco::{made, print as js};
use postc_ir::codes;
use postc_ir::format::Rounding;
use postc_ir::post::{BlockNumbers, Dispatch};
use postc_ir::{
    Body, CommentTarget, Diagnostic, Expr, FunctionId, Justify, Modality, NumberFormat, OutputOptions, Padding,
    PointStyle, Post, SignStyle, SourceText, Span, TextEncoding, ValueSource, VarId, WidthOf,
};

use super::body::{self, at, call, ident, js, name};
use super::refusal;

/// Prints `post`, a CIMCO post with code, or says why it cannot be printed.
pub(super) fn print(post: &Post) -> Result<Vec<u8>, Vec<Diagnostic>> {
    let Some(init) = post.functions.iter().position(|f| f.name == made::INIT) else {
        return Err(vec![refusal(
            codes::CV006.code,
            None,
            format!("this CIMCO post has no `{}`, the start-up function the CIMCO frontend makes", made::INIT),
            "it was not compiled from CNC-Calc JavaScript (a RON post edited by hand?)",
        )]);
    };
    let texts = &post.functions[init].source;
    if texts.is_empty() && !post.globals.is_empty() {
        return Err(vec![refusal(
            codes::CV006.code,
            None,
            "this CIMCO post's IR does not keep its top-level statements (the `source` of `__postc_init`)".into(),
            "a RON post written by an older postc? Convert the JavaScript post to RON again",
        )]);
    }
    // As written where the IR keeps the source's text and that text still
    // compiles to what the IR holds; from the IR otherwise.
    if has_written(post)
        && let Ok(text) = printed(post, texts, init, true)
        && super::check::compiles_back(post, &text).is_ok()
    {
        return Ok(text.into_bytes());
    }
    let text = printed(post, texts, init, false)?;
    super::check::compiles_back(post, &text)?;
    Ok(text.into_bytes())
}

/// Whether the IR keeps any piece of the source as written
/// ([`SourceText::written`]).
fn has_written(post: &Post) -> bool {
    post.functions.iter().flat_map(|f| &f.source).any(|s| !s.written.is_empty())
}

/// The post printed: `as_written`, each piece the IR keeps as the source
/// has it (its comments, blank lines, spellings and line endings) and the
/// rest from the IR; otherwise all from the IR.
fn printed(post: &Post, texts: &[SourceText], init: usize, as_written: bool) -> Result<String, Vec<Diagnostic>> {
    let crlf = as_written && post.functions.iter().flat_map(|f| &f.source).any(|s| s.written.contains("\r\n"));
    let mut p =
        Printer { post, out: String::new(), errors: Vec::new(), as_written, eol: if crlf { "\r\n" } else { "\n" } };
    p.options();
    if !p.errors.is_empty() {
        return Err(p.errors);
    }
    p.header();
    p.top_level(texts);
    p.functions(init);
    if !p.errors.is_empty() {
        return Err(p.errors);
    }
    Ok(p.out)
}

struct Printer<'p> {
    post: &'p Post,
    out: String,
    errors: Vec<Diagnostic>,
    /// Print the pieces the IR keeps as written ([`SourceText::written`]).
    as_written: bool,
    /// The line ending of what the printer writes itself: the source's,
    /// when it prints pieces as written.
    eol: &'static str,
}

/// An object literal: `{key: value, ...}`.
fn object(props: Vec<(&str, Js)>) -> Js {
    let props = props
        .into_iter()
        .map(|(key, value)| Property {
            key: PropertyKey { name: key.to_string(), written: KeyForm::Ident, span: at() },
            value,
            span: at(),
        })
        .collect();
    js(ExprKind::Object(props))
}

impl Printer<'_> {
    fn refuse(&mut self, code: &'static str, span: Option<Span>, message: String, why: &str) {
        self.errors.push(refusal(code, span, message, why));
    }

    /// What a CNC-Calc post cannot set: everything but the line ending
    /// (`linebreak`), the chord tolerance (`tolerance`), the lathe mapping
    /// (`PostInfo.type`) and modal memory kept for the whole program, which
    /// its globals and its semantics say.
    fn options(&mut self) {
        let (o, info) = (&self.post.options, &self.post.info);
        let d = OutputOptions::default();
        if info.dispatch != Dispatch::Sections {
            self.refuse(
                codes::CV001.code,
                None,
                "this post is driven by APT words or application calls".into(),
                "CNC-Calc calls a post's functions per kind of move",
            );
        }
        for (what, yes) in [
            ("block numbers of the runtime", o.block_numbers != BlockNumbers::default()),
            ("substitutions of characters", !o.substitutions.is_empty()),
            ("tape splitting", o.tape_splitting.is_some()),
            ("a spindle speed range", o.spindle_speed_range.is_some()),
            ("a rotary wrap", o.rotary_wrap.is_some()),
            ("a minimum or maximum arc radius", o.min_arc_radius.is_some() || o.max_arc_radius.is_some()),
            ("inverse-time feeds", o.inverse_time_feed),
            ("exact arcs", o.exact_arcs != d.exact_arcs),
            ("a step budget", o.step_budget != d.step_budget),
            ("modal memory cleared when a toolpath starts (Vectric's rule)", o.forget_modal_at_toolpath_start),
            ("modal words that compare values, not text (Vectric's rule)", o.on_change_by_value),
            ("the feed printed again after each rapid (Vectric's rule)", o.rapid_forgets_feed),
            ("output units", info.units.is_some()),
            ("laser support", info.laser_support),
            ("direct output", info.direct_output.is_some() || info.print_direct),
            ("rapid plunges to the start height", info.rapid_plunge_to_start_z),
            ("text in Windows-1252", info.text_encoding != TextEncoding::Utf8),
            ("Sub signatures", !info.subs.is_empty()),
        ] {
            if yes {
                self.refuse(
                    codes::CV004.code,
                    info.span,
                    format!("the post sets {what}, which no CNC-Calc setting sets"),
                    "a CNC-Calc post sets its line ending, chord tolerance and lathe mapping through its globals; the rest is the host's",
                );
            }
        }
        if info.file_extension != "nc" {
            self.refuse(
                codes::CV004.code,
                None,
                format!("the post writes `.{}` files; a CNC-Calc post's programs are `.nc`", info.file_extension),
                "CNC-Calc posts have no setting for the extension",
            );
        }
    }

    fn header(&mut self) {
        if self.as_written {
            // The source's head is in its first piece, as written.
            self.out.push_str(&super::note(self.post));
            self.out.push_str(self.eol);
            return;
        }
        self.out.push_str(&super::header(self.post));
        self.out.push('\n');
    }

    /// Ends the line the output ends in, if it does not end in a line break.
    fn end_line(&mut self) {
        if !self.out.is_empty() && !self.out.ends_with('\n') {
            self.out.push_str(self.eol);
        }
    }

    /// The top-level statements in the source's order: as written, or,
    /// where the IR holds a statement, the constant, format, variable or
    /// object it made; then whatever the IR holds that no statement
    /// placed (a post not compiled from JavaScript).
    fn top_level(&mut self, texts: &[SourceText]) {
        let post = self.post;
        let mut printed: HashSet<&str> = HashSet::new();
        if self.as_written {
            self.written(texts);
        }
        for t in texts {
            if self.as_written && !t.written.is_empty() {
                printed.extend(t.declares.iter().map(String::as_str));
            } else if t.text.is_empty() {
                self.end_line();
                for name in &t.declares {
                    if printed.insert(name) {
                        self.held(name);
                    }
                }
            } else {
                self.end_line();
                printed.extend(t.declares.iter().map(String::as_str));
                self.out.push_str(t.text.trim_end());
                self.out.push('\n');
            }
        }
        // Made by a function kept as written (`onInit`).
        printed.extend(
            post.functions
                .iter()
                .filter(|f| f.name != made::INIT)
                .flat_map(|f| &f.source)
                .flat_map(|t| &t.declares)
                .map(String::as_str),
        );
        for g in &post.globals {
            let name = g.name.as_str();
            if !g.implicit && !name.contains('.') && printed.insert(name) {
                self.end_line();
                self.held(name);
            }
        }
        if !self.as_written {
            self.out.push('\n');
        }
    }

    /// Every piece the IR keeps as written, top-level statements and
    /// functions, in the source's order.
    fn written(&mut self, texts: &[SourceText]) {
        let functions = self.post.functions.iter().filter(|f| f.name != made::INIT).filter_map(|f| f.source.first());
        let mut pieces: Vec<&SourceText> = texts.iter().chain(functions).filter(|t| !t.written.is_empty()).collect();
        pieces.sort_by_key(|t| t.written_at);
        for t in pieces {
            self.out.push_str(&t.written);
        }
    }

    /// The statement that made a global the IR holds: `globals = {...};`
    /// from the properties `globals.decimalMark`, ..., `var xyzFormat =
    /// createFormat({...});`, `var xOutput = createVariable({...}, ...);`,
    /// `var linebreak = "\n";` (without `var` for a global the source
    /// did not declare).
    fn held(&mut self, name: &str) {
        let post = self.post;
        let value = if let Some(props) = self.object(name) {
            Some(props)
        } else if let Some(f) = post.formats.iter().position(|f| f.name.as_deref() == Some(name)) {
            self.create_format(f)
        } else if let Some(v) = post.variables.iter().position(|v| v.name == name) {
            self.out.push_str(&super::comment(post, &CommentTarget::Variable(VarId::new(v as u16))));
            self.create_variable(v)
        } else {
            post.globals.iter().find(|g| g.name == name).and_then(|g| body::literal(&g.initial))
        };
        let Some(value) = value else { return };
        let implicit = post.globals.iter().find(|g| g.name == name).is_none_or(|g| g.implicit);
        let s = if implicit {
            let target = Box::new(body::name(name));
            StmtKind::Expr(js(ExprKind::Assign { op: AssignOp::Assign, target, value: Box::new(value) }))
        } else {
            StmtKind::Var(vec![VarDeclarator { name: ident(name), init: Some(value), span: at() }])
        };
        self.statement(JsStmt::new(s, at()));
    }

    /// `{...}` of the properties of object `name` (`globals.decimalMark`,
    /// ...), if the post has any.
    fn object(&self, name: &str) -> Option<Js> {
        let mut props = Vec::new();
        for g in &self.post.globals {
            let Some(property) = g.name.strip_prefix(name).and_then(|p| p.strip_prefix('.')) else { continue };
            let value = match (g.name.as_str(), &g.initial) {
                ("PostInfo.type", Expr::Number(t)) if *t == 0.0 || *t == 1.0 => {
                    body::name(if *t == 1.0 { "POST_TYPE_TURN" } else { "POST_TYPE_MILL" })
                }
                (_, e) => body::literal(e)?,
            };
            props.push((property, value));
        }
        (!props.is_empty()).then(|| object(props))
    }

    /// One statement, as the frontend's printer writes it.
    fn statement(&mut self, s: JsStmt) {
        self.out.push_str(&js::to_js(&postc_front_cimco::Program { body: vec![s], span: at() }));
    }

    /// `createFormat({...})` with the keys that differ from CNC-Calc's
    /// defaults (`docs/cimco.md`), or a refusal.
    fn create_format(&mut self, f: usize) -> Option<Js> {
        let format = &self.post.formats[f];
        let what = format.name.as_deref().map_or_else(|| format!("format {f}"), |n| format!("format `{n}`"));
        let mark = self.decimal_mark();
        let force_decimal = format.point == PointStyle::Always;
        for (cannot, yes) in [
            ("a width of the whole number", format.width_of != WidthOf::IntegerDigits),
            ("left justification", format.justify != Justify::Right),
            ("trailing zeros kept without a forced point", format.trim_zeros == force_decimal),
            ("no leading zero", !format.leading_zero),
            ("decimal rounding (CNC-Calc rounds the binary double)", format.rounding != Rounding::Binary),
            ("a minus kept on a negative value that rounds to zero", format.negative_zero),
            ("another decimal mark than the post's `decimalMark`", format.decimal_mark != mark),
            ("more than 15 decimals", format.decimals > 15),
            ("a width past 64", format.width > 64),
        ] {
            if yes {
                self.refuse(
                    codes::CV003.code,
                    format.span,
                    format!("{what} has {cannot}, which `createFormat` cannot make"),
                    "createFormat({prefix, width, zeropad, decimals, scale, forceDecimal, forceSign}) is all a CNC-Calc format says",
                );
                return None;
            }
        }
        let d = NumberFormat::default();
        let mut props: Vec<(&str, Js)> = Vec::new();
        if !format.prefix.is_empty() {
            props.push(("prefix", js(ExprKind::String(format.prefix.clone()))));
        }
        if format.width != 0 {
            props.push(("width", js(ExprKind::Number(f64::from(format.width)))));
        }
        if format.padding == Padding::Zero {
            props.push(("zeropad", js(ExprKind::Bool(true))));
        }
        if format.decimals != 0 {
            props.push(("decimals", js(ExprKind::Number(f64::from(format.decimals)))));
        }
        if format.multiplier != d.multiplier {
            props.push(("scale", js(ExprKind::Number(format.multiplier))));
        }
        if force_decimal {
            props.push(("forceDecimal", js(ExprKind::Bool(true))));
        }
        if format.sign == SignStyle::Always {
            props.push(("forceSign", js(ExprKind::Bool(true))));
        }
        Some(call(name("createFormat"), vec![object(props)]))
    }

    /// `createVariable({prefix, force}, format)`, or a refusal.
    fn create_variable(&mut self, v: usize) -> Option<Js> {
        let var = &self.post.variables[v];
        if var.source != ValueSource::Assigned {
            self.refuse(
                codes::CV005.code,
                var.span,
                format!("output variable `{}` prints a runtime value itself", var.name),
                "a CNC-Calc variable prints what the post formats through it",
            );
            return None;
        }
        let Ok(prefix) = String::from_utf8(var.prefix.clone()) else {
            self.refuse(codes::CV005.code, var.span, format!("the prefix of `{}` is not text", var.name), "");
            return None;
        };
        let mut props: Vec<(&str, Js)> = Vec::new();
        if !prefix.is_empty() {
            props.push(("prefix", js(ExprKind::String(prefix))));
        }
        if var.modality == Modality::Always {
            props.push(("force", js(ExprKind::Bool(true))));
        }
        let format = self.post.formats.get(var.format.index());
        let format = match format.and_then(|f| f.name.clone()) {
            Some(format) => name(&format),
            None if format.is_some() => self.create_format(var.format.index())?,
            None => {
                self.refuse(codes::CV005.code, var.span, format!("`{}` has no format", var.name), "");
                return None;
            }
        };
        Some(call(name("createVariable"), vec![object(props), format]))
    }

    /// The decimal mark of every format: the post's `decimalMark`.
    fn decimal_mark(&self) -> char {
        let mark = self.post.globals.iter().find(|g| g.name == "decimalMark" || g.name == "globals.decimalMark");
        match mark.map(|g| &g.initial) {
            Some(Expr::Text(m)) if m == "," => ',',
            _ => '.',
        }
    }

    /// Every function of the post, before postc's own.
    fn functions(&mut self, init: usize) {
        let post = self.post;
        for (i, f) in post.functions[..init].iter().enumerate() {
            if is_postc_feedrate(post, f) {
                continue;
            }
            if self.as_written && f.source.first().is_some_and(|s| !s.written.is_empty()) {
                continue;
            }
            self.end_line();
            self.out.push_str(&super::comment(post, &CommentTarget::Function(FunctionId::new(i as u16))));
            if !f.source.is_empty() {
                let text: Vec<&str> = f.source.iter().map(|s| s.text.trim_end()).collect();
                self.out.push_str(&text.join("\n"));
                self.out.push_str("\n\n");
                continue;
            }
            if let Body::Script(_) = f.body {
                let why = f.why_script.as_ref().map_or(String::new(), |w| format!(" ({})", w.what));
                self.refuse(
                    codes::CV002.code,
                    f.span,
                    format!("function `{}` runs as a script{why} and its JavaScript was not kept", f.name),
                    "a script prints only as its source text (`source` in the IR), which this post has not",
                );
                continue;
            }
            match body::function(post, f) {
                Ok(decl) => {
                    self.statement(decl);
                    self.out.push('\n');
                }
                Err(what) => self.refuse(
                    codes::CV002.code,
                    f.span,
                    format!("function `{}` has {what}, which no CNC-Calc function says", f.name),
                    "a CNC-Calc function's body is JavaScript the CIMCO frontend lowers to the same IR",
                ),
            }
        }
        // One line break ends the file.
        self.end_line();
        while self.out.ends_with("\n\n") || self.out.ends_with("\n\r\n") {
            self.out.pop();
            if self.out.ends_with('\r') {
                self.out.pop();
            }
        }
    }
}

/// Whether `f` is the `getFeedrate` postc adds to a post that has none:
/// it formats through postc's feed variables.
pub(super) fn is_postc_feedrate(post: &Post, f: &postc_ir::Function) -> bool {
    use postc_ir::visit::{Visit, walk_expr};
    struct Feeds<'p>(&'p Post, bool);
    impl Visit for Feeds<'_> {
        fn visit_expr(&mut self, e: &Expr) {
            if let Expr::FormatVar { var, .. } = e
                && self
                    .0
                    .variables
                    .get(var.index())
                    .is_some_and(|v| v.name == made::FEED_VAR || v.name == made::FEED_REV_VAR)
            {
                self.1 = true;
            }
            walk_expr(self, e);
        }
    }
    let Body::Native(body) = &f.body else { return false };
    let mut feeds = Feeds(post, false);
    body.iter().for_each(|s| feeds.visit_stmt(s));
    f.name == made::FEEDRATE && f.source.is_empty() && feeds.1
}
