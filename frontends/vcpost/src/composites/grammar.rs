//! The call sequences Vericut's post-processor notes allow, as two small state machines.
//!
//! Material laying (VCP's Roller Post card):
//!
//! ```text
//! file     = Modals Extent lengths [ cam ] PlyHeader
//!            link(-1) { [ Extent lengths ] packet link(0) } [ Extent lengths ] packet link(+1)
//!            PlyTrailer
//! lengths  = { Length(TowNum > 0) } Length(TowNum = 0)
//! cam      = CamHeader { CamPoint } CamTrailer
//! link     = LinkHeader(LinkType) { MoveTo | OffForm | OnForm | Option | pullout | traverse } LinkTrailer
//! pullout  = PulloutHeader { MoveTo | OffForm | OnForm | Option } PulloutTrailer
//! traverse = TraverseHeader { TraverseTo } TraverseTrailer
//! packet   = PacketHeader { GoTo | Option | restart } PacketTrailer
//! restart  = RestartHeader { RestartBuffer } RestartTrailer
//! ```
//!
//! That is: the ply's initial entry is a link of type -1, links of type 0
//! sit between tow-packets, the final exit is a link of type +1 and is
//! followed by PlyTrailer; each packet may be preceded by its own Extent
//! and Length calls ("subsequently invoked for each individual packet").
//!
//! Composite probing (VCP's Probe card):
//!
//! ```text
//! file  = Modals ProgramHeader { SetAngle MoveTo Probe } ProgramTrailer
//! ```
//!
//! After a call that does not fit, the machine goes on from the state that
//! call implies on its own (a GoTo means "in a packet"), so one misplaced
//! call gives one diagnostic, not one per following line.

/// Where a sequence is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum State {
    Start,
    // Laying.
    AfterModals,
    /// After an Extent: Length calls follow; `ply` says whose.
    Lengths {
        ply: bool,
    },
    /// The ply's Length calls are done.
    PlyLengths,
    Cam,
    CamDone,
    AfterPlyHeader,
    Link {
        kind: i8,
    },
    Pullout {
        kind: i8,
    },
    Traverse {
        kind: i8,
    },
    /// After a LinkTrailer of a link of this kind.
    AfterLink {
        kind: i8,
    },
    /// A packet's Extent and Lengths are done; PacketHeader follows.
    PacketReady,
    Packet,
    Restart,
    AfterPacket,
    // Probing.
    AfterProbeModals,
    Points,
    Angled,
    Moved,
    Done,
}

/// What the machine needs to know about a call.
#[derive(Clone, Copy, Debug)]
pub struct Step<'a> {
    pub routine: &'a str,
    /// `LinkType` of a LinkHeader, `TowNum` of a Length.
    pub number: f64,
}

/// A call that does not fit: what was expected instead.
#[derive(Debug, PartialEq)]
pub struct Misplaced {
    pub expected: String,
}

fn link_kind(n: f64) -> i8 {
    if n < 0.0 {
        -1
    } else if n > 0.0 {
        1
    } else {
        0
    }
}

/// The next state of material laying, or what was expected.
pub fn laying(state: State, step: Step<'_>) -> Result<State, Misplaced> {
    use State::*;
    let r = step.routine;
    let next = match (state, r) {
        (Start, "Modals") => Some(AfterModals),
        (AfterModals, "Extent") => Some(Lengths { ply: true }),
        (Lengths { ply }, "Length") if step.number != 0.0 => Some(Lengths { ply }),
        (Lengths { ply: true }, "Length") => Some(PlyLengths),
        (Lengths { ply: false }, "Length") => Some(PacketReady),
        (PlyLengths, "CamHeader") => Some(Cam),
        (Cam, "CamPoint") => Some(Cam),
        (Cam, "CamTrailer") => Some(CamDone),
        (PlyLengths | CamDone, "PlyHeader") => Some(AfterPlyHeader),
        (AfterPlyHeader, "LinkHeader") if link_kind(step.number) == -1 => Some(Link { kind: -1 }),
        (AfterPacket, "LinkHeader") if link_kind(step.number) >= 0 => Some(Link { kind: link_kind(step.number) }),
        (Link { kind }, "MoveTo" | "OffForm" | "OnForm" | "Option") => Some(Link { kind }),
        (Link { kind }, "PulloutHeader") => Some(Pullout { kind }),
        (Pullout { kind }, "MoveTo" | "OffForm" | "OnForm" | "Option") => Some(Pullout { kind }),
        (Pullout { kind }, "PulloutTrailer") => Some(Link { kind }),
        (Link { kind }, "TraverseHeader") => Some(Traverse { kind }),
        (Traverse { kind }, "TraverseTo") => Some(Traverse { kind }),
        (Traverse { kind }, "TraverseTrailer") => Some(Link { kind }),
        (Link { kind }, "LinkTrailer") => Some(AfterLink { kind }),
        (AfterLink { kind: 1 }, "PlyTrailer") => Some(Done),
        (AfterLink { kind: -1 | 0 }, "Extent") => Some(Lengths { ply: false }),
        (AfterLink { kind: -1 | 0 } | PacketReady, "PacketHeader") => Some(Packet),
        (Packet, "GoTo" | "Option") => Some(Packet),
        (Packet, "RestartHeader") => Some(Restart),
        (Restart, "RestartBuffer") => Some(Restart),
        (Restart, "RestartTrailer") => Some(Packet),
        (Packet, "PacketTrailer") => Some(AfterPacket),
        _ => None,
    };
    next.ok_or_else(|| Misplaced { expected: laying_expected(state) })
}

