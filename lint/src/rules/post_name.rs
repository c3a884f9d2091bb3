//! LN005: the `POST_NAME` promises what the post does not do. The names of
//! Vectric's own posts follow a convention (the 2012 Vectric post guide, "Post Processor
//! Naming Conventions"): `(mm)`/`(inch)` the units, `(*.tap)` the file
//! extension, `Arc`/`Arcs` true arcs, `ATC` tool changes, `TS n` tape
//! splitting, `WX`/`WY` a wrapped axis. A user picks a post by that name.

use postc_ir::codes;
use postc_ir::{Diagnostic, Section, Units};

use crate::{Context, Options, Rule};

pub const RULE: Rule = Rule { code: codes::LN005.code, name: "post-name-convention", check };

fn check(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    let post = cx.post;
    if post.info.dialect != postc_ir::Dialect::Vectric || post.info.name.is_empty() {
        return;
    }
    let name = post.info.name.as_str();
    let lower = name.to_ascii_lowercase();
    let words: Vec<String> =
        lower.split(|c: char| !c.is_ascii_alphanumeric()).filter(|w| !w.is_empty()).map(str::to_string).collect();
    let has = |w: &str| words.iter().any(|x| x == w);
    let mut say = |message: String| {
        let mut d = Diagnostic::warning(RULE.code, message)
            .help("make the name say what the post does (Vectric's naming convention), or change the post");
        if let Some(span) = post.info.span {
            d = d.at(span, "the post's name");
        }
        out.push(d);
    };
    match post.output_units() {
        Some(Units::Inch) if lower.contains("(mm)") => say(format!("`{name}` says (mm), but the post writes inches")),
        Some(Units::Mm) if lower.contains("(inch)") => say(format!("`{name}` says (inch), but the post writes mm")),
        _ => {}
    }
    if let Some(ext) = said_extension(&lower)
        && !ext.eq_ignore_ascii_case(&post.info.file_extension)
    {
        say(format!("`{name}` says *.{ext}, but the post writes .{} files", post.info.file_extension));
    }
    let arcs = cx.sections().any(crate::product::is_arc_section);
    let no_arcs = lower.contains("no arc") || has("noarcs") || has("noarc");
    if no_arcs && arcs {
        say(format!("`{name}` says no arcs, but the post has arc sections: arcs are written as G2/G3"));
    } else if !no_arcs && (has("arc") || has("arcs")) && !arcs {
        say(format!("`{name}` says Arcs, but the post has no arc section: every arc is written as straight moves"));
    }
    if has("atc") && !cx.has(Section::ToolChange) {
        say(format!("`{name}` says ATC, but the post has no TOOLCHANGE section"));
    }
    // `TS` or `TS40`: tape splitting, at most that many lines per file.
    let ts = words.iter().find_map(|w| {
        let n = w.strip_prefix("ts")?;
        n.chars().all(|c| c.is_ascii_digit()).then(|| n.parse::<u64>().ok())
    });
    match (ts, &post.options.tape_splitting) {
        (Some(_), None) => say(format!("`{name}` says TS (tape splitting), but the post has no TAPE_SPLITTING")),
        (Some(Some(n)), Some(t)) if t.max_lines != n => {
            say(format!("`{name}` says TS{n}, but the post splits files at {} lines", t.max_lines))
        }
        _ => {}
    }
    let wrap = post.options.rotary_wrap.map(|w| w.axis);
    for (word, axis, statement) in [
        ("wx", postc_ir::post::WrappedAxis::X, "ROTARY_WRAP_X"),
        ("wy", postc_ir::post::WrappedAxis::Y, "ROTARY_WRAP_Y"),
    ] {
        if has(word) && wrap != Some(axis) {
            say(format!("`{name}` says {}, but the post has no {statement}", word.to_ascii_uppercase()));
        }
    }
}

/// The extension a name gives as `(*.tap)`.
fn said_extension(name: &str) -> Option<&str> {
    let start = name.find("(*.")? + 3;
    let end = name[start..].find(')')? + start;
    let ext = name[start..end].trim();
    (!ext.is_empty() && ext.chars().all(|c| c.is_ascii_alphanumeric())).then_some(ext)
}
