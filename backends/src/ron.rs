//! The RON backend: the IR itself, as the text `postc post` and
//! `postc inspect` read back (`postc post converted.ron TOOLPATH`).
//!
//! Spans are dropped: they point into the source post's files, which a
//! RON post does not come with, and a span into the wrong file would send
//! a diagnostic to the wrong place. Everything else is kept, so the RON
//! post posts exactly as its source does.

use postc_ir::visit::{VisitMut, walk_stmt_mut};
use postc_ir::{Diagnostic, Post, Stmt};

/// The IR of `post` as RON, after a header comment naming its source.
pub fn print(post: &Post) -> Result<String, Vec<Diagnostic>> {
    let mut post = post.clone();
    drop_spans(&mut post);
    let config = ::ron::ser::PrettyConfig::new().struct_names(false).compact_arrays(true);
    let text = ::ron::ser::to_string_pretty(&post, config)
        .map_err(|e| vec![Diagnostic::error("CV009", format!("the IR cannot be written as RON: {e}"))])?;
    Ok(format!(
        "// Converted by postc from {} ({})\n{text}\n",
        crate::source_name(&post),
        crate::dialect_name(post.info.dialect)
    ))
}

fn drop_spans(post: &mut Post) {
    for h in &mut post.handlers {
        h.span = None;
    }
    for f in &mut post.functions {
        f.span = None;
    }
    for s in &mut post.scripts {
        s.span = None;
        s.span_map.clear();
    }
    DropLoopSpans.visit_post_mut(post);
}

/// Clears the span of every loop.
struct DropLoopSpans;

impl VisitMut for DropLoopSpans {
    fn visit_stmt_mut(&mut self, stmt: &mut Stmt) {
        if let Stmt::While { span, .. } = stmt {
            *span = None;
        }
        walk_stmt_mut(self, stmt);
    }
}
