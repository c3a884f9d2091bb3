//! A block number written first, not moved before its words.
//!
//! A field post's `writeBlock()` gathers its words, then puts the block
//! number in front (`words.unshift("N" + sequenceNumber)`). Built in the
//! output ([`super::emit`]), that is: mark, write the words, mark again,
//! write the number, and move it back before the words:
//!
//! ```text
//! mark r; n = 0; word a; word b; ...; if (n == 0) { truncate m; break }
//! mark t; emit "N" seq; if (n > 0) { emit " " }; move back t to r
//! ```
//!
//! When the number cannot depend on the words, and the words cannot
//! depend on it, it is written first and nothing moves:
//!
//! ```text
//! emit "N" seq; emit " "; mark r; n = 0; word a; word b; ...;
//! if (n == 0) { truncate m; break }
//! ```
//!
//! It is done only when all of this holds, so that what the post writes
//! cannot change:
//!
//! - the number's statements write constant text and globals and read
//!   nothing else, but for `if (n > 0)` on the words' count `n`, which at
//!   that point always holds: `n` starts at 0 among the words, only they
//!   count it, and the leaving test `n == 0` follows them;
//! - the words' statements are words, constants stored in locals, marks,
//!   and one leaving test (`if (c) { truncate m; break }`) whose `m` was
//!   marked before, on the way here, with no text dropped since: so it
//!   drops the number too when no word was written. No expression among
//!   them calls, formats or writes a global;
//! - no statement after reads marks `r` or `t`.
//!
//! The count counted up once more for the number right after the move
//! (`n += 1`) goes too when nothing else reads the count: it is a number,
//! so that store has no effect.

use std::collections::HashSet;

use postc_ir::{BinaryOp, LocalId, Place};

use crate::exec::{Expr, LocalUse, Piece, Stmt, WordsBefore};

/// Writes first every block number that a handler's `body` moves back
/// before its words.
#[doc(hidden)]
pub fn block_numbers(body: &mut Vec<Stmt>) {
    let mut reads = Vec::new();
    count_reads(body, &mut reads);
    list(body, HashSet::new(), &reads);
}

/// How many statements read each local (by slot), at any depth.
fn count_reads(body: &mut [Stmt], reads: &mut Vec<usize>) {
    fn bump(reads: &mut Vec<usize>, k: LocalId) {
        let i = k.index();
        if reads.len() <= i {
            reads.resize(i + 1, 0);
        }
        reads[i] += 1;
    }
    for s in body {
        s.for_each_expr_mut(|e| e.for_each_local_mut(&mut |k| bump(reads, *k)));
        s.for_each_named_local_mut(|u, k| {
            if u != LocalUse::Write {
                bump(reads, *k);
            }
        });
        s.for_each_body_mut(|b| count_reads(b, reads));
    }
}

/// Rewrites the statement list; `marks` are the marks set on the way here
/// with no text dropped since.
fn list(body: &mut Vec<Stmt>, mut marks: HashSet<LocalId>, reads: &[usize]) {
    let mut i = 0;
    while i < body.len() {
        if let Some(end) = rewrite_at(body, i, &marks, reads) {
            // The leaving test drops text: no mark is safe after it.
            marks.clear();
            i = end;
            continue;
        }
        let s = &mut body[i];
        // A loop that may run again could have dropped text below a mark
        // on its way round: only a body run once keeps the marks.
        let inner = match s {
            Stmt::While { body, .. } if !super::locals::runs_once(body) => HashSet::new(),
            _ => marks.clone(),
        };
        s.for_each_body_mut(|b| list(b, inner.clone(), reads));
        if let Stmt::Mark(k) = s {
            marks.insert(*k);
        } else if drops_text(s) {
            marks.clear();
        } else {
            s.for_each_named_local_mut(|u, k| {
                if u != LocalUse::Read {
                    marks.remove(k);
                }
            });
        }
        i += 1;
    }
}

/// Whether a statement may drop written text, at any depth.
fn drops_text(s: &mut Stmt) -> bool {
    if matches!(s, Stmt::Truncate(_) | Stmt::Cut { .. } | Stmt::Blocks(_) | Stmt::MoveBack { .. }) {
        return true;
    }
    let mut drops = false;
    s.for_each_body_mut(|b| drops |= b.iter_mut().any(drops_text));
    drops
}

