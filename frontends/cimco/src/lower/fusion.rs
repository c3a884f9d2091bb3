//! Lowering a Fusion `.cps` post: the post and postc's Fusion host API
//! (`fusion/host.js`, JavaScript) as one program, every function in the
//! general form ([`super::general`]), and handlers that call the host's
//! engine functions (`__fusion_*`), which call the post's entry points in
//! Fusion's order.
//!
//! | section | calls |
//! |---|---|
//! | `HEADER` | `__fusion_toolpath(...)` for the first toolpath, `__fusion_job(product)`, then `__fusion_open(mm, file name, notes, date, time, folder, material min x y z, max x y z, job outline, post properties)` |
//! | `TOOLCHANGE` | `__fusion_tool_change()` (the `SPINDLE_ON` after it is the next section's speed) |
//! | `NEW_SEGMENT` | `__fusion_toolpath(tool, diameter, tool name, toolpath name, jet, speed, tool notes, coolant, length offset, cut feed, plunge feed, safe Z, ..., turning tool, feed per revolution, constant surface speed, its highest rpm, toolpath notes, spindle counter-clockwise)` |
//! | `JET_TOOL_ON`, `JET_TOOL_OFF` | `__fusion_power(on)` |
//! | `SPINDLE_ON` | `__fusion_spindle(speed, ..., constant surface speed, its highest rpm, counter-clockwise)` |
//! | `RAPID_MOVE` | `__fusion_rapid(x, y, z)` |
//! | `FEED_MOVE`, `PLUNGE_MOVE` | `__fusion_linear(x, y, z, feed, plunge)` |
//! | arc sections | `__fusion_circular(clockwise, cx, cy, cz, x, y, z, feed, sweep, radius, plane, ..., plunge)`: `plunge` for the helical plunge sections |
//! | `DWELL_MOVE`, `COMMENT` | `__fusion_dwell(seconds)`, `__fusion_comment(text)` |
//! | `INSERT` | `__fusion_insert(text)`: the toolpath's text as it is, each line ended with the host's `EOL` |
//! | `COOLANT`, `CUTTER_COMP` | `__fusion_coolant(kind)`, `__fusion_compensation(side)` |
//! | `DRILL_HEADER` | `__fusion_cycle(kind, clearance, R plane, top, bottom, feed, peck, dwell, pitch)` |
//! | `DRILL_POINT`, `DRILL_FOOTER` | `__fusion_cycle_point(x, y)`, `__fusion_cycle_end()` |
//! | `FOOTER` | `__fusion_close()` |
//!
//! Each call also passes `RECORD_ID` and `NEXT_RECORD_MOTION` (the `...`
//! above, last when nothing follows): where the event is in the toolpath
//! and whether a move follows it.
//!
//! A post that has a construct or host call the general form cannot
//! hold is refused with JS109 at that construct: a Fusion post has no
//! script tier to fall back to.

use postc_ir::{
    BinaryOp, Body, Diagnostic, Expr, Function, Handler, HandlerKey, Post, Quantity, Section, Span, Stmt, codes,
};

use std::collections::HashSet;

use crate::ast::Program;

use super::fold;
use super::general;
use super::layout::{self, Layout};
use super::model::Model;
use super::setup::Setup;

/// Lowers the merged program (host first, then the post) into `post`.
pub(crate) fn lower(
    program: &Program,
    whole: Span,
    stubs: &HashSet<String>,
    post: &mut Post,
    diags: &mut Vec<Diagnostic>,
) {
    let model = Model::build(program);
    let setup = Setup::default();
    let mut layout = Layout::new(&model);
    let init_fn = layout.add_fn(layout::INIT);
    let functions = match functions(program, &model, &setup, &mut layout, whole, stubs) {
        Ok((f, stub_calls)) => {
            for (name, at) in stub_calls {
                diags.push(
                    Diagnostic::warning(
                        codes::JS110,
                        format!("this post calls `{name}` of Fusion's host, which postc does not run yet"),
                    )
                    .at(at, "the post stops here if it gets here")
                    .note("a job whose toolpaths never reach this call posts as usual"),
                );
            }
            f
        }
        Err(why) => {
            diags.push(
                Diagnostic::error(codes::JS109, format!("postc cannot run this Fusion post: it {}", why.what))
                    .at(why.span, "here")
                    .note("no program is written"),
            );
            return;
        }
    };
    if let Some(super::consts::Const::Str(ext)) = model.constant("extension")
        && !ext.is_empty()
    {
        post.info.file_extension = ext.clone();
    }
    post.options.forget_modal_at_toolpath_start = false;
    // The host applies the post's `allowedCircularPlanes` itself.
    post.options.arcs_in_every_plane = true;
    // `getSection(i)`, the tool table and the next tool know the whole job.
    post.options.reads_ahead = true;
    // A Fusion post has no script tier: its interpreter runs what CIMCO's
    // Rhai tier refuses (docs/fusion.md, "Language").
    post.options.function_replacements = true;
    // Text is JavaScript's: `"a" + null` is "anull".
    post.options.js_text = true;
    // Each line ends with the host's `EOL`, which `setEOL` changes
    // (docs/fusion.md, choice 5): the host writes it, so the post's own
    // line ending is empty.
    post.options.line_ending = Vec::new();
    post.handlers = handlers(&layout);
    post.init = vec![Stmt::Eval(Expr::Call(init_fn, vec![]))];
    post.functions = functions;
    post.globals = layout.globals;
    post.scripts.clear();
}

