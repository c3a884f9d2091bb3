//! CYCLE records: canned drilling cycles in every vendor form.
//!
//! Distances in a CL cycle are measured along the tool axis from each hole's
//! `GOTO` point, which is the top of the hole: the bottom is the point minus
//! the depth, the R plane the point plus the clearance, the retract plane the
//! point plus the retract distance. The reader turns them into the absolute
//! heights of a [`DrillCycle`] at each hole.
//!
//! Forms read (keywords in any order, any case):
//!
//! - SolidWorks CAM: `CYCLE/INIT`, then `CYCLE/DRILL|DEEP|DEEP2,FEDTO,d,[1STPECK,p,SUBPECK,q,]MMPM,f,RAPTO,r,RTRCTO,t[,DWELL,s]`;
//! - NX: `CYCLE/DRILL[,DEEP|,BRKCHP],RAPTO,r,FEDTO,d,MMPM,f[,RTRCTO,t][,INCR,p][,DWELL,s]`;
//! - Creo: `CYCLE / DEEP, DEPTH,d, STEP,p, MMPM,f, CLEAR,r`;
//! - classic APT: `CYCLE/DRILL,d,IPM,f,r` (bare numbers are depth, clearance, retract, in that order);
//! - CLT: `CYCLE/ ON`, then `CYCLE/ DRILL,G98,d,PECKING,p,q,MMPM,f,r,t DWELL,s`;
//! - `CYCLE/OFF` ends the cycle; `CYCLE/INIT` and `CYCLE/ON` give no event.
//!
//! Kinds: `DRILL` (G81, G82 with dwell), `DEEP` and `DEEP2` (peck, G83),
//! `BRKCHP` (chip break, G73), `TAP` (G84), `BORE` (G85), `REAM`. `DRILL`
//! with `DEEP`, `BRKCHP` or `PECKING` is that kind.

use postc_ir::event::{DrillCycle, DrillKind};

use crate::machine_records::FeedSpec;
use crate::words::{Arg, Problem, Rec};

/// A cycle as written: distances relative to each hole's point.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct CycleSpec {
    pub kind: DrillKind,
    /// The cycle's word as written (`DRILL`, `DEEP2`).
    pub name: String,
    pub depth: Option<f64>,
    pub clearance: Option<f64>,
    pub retract: Option<f64>,
    pub feed: Option<FeedSpec>,
    pub peck: Option<f64>,
    pub dwell: Option<f64>,
    pub pitch: Option<f64>,
}

/// What a CYCLE record does.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum CycleRecord {
    Start(CycleSpec),
    Off,
    /// `INIT` or `ON`: announces a cycle, no event.
    Prepare,
}

fn kind_of(word: &[u8]) -> Option<DrillKind> {
    let w = |name: &str| word.eq_ignore_ascii_case(name.as_bytes());
    Some(if w("DRILL") || w("FACE") || w("SPOT") {
        DrillKind::Drill
    } else if w("DEEP") || w("DEEP2") || w("PECK") {
        DrillKind::Deep
    } else if w("BRKCHP") || w("CHPBRK") {
        DrillKind::ChipBreak
    } else if w("TAP") || w("RIGID") {
        DrillKind::Tap
    } else if w("BORE") {
        DrillKind::Bore
    } else if w("REAM") {
        DrillKind::Ream
    } else {
        return None;
    })
}