/// Rewrites the pattern starting with `Mark(r)` at `a`, if it is there and
/// every condition holds; returns the index after the rewritten
/// statements.
fn rewrite_at(body: &mut Vec<Stmt>, a: usize, marks: &HashSet<LocalId>, reads: &[usize]) -> Option<usize> {
    let Stmt::Mark(r) = body[a] else { return None };
    // The move back of a mark `t` set after `r`, to `r`.
    let (t_at, mb_at, t) = body[a + 1..]
        .iter()
        .enumerate()
        .find_map(|(j, s)| match s {
            Stmt::MoveBack { to, from } if *to == r => Some((j, *from)),
            _ => None,
        })
        .and_then(|(j, t)| {
            let mb_at = a + 1 + j;
            let t_at = body[a + 1..mb_at].iter().position(|s| *s == Stmt::Mark(t))? + a + 1;
            Some((t_at, mb_at, t))
        })?;
    let words = &body[a + 1..t_at];
    let number = &body[t_at + 1..mb_at];
    let count = words_fit(words, r, t, marks)?;
    let number = number_first(number, count)?;
    // `r` is read by the words and the move back only, `t` by the move back.
    let mut inside = Vec::new();
    count_reads(&mut body[a..=mb_at].to_vec(), &mut inside);
    let only_here = |k: LocalId| reads.get(k.index()) == inside.get(k.index());
    if !only_here(r) || !only_here(t) {
        return None;
    }
    let mut words: Vec<Stmt> = body[a + 1..t_at].to_vec();
    let mut first = merged(number);
    // The mark stays only for the words that ask it whether they were
    // written.
    let mut asked = Vec::new();
    count_reads(&mut words, &mut asked);
    if asked.get(r.index()).is_some_and(|&n| n > 0) {
        first.push(Stmt::Mark(r));
    }
    first.extend(words);
    let end = a + first.len();
    // The count counted up once more for the number (`n += 1` after the
    // move), when nothing reads it after: the words' count is a number,
    // so that store has no effect.
    let mut tail = mb_at + 1;
    if let Some(c) = count {
        let counted_up = |s: &Stmt| {
            matches!(s, Stmt::Assign(Place::Local(k), Expr::Binary(BinaryOp::Add, a, n))
                if *k == c && **a == Expr::Local(c) && matches!(**n, Expr::Number(_)))
        };
        let after = body[tail..].iter().take_while(|s| counted_up(s)).count();
        count_reads(&mut body[mb_at + 1..mb_at + 1 + after].to_vec(), &mut inside);
        if after > 0 && reads.get(c.index()) == inside.get(c.index()) {
            tail += after;
        }
    }
    body.splice(a..tail, first);
    Some(end)
}

/// Whether the statements between the marks are words of the kind the
/// module allows, with one leaving test after the last word; the count
/// local of the words, if they count.
fn words_fit(words: &[Stmt], r: LocalId, t: LocalId, marks: &HashSet<LocalId>) -> Option<Option<LocalId>> {
    let mut count = None;
    let mut zeroed = HashSet::new();
    let mut leaving_seen = false;
    let mut last_word = None;
    // The words' count starts at 0 (`zeroed`), and is then only counted up.
    let counts = |k: LocalId, count: &mut Option<LocalId>, zeroed: &HashSet<LocalId>| match count {
        Some(c) => *c == k,
        None if zeroed.contains(&k) => {
            *count = Some(k);
            true
        }
        None => false,
    };
    for (i, s) in words.iter().enumerate() {
        match s {
            Stmt::Assign(Place::Local(k), _) if marks.contains(k) || *k == r || *k == t => return None,
            Stmt::Assign(Place::Local(k), Expr::Binary(BinaryOp::Add, a, n))
                if **a == Expr::Local(*k) && matches!(**n, Expr::Number(n) if n >= 0.0) =>
            {
                if !counts(*k, &mut count, &zeroed) {
                    return None;
                }
                last_word = Some(i);
            }
            Stmt::Assign(Place::Local(k), _) if count == Some(*k) => return None,
            Stmt::Emit(pieces) if pure_pieces(pieces, r) => {
                last_word = Some(i);
            }
            Stmt::Assign(Place::Local(k), Expr::Number(n)) => {
                if *n == 0.0 {
                    zeroed.insert(*k);
                } else {
                    zeroed.remove(k);
                }
            }
            Stmt::Assign(Place::Local(k), Expr::Text(_) | Expr::Bool(_) | Expr::Null | Expr::Undefined) => {
                zeroed.remove(k);
            }
            Stmt::Mark(k) if *k != r && *k != t && !marks.contains(k) && !zeroed.contains(k) && count != Some(*k) => {}
            Stmt::Word { cond, word, before, .. } => {
                if !pure(cond, r) || !pure_pieces(word, r) {
                    return None;
                }
                match before {
                    WordsBefore::Count(c) => {
                        if !counts(*c, &mut count, &zeroed) {
                            return None;
                        }
                    }
                    WordsBefore::Written(m) if *m == r => {}
                    WordsBefore::Written(_) => return None,
                }
                last_word = Some(i);
            }
            Stmt::If { branches, otherwise } if otherwise.is_empty() && branches.len() == 1 && !leaving_seen => {
                let (cond, then) = &branches[0];
                match then.as_slice() {
                    [Stmt::Truncate(m), Stmt::Break] if marks.contains(m) && pure(cond, r) => leaving_seen = true,
                    _ => return None,
                }
            }
            _ => return None,
        }
    }
    // The leaving test comes after the last word.
    let leaving_at = words.iter().rposition(|s| matches!(s, Stmt::If { .. }))?;
    if last_word.is_some_and(|w| w > leaving_at) {
        return None;
    }
    // A counted block leaves on `n == 0`.
    if let Some(c) = count {
        let Stmt::If { branches, .. } = &words[leaving_at] else { return None };
        if branches[0].0 != count_is_zero(c) {
            return None;
        }
    }
    Some(count)
}

