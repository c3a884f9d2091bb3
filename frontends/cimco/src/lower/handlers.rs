//! Which IR sections a CIMCO post's functions occupy, and the handler
//! bodies that call them.
//!
//! | section | calls |
//! |---|---|
//! | `HEADER` | `onOpen(false)`, then `onToolChange(...)` for the first tool |
//! | `FOOTER` | `onClose()` |
//! | `TOOLCHANGE` | `onToolChange(tool, name, diameter, spindleSpeed)` |
//! | `RAPID_MOVE` | `onLinear(..., MOVEMENT_RAPID)` |
//! | `FEED_MOVE` | `onLinear(..., MOVEMENT_CUTTING)` |
//! | `PLUNGE_MOVE` | `onLinear(..., MOVEMENT_PLUNGE)` |
//! | `CW_ARC_MOVE`, `CCW_ARC_MOVE` and their helical forms | `onCircular(..., isCW, MOVEMENT_CUTTING)`, split under `useRadius` |
//! | `CUTTER_COMP` | `onCompensation(comp)` |
//! | `DRILL_HEADER` / `DRILL_POINT` / `DRILL_FOOTER` | `onDrillingHeader(drillHeader)` / `onDrillingPoint(x, y)` / `onDrillingFooter()` (mill) |
//! | `DRILL_POINT` | `onDrilling(drillHeader)` (lathe) |
//! | `DWELL_MOVE`, `COMMENT`, `TOOLPATH_END` | `onDwell(seconds)`, `onComment(text)`, `onToolpathEnd()` |
//!
//! No `FIRST_` sections, `INITIAL_RAPID_MOVE`, `RETRACT_MOVE` or
//! `NEW_SEGMENT` are occupied, so the runtime's fallbacks send every rapid
//! through `RAPID_MOVE` (rapid retracts too), feed retracts and lead moves
//! through `FEED_MOVE`, and a post without `onCircular` gets arcs as
//! `onLinear` calls along the arc. A handler's locals (the parts of an
//! arc under `useRadius`) live in one frame, as the IR says.

use postc_ir::{
    BinaryOp, Builtin, Expr, FunctionId, GlobalId, Handler, HandlerKey, LocalId, Place, Quantity, Section, Stmt,
    UnaryOp,
};

use super::builtins;
use super::layout::{self, Layout};

/// What the handlers need to know about the post.
pub struct Entry<'l> {
    pub layout: &'l Layout,
    pub lathe: bool,
    /// `useRadius`: known, or read from its global at run time.
    pub use_radius: RadiusSetting,
    /// Number of parameters of each entry point the post defines.
    pub arity: &'l dyn Fn(&str) -> Option<usize>,
}

/// How the post sets `useRadius`.
pub enum RadiusSetting {
    Known(bool),
    Global(GlobalId),
}

