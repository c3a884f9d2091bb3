//! A post driven by APT words (a VcPost milling post: `Sub GOTO`, `Sub
//! FEDRAT`, `Sub CIRCLE`, ...) printed as a CNC-Calc post that CNC-Calc
//! runs: every Sub and Function becomes a JavaScript function under its
//! own name, registers become objects that keep their value, the value
//! before it (`.Previous`) and what they printed, and a small adapter maps
//! the entry points of the CNC-Calc manual onto the Subs of the APT
//! records the runtime would make (docs/convert.md, "VcPost posts as
//! CNC-Calc posts"):
//!
//! | CNC-Calc calls | the adapter sets, then calls |
//! |---|---|
//! | `onOpen(isClipboard)` | `Word`, `Minor`, `Text`, `Metric` (from the post's units); `PARTNO` |
//! | `onLinear(x, y, z, MOVEMENT_RAPID)` | `G` = 0, `RAPID`; `X Y Z`, `G` = 0, `GOTO` |
//! | `onLinear(x, y, z, movement)` | `F` (from `getFeedrate`), `FEDRAT` when it changed; `X Y Z`, `G` = 1, `GOTO` |
//! | `onCircular(cx, cy, cz, x, y, z, isCW, movement)` | the feed as above; `X Y Z`, `G` 2 or 3, `Plane` 17, `I J K`, `CX CY CZ`, `R`; `CIRCLE` |
//! | `onClose()` | `FINI` |
//!
//! BASIC's values are JavaScript's with the runtime's rules written out as
//! functions (`vbNum`, `vbText`, `vbAdd`, `vbCmp`, `vbTrue`, ...), the
//! registers' formats as `formatNumber` (the one the native CNC-Calc posts
//! print, `crate::js_sections`).
//!
//! What has no form in CNC-Calc is refused per construct, at its place in
//! the source: a value the engine never hands (the part name `PARTNO`
//! reads as `Text`, `Metric` in a post without fixed units) is `CV007`;
//! Subs of words the engine never calls (`LOADTL`, `SPINDL`, `COOLNT`,
//! `CYCLE`, `PPRINT`, ...) are left out with warning `CV008`; an arc cut
//! into `GOTO` moves (no `Sub CIRCLE`) and an empty `Out` line (the
//! engine writes no empty line) are `CV010`; BASIC code the printer has
//! no JavaScript for is `CV002`; posts driven by application calls (probe
//! tables, composites) and by sections are `CV001`.
//!
//! The same Subs print for Fusion ([`Host::Fusion`], `crate::fusion`'s
//! APT-word form) as the body of a function whose value is an object of
//! one adapter function per APT record the runtime makes (PARTNO, LOADTL,
//! TOOLPATH, SPINDL, COOLNT, CUTCOM, RAPID, GOTO, FEDRAT, CIRCLE, DELAY,
//! PPRINT, CYCLE, FINI): Fusion hands the values CNC-Calc does not, so
//! nothing is refused for them, and an empty `Out` line is Fusion's
//! empty line.

use std::collections::{BTreeSet, HashMap};

use postc_ir::codes;
use postc_ir::post::Dispatch;
use postc_ir::{
    BinaryOp, Body, Builtin, Diagnostic, Expr, HandlerKey, Modality, OutputOptions, Piece, Place, Post, Quantity, Span,
    Stmt, TextEncoding, UnaryOp, ValueSource,
};

use crate::js_sections::{LIBRARY, format_object, is_js_name, js_string, number};

use super::refusal;

/// The APT words whose Subs CNC-Calc's entry points reach.
const CALLED: &[&str] = &["PARTNO", "RAPID", "GOTO", "FEDRAT", "CIRCLE", "FINI"];

/// The APT words whose Subs Fusion's entry points reach
/// (`crate::fusion`'s APT-word form).
const FUSION_CALLED: &[&str] = &[
    "PARTNO", "LOADTL", "TOOLPATH", "SPINDL", "COOLNT", "CUTCOM", "RAPID", "GOTO", "FEDRAT", "CIRCLE", "DELAY",
    "PPRINT", "CYCLE", "FINI",
];

/// The engine whose entry points the printed post's adapter answers.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Host {
    /// CNC-Calc: the post is the whole program, its entry points the CNC-Calc manual's.
    CncCalc,
    /// Autodesk Fusion: the Subs and the adapter are the body of a function
    /// whose value is the adapter's object of record calls
    /// (`crate::fusion`'s APT-word form calls them from Fusion's entry points).
    Fusion,
}

impl Host {
    fn called(self) -> &'static [&'static str] {
        match self {
            Host::CncCalc => CALLED,
            Host::Fusion => FUSION_CALLED,
        }
    }

    fn engine(self) -> &'static str {
        match self {
            Host::CncCalc => "CNC-Calc",
            Host::Fusion => "Fusion",
        }
    }
}

/// The names the printed post gives a meaning of its own.
const OWN: &[&str] = &[
    "linebreak",
    "aptOut",
    "aptBlock",
    "aptBlockPrinted",
    "aptX",
    "aptY",
    "aptZ",
    "aptFeed",
    "aptSet",
    "aptWord",
    "aptEnd",
    "aptPut",
    "aptPutBlock",
    "aptRecord",
    "aptFeedOf",
    "aptMove",
    "createRegister",
    "setRegister",
    "vbNum",
    "vbText",
    "vbAdd",
    "vbCmp",
    "vbTrue",
    "vbAnd",
    "vbOr",
    "vbIntDiv",
    "vbRound",
    "vbVal",
    "vbLeft",
    "vbRight",
    "vbMid",
    "vbMin",
    "vbMax",
    "vbChr",
    "vbFormat",
    "vbTrunc",
    "aptTake",
    "aptFeedTo",
    "onOpen",
    "onLinear",
    "onCircular",
    "onClose",
    "getFeedrate",
    "MOVEMENT_RAPID",
    "Math",
    "String",
    "Number",
    "parseFloat",
    // The Fusion form's adapter (`fusion_adapter`).
    "aptCX",
    "aptCY",
    "aptCZ",
    "aptCcw",
    "aptD",
    "aptDepth",
    "aptF",
    "aptFeedTo",
    "aptG",
    "aptH",
    "aptMetric",
    "aptMinor",
    "aptName",
    "aptP",
    "aptPlane",
    "aptQ",
    "aptR",
    "aptS",
    "aptSeconds",
    "aptT",
    "aptTake",
    "aptText",
    "aptToX",
    "aptToY",
    "aptToZ",
    "aptTop",
    "vcPost",
];

