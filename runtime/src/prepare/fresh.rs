//! Which locals a handler must find `null` at every event.
//!
//! A handler's locals live in one frame the engine keeps from event to
//! event. A local the handler always writes before it reads it needs
//! nothing at the start of an event: whatever the last event left there
//! is overwritten before anyone looks. Only a local some path may read
//! first (`var s; if (a) s = "M8"; return s;`) must start as `null`, as a
//! call's frame does; for those, and only those, the handler begins with
//! `k = null`. The engine then neither clears nor grows the frame per
//! event (a move of a field post saved a few hundred instructions).
//!
//! The question is answered by *definite assignment*, forwards over the
//! structured code: a local is assigned after a statement when every path
//! through it that goes on assigns it. An `if` assigns what all its arms
//! that go on assign; a loop's body is read with what held before the loop
//! (a later pass round only adds), and after `while (true)` what held at
//! every `break` of it holds. Anything the analysis cannot follow counts as
//! not assigned, so it errs only towards a `null` too many.

use postc_ir::{LocalId, Place};

use crate::exec::{Expr, LocalUse, Stmt};

/// `body` with its leading `k = null` (or `k = undefined`) statements
/// replaced by those its statements need: one for each local that some
/// path may read before it writes it, in slot order, starting as the
/// statement it replaces said (null for a local none named).
#[doc(hidden)]
pub fn start_nulls(mut body: Vec<Stmt>) -> Vec<Stmt> {
    let leading =
        body.iter().take_while(|s| matches!(s, Stmt::Assign(Place::Local(_), Expr::Null | Expr::Undefined))).count();
    let undefined: Vec<LocalId> = body[..leading]
        .iter()
        .filter_map(|s| match s {
            Stmt::Assign(Place::Local(k), Expr::Undefined) => Some(*k),
            _ => None,
        })
        .collect();
    body.drain(..leading);
    let mut reads = Reads::default();
    reads.list(&mut body, &mut Assigned::default(), &mut Vec::new());
    let mut out: Vec<Stmt> = (0..reads.first.len())
        .filter(|&k| reads.first[k])
        .map(|k| {
            let k = LocalId::new(k as u16);
            Stmt::Assign(Place::Local(k), if undefined.contains(&k) { Expr::Undefined } else { Expr::Null })
        })
        .collect();
    out.append(&mut body);
    out
}

/// The locals definitely assigned at a point, by slot.
#[derive(Clone, Default)]
struct Assigned(Vec<bool>);

impl Assigned {
    fn has(&self, k: LocalId) -> bool {
        self.0.get(k.index()).copied().unwrap_or(false)
    }

    fn add(&mut self, k: LocalId) {
        let i = k.index();
        if self.0.len() <= i {
            self.0.resize(i + 1, false);
        }
        self.0[i] = true;
    }

    /// What both hold.
    fn meet(&mut self, other: &Assigned) {
        for (i, a) in self.0.iter_mut().enumerate() {
            *a = *a && other.0.get(i).copied().unwrap_or(false);
        }
    }

    /// What all of `sets` hold; `None` when there is none.
    fn meet_all(sets: Vec<Assigned>) -> Option<Assigned> {
        let mut sets = sets.into_iter();
        let mut all = sets.next()?;
        sets.for_each(|s| all.meet(&s));
        Some(all)
    }
}

/// The locals read where they may not have been assigned.
#[derive(Default)]
struct Reads {
    first: Vec<bool>,
}

impl Reads {
    fn read(&mut self, k: LocalId, assigned: &Assigned) {
        if !assigned.has(k) {
            let i = k.index();
            if self.first.len() <= i {
                self.first.resize(i + 1, false);
            }
            self.first[i] = true;
        }
    }

    fn expr(&mut self, e: &mut Expr, assigned: &Assigned) {
        e.for_each_local_mut(&mut |k| self.read(*k, assigned));
    }

    /// Follows a statement list from `assigned`, which it leaves holding
    /// what is assigned when the list goes on past its end; `breaks` takes
    /// what holds at each `break` of the innermost loop. Whether the list
    /// can go on past its end.
    fn list(&mut self, body: &mut [Stmt], assigned: &mut Assigned, breaks: &mut Vec<Assigned>) -> bool {
        for s in body {
            if !self.stmt(s, assigned, breaks) {
                // What follows is never reached.
                return false;
            }
        }
        true
    }

    /// [`Self::list`] for one statement.
    fn stmt(&mut self, s: &mut Stmt, assigned: &mut Assigned, breaks: &mut Vec<Assigned>) -> bool {
        // Expressions write no local; a statement reads its own first.
        s.for_each_expr_mut(|e| self.expr(e, assigned));
        match s {
            Stmt::If { branches, otherwise } => {
                let mut goes_on = Vec::new();
                for body in branches.iter_mut().map(|(_, b)| b).chain(std::iter::once(otherwise)) {
                    let mut arm = assigned.clone();
                    if self.list(body, &mut arm, breaks) {
                        goes_on.push(arm);
                    }
                }
                match Assigned::meet_all(goes_on) {
                    Some(after) => *assigned = after,
                    None => return false,
                }
            }
            Stmt::While { cond, body, .. } => {
                let mut inner = assigned.clone();
                let mut own_breaks = Vec::new();
                self.list(body, &mut inner, &mut own_breaks);
                if matches!(cond, Expr::Bool(true)) {
                    match Assigned::meet_all(own_breaks) {
                        Some(after) => *assigned = after,
                        // Left by `return` only, or never.
                        None => return false,
                    }
                }
            }
            Stmt::Break => {
                breaks.push(assigned.clone());
                return false;
            }
            Stmt::Continue | Stmt::Return(_) => return false,
            _ => {
                let mut written = Vec::new();
                s.for_each_named_local_mut(|u, k| match u {
                    LocalUse::Read => self.read(*k, assigned),
                    LocalUse::Update => {
                        self.read(*k, assigned);
                        written.push(*k);
                    }
                    LocalUse::Write => written.push(*k),
                });
                written.into_iter().for_each(|k| assigned.add(k));
            }
        }
        true
    }
}
