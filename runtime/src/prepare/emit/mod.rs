//! The fast path: a handler that writes what a native function returns
//! (`Write(onLinear(x, y, z, 1))`) instead builds that text straight in
//! the output, with no string allocated.
//!
//! The function is inlined into the handler and every `return E` becomes
//! "emit the text of E, then leave". Concatenations emit their parts in
//! order; `xOutput.format(x)` formats into the output; calls of other
//! native functions in a concatenation are inlined the same way. A string
//! parameter (`writeBlock(text)`) is bound by emitting its argument first
//! and keeping the mark where it starts: `text == ""` becomes "nothing was
//! written since the mark", `text = "N10 " + text` writes the new text and
//! moves it back to the mark, `return text + linebreak` just appends,
//! `return text.substring(1) + linebreak` cuts the first character after
//! the mark ([`Stmt::Cut`]) and appends. A local that starts as text is
//! kept the same way; `text = text == "" ? w : text + " " + w` is an `if`
//! on "nothing written". Emptiness is "nothing written" only while the
//! text is text: a region set to a parameter that may be a number or
//! `undefined` makes the inlined body run only when each such argument is
//! text (`typeof a == "string"`), and the function is called otherwise.
//! A function whose shape is outside these rules keeps the allocating
//! `Write`; the result is the same either way.

pub(crate) mod marks;
mod shape;

use crate::exec::{Body, Expr, Function, Piece, Stmt};
use postc_ir::{BinaryOp, FunctionId, LocalId, Place, UnaryOp};

pub(crate) use marks::{drop_truncates, tidy};
pub(crate) use shape::max_slot;
use shape::*;

/// Rewrites handler bodies.
pub struct Emitter<'f> {
    functions: &'f [Function],
    returns_text: Vec<bool>,
    /// Functions every path of which ends in `return value`.
    always: Vec<bool>,
    /// Next free slot of the handler's frame.
    next: u16,
    /// Statements inlined so far, to bound the size of a handler.
    budget: usize,
}

/// Inlining nests at most this deep.
const MAX_DEPTH: usize = 6;

/// A handler's frame holds at most this many slots: an inlining that needs
/// more (a post read from RON may say a function has 65,535 locals) keeps
/// the plain call.
const MAX_FRAME: usize = 4096;

/// Where each local of an inlined function lives.
#[derive(Clone)]
struct Frame {
    /// Expressions are already in the handler's terms (the handler itself).
    identity: bool,
    /// Callee slot -> what it reads as.
    map: Vec<Binding>,
    /// The mark where this function's text starts.
    base: LocalId,
    depth: usize,
    /// A region local not assigned yet (its first assignment starts it).
    pending: std::cell::Cell<Option<LocalId>>,
    /// How many of the function's slots are its parameters.
    params: usize,
    /// The parameters a region is replaced by that may not be text
    /// (`text = word` in a `writeBlock` joining its words): the inlined
    /// body runs only when each is text; see [`Emitter::call_bound`].
    guards: std::cell::RefCell<Vec<usize>>,
}

#[derive(Clone)]
enum Binding {
    /// A slot of the handler's frame.
    Slot(LocalId),
    /// An argument substituted where it is read (pure and never assigned).
    Value(Expr),
    /// Text already written since the mark in this slot.
    Region(LocalId),
}