/// Prints an APT-word post as a CNC-Calc post, with the conversion's
/// warnings, or every reason it cannot be one.
pub(crate) fn print(post: &Post) -> Result<(Vec<u8>, Vec<Diagnostic>), Vec<Diagnostic>> {
    print_for(post, Host::CncCalc)
}

/// Prints an APT-word post for `host`: for CNC-Calc the whole post, for
/// Fusion the body of the function that makes the adapter's object.
pub(crate) fn print_for(post: &Post, host: Host) -> Result<(Vec<u8>, Vec<Diagnostic>), Vec<Diagnostic>> {
    let mut p = Printer {
        post,
        host,
        out: String::new(),
        errors: Vec::new(),
        warnings: Vec::new(),
        registers: Vec::new(),
        globals: Vec::new(),
        functions: Vec::new(),
        locals: Vec::new(),
        at: None,
        within: String::new(),
    };
    p.check_shape();
    if !p.errors.is_empty() {
        return Err(p.errors);
    }
    p.name_everything();
    if host == Host::CncCalc {
        p.check_values();
    }
    p.header();
    p.registers();
    p.globals();
    p.functions();
    match host {
        Host::CncCalc => p.adapter(),
        Host::Fusion => p.fusion_adapter(),
    }
    if p.errors.is_empty() { Ok((p.out.into_bytes(), p.warnings)) } else { Err(p.errors) }
}

struct Printer<'p> {
    post: &'p Post,
    host: Host,
    out: String,
    errors: Vec<Diagnostic>,
    warnings: Vec<Diagnostic>,
    /// Each variable's JavaScript name (`None`: not a register).
    registers: Vec<Option<String>>,
    globals: Vec<String>,
    functions: Vec<String>,
    locals: Vec<Vec<String>>,
    /// The place of the statement being printed (`Stmt::Origin`), else
    /// the function's.
    at: Option<Span>,
    /// The function being printed, as a diagnostic names it.
    within: String,
}