impl Entry<'_> {
    fn has(&self, name: &str) -> Option<FunctionId> {
        (self.arity)(name)?;
        self.layout.function(name)
    }

    /// Every handler of the post.
    pub fn handlers(&self) -> Vec<Handler> {
        let mut hs = Vec::new();
        let mut add = |section: Section, body: Vec<Stmt>| {
            if !body.is_empty() {
                hs.push(Handler { key: HandlerKey::Section(section), body, span: None });
            }
        };
        let tool = self.tool_change();
        let mut header = self.call_write("onOpen", vec![Expr::Bool(false)]);
        header.extend(tool.clone());
        add(Section::Header, header);
        add(Section::Footer, self.call_write("onClose", vec![]));
        add(Section::ToolChange, tool);
        let (x, y, z) = self.axes();
        for (section, movement) in [
            (Section::RapidMove, builtins::MOVEMENT_RAPID),
            (Section::FeedMove, builtins::MOVEMENT_CUTTING),
            (Section::PlungeMove, builtins::MOVEMENT_PLUNGE),
        ] {
            let mut args = vec![x.clone()];
            if !self.lathe {
                args.push(y.clone());
            }
            args.push(z.clone());
            args.push(Expr::Number(movement));
            add(section, self.call_write("onLinear", args));
        }
        if self.has("onCircular").is_some() {
            for (section, cw) in [
                (Section::CwArcMove, true),
                (Section::CcwArcMove, false),
                (Section::CwHelicalArcMove, true),
                (Section::CcwHelicalArcMove, false),
            ] {
                add(section, self.arc(cw));
            }
        }
        if self.has("onCompensation").is_some() {
            add(Section::CutterComp, self.call_write(layout::COMPENSATION, vec![]));
        }
        if self.lathe {
            if self.has("onDrilling").is_some() {
                add(Section::DrillPoint, self.call_write(layout::TURN_DRILL, vec![]));
            }
        } else {
            if self.has("onDrillingHeader").is_some() {
                add(Section::DrillHeader, self.call_write(layout::DRILL_HEADER, vec![]));
            }
            add(Section::DrillPoint, self.call_write("onDrillingPoint", vec![x.clone(), y.clone()]));
            add(Section::DrillFooter, self.call_write("onDrillingFooter", vec![]));
        }
        add(Section::DwellMove, self.call_write("onDwell", vec![Expr::Quantity(Quantity::DwellTime)]));
        add(Section::Comment, self.call_write("onComment", vec![Expr::Quantity(Quantity::CommentText)]));
        add(Section::ToolpathEnd, self.call_write("onToolpathEnd", vec![]));
        hs
    }

    /// The coordinates the post's functions receive. A lathe's toolpath
    /// reaches the runtime turned: its Z in X, its X (the radius) in Y.
    fn axes(&self) -> (Expr, Expr, Expr) {
        if self.lathe {
            (Expr::Quantity(Quantity::Y), Expr::Number(0.0), Expr::Quantity(Quantity::X))
        } else {
            (Expr::Quantity(Quantity::X), Expr::Quantity(Quantity::Y), Expr::Quantity(Quantity::Z))
        }
    }

    fn tool_change(&self) -> Vec<Stmt> {
        self.call_write(
            "onToolChange",
            vec![
                Expr::Quantity(Quantity::Tool),
                Expr::Quantity(Quantity::ToolName),
                Expr::Quantity(Quantity::ToolDiameter),
                Expr::Quantity(Quantity::SpindleSpeed),
            ],
        )
    }

    /// `Write(name(args))` when the function exists (postc's glue always does).
    fn call_write(&self, name: &str, args: Vec<Expr>) -> Vec<Stmt> {
        let f = if name.starts_with("__postc") { self.layout.function(name) } else { self.has(name) };
        match f {
            Some(f) => vec![Stmt::Write(Expr::Call(f, args))],
            None => Vec::new(),
        }
    }

    /// The arguments of one `onCircular` call ending at `(ex, ey, ez)`.
    fn circular_args(&self, cw: bool, end: (Expr, Expr, Expr)) -> Vec<Expr> {
        let (ex, ey, ez) = end;
        let mut args = Vec::new();
        if self.lathe {
            // Turned: the arc's X is the lathe's Z, its Y the radius.
            args.extend([Expr::Quantity(Quantity::JA), Expr::Quantity(Quantity::IA), ey, ex]);
        } else {
            args.extend([
                Expr::Quantity(Quantity::IA),
                Expr::Quantity(Quantity::JA),
                Expr::Quantity(Quantity::KA),
                ex,
                ey,
                ez,
            ]);
        }
        args.push(Expr::Bool(cw));
        args.push(Expr::Number(builtins::MOVEMENT_CUTTING));
        args
    }

    /// An arc: one `onCircular` call, or under `useRadius` as many as keep
    /// each part under 180 degrees: n = floor(|sweep| / pi + 1e-9) + 1
    /// equal parts, the intermediate ends on the arc (Z moving evenly).
    fn arc(&self, cw: bool) -> Vec<Stmt> {
        let Some(f) = self.has("onCircular") else { return Vec::new() };
        let q = |q: Quantity| Expr::Quantity(q);
        let whole =
            Stmt::Write(Expr::Call(f, self.circular_args(cw, (q(Quantity::X), q(Quantity::Y), q(Quantity::Z)))));
        let split = |radius_cond: Option<Expr>| -> Vec<Stmt> {
            let num = |n: f64| Expr::Number(n);
            let b = |op, a: Expr, c: Expr| Expr::Binary(op, Box::new(a), Box::new(c));
            let call = |bu: Builtin, args: Vec<Expr>| Expr::Builtin(bu, args);
            let (n, a0, i, t) = (LocalId::new(0), LocalId::new(1), LocalId::new(2), LocalId::new(3));
            let parts = b(
                BinaryOp::Add,
                call(
                    Builtin::Floor,
                    vec![b(
                        BinaryOp::Add,
                        b(BinaryOp::Div, call(Builtin::Abs, vec![q(Quantity::Angle)]), num(std::f64::consts::PI)),
                        num(1e-9),
                    )],
                ),
                num(1.0),
            );
            let start_angle = call(
                Builtin::Atan2,
                vec![
                    b(BinaryOp::Sub, q(Quantity::ArcStartY), q(Quantity::JA)),
                    b(BinaryOp::Sub, q(Quantity::ArcStartX), q(Quantity::IA)),
                ],
            );
            let angle = b(BinaryOp::Add, Expr::Local(a0), b(BinaryOp::Mul, q(Quantity::Angle), Expr::Local(t)));
            let end = (
                b(
                    BinaryOp::Add,
                    q(Quantity::IA),
                    b(BinaryOp::Mul, q(Quantity::Radius), call(Builtin::Cos, vec![angle.clone()])),
                ),
                b(
                    BinaryOp::Add,
                    q(Quantity::JA),
                    b(BinaryOp::Mul, q(Quantity::Radius), call(Builtin::Sin, vec![angle])),
                ),
                b(
                    BinaryOp::Add,
                    q(Quantity::KA),
                    b(BinaryOp::Mul, b(BinaryOp::Sub, q(Quantity::Z), q(Quantity::KA)), Expr::Local(t)),
                ),
            );
            let part = Stmt::Write(Expr::Call(f, self.circular_args(cw, end)));
            let mut body = vec![
                Stmt::Assign(Place::Local(n), parts),
                Stmt::Assign(Place::Local(a0), start_angle),
                Stmt::Assign(Place::Local(i), num(1.0)),
                Stmt::While {
                    cond: b(BinaryOp::Lt, Expr::Local(i), Expr::Local(n)),
                    body: vec![
                        Stmt::Assign(Place::Local(t), b(BinaryOp::Div, Expr::Local(i), Expr::Local(n))),
                        part,
                        Stmt::Assign(Place::Local(i), b(BinaryOp::Add, Expr::Local(i), num(1.0))),
                    ],
                    span: None,
                    step: vec![],
                },
                whole.clone(),
            ];
            if let Some(c) = radius_cond {
                body = vec![Stmt::If { branches: vec![(c, body)], otherwise: vec![whole.clone()] }];
            }
            body
        };
        match self.use_radius {
            RadiusSetting::Known(false) => vec![whole],
            RadiusSetting::Known(true) => split(None),
            RadiusSetting::Global(g) => {
                split(Some(Expr::Unary(UnaryOp::Not, Box::new(Expr::Unary(UnaryOp::Not, Box::new(Expr::Global(g)))))))
            }
        }
    }
}
