//! Copy coalescing over a function's native body: `var text =
//! words.join(" ")` is `t = w` with `w` never used again and `t` not
//! used before, so `t` can live in `w`'s slot. The fast path (`emit`) then
//! sees one local built by concatenation, which it keeps in the output.

use postc_ir::{Expr, LocalId, Place, Stmt};

/// Coalesces top-level copies between locals at or past `first_var` (the
/// parameters keep their slots), and drops top-level stores of constants
/// into locals nothing reads (an unrolled loop's counter at its end).
pub fn copies(body: &mut Vec<Stmt>, first_var: usize) {
    let dead: Vec<usize> = (0..body.len())
        .filter(|&i| {
            matches!(&body[i], Stmt::Assign(Place::Local(k), Expr::Number(_) | Expr::Bool(_) | Expr::Null)
                if k.index() >= first_var && !body_reads(body, *k))
        })
        .collect();
    for i in dead.into_iter().rev() {
        body.remove(i);
    }
    let mut i = 0;
    while i < body.len() {
        if let Stmt::Assign(Place::Local(t), Expr::Local(w)) = &body[i] {
            let (t, w) = (*t, *w);
            if t != w
                && t.index() >= first_var
                && w.index() >= first_var
                && !body[..i].iter().any(|s| mentions(s, t))
                && !body[i + 1..].iter().any(|s| mentions(s, w))
            {
                body.remove(i);
                for s in &mut body[i..] {
                    rename(s, t, w);
                }
                continue;
            }
        }
        i += 1;
    }
}

/// Whether anything reads local `k` (a store into it is not a read).
fn body_reads(body: &[Stmt], k: LocalId) -> bool {
    body.iter().any(|s| {
        let mut s = s.clone();
        if let Stmt::Assign(Place::Local(x), _) = &mut s
            && *x == k
        {
            // Only the value side can read it.
            *x = LocalId::new(u16::MAX);
        }
        mentions(&s, k)
    })
}

fn mentions(s: &Stmt, k: LocalId) -> bool {
    let mut found = false;
    visit(s, &mut |x| found |= *x == k);
    found
}

fn rename(s: &mut Stmt, from: LocalId, to: LocalId) {
    visit_mut(s, &mut |x| {
        if *x == from {
            *x = to;
        }
    });
}

/// Every local a statement mentions.
fn visit(s: &Stmt, f: &mut dyn FnMut(&LocalId)) {
    let mut s = s.clone();
    visit_mut(&mut s, &mut |x| f(x));
}

fn visit_mut(s: &mut Stmt, f: &mut dyn FnMut(&mut LocalId)) {
    postc_ir::visit::locals_mut(s, f);
}