impl Printer<'_> {
    fn refuse(&mut self, code: &'static str, span: Option<Span>, message: String, why: &str) {
        if self.errors.iter().any(|e| e.message == message) {
            return;
        }
        self.errors.push(refusal(code, span, message, why));
    }

    /// Code the printer has no JavaScript for, at the statement's place.
    fn cannot(&mut self, what: &str) {
        let message = format!("{} uses {what}, which the {} post cannot say", self.within, self.host.engine());
        self.refuse(codes::CV002.code, self.at, message, "the converted post has BASIC's statements and operators");
    }

    fn check_shape(&mut self) {
        let post = self.post;
        if post.info.dispatch != Dispatch::AptWords {
            self.refuse(
                codes::CV001.code,
                None,
                format!("this post is driven by sections, which this form of {} post is not", self.host.engine()),
                "",
            );
            return;
        }
        // Subs Vericut's applications call by name (probe-table rows,
        // composites routines): CNC-Calc has no call for them.
        for sig in &post.info.subs {
            if let Some(k) = &sig.keyword {
                let span = post.functions.iter().find(|f| f.name.eq_ignore_ascii_case(&sig.name)).and_then(|f| f.span);
                self.refuse(
                    codes::CV001.code,
                    span,
                    format!(
                        "`{}` is a #{k} row of a probe-cycle table, which {} has no call for",
                        sig.name,
                        self.host.engine()
                    ),
                    "the engine calls a post per move of an operation, not per row of a table",
                );
            }
        }
        for h in &post.handlers {
            let HandlerKey::Word(word) = &h.key else { continue };
            let composites =
                postc_front_vcpost::routines::COMPOSITES_ROUTINES.iter().any(|r| r.eq_ignore_ascii_case(word));
            if composites && !postc_front_vcpost::routines::APT_WORDS.contains(&word.as_str()) {
                self.refuse(
                    codes::CV001.code,
                    h.span,
                    format!("`{word}` is a composites routine, which {} has no call for", self.host.engine()),
                    "the engine calls a post per move of an operation, not per tow-placement routine",
                );
            }
        }
        if !post.call_lists.is_empty() {
            self.refuse(codes::CV001.code, None, "the post reads the lists of application calls".into(), "");
        }
        let o = &post.options;
        let d = OutputOptions::default();
        let line_ending = [&b"\r\n"[..], b"\n", b"\r"].contains(&o.line_ending.as_slice());
        for (what, yes) in [
            ("a line ending other than CR LF, LF or CR", !line_ending),
            ("substitutions", !o.substitutions.is_empty()),
            ("tape splitting", o.tape_splitting.is_some()),
            ("a spindle speed range", o.spindle_speed_range.is_some()),
            ("a rotary wrap", o.rotary_wrap.is_some()),
            ("arc radius limits", o.min_arc_radius.is_some() || o.max_arc_radius.is_some()),
            ("inverse time feeds", o.inverse_time_feed),
            ("exact arcs", o.exact_arcs),
            ("a lathe mapping", o.lathe),
            ("a step budget", o.step_budget != d.step_budget),
            ("modal memory compared by value", o.on_change_by_value),
            ("Windows-1252 text", post.info.text_encoding == TextEncoding::Windows1252),
        ] {
            if yes {
                self.refuse(
                    codes::CV004.code,
                    None,
                    format!("the post sets {what}, which the {} post does not carry", self.host.engine()),
                    "",
                );
            }
        }
        for f in &post.functions {
            if let Body::Script(_) = f.body {
                self.refuse(codes::CV002.code, f.span, format!("`{}` runs as a script", f.name), "");
            }
        }
        let milling = !self.errors.iter().any(|e| e.code == codes::CV001.code);
        if milling && !post.handlers.iter().any(|h| h.key == HandlerKey::Word("CIRCLE".into())) {
            self.refuse(
                codes::CV010.code,
                None,
                "the post has no Sub CIRCLE, so postc cuts arcs into GOTO moves; onCircular hands whole arcs".into(),
                "add a Sub CIRCLE, or convert a post that prints arcs",
            );
        }
        for h in &post.handlers {
            let HandlerKey::Word(word) = &h.key else { continue };
            if !self.host.called().contains(&word.as_str()) {
                let note = match self.host {
                    Host::CncCalc => {
                        "the CNC-Calc manual's entry points are onOpen, onLinear, onCircular, the drilling functions and onClose: the converted post prints as its source for a job of moves"
                    }
                    Host::Fusion => {
                        "Fusion's entry points make PARTNO, LOADTL, TOOLPATH, SPINDL, COOLNT, CUTCOM, RAPID, GOTO, FEDRAT, CIRCLE, DELAY, PPRINT, CYCLE and FINI records (docs/convert.md, \"VcPost posts as Fusion posts\")"
                    }
                };
                self.warnings.push(
                    Diagnostic::warning(
                        codes::CV008.code,
                        format!(
                            "`Sub {word}` is left out: {} calls no function for {word} records",
                            self.host.engine()
                        ),
                    )
                    .note(note.to_string()),
                );
                if let Some(span) = h.span.or_else(|| self.handler_function(h).and_then(|f| post.functions[f].span)) {
                    let w = self.warnings.pop().expect("pushed");
                    self.warnings.push(w.at(span, "never called"));
                }
            }
        }
    }

    /// The JavaScript name of the Sub of each word of `called` the post has.
    fn subs(&self, called: &[&'static str]) -> HashMap<&'static str, String> {
        let mut subs = HashMap::new();
        for h in &self.post.handlers {
            if let HandlerKey::Word(w) = &h.key
                && let Some(f) = self.handler_function(h)
                && let Some(c) = called.iter().find(|c| **c == w.as_str())
            {
                subs.insert(*c, self.functions[f].clone());
            }
        }
        subs
    }

    /// The function a word's handler calls.
    fn handler_function(&self, h: &postc_ir::Handler) -> Option<usize> {
        match h.body.as_slice() {
            [Stmt::Eval(Expr::Call(f, args))] if args.is_empty() => Some(f.index()),
            _ => None,
        }
    }

    fn give(taken: &mut BTreeSet<String>, wanted: &str) -> String {
        let mut name = wanted.to_string();
        if !is_js_name(&name, OWN) || taken.contains(&name) {
            name = format!("{wanted}_");
            while !is_js_name(&name, OWN) || taken.contains(&name) {
                name.push('_');
            }
        }
        taken.insert(name.clone());
        name
    }

    fn name_everything(&mut self) {
        let post = self.post;
        let mut taken = BTreeSet::new();
        for f in &post.functions {
            self.functions.push(Self::give(&mut taken, &f.name));
        }
        for v in &post.variables {
            let name = match v.source {
                ValueSource::Assigned => Some(Self::give(&mut taken, &v.name)),
                ValueSource::Quantity(Quantity::BlockNumber) => Some(Self::give(&mut taken, &v.name)),
                ValueSource::Quantity(q) => {
                    self.refuse(
                        codes::CV005.code,
                        v.span,
                        format!("`{}` prints {q:?}, a value the runtime gives by name", v.name),
                        "",
                    );
                    None
                }
            };
            self.registers.push(name);
        }
        for g in &post.globals {
            self.globals.push(Self::give(&mut taken, &g.name));
        }
        for (i, f) in post.functions.iter().enumerate() {
            let mut mine = taken.clone();
            let mut slots = Vec::new();
            for k in 0..(f.slots as usize).max(f.params.len()) {
                let wanted = match f.params.get(k) {
                    Some(p) => p.clone(),
                    None => f
                        .locals
                        .get(k - f.params.len())
                        .filter(|n| !n.starts_with('$'))
                        .cloned()
                        .unwrap_or_else(|| format!("l{k}")),
                };
                // A Function's result has the Function's name.
                let wanted = if wanted.eq_ignore_ascii_case(&f.name) { format!("{wanted}Result") } else { wanted };
                slots.push(Self::give(&mut mine, &wanted));
            }
            let _ = i;
            self.locals.push(slots);
        }
    }

    /// The names the adapter sets, as the runtime finds them: a register
    /// first, else a global, by name without case.
    fn slot(&self, upper: &str) -> Option<String> {
        let post = self.post;
        if let Some(i) =
            post.variables.iter().position(|v| v.source == ValueSource::Assigned && v.name.eq_ignore_ascii_case(upper))
        {
            return self.registers[i].clone().map(|n| format!("setRegister({n}, "));
        }
        post.globals.iter().position(|g| g.name.eq_ignore_ascii_case(upper)).map(|i| format!("{} = (", self.globals[i]))
    }

    /// Values the engine never hands: the part name `PARTNO` reads as
    /// `Text`, and `Metric` when the post's units are not fixed.
    fn check_values(&mut self) {
        let post = self.post;
        let partno = post
            .handlers
            .iter()
            .find(|h| h.key == HandlerKey::Word("PARTNO".into()))
            .and_then(|h| self.handler_function(h));
        if let Some(f) = partno {
            let mut reach = BTreeSet::new();
            self.reach(f, &mut reach);
            for g in reach {
                if let Some(span) = self.reads(g, "TEXT") {
                    self.refuse(
                        codes::CV007.code,
                        span.or(post.functions[g].span),
                        format!(
                            "`{}` reads the part name (`Text` of PARTNO), which CNC-Calc never hands",
                            post.functions[g].name
                        ),
                        "CNC-Calc's onOpen(isClipboard) hands no part or file name",
                    );
                }
            }
        }
        if post.info.units.is_none() {
            for g in 0..post.functions.len() {
                if let Some(span) = self.reads(g, "METRIC") {
                    self.refuse(
                        codes::CV007.code,
                        span.or(post.functions[g].span),
                        format!(
                            "`{}` reads `Metric`, the units of the job, which CNC-Calc never hands",
                            post.functions[g].name
                        ),
                        "set the post's units (`Postc.Units = \"MM\"`) so that Metric is known",
                    );
                }
            }
        }
    }

    /// The functions `f` calls, itself included.
    fn reach(&self, f: usize, seen: &mut BTreeSet<usize>) {
        if !seen.insert(f) {
            return;
        }
        struct Calls(Vec<usize>);
        impl postc_ir::visit::Visit for Calls {
            fn visit_expr(&mut self, e: &Expr) {
                if let Expr::Call(f, _) = e {
                    self.0.push(f.index());
                }
                postc_ir::visit::walk_expr(self, e);
            }
        }
        let mut calls = Calls(Vec::new());
        if let Body::Native(body) = &self.post.functions[f].body {
            for s in body {
                postc_ir::visit::Visit::visit_stmt(&mut calls, s);
            }
        }
        for c in calls.0 {
            self.reach(c, seen);
        }
    }

    /// Whether function `f` reads the register or global named `upper`:
    /// `Some(the place of the statement)`.
    fn reads(&self, f: usize, upper: &str) -> Option<Option<Span>> {
        let post = self.post;
        let var = post.variables.iter().position(|v| v.name.eq_ignore_ascii_case(upper));
        let global = post.globals.iter().position(|g| g.name.eq_ignore_ascii_case(upper));
        struct Find {
            var: Option<usize>,
            global: Option<usize>,
            at: Option<Span>,
            found: Option<Option<Span>>,
        }
        impl postc_ir::visit::Visit for Find {
            fn visit_stmt(&mut self, s: &Stmt) {
                if let Stmt::Origin(span) = s {
                    self.at = Some(*span);
                }
                postc_ir::visit::walk_stmt(self, s);
            }
            fn visit_piece(&mut self, p: &Piece) {
                if let Piece::Var(v) = p
                    && Some(v.index()) == self.var
                    && self.found.is_none()
                {
                    self.found = Some(self.at);
                }
                postc_ir::visit::walk_piece(self, p);
            }
            fn visit_expr(&mut self, e: &Expr) {
                let hit = match e {
                    Expr::Var(v) | Expr::Previous(v) => Some(v.index()) == self.var,
                    Expr::Global(g) => Some(g.index()) == self.global,
                    _ => false,
                };
                if hit && self.found.is_none() {
                    self.found = Some(self.at);
                }
                postc_ir::visit::walk_expr(self, e);
            }
        }
        let mut find = Find { var, global, at: None, found: None };
        if let Body::Native(body) = &post.functions[f].body {
            for s in body {
                postc_ir::visit::Visit::visit_stmt(&mut find, s);
            }
        }
        find.found
    }

    fn line(&mut self, indent: usize, text: &str) {
        for _ in 0..indent {
            self.out.push_str("    ");
        }
        self.out.push_str(text);
        self.out.push('\n');
    }

    fn header(&mut self) {
        let post = self.post;
        if self.host == Host::CncCalc {
            self.out.push_str(&super::header(post));
            self.out.push_str(NOTE);
        }
        let linebreak = String::from_utf8_lossy(&post.options.line_ending).into_owned();
        self.line(0, &format!("var linebreak = {};", js_string(&linebreak)));
        self.out.push('\n');
        self.out.push_str(LIBRARY);
        self.out.push('\n');
        self.out.push_str(BASIC);
        let b = post.options.block_numbers;
        self.line(
            0,
            &format!(
                "var aptBlock = {{next: {}, start: {}, increment: {}, maximum: {}, printed: false}};",
                b.start, b.start, b.increment, b.maximum
            ),
        );
        self.out.push('\n');
    }

    fn registers(&mut self) {
        let post = self.post;
        if post.variables.is_empty() {
            return;
        }
        self.line(0, "// The registers: value, the value before it (.Previous), the word it prints.");
        for (i, v) in post.variables.iter().enumerate() {
            let Some(name) = self.registers[i].clone() else { continue };
            let Some(f) = post.formats.get(v.format.index()) else { continue };
            let prefix = String::from_utf8_lossy(&v.prefix).into_owned();
            let modal = v.modality == Modality::OnChange;
            self.line(
                0,
                &format!("var {name} = createRegister({}, {modal}, {});", js_string(&prefix), format_object(f)),
            );
        }
        self.out.push('\n');
    }

    fn globals(&mut self) {
        let post = self.post;
        self.line(0, "// The post's variables, and what runs first.");
        for (i, g) in post.globals.iter().enumerate() {
            let name = self.globals[i].clone();
            self.within = format!("global `{}`", g.name);
            self.at = g.span;
            let value = match &g.initial {
                Expr::Number(_) | Expr::Text(_) | Expr::Bool(_) => self.expr(&g.initial, None),
                _ => {
                    self.cannot("a starting value that is not a number, a text or a Boolean");
                    String::new()
                }
            };
            self.line(0, &format!("var {name} = {value};"));
        }
        let init = post.init.clone();
        self.within = "the post's first statements".into();
        self.at = None;
        self.block(&init, None, 0);
        self.out.push('\n');
    }

    fn functions(&mut self) {
        let post = self.post;
        for (i, f) in post.functions.iter().enumerate() {
            let Body::Native(body) = &f.body else { continue };
            // Made by the frontend for a host function: nothing to print.
            if f.span.is_none() && postc_front_vcpost::routines::host_function(&f.name).is_some() {
                self.within = format!("`{}`", f.name);
                self.at = None;
                self.cannot("a function of Vericut's applications");
                continue;
            }
            self.within = format!("`{}`", f.name);
            self.at = f.span;
            self.out.push_str(&super::comment(
                post,
                &postc_ir::CommentTarget::Function(postc_ir::post::FunctionId::new(i as u16)),
            ));
            let params = self.locals[i][..f.params.len()].join(", ");
            self.line(0, &format!("function {}({params}) {{", self.functions[i]));
            for k in f.params.len()..self.locals[i].len() {
                let l = self.locals[i][k].clone();
                self.line(1, &format!("var {l} = null;"));
            }
            let body = body.clone();
            self.block(&body, Some(i), 1);
            self.line(0, "}");
            self.out.push('\n');
        }
    }

    fn block(&mut self, stmts: &[Stmt], f: Option<usize>, indent: usize) {
        for s in stmts {
            self.stmt(s, f, indent);
        }
    }

    fn stmt(&mut self, s: &Stmt, f: Option<usize>, indent: usize) {
        match s {
            Stmt::Origin(span) => self.at = Some(*span),
            Stmt::Line { pieces, span } => {
                if span.is_some() {
                    self.at = *span;
                }
                if self.host == Host::CncCalc && pieces.iter().all(|p| matches!(p, Piece::Text(t) if t.is_empty())) {
                    self.refuse(
                        codes::CV010.code,
                        self.at,
                        format!("{} writes an empty line, which CNC-Calc does not write", self.within),
                        "CNC-Calc writes only the lines that are not empty",
                    );
                    return;
                }
                let mut parts = Vec::new();
                for p in pieces {
                    let part = match p {
                        Piece::Text(bytes) => js_string(&String::from_utf8_lossy(bytes)),
                        Piece::Var(v) => {
                            match (self.registers.get(v.index()).cloned().flatten(), self.post.variables.get(v.index()))
                            {
                                (Some(n), Some(var)) if var.source == ValueSource::Quantity(Quantity::BlockNumber) => {
                                    format!("aptPutBlock({n})")
                                }
                                (Some(n), _) => format!("aptPut({n})"),
                                _ => {
                                    self.cannot("a value the runtime gives by name");
                                    String::new()
                                }
                            }
                        }
                        Piece::Expr(e) => format!("vbText({})", self.expr(e, f)),
                    };
                    parts.push(part);
                }
                self.line(indent, &format!("aptEnd({});", parts.join(" + ")));
            }
            Stmt::Assign(place, e) => {
                let value = self.expr(e, f);
                match place {
                    Place::Var(v) => {
                        let n = self.registers.get(v.index()).cloned().flatten().unwrap_or_default();
                        self.line(indent, &format!("setRegister({n}, {value});"));
                    }
                    Place::Global(g) => {
                        let n = self.globals.get(g.index()).cloned().unwrap_or_default();
                        self.line(indent, &format!("{n} = {value};"));
                    }
                    Place::Local(k) => {
                        let n = self.local(k.index(), f);
                        self.line(indent, &format!("{n} = {value};"));
                    }
                }
            }
            Stmt::Eval(Expr::Call(id, args)) => {
                let args: Vec<String> = args.iter().map(|a| self.expr(a, f)).collect();
                let name = self.functions.get(id.index()).cloned().unwrap_or_default();
                self.line(indent, &format!("{name}({});", args.join(", ")));
            }
            Stmt::If { branches, otherwise } => {
                if branches.is_empty() {
                    self.block(otherwise, f, indent);
                    return;
                }
                for (n, (cond, body)) in branches.iter().enumerate() {
                    let c = self.expr(cond, f);
                    let head = if n == 0 { "if" } else { "} else if" };
                    self.line(indent, &format!("{head} (vbTrue({c})) {{"));
                    self.block(body, f, indent + 1);
                }
                if !otherwise.is_empty() {
                    self.line(indent, "} else {");
                    self.block(otherwise, f, indent + 1);
                }
                self.line(indent, "}");
            }
            Stmt::While { cond, body, step, .. } => {
                if !step.is_empty() {
                    self.cannot("a loop with a step (`continue`)");
                    return;
                }
                let c = self.expr(cond, f);
                self.line(indent, &format!("while (vbTrue({c})) {{"));
                self.block(body, f, indent + 1);
                self.line(indent, "}");
            }
            Stmt::Break => self.line(indent, "break;"),
            Stmt::Return(None) => self.line(indent, "return;"),
            Stmt::Return(Some(e)) => {
                let v = self.expr(e, f);
                self.line(indent, &format!("return {v};"));
            }
            Stmt::Write(_) => self.cannot("a statement that writes computed text as blocks"),
            Stmt::Continue => self.cannot("`continue`"),
            Stmt::Forget(_) => self.cannot("making a register forget what it printed"),
            Stmt::Eval(_) => self.cannot("a value computed for nothing"),
            _ => self.cannot("a statement of another dialect"),
        }
    }

    fn local(&mut self, k: usize, f: Option<usize>) -> String {
        match f.and_then(|i| self.locals.get(i)).and_then(|l| l.get(k)) {
            Some(n) => n.clone(),
            None => {
                self.cannot("a local outside a Sub");
                String::new()
            }
        }
    }

    fn expr(&mut self, e: &Expr, f: Option<usize>) -> String {
        match e {
            Expr::Number(n) if n.is_finite() => {
                if *n < 0.0 || (*n == 0.0 && n.is_sign_negative()) {
                    format!("({})", if *n == 0.0 { "-0".to_string() } else { number(*n) })
                } else {
                    number(*n)
                }
            }
            Expr::Text(t) => js_string(t),
            Expr::Bool(b) => b.to_string(),
            Expr::Null => "null".into(),
            Expr::Local(k) => self.local(k.index(), f),
            // `N` read as a value: the number the next `<N>` prints.
            Expr::Quantity(Quantity::BlockNumber) => "aptBlock.next".into(),
            Expr::Global(g) => self.globals.get(g.index()).cloned().unwrap_or_default(),
            Expr::Var(v) => match self.registers.get(v.index()).cloned().flatten() {
                Some(n) => format!("{n}.value"),
                None => {
                    self.cannot("a value the runtime gives by name");
                    String::new()
                }
            },
            Expr::Previous(v) => match self.registers.get(v.index()).cloned().flatten() {
                Some(n) => format!("{n}.previous"),
                None => {
                    self.cannot("`.Previous` of a value the runtime gives by name");
                    String::new()
                }
            },
            Expr::Unary(UnaryOp::Neg, a) => format!("(-vbNum({}))", self.expr(a, f)),
            Expr::Unary(UnaryOp::Not, a) => format!("(!vbTrue({}))", self.expr(a, f)),
            Expr::Binary(op, a, b) => {
                let (x, y) = (self.expr(a, f), self.expr(b, f));
                match op {
                    BinaryOp::Add => format!("vbAdd({x}, {y})"),
                    BinaryOp::Concat => format!("(vbText({x}) + vbText({y}))"),
                    BinaryOp::Sub => format!("(vbNum({x}) - vbNum({y}))"),
                    BinaryOp::Mul => format!("(vbNum({x}) * vbNum({y}))"),
                    BinaryOp::Div => format!("(vbNum({x}) / vbNum({y}))"),
                    BinaryOp::Rem => format!("(vbNum({x}) % vbNum({y}))"),
                    BinaryOp::Pow => format!("Math.pow(vbNum({x}), vbNum({y}))"),
                    BinaryOp::IntDiv => format!("vbIntDiv({x}, {y})"),
                    BinaryOp::Eq => format!("(vbCmp({x}, {y}) === 0)"),
                    BinaryOp::Ne => format!("(vbCmp({x}, {y}) !== 0)"),
                    BinaryOp::Lt => format!("(vbCmp({x}, {y}) === -1)"),
                    BinaryOp::Le => format!("(vbCmp({x}, {y}) <= 0)"),
                    BinaryOp::Gt => format!("(vbCmp({x}, {y}) === 1)"),
                    BinaryOp::Ge => format!("(vbCmp({x}, {y}) >= 0)"),
                    BinaryOp::And => format!("vbAnd({x}, function () {{ return {y}; }})"),
                    BinaryOp::Or => format!("vbOr({x}, function () {{ return {y}; }})"),
                    other => {
                        self.cannot(&format!("the operator {other:?}"));
                        String::new()
                    }
                }
            }
            Expr::Choose(c, a, b) => {
                let (c, a, b) = (self.expr(c, f), self.expr(a, f), self.expr(b, f));
                format!("(vbTrue({c}) ? {a} : {b})")
            }
            Expr::Call(id, args) => {
                let args: Vec<String> = args.iter().map(|a| self.expr(a, f)).collect();
                let name = self.functions.get(id.index()).cloned().unwrap_or_default();
                format!("{name}({})", args.join(", "))
            }
            Expr::Builtin(b, args) => {
                let a: Vec<String> = args.iter().map(|a| self.expr(a, f)).collect();
                let arg = |i: usize| a.get(i).cloned().unwrap_or_else(|| "null".into());
                let math = |name: &str| format!("Math.{name}(vbNum({}))", arg(0));
                match b {
                    Builtin::Abs => math("abs"),
                    Builtin::Sqrt => math("sqrt"),
                    Builtin::Sin => math("sin"),
                    Builtin::Cos => math("cos"),
                    Builtin::Tan => math("tan"),
                    Builtin::Atan => math("atan"),
                    Builtin::Asin => math("asin"),
                    Builtin::Acos => math("acos"),
                    Builtin::Exp => math("exp"),
                    Builtin::Log => math("log"),
                    Builtin::Floor => math("floor"),
                    Builtin::Ceil => math("ceil"),
                    Builtin::Atan2 => format!("Math.atan2(vbNum({}), vbNum({}))", arg(0), arg(1)),
                    Builtin::Trunc => format!("vbTrunc({})", arg(0)),
                    Builtin::Round => format!("vbRound({}, {})", arg(0), arg(1)),
                    Builtin::Min => format!("vbMin([{}])", a.join(", ")),
                    Builtin::Max => format!("vbMax([{}])", a.join(", ")),
                    Builtin::Len => format!("vbText({}).length", arg(0)),
                    Builtin::Left => format!("vbLeft({}, {})", arg(0), arg(1)),
                    Builtin::Right => format!("vbRight({}, {})", arg(0), arg(1)),
                    Builtin::Mid if a.len() > 2 => format!("vbMid({}, {}, {})", arg(0), arg(1), arg(2)),
                    Builtin::Mid => format!("vbMid({}, {})", arg(0), arg(1)),
                    Builtin::Upper => format!("vbText({}).toUpperCase()", arg(0)),
                    Builtin::Lower => format!("vbText({}).toLowerCase()", arg(0)),
                    Builtin::Str => format!("vbText({})", arg(0)),
                    Builtin::Val => format!("vbVal({})", arg(0)),
                    Builtin::Chr => format!("vbChr({})", arg(0)),
                    Builtin::FormatPicture if a.len() == 2 => format!("vbFormat({}, {})", arg(0), arg(1)),
                    other => {
                        self.cannot(&format!("the built-in {other:?}"));
                        String::new()
                    }
                }
            }
            other => {
                self.cannot(match other {
                    Expr::Quantity(_) => "a value the runtime gives by name",
                    Expr::FormatVar { .. } | Expr::Format { .. } => "formatting through a CIMCO variable or format",
                    _ => "an expression of another dialect",
                });
                String::new()
            }
        }
    }

    /// The entry points: CNC-Calc's calls set what each APT record sets,
    /// then call the record's Sub.
    fn adapter(&mut self) {
        let post = self.post;
        let subs = self.subs(CALLED);
        let call = |word: &str| subs.get(word).map(|f| format!("{f}();")).unwrap_or_default();
        let set = |name: &str, value: &str| match self.slot(name) {
            Some(s) => format!("{s}{value});"),
            None => String::new(),
        };
        let record = |word: &str| {
            [set("WORD", &js_string(word)), set("MINOR", "\"\""), set("TEXT", "\"\"")]
                .into_iter()
                .filter(|s| !s.is_empty())
                .collect::<Vec<_>>()
                .join("\n    ")
        };
        let metric = match post.info.units {
            Some(postc_ir::Units::Mm) => set("METRIC", "1"),
            Some(postc_ir::Units::Inch) => set("METRIC", "0"),
            None => String::new(),
        };
        let xyz = |g: &str| {
            [set("X", "vx"), set("Y", "vy"), set("Z", "vz"), set("G", g)]
                .into_iter()
                .filter(|s| !s.is_empty())
                .collect::<Vec<_>>()
                .join("\n    ")
        };
        let lines =
            |parts: &[String]| parts.iter().filter(|s| !s.is_empty()).cloned().collect::<Vec<_>>().join("\n    ");
        let open = lines(&[metric, record("PARTNO"), call("PARTNO")]);
        let rapid = lines(&[set("G", "0"), record("RAPID"), call("RAPID"), xyz("0"), record("GOTO"), call("GOTO")]);
        let feed = lines(&[
            set("F", "f"),
            "if (aptFeed !== f) {".into(),
            "    aptFeed = f;".into(),
            {
                let r = record("FEDRAT").replace("\n    ", "\n        ");
                if r.is_empty() { String::new() } else { format!("    {r}") }
            },
            {
                let c = call("FEDRAT");
                if c.is_empty() { String::new() } else { format!("    {c}") }
            },
            "}".into(),
        ]);
        let goto = lines(&[xyz("1"), record("GOTO"), call("GOTO")]);
        let circle = lines(&[
            set("X", "ex"),
            set("Y", "ey"),
            set("Z", "ez"),
            set("G", "isCW ? 2 : 3"),
            set("PLANE", "17"),
            set("I", "cx - aptX"),
            set("J", "cy - aptY"),
            set("K", "cz - aptZ"),
            set("CX", "cx"),
            set("CY", "cy"),
            set("CZ", "cz"),
            set("R", "Math.sqrt((aptX - cx) * (aptX - cx) + (aptY - cy) * (aptY - cy))"),
            record("CIRCLE"),
            call("CIRCLE"),
        ]);
        let close = lines(&[record("FINI"), call("FINI")]);
        self.out.push_str(&format!(
            r#"// The adapter: CNC-Calc's calls as the APT records of the source's Subs.
var aptOut = "";
var aptX = 0;
var aptY = 0;
var aptZ = 0;
var aptFeed = null;

function onOpen(isClipboard) {{
    aptOut = "";
    {open}
    return aptTake();
}}

function aptFeedOf(movement) {{
    var text = getFeedrate(movement);
    return parseFloat(text.substring(1).replace(",", "."));
}}

function aptFeedTo(f) {{
    {feed}
}}

function onLinear(vx, vy, vz, movement) {{
    aptOut = "";
    if (movement == MOVEMENT_RAPID) {{
        {rapid}
    }} else {{
        aptFeedTo(aptFeedOf(movement));
        {goto}
    }}
    aptX = vx;
    aptY = vy;
    aptZ = vz;
    return aptTake();
}}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {{
    aptOut = "";
    aptFeedTo(aptFeedOf(movement));
    {circle}
    aptX = ex;
    aptY = ey;
    aptZ = ez;
    return aptTake();
}}

function onClose() {{
    aptOut = "";
    {close}
    return aptTake();
}}

function aptTake() {{
    var text = aptOut;
    aptOut = "";
    return text;
}}
"#
        ));
    }
}

impl Printer<'_> {
    /// The adapter of the Fusion form: one function per APT record the
    /// runtime makes (`runtime/src/apt_words.rs`), each setting what its
    /// record sets, in the runtime's order, calling the record's Sub and
    /// returning the lines the Subs wrote; the object of them is the value
    /// of the function the printed code is the body of.
    fn fusion_adapter(&mut self) {
        let subs = self.subs(FUSION_CALLED);
        let call = |word: &str| subs.get(word).map(|f| format!("{f}();")).unwrap_or_default();
        let set = |name: &str, value: &str| match self.slot(name) {
            Some(s) => format!("{s}{value});"),
            None => String::new(),
        };
        // Every record sets `Word`, `Minor` and `Text`, then calls its Sub.
        let record = |word: &str, minor: &str, text: &str| {
            [set("WORD", &js_string(word)), set("MINOR", minor), set("TEXT", text), call(word)]
        };
        let body = |parts: Vec<String>| {
            let lines: Vec<String> = parts.into_iter().filter(|s| !s.is_empty()).collect();
            lines.iter().map(|l| format!("        {l}\n")).collect::<String>()
        };
        let with = |mut sets: Vec<String>, word: &str, minor: &str, text: &str| {
            sets.extend(record(word, minor, text));
            body(sets)
        };
        let xyz = |x: &str, y: &str, z: &str, g: &str| vec![set("X", x), set("Y", y), set("Z", z), set("G", g)];
        let open = with(vec![set("METRIC", "aptMetric")], "PARTNO", "\"\"", "aptName");
        let loadtl = with(vec![set("T", "aptT"), set("H", "aptH"), set("D", "aptD")], "LOADTL", "\"\"", "aptName");
        let toolpath = with(Vec::new(), "TOOLPATH", "\"\"", "aptName");
        let spindle_on = with(vec![set("S", "aptS")], "SPINDL", "aptCcw ? \"CCLW\" : \"CLW\"", "\"\"");
        let spindle_off = with(Vec::new(), "SPINDL", "\"OFF\"", "\"\"");
        let coolant = with(Vec::new(), "COOLNT", "aptMinor", "\"\"");
        let cutcom = with(vec![set("D", "aptD")], "CUTCOM", "aptMinor", "\"\"");
        let rapid = {
            let mut parts = vec![set("G", "0")];
            parts.extend(record("RAPID", "\"\"", "\"\""));
            parts.extend(xyz("aptToX", "aptToY", "aptToZ", "0"));
            parts.extend(record("GOTO", "\"\"", "\"\""));
            body(parts)
        };
        let feed = with(Vec::new(), "FEDRAT", "\"\"", "\"\"");
        let goto = with(xyz("aptToX", "aptToY", "aptToZ", "1"), "GOTO", "\"\"", "\"\"");
        let circle = with(
            vec![
                set("X", "aptToX"),
                set("Y", "aptToY"),
                set("Z", "aptToZ"),
                set("G", "aptG"),
                set("PLANE", "aptPlane"),
                set("I", "aptCX - aptX"),
                set("J", "aptCY - aptY"),
                set("K", "aptCZ - aptZ"),
                set("CX", "aptCX"),
                set("CY", "aptCY"),
                set("CZ", "aptCZ"),
                set("R", "aptR"),
            ],
            "CIRCLE",
            "\"\"",
            "\"\"",
        );
        let delay = with(vec![set("R", "aptSeconds")], "DELAY", "\"\"", "\"\"");
        let pprint = with(Vec::new(), "PPRINT", "\"\"", "aptText");
        let cycle = with(
            vec![
                set("X", "aptToX"),
                set("Y", "aptToY"),
                set("Z", "aptDepth"),
                set("R", "aptR"),
                set("Q", "aptQ"),
                set("P", "aptP"),
                set("F", "aptF"),
            ],
            "CYCLE",
            "aptMinor",
            "\"\"",
        );
        let cycle_off = with(Vec::new(), "CYCLE", "\"OFF\"", "\"\"");
        let fini = with(Vec::new(), "FINI", "\"\"", "\"\"");
        let feed_f = set("F", "aptF");
        self.out.push_str(&format!(
            r#"// The adapter: each APT record of the source's engine, setting what the
// record sets and calling its Sub; each gives the lines the Subs wrote.
var aptOut = "";
var aptX = 0;
var aptY = 0;
var aptZ = 0;
var aptFeed = null;

function aptTake() {{
    var text = aptOut;
    aptOut = "";
    return text;
}}

// The feed of a move: FEDRAT when it changed.
function aptFeedTo(aptF) {{
    {feed_f}
    if (aptFeed !== aptF) {{
        aptFeed = aptF;
{feed}    }}
}}

return {{
    open: function (aptName, aptMetric) {{
{open}        return aptTake();
    }},
    loadtl: function (aptT, aptH, aptD, aptName) {{
{loadtl}        return aptTake();
    }},
    toolpath: function (aptName) {{
{toolpath}        return aptTake();
    }},
    spindleOn: function (aptS, aptCcw) {{
{spindle_on}        return aptTake();
    }},
    spindleOff: function () {{
{spindle_off}        return aptTake();
    }},
    coolant: function (aptMinor) {{
{coolant}        return aptTake();
    }},
    cutcom: function (aptMinor, aptD) {{
{cutcom}        return aptTake();
    }},
    rapid: function (aptToX, aptToY, aptToZ) {{
{rapid}        aptX = aptToX;
        aptY = aptToY;
        aptZ = aptToZ;
        return aptTake();
    }},
    linear: function (aptToX, aptToY, aptToZ, aptF) {{
        aptFeedTo(aptF);
{goto}        aptX = aptToX;
        aptY = aptToY;
        aptZ = aptToZ;
        return aptTake();
    }},
    circle: function (aptToX, aptToY, aptToZ, aptCX, aptCY, aptCZ, aptG, aptPlane, aptR, aptF) {{
        aptFeedTo(aptF);
{circle}        aptX = aptToX;
        aptY = aptToY;
        aptZ = aptToZ;
        return aptTake();
    }},
    delay: function (aptSeconds) {{
{delay}        return aptTake();
    }},
    pprint: function (aptText) {{
{pprint}        return aptTake();
    }},
    cycle: function (aptMinor, aptToX, aptToY, aptTop, aptDepth, aptR, aptQ, aptP, aptF) {{
{cycle}        aptX = aptToX;
        aptY = aptToY;
        aptZ = aptTop;
        return aptTake();
    }},
    hole: function (aptToX, aptToY, aptToZ) {{
{goto}        aptX = aptToX;
        aptY = aptToY;
        aptZ = aptToZ;
        return aptTake();
    }},
    cycleOff: function () {{
{cycle_off}        return aptTake();
    }},
    fini: function () {{
{fini}        return aptTake();
    }}
}};
"#
        ));
    }
}