/// Reads a CYCLE record; `ignored` receives the index of each word that is
/// not understood.
pub(crate) fn parse_cycle(rec: &Rec<'_>, ignored: &mut dyn FnMut(usize)) -> Result<CycleRecord, Problem> {
    let Some(first) = rec.arg(0) else {
        return Err(Problem::new("CYCLE needs a cycle type: DRILL, DEEP, TAP, BORE, ... or OFF", None));
    };
    if first.is("OFF") {
        return Ok(CycleRecord::Off);
    }
    if first.is("INIT") || first.is("ON") {
        return Ok(CycleRecord::Prepare);
    }
    let Some(kind) = first.word().and_then(kind_of) else {
        return Err(Problem::new(
            "unknown cycle type: CYCLE needs DRILL, DEEP, DEEP2, BRKCHP, TAP, BORE, REAM or OFF first",
            Some(0),
        ));
    };
    let mut spec = CycleSpec {
        kind,
        name: String::from_utf8_lossy(first.word().unwrap_or_default()).to_ascii_uppercase(),
        depth: None,
        clearance: None,
        retract: None,
        feed: None,
        peck: None,
        dwell: None,
        pitch: None,
    };
    let mut positional = 0;
    let mut i = 1;
    let len = rec.len();
    let number_at = |i: usize| rec.arg(i).and_then(|a| a.num());
    while i < len {
        let Some(arg) = rec.arg(i) else { break };
        let taken = match arg {
            Arg::Num(v) => {
                // Bare numbers: depth, clearance, retract, in that order.
                let slot = [&mut spec.depth, &mut spec.clearance, &mut spec.retract].into_iter().find(|s| s.is_none());
                if let (true, Some(slot)) = (positional < 3, slot) {
                    *slot = Some(v);
                }
                positional += 1;
                1
            }
            Arg::Word(w) => {
                let is = |name: &str| w.eq_ignore_ascii_case(name.as_bytes());
                let next = number_at(i + 1);
                if is("DEEP") || is("BRKCHP") {
                    spec.kind = kind_of(w).unwrap_or(spec.kind);
                    1
                } else if is("FEDTO") || is("DEPTH") {
                    spec.depth = next.or(spec.depth);
                    2
                } else if is("RAPTO") || is("CLEAR") {
                    spec.clearance = next.or(spec.clearance);
                    2
                } else if is("RTRCTO") || is("RETURN") {
                    spec.retract = next.or(spec.retract);
                    2
                } else if is("STEP") || is("INCR") || is("1STPECK") || is("PECK") {
                    spec.peck = next.or(spec.peck);
                    2
                } else if is("PECKING") {
                    spec.peck = next.or(spec.peck);
                    if spec.kind == DrillKind::Drill {
                        spec.kind = DrillKind::Deep;
                    }
                    if number_at(i + 2).is_some() { 3 } else { 2 }
                } else if is("SUBPECK") {
                    2
                } else if is("DWELL") {
                    spec.dwell = next.filter(|&s| s > 0.0);
                    2
                } else if is("PITCH") || is("LEAD") {
                    spec.pitch = next;
                    2
                } else if let Some(unit) = FeedSpec::unit_word(w) {
                    if let Some(value) = next {
                        spec.feed = Some(FeedSpec { value, ..unit });
                    }
                    2
                } else {
                    if !(is("G98") || is("G99") || is("AUTO") || is("IPM") || is("MMPM")) {
                        ignored(i);
                    }
                    1
                }
            }
            Arg::Open(_) | Arg::Close => {
                ignored(i);
                1
            }
        };
        i += taken;
    }
    Ok(CycleRecord::Start(spec))
}

/// The absolute cycle for a hole at height `z`; `clearance_z` is where the
/// tool stood before the cycle (the retract plane when the cycle has none).
pub(crate) fn drill_cycle(spec: &CycleSpec, z: f64, clearance_z: Option<f64>, feed: Option<f64>) -> DrillCycle {
    let reference = z + spec.clearance.unwrap_or(0.0);
    let retract = match (spec.retract, clearance_z) {
        (Some(r), _) => z + r,
        (None, Some(c)) if c > reference => c,
        _ => reference,
    };
    DrillCycle {
        kind: spec.kind,
        name: spec.name.clone(),
        retract_plane: retract,
        reference_plane: reference,
        surface: Some(z),
        depth: z - spec.depth.unwrap_or(0.0).abs(),
        feed,
        peck: spec.peck.filter(|&p| p > 0.0),
        dwell: spec.dwell,
        pitch: spec.pitch,
    }
}
