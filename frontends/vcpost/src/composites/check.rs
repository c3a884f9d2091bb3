//! Checks of the values of composites calls, where Vericut's post-processor notes bound them:
//! `LinkType` and `Rotation` are -1, 0 or +1; `TowNum` is 0 or a tow
//! number; a function table has at most [`MAX_LIST`] entries and, for a
//! GoTo, one per tow of the packet; the four AddCut variables encode the
//! same tow states (`AddCutA` a string of 0 and 1, `AddCutB` its reverse,
//! `AddCutI` and `AddCutJ` their binary values).

use postc_ir::codes;
use postc_ir::{Diagnostic, Span};

use super::calls::{LayingCall, PacketPoint, ProbingCall, RestartPoint};
use crate::ast::SubKeyword;

/// Most entries of a function table (the runtime's table size).
pub const MAX_LIST: usize = 64;

/// What the reader needs of a call besides its variables.
pub trait Checked {
    /// The number the sequence depends on: `LinkType`, `TowNum`, else 0.
    fn number(&self) -> f64;
    /// The keyword the named Sub of an option or probe call should carry.
    fn named_keyword(&self) -> Option<SubKeyword>;
    /// Value checks; problems go into `diagnostics`.
    fn check(&self, span: Span, diagnostics: &mut Vec<Diagnostic>);
}

impl Checked for LayingCall {
    fn number(&self) -> f64 {
        match self {
            LayingCall::LinkHeader(l) => l.LinkType,
            LayingCall::Length(l) => l.TowNum,
            _ => 0.0,
        }
    }

    fn named_keyword(&self) -> Option<SubKeyword> {
        matches!(self, LayingCall::Option(_)).then_some(SubKeyword::Option)
    }

    fn check(&self, span: Span, diagnostics: &mut Vec<Diagnostic>) {
        match self {
            LayingCall::LinkHeader(l) => {
                unit("LinkType", l.LinkType, span, diagnostics);
                unit("Rotation", l.Rotation, span, diagnostics);
            }
            LayingCall::Extent(e) => unit("Rotation", e.Rotation, span, diagnostics),
            LayingCall::Length(l) if l.TowNum < 0.0 || l.TowNum.fract() != 0.0 => diagnostics.push(
                Diagnostic::error(codes::CP006, format!("TowNum is {}: a tow number, or 0 for all tows", l.TowNum))
                    .at(span, "in this call"),
            ),
            LayingCall::GoTo(p) => goto(p, span, diagnostics),
            LayingCall::RestartBuffer(p) => restart(p, span, diagnostics),
            _ => {}
        }
    }
}

impl Checked for ProbingCall {
    fn number(&self) -> f64 {
        0.0
    }

    fn named_keyword(&self) -> Option<SubKeyword> {
        matches!(self, ProbingCall::Probe(_)).then_some(SubKeyword::Probe)
    }

    fn check(&self, _span: Span, _diagnostics: &mut Vec<Diagnostic>) {}
}

fn unit(name: &str, v: f64, span: Span, diagnostics: &mut Vec<Diagnostic>) {
    if ![-1.0, 0.0, 1.0].contains(&v) {
        diagnostics.push(
            Diagnostic::error(codes::CP006, format!("{name} is {v}; Vericut's application notes allow -1, 0 or +1"))
                .at(span, "in this call"),
        );
    }
}

fn goto(p: &PacketPoint, span: Span, diagnostics: &mut Vec<Diagnostic>) {
    add_cut(&p.AddCutA, &p.AddCutB, p.AddCutI, p.AddCutJ, span, diagnostics);
    for (name, list) in
        [("getNthLength1", &p.getNthLength1), ("getNthLength2", &p.getNthLength2), ("getNthLength3", &p.getNthLength3)]
    {
        let Some(list) = list else { continue };
        if list_too_long(name, list, span, diagnostics) {
            continue;
        }
        if list.len() as f64 != p.TowsInPacket {
            diagnostics.push(
                Diagnostic::warning(
                    codes::CP009,
                    format!("{name} has {} entries but the packet has {} tows", list.len(), p.TowsInPacket),
                )
                .at(span, "in this call")
                .help("give one number per tow, tow 0 first; missing tows read 0"),
            );
        }
    }
}

fn restart(p: &RestartPoint, span: Span, diagnostics: &mut Vec<Diagnostic>) {
    add_cut(&p.AddCutA, &p.AddCutB, p.AddCutI, p.AddCutJ, span, diagnostics);
    if let Some(list) = &p.getNthAddCut {
        list_too_long("getNthAddCut", list, span, diagnostics);
    }
}

fn list_too_long(name: &str, list: &[f64], span: Span, diagnostics: &mut Vec<Diagnostic>) -> bool {
    let long = list.len() > MAX_LIST;
    if long {
        diagnostics.push(
            Diagnostic::error(
                codes::CP006,
                format!("{name} has {} entries; postc holds at most {MAX_LIST}", list.len()),
            )
            .at(span, "in this call"),
        );
    }
    long
}

/// The binary value of a string of 0 and 1, if it is one (and fits).
fn binary(s: &str) -> Option<f64> {
    if s.is_empty() || s.len() > 52 || !s.bytes().all(|b| b == b'0' || b == b'1') {
        return None;
    }
    Some(s.bytes().fold(0.0, |acc, b| acc * 2.0 + f64::from(b - b'0')))
}

#[doc(hidden)]
pub fn add_cut(a: &str, b: &str, i: f64, j: f64, span: Span, diagnostics: &mut Vec<Diagnostic>) {
    let reversed: String = a.chars().rev().collect();
    let problem = match (binary(a), binary(b)) {
        (None, _) => Some(format!("AddCutA \"{a}\" is not a string of 0 and 1")),
        (_, None) => Some(format!("AddCutB \"{b}\" is not a string of 0 and 1")),
        _ if reversed != b => Some(format!("AddCutB \"{b}\" is not AddCutA \"{a}\" reversed")),
        (Some(va), _) if va != i => Some(format!("AddCutI is {i} but AddCutA \"{a}\" is {va}")),
        (_, Some(vb)) if vb != j => Some(format!("AddCutJ is {j} but AddCutB \"{b}\" is {vb}")),
        _ => None,
    };
    if let Some(message) = problem {
        diagnostics.push(
            Diagnostic::warning(codes::CP008, message).at(span, "in this call").help(
                "Vericut's application notes: AddCutA \"0001111111111100\", AddCutB \"0011111111111000\", AddCutI 8188, AddCutJ 16376",
            ),
        );
    }
}