/// Under the conversion note.
const NOTE: &str = "// A CNC-Calc post: CNC-Calc calls onOpen, onLinear, onCircular and
// onClose; the adapter at the end turns each call into the APT records
// (PARTNO, RAPID, FEDRAT, GOTO, CIRCLE, FINI) whose Subs the source
// post defines, each Sub a function below.
";

/// BASIC's values and built-ins as the runtime computes them.
const BASIC: &str = r##"// BASIC's values as the source's engine computes them.
function vbNum(a) {
    if (typeof a == "number") {
        return a;
    }
    if (typeof a == "boolean") {
        return a ? 1 : 0;
    }
    if (typeof a == "string") {
        var t = a.trim();
        return /^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?$/.test(t) ? Number(t) : 0;
    }
    return a === null ? 0 : NaN;
}

function vbText(a) {
    return a === null ? "" : String(a);
}

function vbTrue(a) {
    if (typeof a == "number") {
        return a != 0 && a == a;
    }
    if (typeof a == "string") {
        return a != "";
    }
    return a === true;
}

function vbAdd(a, b) {
    if (typeof a == "string" || typeof b == "string") {
        return vbText(a) + vbText(b);
    }
    return vbNum(a) + vbNum(b);
}

// -1, 0 or 1; NaN when the numbers are unordered.
function vbCmp(a, b) {
    if (typeof a == "string" && typeof b == "string") {
        return a < b ? -1 : a > b ? 1 : 0;
    }
    var x = vbNum(a);
    var y = vbNum(b);
    return x < y ? -1 : x > y ? 1 : x == y ? 0 : NaN;
}

