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
pub(super) fn stmts(body: &mut [Stmt]) {
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
pub(super) fn runs(body: &mut Vec<Stmt>) {
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
        let [Piece::Expr(Expr::Local(w))] = word.as_slice() else { break };
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
pub(super) fn expressions(body: &mut [Stmt]) {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::prepare::testing::local;

    fn not_empty(e: Expr) -> Expr {
        Expr::Binary(BinaryOp::JsNe, Box::new(e), Box::new(Expr::text("")))
    }

    fn counted(word: u16, n: u16, zero: f64) -> Stmt {
        Stmt::If {
            branches: vec![(
                not_empty(local(word)),
                vec![
                    Stmt::If {
                        branches: vec![(
                            Expr::Binary(BinaryOp::JsGt, Box::new(local(n)), Box::new(Expr::Number(zero))),
                            vec![Stmt::Emit(vec![Piece::Text(b" ".to_vec())])],
                        )],
                        otherwise: vec![],
                    },
                    Stmt::Emit(vec![Piece::Expr(local(word))]),
                    Stmt::Assign(
                        Place::Local(LocalId::new(n)),
                        Expr::Binary(BinaryOp::Add, Box::new(local(n)), Box::new(Expr::Number(1.0))),
                    ),
                ],
            )],
            otherwise: vec![],
        }
    }

    #[test]
    fn a_counted_word_is_fused_and_a_near_miss_is_not() {
        let mut body = vec![Stmt::While {
            cond: Expr::Bool(true),
            body: vec![counted(2, 9, 0.0), counted(3, 9, 1.0)],
            span: None,
            step: vec![],
        }];
        stmts(&mut body);
        let Stmt::While { body, .. } = &body[0] else { panic!() };
        assert!(
            matches!(&body[0], Stmt::Word { before: WordsBefore::Count(k), sep, .. } if sep == b" " && k.index() == 9),
            "{:?}",
            body[0]
        );
        // `n > 1` is not the shape: left as it is.
        assert_eq!(body[1], counted(3, 9, 1.0));
    }

    #[test]
    fn a_word_after_written_text_is_fused() {
        let m = LocalId::new(4);
        let w = vec![Piece::Expr(local(1))];
        let stmt = Stmt::If {
            branches: vec![(
                not_empty(local(1)),
                vec![Stmt::If {
                    branches: vec![(
                        Expr::Unary(UnaryOp::Not, Box::new(Expr::Written(m))),
                        vec![Stmt::Truncate(m), Stmt::Emit(w.clone())],
                    )],
                    otherwise: vec![Stmt::Emit(vec![Piece::Text(b" ".to_vec()), Piece::Expr(local(1))])],
                }],
            )],
            otherwise: vec![],
        };
        let mut body = vec![stmt];
        stmts(&mut body);
        assert_eq!(
            body[0],
            Stmt::Word { cond: not_empty(local(1)), word: w, sep: b" ".to_vec(), before: WordsBefore::Written(m) }
        );
    }

    #[test]
    fn chains_of_and_and_or_become_lists() {
        let (a, b, c) = (local(0), local(1), local(2));
        let and = |x: Expr, y: Expr| Expr::Binary(BinaryOp::And, Box::new(x), Box::new(y));
        let or = |x: Expr, y: Expr| Expr::Binary(BinaryOp::Or, Box::new(x), Box::new(y));
        let mut body = vec![Stmt::Eval(or(and(and(a.clone(), b.clone()), c.clone()), a.clone()))];
        expressions(&mut body);
        let all = Expr::Chain { all: true, operands: vec![a.clone(), b, c] };
        assert_eq!(body, vec![Stmt::Eval(Expr::Chain { all: false, operands: vec![all, a] })]);
    }

    #[test]
    fn parse_float_of_a_cut_text_becomes_one_expression() {
        let cut = |k: f64| {
            Expr::Builtin(Builtin::ParseFloat, vec![Expr::Builtin(Builtin::Substring, vec![local(0), Expr::Number(k)])])
        };
        let mut body = vec![Stmt::Eval(cut(1.0)), Stmt::Eval(cut(1.5)), Stmt::Eval(cut(-1.0))];
        expressions(&mut body);
        assert_eq!(body[0], Stmt::Eval(Expr::ParseFloatFrom { value: Box::new(local(0)), from: 1 }));
        assert_eq!(body[1..], [Stmt::Eval(cut(1.5)), Stmt::Eval(cut(-1.0))]);
        // `+parseFloat(...)`: parseFloat gives a number, the `+` goes.
        let mut body = vec![Stmt::Eval(Expr::Unary(UnaryOp::Plus, Box::new(cut(1.0))))];
        expressions(&mut body);
        assert_eq!(body[0], Stmt::Eval(Expr::ParseFloatFrom { value: Box::new(local(0)), from: 1 }));
    }

    #[test]
    fn empty_and_typeof_tests_of_a_local_become_one_expression() {
        let typeof_is = |op, name: &str| {
            Expr::Binary(op, Box::new(Expr::Unary(UnaryOp::Typeof, Box::new(local(2)))), Box::new(Expr::text(name)))
        };
        let mut body = vec![Stmt::If {
            branches: vec![(
                Expr::Binary(
                    BinaryOp::And,
                    Box::new(typeof_is(BinaryOp::StrictEq, "string")),
                    Box::new(not_empty(local(1))),
                ),
                vec![
                    Stmt::Eval(typeof_is(BinaryOp::JsEq, "string")),
                    Stmt::Eval(typeof_is(BinaryOp::StrictNe, "number")),
                ],
            )],
            otherwise: vec![],
        }];
        expressions(&mut body);
        let want = vec![Stmt::If {
            branches: vec![(
                Expr::Chain {
                    all: true,
                    operands: vec![
                        Expr::LocalIsText { local: LocalId::new(2), is: true },
                        Expr::LocalEmpty { local: LocalId::new(1), op: BinaryOp::JsNe },
                    ],
                },
                // Near misses stay as they are.
                vec![
                    Stmt::Eval(typeof_is(BinaryOp::JsEq, "string")),
                    Stmt::Eval(typeof_is(BinaryOp::StrictNe, "number")),
                ],
            )],
            otherwise: vec![],
        }];
        assert_eq!(body, want);
    }

    fn word_of(w: u16, before: WordsBefore, sep: &[u8]) -> Stmt {
        Stmt::Word {
            cond: Expr::LocalEmpty { local: LocalId::new(w), op: BinaryOp::JsNe },
            word: vec![Piece::Expr(local(w))],
            sep: sep.to_vec(),
            before,
        }
    }

    #[test]
    fn a_run_of_words_becomes_one_statement_with_the_if_of_an_empty_block() {
        let (n, m) = (LocalId::new(9), LocalId::new(8));
        // Counted (`n = 0 ... if (n == 0)`) and asked of the output
        // (`mark n ... if (!written(n))`).
        let forms = [
            (
                WordsBefore::Count(n),
                Stmt::Assign(Place::Local(n), Expr::Number(0.0)),
                Expr::Binary(BinaryOp::JsEq, Box::new(Expr::Local(n)), Box::new(Expr::Number(0.0))),
            ),
            (WordsBefore::Written(n), Stmt::Mark(n), Expr::Unary(UnaryOp::Not, Box::new(Expr::Written(n)))),
        ];
        for (before, start, none_printed) in forms {
            let empty =
                Stmt::If { branches: vec![(none_printed, vec![Stmt::Truncate(m), Stmt::Break])], otherwise: vec![] };
            let general = vec![start, word_of(1, before, b" "), word_of(2, before, b" "), empty];
            let mut body = vec![Stmt::While {
                cond: Expr::Bool(true),
                body: [general.clone(), vec![Stmt::Break]].concat(),
                span: None,
                step: vec![],
            }];
            runs(&mut body);
            let want = WordRun {
                general,
                locals: vec![LocalId::new(1), LocalId::new(2)],
                sep: b" ".to_vec(),
                before,
                empty: Some(m),
            };
            let Stmt::While { body, .. } = &body[0] else { panic!() };
            assert_eq!(body.as_slice(), [Stmt::Words(Box::new(want)), Stmt::Break]);
        }
    }

    #[test]
    fn near_misses_of_a_run_stay_as_they_are() {
        let n = LocalId::new(9);
        let count = WordsBefore::Count(n);
        let start = Stmt::Assign(Place::Local(n), Expr::Number(0.0));
        let cases = [
            // One word: nothing to gain.
            vec![start.clone(), word_of(1, count, b" ")],
            // Two separators.
            vec![start.clone(), word_of(1, count, b" "), word_of(2, count, b",")],
            // Another count.
            vec![start.clone(), word_of(1, WordsBefore::Count(LocalId::new(7)), b" "), word_of(2, count, b" ")],
            // The count started at 1.
            vec![Stmt::Assign(Place::Local(n), Expr::Number(1.0)), word_of(1, count, b" "), word_of(2, count, b" ")],
        ];
        for case in cases {
            let mut body = case.clone();
            runs(&mut body);
            assert_eq!(body, case);
        }
        // A word of a test on another local ends the run.
        let mut other = word_of(3, count, b" ");
        if let Stmt::Word { cond, .. } = &mut other {
            *cond = Expr::Local(LocalId::new(4));
        }
        let mut body = vec![start, word_of(1, count, b" "), word_of(2, count, b" "), other.clone()];
        runs(&mut body);
        assert!(matches!(&body[0], Stmt::Words(run) if run.locals.len() == 2 && run.empty.is_none()));
        assert_eq!(body[1], other);
    }
}
