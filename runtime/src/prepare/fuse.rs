//! Superinstructions: a run of statements the fast path makes again and
//! again becomes one statement that does the same, so that a move pays one
//! dispatch for it instead of four or five.
//!
//! Today: one word of a block built in the output ([`Stmt::Word`]), in the
//! two shapes [`super::emit`] gives a word array joined with a separator,
//! counted (`writeBlock` of `words.push(w)` and `words.join(" ")`):
//!
//! ```text
//! if (w != "") { if (n > 0) { emit " " }  emit w;  n = n + 1 }
//! ```
//!
//! or asked of the output (`text = text == "" ? w : text + " " + w`):
//!
//! ```text
//! if (w != "") { if (!written(m)) { truncate m; emit w } else { emit " " + w } }
//! ```
//!
//! And expressions a field post evaluates for every word: `w != ""` and
//! `typeof w === "string"` of a local, asked of the local in one step,
//! `parseFloat(text.substring(k))`, the number read where the text is
//! formatted, and chains of `&&` or `||` as one list ([`expressions`]).
//!
//! Only those exact shapes are fused; the interpreter's [`Stmt::Word`]
//! runs the same tests, writes and assignments in the same order, and
//! counts the same steps, so nothing a post writes can change.

use postc_ir::{BinaryOp, Builtin, LocalId, Place, UnaryOp};

use crate::exec::{Expr, Piece, Stmt, WordRun, WordsBefore};

/// Fuses every word in the statements, at any depth.
#[doc(hidden)]
pub fn stmts(body: &mut [Stmt]) {
    for stmt in body.iter_mut() {
        match stmt {
            Stmt::If { branches, otherwise } => {
                for (_, b) in branches.iter_mut() {
                    stmts(b);
                }
                stmts(otherwise);
            }
            Stmt::While { body, .. } => stmts(body),
            _ => {}
        }
        if let Some(word) = word(stmt) {
            *stmt = word;
        }
    }
}

/// Every run of two or more words of locals joined into a block, at any
/// depth, as one [`Stmt::Words`]: the count set to 0 (or the mark set)
/// and the words after it, each `if (w != "")` or `if (w)` of one local
/// printing that local, with one separator; and the `if` after them that
/// drops an empty block and leaves (`if (n == 0)` or `if (!written(m))`
/// of `truncate; break`), when it is there. Runs last, after every pass
/// that rewrites locals.
#[doc(hidden)]
pub fn runs(body: &mut Vec<Stmt>) {
    for s in body.iter_mut() {
        s.for_each_body_mut(runs);
    }
    let mut i = 0;
    while i < body.len() {
        if let Some((run, len)) = run_at(&body[i..]) {
            let general: Vec<Stmt> = body.drain(i..i + len).collect();
            body.insert(i, Stmt::Words(Box::new(WordRun { general, ..run })));
        }
        i += 1;
    }
}

/// The run of words that starts `body`, if one does, and how many
/// statements it is (its `general` left empty).
fn run_at(body: &[Stmt]) -> Option<(WordRun, usize)> {
    let before = match body.first()? {
        Stmt::Assign(Place::Local(n), Expr::Number(z)) if *z == 0.0 => WordsBefore::Count(*n),
        Stmt::Mark(m) => WordsBefore::Written(*m),
        _ => return None,
    };
    let (WordsBefore::Count(counter) | WordsBefore::Written(counter)) = before;
    let (mut sep, mut locals): (Option<&Vec<u8>>, _) = (None, Vec::new());
    for s in &body[1..] {
        let Stmt::Word { cond, word, sep: this_sep, before: b } = s else { break };
        // A word kept as its joined text is the same when it is text, the
        // only case the run writes in one step.
        let [Piece::Expr(Expr::Local(w)) | Piece::Joined(Expr::Local(w))] = word.as_slice() else { break };
        let printed = match cond {
            Expr::Local(c) => c == w,
            Expr::LocalEmpty { local, op: BinaryOp::JsNe | BinaryOp::StrictNe } => local == w,
            _ => false,
        };
        if !printed || *b != before || *w == counter || sep.is_some_and(|s| s != this_sep) {
            break;
        }
        sep = Some(this_sep);
        locals.push(*w);
    }
    if locals.len() < 2 {
        return None;
    }
    let mut len = 1 + locals.len();
    let empty = body.get(len).and_then(|s| empty_block(s, before));
    len += usize::from(empty.is_some());
    Some((WordRun { general: Vec::new(), locals, sep: sep.cloned().unwrap_or_default(), before, empty }, len))
}

/// The mark an `if` after the words truncates to before it leaves, when
/// the `if` asks whether no word printed: `if (n == 0)` of the count, or
/// `if (!written(m))` of the mark.
fn empty_block(s: &Stmt, before: WordsBefore) -> Option<LocalId> {
    let Stmt::If { branches, otherwise } = s else { return None };
    let [(cond, then)] = branches.as_slice() else { return None };
    let [Stmt::Truncate(t), Stmt::Break] = then.as_slice() else { return None };
    let asks = match (cond, before) {
        (Expr::Binary(BinaryOp::JsEq | BinaryOp::StrictEq, n, zero), WordsBefore::Count(k)) => {
            matches!((&**n, &**zero), (Expr::Local(n), Expr::Number(z)) if *n == k && *z == 0.0)
        }
        (Expr::Unary(UnaryOp::Not, w), WordsBefore::Written(k)) => matches!(&**w, Expr::Written(m) if *m == k),
        _ => false,
    };
    (asks && otherwise.is_empty()).then_some(*t)
}