function vbAnd(a, b) {
    return vbTrue(a) ? b() : a;
}

function vbOr(a, b) {
    return vbTrue(a) ? a : b();
}

function vbTrunc(a) {
    var v = vbNum(a);
    return v < 0 ? Math.ceil(v) : Math.floor(v);
}

function vbIntDiv(a, b) {
    var d = vbRound(b, 0);
    return d == 0 ? NaN : vbTrunc(vbRound(a, 0) / d);
}

function vbRound(a, n) {
    var d = vbNum(n);
    d = d > 0 ? Math.min(Math.floor(d), 15) : 0;
    var p = Math.pow(10, d);
    var v = vbNum(a) * p;
    var r = Math.floor(Math.abs(v));
    if (Math.abs(v) - r >= 0.5) {
        r += 1;
    }
    return (v < 0 ? -r : r) / p;
}

function vbMin(values) {
    var m = Infinity;
    for (var i = 0; i < values.length; i++) {
        m = Math.min(m, vbNum(values[i]));
    }
    return m;
}

function vbMax(values) {
    var m = -Infinity;
    for (var i = 0; i < values.length; i++) {
        m = Math.max(m, vbNum(values[i]));
    }
    return m;
}

function vbLeft(a, n) {
    var t = vbText(a);
    return t.substring(0, Math.min(Math.max(Math.floor(vbNum(n)), 0), t.length));
}