/// The block number's statements, written first: constant text and
/// globals, and `if (n > 0)` on the words' count, which then holds.
fn number_first(number: &[Stmt], count: Option<LocalId>) -> Option<Vec<Stmt>> {
    let plain = |pieces: &[Piece]| {
        pieces
            .iter()
            .all(|p| matches!(p, Piece::Text(_) | Piece::Expr(Expr::Global(_) | Expr::Number(_) | Expr::Text(_))))
    };
    let mut first = Vec::new();
    for s in number {
        match s {
            Stmt::Emit(pieces) if plain(pieces) => first.push(s.clone()),
            Stmt::If { branches, otherwise } if otherwise.is_empty() && branches.len() == 1 => {
                let (cond, then) = &branches[0];
                let c = count?;
                match then.as_slice() {
                    [Stmt::Emit(pieces)] if plain(pieces) && *cond == count_is_positive(c) => {
                        first.push(Stmt::Emit(pieces.clone()))
                    }
                    _ => return None,
                }
            }
            _ => return None,
        }
    }
    Some(first)
}

/// Emits in a row as one.
fn merged(stmts: Vec<Stmt>) -> Vec<Stmt> {
    let mut out: Vec<Stmt> = Vec::with_capacity(stmts.len());
    for s in stmts {
        match (out.last_mut(), s) {
            (Some(Stmt::Emit(before)), Stmt::Emit(pieces)) => before.extend(pieces),
            (_, s) => out.push(s),
        }
    }
    out
}

#[doc(hidden)]
pub fn count_is_zero(c: LocalId) -> Expr {
    Expr::Binary(BinaryOp::JsEq, Box::new(Expr::Local(c)), Box::new(Expr::Number(0.0)))
}

#[doc(hidden)]
pub fn count_is_positive(c: LocalId) -> Expr {
    Expr::Binary(BinaryOp::JsGt, Box::new(Expr::Local(c)), Box::new(Expr::Number(0.0)))
}

/// Pieces of text and [`pure`] expressions.
fn pure_pieces(pieces: &[Piece], r: LocalId) -> bool {
    pieces.iter().all(|p| match p {
        Piece::Text(_) => true,
        Piece::Expr(e) | Piece::Joined(e) => pure(e, r),
        Piece::Var(_) => false,
    })
}

/// An expression that reads locals, globals, constants and whether words
/// were written since mark `r` only, and calls, formats and writes nothing.
fn pure(e: &Expr, r: LocalId) -> bool {
    match e {
        Expr::Written(k) => *k == r,
        Expr::Call(..)
        | Expr::Builtin(..)
        | Expr::FormatVar { .. }
        | Expr::Format { .. }
        | Expr::ParseFloatFrom { .. }
        | Expr::Quantity(_)
        | Expr::Var(_)
        | Expr::Previous(_) => false,
        // `+` may build text past the text budget.
        Expr::Binary(BinaryOp::Add | BinaryOp::Concat, ..) => false,
        e => {
            let mut all = true;
            e.clone().for_each_operand_mut(|a| all &= pure(a, r));
            all
        }
    }
}