impl<'f> Emitter<'f> {
    pub fn new(functions: &'f [Function], first_free_slot: u16) -> Emitter<'f> {
        let always = functions.iter().map(|f| matches!(&f.body, Body::Native(b) if always_returns(b))).collect();
        let mut e =
            Emitter { functions, returns_text: vec![false; functions.len()], always, next: first_free_slot, budget: 0 };
        e.infer_text_returns();
        e
    }

    /// Which functions always return text (every path ends in `return
    /// TEXT`), so that their calls can be inlined inside a concatenation.
    fn infer_text_returns(&mut self) {
        let mut known = vec![true; self.functions.len()];
        loop {
            let mut changed = false;
            for (i, f) in self.functions.iter().enumerate() {
                let ok = match &f.body {
                    Body::Native(body) => always_returns(body) && all_returns(body, &|e| is_text(e, &known)),
                    Body::Script(_) => false,
                };
                if known[i] && !ok {
                    known[i] = false;
                    changed = true;
                }
            }
            if !changed {
                break;
            }
        }
        self.returns_text = known;
    }

    /// Rewrites a handler body: each `Write(call)` of a native function
    /// becomes the inlined text-building statements when possible.
    pub fn handler(&mut self, body: Vec<Stmt>) -> Vec<Stmt> {
        body.into_iter().map(|s| self.stmt(s)).collect()
    }

    fn stmt(&mut self, s: Stmt) -> Stmt {
        match s {
            Stmt::Write(Expr::Call(f, args)) => {
                let saved = (self.next, self.budget);
                let mark = self.slot();
                match self.call(f, &args, 0, false).filter(|_| usize::from(self.next) < MAX_FRAME) {
                    Some(mut inlined) => {
                        inlined.insert(0, Stmt::Mark(mark));
                        inlined.push(Stmt::Blocks(mark));
                        Stmt::If { branches: vec![(Expr::Bool(true), merge(inlined))], otherwise: vec![] }
                    }
                    None => {
                        (self.next, self.budget) = saved;
                        Stmt::Write(Expr::Call(f, args))
                    }
                }
            }
            Stmt::If { branches, otherwise } => Stmt::If {
                branches: branches.into_iter().map(|(c, b)| (c, self.handler(b))).collect(),
                otherwise: self.handler(otherwise),
            },
            Stmt::While { cond, body, span, step } => {
                Stmt::While { cond, body: self.handler(body), span, step: self.handler(step) }
            }
            other => other,
        }
    }

    /// A new slot of the handler's frame. Past [`MAX_FRAME`] the slots
    /// repeat, and [`Emitter::stmt`] drops the inlining that asked for them.
    fn slot(&mut self) -> LocalId {
        self.next = self.next.saturating_add(1);
        LocalId::new(self.next - 1)
    }

    /// The statements that write what `f(args)` returns, wrapped so that
    /// a `return` leaves. `in_text`: the call sits inside a concatenation,
    /// where only functions that always return text may be inlined.
    fn call(&mut self, f: FunctionId, args: &[Expr], depth: usize, in_text: bool) -> Option<Vec<Stmt>> {
        self.call_bound(f, args, depth, in_text, None)
    }

    /// `call`, with parameter `bound.0` already written as the text since
    /// mark `bound.1` (the caller's region, passed on). A local kept as a
    /// region that cannot be passed on where the function hands it to
    /// another (`return writeBlock(..., f)` to a `writeBlock` that joins
    /// its words) is tried again as a value.
    fn call_bound(
        &mut self,
        f: FunctionId,
        args: &[Expr],
        depth: usize,
        in_text: bool,
        bound: Option<(usize, LocalId)>,
    ) -> Option<Vec<Stmt>> {
        let saved = (self.next, self.budget);
        if let Some(out) = self.call_with(f, args, depth, in_text, bound, true) {
            return Some(out);
        }
        let has_region_local = self.functions.get(f.index()).is_some_and(|g| match &g.body {
            Body::Native(body) => region_local(body, g.params, (g.slots as usize).max(g.params)).is_some(),
            Body::Script(_) => false,
        });
        if !has_region_local {
            return None;
        }
        (self.next, self.budget) = saved;
        self.call_with(f, args, depth, in_text, bound, false)
    }

    /// [`Self::call_bound`]; `local_region`: a local may be a region.
    fn call_with(
        &mut self,
        f: FunctionId,
        args: &[Expr],
        depth: usize,
        in_text: bool,
        bound: Option<(usize, LocalId)>,
        local_region: bool,
    ) -> Option<Vec<Stmt>> {
        if depth >= MAX_DEPTH {
            return None;
        }
        let function = self.functions.get(f.index())?;
        let Body::Native(body) = &function.body else { return None };
        // Inside a concatenation, a function that can return nothing would
        // add nothing either way; one that may fall off its end is left alone.
        if in_text && !self.always[f.index()] {
            return None;
        }
        if has_loop(body) {
            return None;
        }
        self.budget += count(body);
        if self.budget > 400 {
            return None;
        }
        let params = function.params;
        let slots = (function.slots as usize).max(params);
        if usize::from(self.next) + slots >= MAX_FRAME {
            return None;
        }
        let (base, mut out) = match bound {
            Some((_, mark)) => (mark, Vec::new()),
            None => {
                let b = self.slot();
                (b, vec![Stmt::Mark(b)])
            }
        };
        let mut map = Vec::with_capacity(slots);
        let region_param = match bound {
            Some((k, _)) => (k < params && region_uses_ok(body, LocalId::new(k as u16))).then_some(k),
            None => region_param(body, params, args, &self.returns_text),
        };
        if bound.is_some() && region_param.is_none() {
            return None;
        }
        let region_local =
            if region_param.is_none() && local_region { region_local(body, params, slots) } else { None };
        // What the locals start as: after the arguments, inside the guard.
        let mut starts = Vec::new();
        for k in 0..slots {
            if Some(k) == region_local {
                map.push(Binding::Region(self.slot()));
                continue;
            }
            if k >= params {
                let s = self.slot();
                // A local starts undefined, unless it is set before any use
                // (or never used at all).
                let first = body.iter().find(|st| stmt_mentions(st, LocalId::new(k as u16)));
                if first.is_some()
                    && !matches!(first, Some(Stmt::Assign(Place::Local(x), e)) if x.index() == k && !expr_reads(e, LocalId::new(k as u16)))
                {
                    starts.push(Stmt::Assign(Place::Local(s), function.fill()));
                }
                map.push(Binding::Slot(s));
                continue;
            }
            let arg = args.get(k).cloned().unwrap_or_else(|| function.fill());
            if Some(k) == region_param {
                // Bound by writing it: its text starts at the function's base.
                if bound.is_none() {
                    out.extend(self.text(&arg, &Frame::root(), depth + 1)?);
                }
                map.push(Binding::Region(base));
            } else if (is_pure(&arg) || matches!(arg, Expr::Local(_))) && !assigns(body, LocalId::new(k as u16)) {
                // A handler local is read where it is: nothing the inlined
                // body does assigns it.
                map.push(Binding::Value(arg));
            } else {
                let s = self.slot();
                out.push(Stmt::Assign(Place::Local(s), arg));
                map.push(Binding::Slot(s));
            }
        }
        // Arguments past the parameters are evaluated for their effects.
        for extra in args.iter().skip(params) {
            if !is_pure(extra) {
                out.push(Stmt::Eval(extra.clone()));
            }
        }
        let frame = Frame {
            identity: false,
            map,
            base,
            depth,
            pending: std::cell::Cell::new(region_local.map(|k| LocalId::new(k as u16))),
            params,
            guards: Default::default(),
        };
        let mut inner = self.stmts(body, &frame)?;
        let ends = matches!(inner.last(), Some(Stmt::Break));
        if ends {
            inner.pop();
        } else {
            // Falling off the end returns undefined: nothing is written.
            inner.push(Stmt::Truncate(base));
        }
        if breaks(&inner) {
            // An early `return`: a loop to leave.
            inner.push(Stmt::Break);
            starts.push(Stmt::While { cond: Expr::Bool(true), body: merge(inner), span: None, step: vec![] });
        } else {
            starts.extend(inner);
        }
        let mut guards = frame.guards.take();
        if guards.is_empty() {
            out.extend(starts);
            return Some(merge(out));
        }
        // The region is set to an argument that may not be text: when one
        // is not (a number, `undefined`), `text == ""` is not "nothing
        // written", so the function then runs as a call whose value is
        // written (the same text the allocating path writes).
        if bound.is_some() || region_param.is_some() {
            return None;
        }
        guards.sort_unstable();
        guards.dedup();
        let args: Vec<Expr> = (0..params)
            .map(|k| match frame.map.get(k) {
                Some(Binding::Value(v)) => Some(v.clone()),
                Some(Binding::Slot(s)) => Some(Expr::Local(*s)),
                _ => None,
            })
            .collect::<Option<_>>()?;
        let is_text = |k: usize| {
            let kind = Expr::Unary(UnaryOp::Typeof, Box::new(args[k].clone()));
            Expr::Binary(BinaryOp::StrictEq, Box::new(kind), Box::new(Expr::text("string")))
        };
        let cond = guards
            .iter()
            .skip(1)
            .fold(is_text(guards[0]), |all, &k| Expr::Binary(BinaryOp::And, Box::new(all), Box::new(is_text(k))));
        out.push(Stmt::If {
            branches: vec![(cond, merge(starts))],
            otherwise: vec![Stmt::Emit(vec![Piece::Expr(Expr::Call(f, args))])],
        });
        Some(merge(out))
    }

    fn stmts(&mut self, body: &[Stmt], fr: &Frame) -> Option<Vec<Stmt>> {
        let mut out = Vec::new();
        for s in body {
            match s {
                Stmt::Return(e) => {
                    out.extend(self.ret(e.as_ref(), fr)?);
                    out.push(Stmt::Break);
                    return Some(out);
                }
                Stmt::If { branches, otherwise } => {
                    let mut bs = Vec::new();
                    for (c, b) in branches {
                        bs.push((self.cond(c, fr)?, self.stmts(b, fr)?));
                    }
                    out.push(Stmt::If { branches: bs, otherwise: self.stmts(otherwise, fr)? });
                }
                Stmt::Assign(Place::Local(k), e) => match fr.map.get(k.index())? {
                    Binding::Slot(s) => out.push(Stmt::Assign(Place::Local(*s), value(e, fr)?)),
                    Binding::Region(mark) => {
                        let mark = *mark;
                        if fr.pending.get() == Some(*k) {
                            // The first assignment of a region local starts it.
                            fr.pending.set(None);
                            out.push(Stmt::Mark(mark));
                            out.extend(self.text(e, fr, fr.depth + 1)?);
                        } else if let Expr::Choose(c, a, b) = e {
                            // `text = text == "" ? word : text + " " + word`
                            let cond = self.cond(c, fr)?;
                            let yes = self.region_text(a, *k, mark, fr)?;
                            let no = self.region_text(b, *k, mark, fr)?;
                            out.push(Stmt::If { branches: vec![(cond, yes)], otherwise: no });
                        } else {
                            out.extend(self.region_text(e, *k, mark, fr)?);
                        }
                    }
                    Binding::Value(_) => return None,
                },
                Stmt::Assign(place, e) => out.push(Stmt::Assign(*place, value(e, fr)?)),
                Stmt::Eval(e) => out.push(Stmt::Eval(value(e, fr)?)),
                Stmt::Origin(span) => out.push(Stmt::Origin(*span)),
                _ => return None,
            }
        }
        Some(out)
    }

    /// `return e`: the function's text becomes the text of `e`.
    fn ret(&mut self, e: Option<&Expr>, fr: &Frame) -> Option<Vec<Stmt>> {
        let Some(e) = e else { return Some(vec![Stmt::Truncate(fr.base)]) };
        if let Expr::Choose(c, a, b) = e {
            let cond = self.cond(c, fr)?;
            let yes = self.ret(Some(a), fr)?;
            let no = self.ret(Some(b), fr)?;
            return Some(vec![Stmt::If { branches: vec![(cond, yes)], otherwise: no }]);
        }
        if let Expr::Call(g, args) = e
            && let Some(out) = self.pass_region(*g, args, fr)
        {
            return Some(out);
        }
        if let Some(k) = region_in(e, fr) {
            return self.region_text(e, k, fr.base, fr);
        }
        if mentions_region(e, fr) {
            return None;
        }
        let mut out = vec![Stmt::Truncate(fr.base)];
        let mut text = self.text(e, fr, fr.depth + 1)?;
        // A value returned whole is written as a handler's value is: null
        // and `undefined` as nothing (in JavaScript, an operand of `+`
        // writes null as `null`).
        if let [Stmt::Emit(pieces)] = text.as_mut_slice()
            && let [piece @ Piece::Expr(_)] = pieces.as_mut_slice()
            && !matches!(piece, Piece::Expr(Expr::FormatVar { .. } | Expr::Format { .. } | Expr::Var(_)))
            && let Piece::Expr(x) = std::mem::replace(piece, Piece::Text(Vec::new()))
        {
            *piece = Piece::Joined(x);
        }
        out.extend(text);
        Some(out)
    }

    /// `return g(..., text-with-region, ...)`: the region is extended to
    /// the argument's text and handed to `g` as its text parameter.
    fn pass_region(&mut self, g: FunctionId, args: &[Expr], fr: &Frame) -> Option<Vec<Stmt>> {
        let with = |a: &Expr| region_in(a, fr);
        let i = args.iter().position(|a| with(a).is_some())?;
        if args.iter().enumerate().any(|(j, a)| j != i && mentions_region(a, fr)) {
            return None;
        }
        let k = with(&args[i])?;
        let Binding::Region(mark) = fr.map.get(k.index())? else { return None };
        let mark = *mark;
        let mut hargs = Vec::with_capacity(args.len());
        for (j, a) in args.iter().enumerate() {
            hargs.push(if j == i { Expr::Null } else { value(a, fr)? });
        }
        let saved = (self.next, self.budget);
        let mut out = self.region_text(&args[i], k, mark, fr)?;
        match self.call_bound(g, &hargs, fr.depth + 1, false, Some((i, mark))) {
            Some(inlined) => {
                out.extend(inlined);
                Some(out)
            }
            None => {
                (self.next, self.budget) = saved;
                None
            }
        }
    }

    /// Writes `e`, a concatenation with region local `k` once in it, so
    /// that the region (starting at `mark`) holds its text afterwards.
    fn region_text(&mut self, e: &Expr, k: LocalId, mark: LocalId, fr: &Frame) -> Option<Vec<Stmt>> {
        let mut leaves = Vec::new();
        concat_leaves(e, &mut leaves);
        let pos = leaves.iter().position(|l| region_part(l, k).is_some());
        let Some(pos) = pos else {
            // The region is replaced: by text, or by a parameter that the
            // inlined body then requires to be text (`Frame::guards`).
            if !is_text(e, &self.returns_text) {
                match e {
                    Expr::Local(p) if p.index() < fr.params && !fr.identity => fr.guards.borrow_mut().push(p.index()),
                    _ => return None,
                }
            }
            let mut out = vec![Stmt::Truncate(mark)];
            for l in &leaves {
                if mentions_region(l, fr) {
                    return None;
                }
                out.extend(self.text(l, fr, fr.depth + 1)?);
            }
            return Some(out);
        };
        if leaves.iter().enumerate().any(|(i, l)| i != pos && mentions_region(l, fr)) {
            return None;
        }
        let mut out = Vec::new();
        if let Some(chars) = region_part(leaves[pos], k).filter(|&n| n > 0) {
            out.push(Stmt::Cut { at: mark, chars });
        }
        if pos > 0 {
            let t = self.slot();
            out.push(Stmt::Mark(t));
            for l in &leaves[..pos] {
                out.extend(self.text(l, fr, fr.depth + 1)?);
            }
            out.push(Stmt::MoveBack { to: mark, from: t });
        }
        for l in &leaves[pos + 1..] {
            out.extend(self.text(l, fr, fr.depth + 1)?);
        }
        Some(out)
    }

    /// A condition, with tests of a region's emptiness rewritten.
    fn cond(&self, c: &Expr, fr: &Frame) -> Option<Expr> {
        let region = |e: &Expr| match e {
            Expr::Local(k) => match fr.map.get(k.index()) {
                Some(Binding::Region(m)) => Some(*m),
                _ => None,
            },
            _ => None,
        };
        let empty = |e: &Expr| matches!(e, Expr::Text(t) if t.is_empty());
        match c {
            Expr::Binary(BinaryOp::Eq | BinaryOp::JsEq | BinaryOp::StrictEq, a, b)
                if region(a).is_some() && empty(b) =>
            {
                Some(Expr::Unary(UnaryOp::Not, Box::new(Expr::Written(region(a)?))))
            }
            Expr::Binary(BinaryOp::Ne | BinaryOp::JsNe | BinaryOp::StrictNe, a, b)
                if region(a).is_some() && empty(b) =>
            {
                Some(Expr::Written(region(a)?))
            }
            Expr::Unary(UnaryOp::Not, a) if region(a).is_some() => {
                Some(Expr::Unary(UnaryOp::Not, Box::new(Expr::Written(region(a)?))))
            }
            e if region(e).is_some() => Some(Expr::Written(region(e)?)),
            other => value(other, fr),
        }
    }

    /// Statements that write the text of `e`, an expression in the terms
    /// of frame `fr`.
    fn text(&mut self, e: &Expr, fr: &Frame, depth: usize) -> Option<Vec<Stmt>> {
        Some(match e {
            Expr::Text(t) if t.is_empty() => Vec::new(),
            Expr::Text(t) => vec![Stmt::Emit(vec![Piece::Text(t.as_bytes().to_vec())])],
            Expr::Binary(BinaryOp::Add, a, b) if is_text(e, &self.returns_text) => {
                let mut out = self.text(a, fr, depth)?;
                out.extend(self.text(b, fr, depth)?);
                out
            }
            // An element of a word array: `w == null ? "" : w`.
            Expr::Choose(c, a, b)
                if matches!(&**a, Expr::Text(t) if t.is_empty())
                    && matches!(&**c, Expr::Binary(BinaryOp::JsEq, x, null) if **x == **b && **null == Expr::Null)
                    && (shape::is_pure(b) || matches!(&**b, Expr::Local(_))) =>
            {
                vec![Stmt::Emit(vec![Piece::Joined(value(b, fr)?)])]
            }
            Expr::Choose(c, a, b) => {
                let cond = value(c, fr)?;
                let yes = self.text(a, fr, depth)?;
                let no = self.text(b, fr, depth)?;
                vec![Stmt::If { branches: vec![(cond, yes)], otherwise: no }]
            }
            Expr::Call(f, args) => {
                let args = args.iter().map(|a| value(a, fr)).collect::<Option<Vec<_>>>()?;
                let saved = (self.next, self.budget);
                match self.call(*f, &args, depth, true) {
                    Some(s) => s,
                    None => {
                        (self.next, self.budget) = saved;
                        vec![Stmt::Emit(vec![Piece::Expr(Expr::Call(*f, args))])]
                    }
                }
            }
            other => vec![Stmt::Emit(vec![Piece::Expr(value(other, fr)?)])],
        })
    }
}

impl Frame {
    /// The handler's own frame: expressions are already in its terms.
    fn root() -> Frame {
        Frame {
            identity: true,
            map: Vec::new(),
            base: LocalId::new(0),
            depth: 0,
            pending: std::cell::Cell::new(None),
            params: 0,
            guards: Default::default(),
        }
    }
}

/// A callee expression in handler terms; `None` if it reads a region.
fn value(e: &Expr, fr: &Frame) -> Option<Expr> {
    if fr.identity {
        return Some(e.clone());
    }
    Some(match e {
        Expr::Local(k) => match fr.map.get(k.index())? {
            Binding::Slot(s) => Expr::Local(*s),
            Binding::Value(v) => v.clone(),
            Binding::Region(_) => return None,
        },
        Expr::FormatVar { var, value: v, span } => {
            Expr::FormatVar { var: *var, value: Box::new(value(v, fr)?), span: *span }
        }
        Expr::Format { format, value: v, span } => {
            Expr::Format { format: *format, value: Box::new(value(v, fr)?), span: *span }
        }
        Expr::Unary(op, a) => Expr::Unary(*op, Box::new(value(a, fr)?)),
        Expr::Binary(op, a, b) => Expr::Binary(*op, Box::new(value(a, fr)?), Box::new(value(b, fr)?)),
        Expr::Choose(c, a, b) => {
            Expr::Choose(Box::new(value(c, fr)?), Box::new(value(a, fr)?), Box::new(value(b, fr)?))
        }
        Expr::Call(f, args) => Expr::Call(*f, args.iter().map(|a| value(a, fr)).collect::<Option<_>>()?),
        Expr::Builtin(b, args) => Expr::Builtin(*b, args.iter().map(|a| value(a, fr)).collect::<Option<_>>()?),
        other => other.clone(),
    })
}

fn mentions_region(e: &Expr, fr: &Frame) -> bool {
    value(e, fr).is_none()
}

/// The region local a concatenation has as one of its parts.
fn region_in(e: &Expr, fr: &Frame) -> Option<LocalId> {
    let mut leaves = Vec::new();
    concat_leaves(e, &mut leaves);
    leaves.iter().find_map(|l| {
        let k = match l {
            Expr::Local(k) => *k,
            Expr::Builtin(_, args) => match args.first() {
                Some(Expr::Local(k)) => *k,
                _ => return None,
            },
            _ => return None,
        };
        (matches!(fr.map.get(k.index()), Some(Binding::Region(_))) && region_part(l, k).is_some()).then_some(k)
    })
}