function vbRight(a, n) {
    var t = vbText(a);
    var k = Math.min(Math.max(Math.floor(vbNum(n)), 0), t.length);
    return t.substring(t.length - k);
}

function vbMid(a, start, n) {
    var t = vbText(a);
    var s = Math.min(Math.floor(Math.max(vbNum(start), 1)) - 1, t.length);
    var len = n === undefined ? t.length : Math.floor(Math.max(vbNum(n), 0));
    return t.substring(s, Math.min(s + len, t.length));
}

function vbVal(a) {
    var t = vbText(a).trim();
    var m = /^[+-]?[0-9.]*/.exec(t)[0];
    return /^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)$/.test(m) ? Number(m) : 0;
}

// Format(value, "000.0##"): zeros are digits always written, # digits
// written when they are not trailing zeros.
function vbFormat(a, picture) {
    var v = vbNum(a);
    var pic = vbText(picture);
    var dot = pic.indexOf(".");
    var intPic = dot < 0 ? pic : pic.substring(0, dot);
    var fracPic = dot < 0 ? "" : pic.substring(dot + 1);
    var fixed = fracPic.split("0").length - 1;
    var optional = fracPic.split("#").length - 1;
    var decimals = fixed + optional;
    var rounded = vbRound(v, decimals);
    var text = Math.abs(rounded).toFixed(decimals);
    if (optional > 0) {
        while (text.charAt(text.length - 1) == "0" && text.length - text.indexOf(".") - 1 > fixed) {
            text = text.substring(0, text.length - 1);
        }
        if (text.charAt(text.length - 1) == ".") {
            text = text.substring(0, text.length - 1);
        }
    }
    var minInt = intPic.split("0").length - 1;
    var intLen = text.indexOf(".") < 0 ? text.length : text.indexOf(".");
    if (intLen < minInt) {
        text = repeatText("0", minInt - intLen) + text;
    }
    return rounded < 0 ? "-" + text : text;
}

function vbChr(a) {
    return String.fromCharCode(vbNum(a));
}

// A register: its value, the one before, and the word it prints.
function createRegister(prefix, modal, format) {
    return {value: null, previous: null, w: createWord(prefix, modal, false, format)};
}

function setRegister(r, v) {
    r.previous = r.value;
    r.value = v;
}

// `<NAME>` of an Out line: the word, or text as it is.
function aptPut(r) {
    var v = r.value;
    if (typeof v == "string") {
        var text = r.w.prefix + v;
        if (r.w.modal && text === r.w.last) {
            return "";
        }
        r.w.last = text;
        return text;
    }
    return word(r.w, vbNum(v));
}

// `<N>`: the block number, advanced after the line.
function aptPutBlock(r) {
    aptBlock.printed = true;
    return word(r.w, aptBlock.next);
}

// An Out line ends.
function aptEnd(text) {
    aptOut += text + "\n";
    if (aptBlock.printed) {
        aptBlock.printed = false;
        aptBlock.next += aptBlock.increment;
        if (aptBlock.next > aptBlock.maximum) {
            aptBlock.next = aptBlock.start;
        }
    }
}
"##;