/// The post's calls to host functions postc does not run yet, by name.
type StubCalls = Vec<(String, Span)>;

fn functions(
    program: &Program,
    model: &Model,
    setup: &Setup,
    layout: &mut Layout,
    whole: Span,
    stubs: &HashSet<String>,
) -> Result<(Vec<Function>, StubCalls), super::native::Why> {
    let init_stmts = super::init_statements(program, model, setup);
    let mut shared = general::Shared::new(model, setup, layout);
    shared.fusion = true;
    shared.stubs = stubs.clone();
    shared.post_file = Some(whole.file);
    let mut functions = Vec::new();
    for &id in &model.scopes.top_fns {
        let f = &model.scopes.funcs[id];
        let func = f.func.expect("top-level functions have a body");
        functions.push(shared.function(id, &func.body, false, func.span)?);
    }
    let mut init = shared.function(0, &init_stmts, false, whole)?;
    init.name = layout::INIT.into();
    init.params.clear();
    functions.push(init);
    for (id, f) in shared.nested_functions()? {
        if id.index() != functions.len() {
            return Err(super::native::Why { what: "has a nested function out of order".into(), span: whole });
        }
        functions.push(f);
    }
    let stub_calls = std::mem::take(&mut shared.stub_calls);
    for f in &mut functions {
        if let Body::Native(b) = &mut f.body {
            *b = fold::stmts(std::mem::take(b));
        }
    }
    Ok((functions, stub_calls))
}

