//! Tidying the marks of an emitted handler: a mark set where another was
//! just set (nothing written between) is the same mark; a truncation to a
//! mark with nothing written since does nothing; a mark nobody reads is
//! not set. Each mark slot is set by exactly one `Mark`, so renaming is
//! safe.

use std::collections::{HashMap, HashSet};

use crate::exec::{Expr, Piece, Stmt};
use postc_ir::LocalId;

/// Tidies a handler body.
pub fn tidy(body: Vec<Stmt>) -> Vec<Stmt> {
    let mut alias = HashMap::new();
    find_aliases(&body, &mut alias);
    let body = rename(body, &alias);
    let body = drop_truncates(body);
    let mut read = HashSet::new();
    reads(&body, &mut read);
    drop_unread(body, &read)
}

/// Statements that cannot write output (value-mode code).
fn silent(s: &Stmt) -> bool {
    matches!(s, Stmt::Assign(..) | Stmt::Origin(_))
}

fn find_aliases(body: &[Stmt], alias: &mut HashMap<LocalId, LocalId>) {
    let mut current: Option<LocalId> = None;
    for s in body {
        match s {
            Stmt::Mark(m) => match current {
                Some(c) => {
                    alias.insert(*m, c);
                }
                None => current = Some(*m),
            },
            s if silent(s) => {}
            Stmt::If { branches, otherwise } => {
                current = None;
                branches.iter().for_each(|(_, b)| find_aliases(b, alias));
                find_aliases(otherwise, alias);
            }
            Stmt::While { body, .. } => {
                current = None;
                find_aliases(body, alias);
            }
            _ => current = None,
        }
    }
}

fn rename(body: Vec<Stmt>, alias: &HashMap<LocalId, LocalId>) -> Vec<Stmt> {
    let to = |m: LocalId| *alias.get(&m).unwrap_or(&m);
    body.into_iter()
        .filter(|s| !matches!(s, Stmt::Mark(m) if alias.contains_key(m)))
        .map(|s| match s {
            Stmt::Truncate(m) => Stmt::Truncate(to(m)),
            Stmt::Cut { at, chars } => Stmt::Cut { at: to(at), chars },
            Stmt::Blocks(m) => Stmt::Blocks(to(m)),
            Stmt::MoveBack { to: a, from: b } => Stmt::MoveBack { to: to(a), from: to(b) },
            Stmt::If { branches, otherwise } => Stmt::If {
                branches: branches.into_iter().map(|(c, b)| (rename_expr(c, alias), rename(b, alias))).collect(),
                otherwise: rename(otherwise, alias),
            },
            Stmt::While { cond, body, span, step } => {
                Stmt::While { cond, body: rename(body, alias), span, step: rename(step, alias) }
            }
            other => other,
        })
        .collect()
}

fn rename_expr(e: Expr, alias: &HashMap<LocalId, LocalId>) -> Expr {
    match e {
        Expr::Written(m) => Expr::Written(*alias.get(&m).unwrap_or(&m)),
        Expr::Unary(op, a) => Expr::Unary(op, Box::new(rename_expr(*a, alias))),
        Expr::Binary(op, a, b) => Expr::Binary(op, Box::new(rename_expr(*a, alias)), Box::new(rename_expr(*b, alias))),
        other => other,
    }
}

/// Removes `Truncate(m)` where nothing was written since `Mark(m)`: in
/// the mark's list, in the arms of an `if` and in a loop run once after
/// it, and after such statements when they write nothing.
#[doc(hidden)]
pub fn drop_truncates(body: Vec<Stmt>) -> Vec<Stmt> {
    drop_truncates_after(body, None).0
}