/// Every `local == ""`, `typeof local === "string"`,
/// `parseFloat(text.substring(k))` (with or without a `+` before it) and
/// chain of `&&` or `||` in the statements, at any depth, as the one
/// expression that does it
/// ([`Expr::LocalEmpty`], [`Expr::LocalIsText`], [`Expr::ParseFloatFrom`],
/// [`Expr::Chain`]).
#[doc(hidden)]
pub fn expressions(body: &mut [Stmt]) {
    for s in body {
        s.for_each_expr_mut(expression);
        s.for_each_body_mut(|b| expressions(b));
    }
}

fn expression(e: &mut Expr) {
    e.for_each_operand_mut(expression);
    // a && b && c (or ||), flattened
    if let Expr::Binary(op @ (BinaryOp::And | BinaryOp::Or), a, b) = e {
        let all = *op == BinaryOp::And;
        let mut operands = match std::mem::replace(&mut **a, Expr::Null) {
            Expr::Chain { all: inner, operands } if inner == all => operands,
            a => vec![a],
        };
        operands.push(std::mem::replace(&mut **b, Expr::Null));
        *e = Expr::Chain { all, operands };
        return;
    }
    // parseFloat(text.substring(k)), k a whole number
    if let Expr::Builtin(Builtin::ParseFloat, args) = e
        && let [Expr::Builtin(Builtin::Substring, cut)] = args.as_mut_slice()
        && let [_, Expr::Number(k)] = cut.as_slice()
        && *k >= 0.0
        && k.fract() == 0.0
        && *k < 1e9
    {
        let from = *k as usize;
        let value = cut.swap_remove(0);
        *e = Expr::ParseFloatFrom { value: Box::new(value), from };
        return;
    }
    // +parseFloat(...) is the number parseFloat gives
    if let Expr::Unary(UnaryOp::Plus, inner) = e
        && matches!(**inner, Expr::ParseFloatFrom { .. })
    {
        *e = std::mem::replace(&mut **inner, Expr::Null);
        return;
    }
    let Expr::Binary(op @ (BinaryOp::JsEq | BinaryOp::JsNe | BinaryOp::StrictEq | BinaryOp::StrictNe), a, b) = e else {
        return;
    };
    let Expr::Text(text) = &**b else { return };
    *e = match &**a {
        Expr::Local(local) if text.is_empty() => Expr::LocalEmpty { local: *local, op: *op },
        Expr::Unary(UnaryOp::Typeof, operand)
            if let Expr::Local(local) = &**operand
                && matches!(op, BinaryOp::StrictEq | BinaryOp::StrictNe)
                && **text == *"string" =>
        {
            Expr::LocalIsText { local: *local, is: *op == BinaryOp::StrictEq }
        }
        _ => return,
    };
}

/// The word a statement is, if it is one of the two shapes.
fn word(stmt: &Stmt) -> Option<Stmt> {
    let Stmt::If { branches, otherwise } = stmt else { return None };
    let [(cond, then)] = branches.as_slice() else { return None };
    if !otherwise.is_empty() {
        return None;
    }
    let (word, sep, before) = match then.as_slice() {
        // if (n > 0) { emit sep }  emit w;  n = n + 1
        [Stmt::If { branches: inner, otherwise: none }, Stmt::Emit(word), Stmt::Assign(Place::Local(n), step)]
            if none.is_empty() =>
        {
            let [(Expr::Binary(BinaryOp::JsGt, count, zero), sep)] = inner.as_slice() else { return None };
            let (Expr::Local(c), Expr::Number(z)) = (&**count, &**zero) else { return None };
            let [Stmt::Emit(sep)] = sep.as_slice() else { return None };
            let [Piece::Text(sep)] = sep.as_slice() else { return None };
            let Expr::Binary(BinaryOp::Add, l, one) = step else { return None };
            let (Expr::Local(l), Expr::Number(one)) = (&**l, &**one) else { return None };
            if c != n || l != n || *z != 0.0 || *one != 1.0 {
                return None;
            }
            (word, sep, WordsBefore::Count(*n))
        }
        // if (!written(m)) { truncate m; emit w } else { emit sep + w }: with
        // nothing written since `m` the truncation drops nothing, and a
        // first word may come without it (`super::emit` drops it there).
        [Stmt::If { branches: inner, otherwise: joined }] => {
            let [(Expr::Unary(UnaryOp::Not, written), first)] = inner.as_slice() else { return None };
            let Expr::Written(m) = &**written else { return None };
            let word = match first.as_slice() {
                [Stmt::Truncate(t), Stmt::Emit(word)] if t == m => word,
                [Stmt::Emit(word)] => word,
                _ => return None,
            };
            let [Stmt::Emit(joined)] = joined.as_slice() else { return None };
            let (Some(Piece::Text(sep)), rest) = (joined.first(), joined.get(1..)?) else { return None };
            if rest != word.as_slice() {
                return None;
            }
            (word, sep, WordsBefore::Written(*m))
        }
        _ => return None,
    };
    Some(Stmt::Word { cond: cond.clone(), word: word.clone(), sep: sep.clone(), before })
}