/// The handlers: each section calls the host's engine function for it.
fn handlers(layout: &Layout) -> Vec<Handler> {
    let q = Expr::Quantity;
    // Every engine function also gets where the event is in the toolpath
    // and whether a move follows it (`getCurrentRecordId`, `getNextRecord`).
    // Arguments after those two are the turning job's (docs/fusion.md,
    // "Turning"), last so that a caller that does not give them (the
    // Node.js referee) gives `undefined`, read as false.
    let call_with = |name: &str, mut args: Vec<Expr>, after: Vec<Expr>| -> Vec<Stmt> {
        args.extend([q(Quantity::RecordId), q(Quantity::NextRecordMotion)]);
        args.extend(after);
        match layout.function(name) {
            Some(f) => vec![Stmt::Eval(Expr::Call(f, args))],
            None => Vec::new(),
        }
    };
    let call = |name: &str, args: Vec<Expr>| call_with(name, args, Vec::new());
    let toolpath = || {
        call_with(
            "__fusion_toolpath",
            vec![
                q(Quantity::Tool),
                q(Quantity::ToolDiameter),
                q(Quantity::ToolName),
                q(Quantity::ToolpathName),
                Expr::Binary(BinaryOp::Ne, Box::new(q(Quantity::JetTool)), Box::new(Expr::Number(0.0))),
                q(Quantity::SpindleSpeed),
                q(Quantity::ToolNotes),
                q(Quantity::CoolantKind),
                q(Quantity::LengthOffset),
                q(Quantity::CutFeed),
                q(Quantity::PlungeFeed),
                q(Quantity::SafeZ),
            ],
            vec![
                Expr::Binary(BinaryOp::Ne, Box::new(q(Quantity::TurningTool)), Box::new(Expr::Number(0.0))),
                Expr::Binary(BinaryOp::Ne, Box::new(q(Quantity::FeedPerRev)), Box::new(Expr::Number(0.0))),
                Expr::Binary(BinaryOp::Ne, Box::new(q(Quantity::SpindleCss)), Box::new(Expr::Number(0.0))),
                q(Quantity::SpindleMaxRpm),
                q(Quantity::ToolpathNotes),
                Expr::Binary(BinaryOp::Ne, Box::new(q(Quantity::SpindleCcw)), Box::new(Expr::Number(0.0))),
            ],
        )
    };
    let mm = Expr::Binary(
        BinaryOp::Eq,
        Box::new(q(Quantity::UnitsText)),
        Box::new(Expr::Text(postc_ir::Units::Mm.name().into())),
    );
    // The first section exists before `onOpen`, so that `getSection(0)` and
    // the tool table answer there.
    let mut header = toolpath();
    // The job's product: Fusion's `generated-by` parameter.
    header.extend(call("__fusion_job", vec![q(Quantity::Product)]));
    header.extend(call(
        "__fusion_open",
        vec![
            mm,
            q(Quantity::FileName),
            q(Quantity::FileNotes),
            q(Quantity::Date),
            q(Quantity::Time),
            q(Quantity::PathName),
            q(Quantity::XMin),
            q(Quantity::YMin),
            q(Quantity::ZMin),
            q(Quantity::XMax),
            q(Quantity::YMax),
            q(Quantity::ZMax),
            q(Quantity::JobOutline),
            q(Quantity::PostProperties),
        ],
    ));
    let linear = |plunge: bool| {
        call(
            "__fusion_linear",
            vec![q(Quantity::X), q(Quantity::Y), q(Quantity::Z), q(Quantity::Feed), Expr::Bool(plunge)],
        )
    };
    // A helix the toolpath marks as plunging (the helical plunge sections)
    // is Fusion's helical ramp.
    let arc = |cw: bool, plunge: bool| {
        call_with(
            "__fusion_circular",
            vec![
                Expr::Bool(cw),
                q(Quantity::IA),
                q(Quantity::JA),
                q(Quantity::KA),
                q(Quantity::X),
                q(Quantity::Y),
                q(Quantity::Z),
                q(Quantity::Feed),
                q(Quantity::Angle),
                q(Quantity::Radius),
                q(Quantity::ArcPlane),
            ],
            vec![Expr::Bool(plunge)],
        )
    };
    let mut hs = Vec::new();
    let mut add = |section: Section, body: Vec<Stmt>| {
        if !body.is_empty() {
            hs.push(Handler { key: HandlerKey::Section(section), body, span: None });
        }
    };
    add(Section::Header, header);
    add(Section::ToolChange, call("__fusion_tool_change", vec![]));
    add(Section::NewSegment, toolpath());
    add(
        Section::SpindleOn,
        call_with(
            "__fusion_spindle",
            vec![q(Quantity::SpindleSpeed)],
            vec![
                Expr::Binary(BinaryOp::Ne, Box::new(q(Quantity::SpindleCss)), Box::new(Expr::Number(0.0))),
                q(Quantity::SpindleMaxRpm),
                Expr::Binary(BinaryOp::Ne, Box::new(q(Quantity::SpindleCcw)), Box::new(Expr::Number(0.0))),
            ],
        ),
    );
    add(Section::RapidMove, call("__fusion_rapid", vec![q(Quantity::X), q(Quantity::Y), q(Quantity::Z)]));
    add(Section::FeedMove, linear(false));
    add(Section::PlungeMove, linear(true));
    add(Section::CwArcMove, arc(true, false));
    add(Section::CcwArcMove, arc(false, false));
    add(Section::CwHelicalArcMove, arc(true, false));
    add(Section::CcwHelicalArcMove, arc(false, false));
    add(Section::CwHelicalArcPlungeMove, arc(true, true));
    add(Section::CcwHelicalArcPlungeMove, arc(false, true));
    add(Section::JetToolOn, call("__fusion_power", vec![Expr::Bool(true)]));
    add(Section::JetToolOff, call("__fusion_power", vec![Expr::Bool(false)]));
    add(Section::DwellMove, call("__fusion_dwell", vec![q(Quantity::DwellTime)]));
    add(Section::Comment, call("__fusion_comment", vec![q(Quantity::CommentText)]));
    add(Section::Insert, call("__fusion_insert", vec![q(Quantity::CommentText)]));
    add(Section::Coolant, call("__fusion_coolant", vec![q(Quantity::CoolantKind)]));
    add(Section::CutterComp, call("__fusion_compensation", vec![q(Quantity::CompSide)]));
    add(
        Section::DrillHeader,
        call(
            "__fusion_cycle",
            vec![
                q(Quantity::DrillKind),
                q(Quantity::DrillClearance),
                q(Quantity::DrillReference),
                q(Quantity::DrillSurface),
                q(Quantity::DrillBottom),
                q(Quantity::DrillFeed),
                q(Quantity::DrillPeck),
                q(Quantity::DrillDwell),
                q(Quantity::DrillPitch),
            ],
        ),
    );
    add(Section::DrillPoint, call("__fusion_cycle_point", vec![q(Quantity::X), q(Quantity::Y)]));
    add(Section::DrillFooter, call("__fusion_cycle_end", vec![]));
    add(Section::Footer, call("__fusion_close", vec![]));
    for h in &mut hs {
        h.body = fold::stmts(std::mem::take(&mut h.body));
    }
    hs
}