/// [`drop_truncates`] of a list entered with nothing written since mark
/// `fresh`; the mark with nothing written since at the list's end.
fn drop_truncates_after(body: Vec<Stmt>, mut fresh: Option<LocalId>) -> (Vec<Stmt>, Option<LocalId>) {
    let mut out: Vec<Stmt> = Vec::with_capacity(body.len());
    for s in body {
        match s {
            Stmt::Mark(m) => {
                fresh = Some(m);
                out.push(Stmt::Mark(m));
            }
            Stmt::Truncate(m) if fresh == Some(m) => {}
            s if silent(&s) => out.push(s),
            Stmt::Break | Stmt::Continue => out.push(s),
            Stmt::If { branches, otherwise } => {
                let mut quiet = true;
                let mut arm = |b: Vec<Stmt>| {
                    let (b, _) = drop_truncates_after(b, fresh);
                    quiet &= writes_nothing(&b);
                    b
                };
                let branches = branches.into_iter().map(|(c, b)| (c, arm(b))).collect();
                let otherwise = arm(otherwise);
                out.push(Stmt::If { branches, otherwise });
                fresh = fresh.filter(|_| quiet);
            }
            Stmt::While { cond, body, span, step } if step.is_empty() => {
                let inherited = fresh.filter(|_| super::super::locals::runs_once(&body));
                let (body, _) = drop_truncates_after(body, inherited);
                fresh = fresh.filter(|_| writes_nothing(&body));
                out.push(Stmt::While { cond, body, span, step });
            }
            other => {
                fresh = None;
                out.push(other);
            }
        }
    }
    (out, fresh)
}

/// Whether statements write nothing and move no mark, at any depth.
fn writes_nothing(body: &[Stmt]) -> bool {
    body.iter().all(|s| match s {
        Stmt::If { branches, otherwise } => {
            branches.iter().all(|(_, b)| writes_nothing(b)) && writes_nothing(otherwise)
        }
        Stmt::While { body, .. } => writes_nothing(body),
        Stmt::Break | Stmt::Continue => true,
        s => silent(s),
    })
}

fn reads(body: &[Stmt], read: &mut HashSet<LocalId>) {
    let expr = |e: &Expr, read: &mut HashSet<LocalId>| {
        fn walk(e: &Expr, read: &mut HashSet<LocalId>) {
            match e {
                Expr::Written(m) | Expr::Local(m) => {
                    read.insert(*m);
                }
                Expr::Unary(_, a) | Expr::FormatVar { value: a, .. } | Expr::Format { value: a, .. } => walk(a, read),
                Expr::Binary(_, a, b) => {
                    walk(a, read);
                    walk(b, read);
                }
                Expr::Choose(c, a, b) => {
                    walk(c, read);
                    walk(a, read);
                    walk(b, read);
                }
                Expr::Call(_, args) | Expr::Builtin(_, args) => args.iter().for_each(|a| walk(a, read)),
                _ => {}
            }
        }
        walk(e, read)
    };
    for s in body {
        match s {
            Stmt::Truncate(m) | Stmt::Blocks(m) | Stmt::Cut { at: m, .. } => {
                read.insert(*m);
            }
            Stmt::MoveBack { to, from } => {
                read.insert(*to);
                read.insert(*from);
            }
            Stmt::If { branches, otherwise } => {
                for (c, b) in branches {
                    expr(c, read);
                    reads(b, read);
                }
                reads(otherwise, read);
            }
            Stmt::While { cond, body, .. } => {
                expr(cond, read);
                reads(body, read);
            }
            Stmt::Assign(_, e) | Stmt::Eval(e) | Stmt::Write(e) | Stmt::Return(Some(e)) => expr(e, read),
            Stmt::Emit(p) | Stmt::Line { pieces: p, .. } => p.iter().for_each(|p| {
                if let Piece::Expr(e) | Piece::Joined(e) = p {
                    expr(e, read)
                }
            }),
            _ => {}
        }
    }
}

fn drop_unread(body: Vec<Stmt>, read: &HashSet<LocalId>) -> Vec<Stmt> {
    body.into_iter()
        .filter(|s| !matches!(s, Stmt::Mark(m) if !read.contains(m)))
        .map(|s| match s {
            Stmt::If { branches, otherwise } => Stmt::If {
                branches: branches.into_iter().map(|(c, b)| (c, drop_unread(b, read))).collect(),
                otherwise: drop_unread(otherwise, read),
            },
            Stmt::While { cond, body, span, step } => {
                Stmt::While { cond, body: drop_unread(body, read), span, step: drop_unread(step, read) }
            }
            other => other,
        })
        .collect()
}