fn laying_expected(state: State) -> String {
    use State::*;
    match state {
        Start => "Modals (the first call)",
        AfterModals => "Extent (the ply's extent)",
        Lengths { .. } => "Length (one per tow, then one with TowNum = 0 for all tows)",
        PlyLengths => "CamHeader or PlyHeader",
        Cam => "CamPoint or CamTrailer",
        CamDone => "PlyHeader",
        AfterPlyHeader => "LinkHeader with LinkType = -1 (the initial entry)",
        Link { .. } => "MoveTo, OffForm, OnForm, an Option, PulloutHeader, TraverseHeader or LinkTrailer",
        Pullout { .. } => "MoveTo, OffForm, OnForm, an Option or PulloutTrailer",
        Traverse { .. } => "TraverseTo or TraverseTrailer",
        AfterLink { kind: 1 } => "PlyTrailer (after the final exit)",
        AfterLink { .. } => "Extent or PacketHeader (a tow-packet follows each link but the final exit)",
        PacketReady => "PacketHeader",
        Packet => "GoTo, an Option, RestartHeader or PacketTrailer",
        Restart => "RestartBuffer or RestartTrailer",
        AfterPacket => "LinkHeader with LinkType = 0 (a link) or +1 (the final exit)",
        Done => "nothing (PlyTrailer ends the file)",
        _ => "a material-laying call",
    }
    .to_string()
}

/// The state a laying call implies on its own, to go on after a misplaced one.
pub fn laying_resync(step: Step<'_>) -> State {
    use State::*;
    match step.routine {
        "Modals" => AfterModals,
        "Extent" => Lengths { ply: false },
        "Length" if step.number != 0.0 => Lengths { ply: false },
        "Length" => PacketReady,
        "CamHeader" | "CamPoint" => Cam,
        "CamTrailer" => CamDone,
        "PlyHeader" => AfterPlyHeader,
        "LinkHeader" | "MoveTo" | "OffForm" | "OnForm" | "PulloutTrailer" | "TraverseTrailer" => {
            Link { kind: if step.routine == "LinkHeader" { link_kind(step.number) } else { 0 } }
        }
        "PulloutHeader" => Pullout { kind: 0 },
        "TraverseHeader" | "TraverseTo" => Traverse { kind: 0 },
        "LinkTrailer" => AfterLink { kind: 0 },
        "PacketHeader" | "GoTo" | "Option" | "RestartTrailer" => Packet,
        "RestartHeader" | "RestartBuffer" => Restart,
        "PacketTrailer" => AfterPacket,
        _ => Done,
    }
}

/// The next state of composite probing, or what was expected.
pub fn probing(state: State, step: Step<'_>) -> Result<State, Misplaced> {
    use State::*;
    let next = match (state, step.routine) {
        (Start, "Modals") => Some(AfterProbeModals),
        (AfterProbeModals, "ProgramHeader") => Some(Points),
        (Points, "SetAngle") => Some(Angled),
        (Angled, "MoveTo") => Some(Moved),
        (Moved, "Probe") => Some(Points),
        (Points, "ProgramTrailer") => Some(Done),
        _ => None,
    };
    next.ok_or_else(|| Misplaced {
        expected: match state {
            Start => "Modals (the first call)",
            AfterProbeModals => "ProgramHeader",
            Points => "SetAngle (before each probe point) or ProgramTrailer",
            Angled => "MoveTo (the probe point)",
            Moved => "a Probe call (the probe Sub of the point)",
            Done => "nothing (ProgramTrailer ends the file)",
            _ => "a composite-probing call",
        }
        .to_string(),
    })
}

/// The state a probing call implies on its own.
pub fn probing_resync(step: Step<'_>) -> State {
    match step.routine {
        "Modals" => State::AfterProbeModals,
        "ProgramHeader" | "Probe" => State::Points,
        "SetAngle" => State::Angled,
        "MoveTo" => State::Moved,
        _ => State::Done,
    }
}

/// What a file that ends in `state` still lacks, if anything.
pub fn unfinished(state: State) -> Option<&'static str> {
    match state {
        State::Done => None,
        State::Start => Some("the file has no calls"),
        State::AfterProbeModals | State::Points | State::Angled | State::Moved => {
            Some("the file ends before ProgramTrailer")
        }
        _ => Some("the file ends before PlyTrailer"),
    }
}
