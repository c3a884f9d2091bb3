//! The serde types of composites event files: one type per routine of seed
//! 003, with one field per variable the seed lists for it, spelled as the
//! seed spells it (`FOn`, `TowsInPacket`, `X`).
//!
//! A plain field (`f64`, `String`) is required: a call without it is an
//! error. An `Option` field is one the seed sets only sometimes (`SumThick`
//! "provided the variable NeedThickness is defined", `TowWidth` of a
//! LinkHeader "if there is one", probing's `I J K` "if supplied", every
//! option parameter). Unknown fields are errors. `getNthLength1` ...
//! are the tables of the functions of the same name, one number per tow.

#![allow(non_snake_case)]

use postc_ir::CallValue;
use serde::{Deserialize, Serialize};

/// A value a field gives to the call.
pub trait PushVar {
    fn push_var(&self, name: &str, out: &mut Vec<(String, CallValue)>);
}

impl PushVar for f64 {
    fn push_var(&self, name: &str, out: &mut Vec<(String, CallValue)>) {
        out.push((name.to_string(), CallValue::Number(*self)));
    }
}

impl PushVar for String {
    fn push_var(&self, name: &str, out: &mut Vec<(String, CallValue)>) {
        out.push((name.to_string(), CallValue::Text(self.clone())));
    }
}

impl PushVar for Vec<f64> {
    fn push_var(&self, name: &str, out: &mut Vec<(String, CallValue)>) {
        out.push((name.to_string(), CallValue::List(self.clone())));
    }
}

impl<T: PushVar> PushVar for Option<T> {
    fn push_var(&self, name: &str, out: &mut Vec<(String, CallValue)>) {
        if let Some(v) = self {
            v.push_var(name, out);
        }
    }
}

/// The name of the Sub an option or probe call runs; not a variable.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct SubName(pub String);

impl PushVar for SubName {
    fn push_var(&self, _name: &str, _out: &mut Vec<(String, CallValue)>) {}
}

/// The variables of a call, in field order.
pub trait Vars {
    fn vars(&self) -> Vec<(String, CallValue)>;
}

macro_rules! routine {
    ($(#[$doc:meta])* $name:ident { $($field:ident: $ty:ty),* $(,)? }) => {
        $(#[$doc])*
        #[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
        #[serde(deny_unknown_fields)]
        pub struct $name { $(pub $field: $ty,)* }

        impl Vars for $name {
            fn vars(&self) -> Vec<(String, CallValue)> {
                let mut out = Vec::new();
                $( self.$field.push_var(stringify!($field), &mut out); )*
                out
            }
        }
    };
}

routine! {
    /// Modals (material laying): once, at the start.
    Modals {
        AccDecDist: f64, AddAdjustMax: f64, AddAdjustMin: f64, AngleSpacing: f64, AngleTol: f64,
        Compression: f64, CourseSpread: f64, CutAdjustMax: f64, CutAdjustMin: f64, Directions: f64,
        EgressLength: f64, FileName: String, FOff: f64, FOn: f64, Header: String, HeadReverse: f64,
        IngressLength: f64, LandOnShelf: f64, LeadInLen: f64, LimitedEntry: f64, MandrelRPM: f64,
        MatDense: f64, MatThick: f64, MaxGrader: f64, MaxTraverse: f64, MinGapLen: f64, MinGrader: f64,
        MinSteering: f64, MinTowLen: f64, Natural: f64, NominalPress: f64, Numbering: f64,
        OffSpacing: f64, OnSpacing: f64, Part: String, PlyAngle: f64, PlyIdent: String, PlyNumber: f64,
        Post: String, Product: String, RetractDist: f64, RollerAction: f64, RollerClear: f64,
        RollOffset: f64, Rotisserie: f64, RunOutLen: f64, ScrewHand: f64, SeqIdent: String,
        SeqNumber: f64, ShelfAngle: f64, ShelfInset: f64, SpinAxis: f64, SpiralAngle: f64,
        SpliceLen: f64, SpliceSpace: f64, Stamp: String, StartX: f64, StartY: f64, StartZ: f64,
        Thumb: String, TowCount: f64, TowEdgeLap: f64, TowReduction: f64, TowTowLap: f64,
        TowWidth: f64, TraverseSpeed: f64, UnitPerMm: f64, User: String, Version: String,
        VirtualAxis: f64,
    }
}

routine! {
    /// Extent: the ply's extent once after Modals, then each packet's.
    Extent {
        AMax: f64, AMin: f64, RMax: f64, Rotation: f64, TowWidth: f64,
        XMax: f64, XMin: f64, YMax: f64, YMin: f64, ZMax: f64, ZMin: f64,
    }
}

routine! {
    /// Length: one per tow number, then one for all tows (`TowNum` 0).
    Length { TowArea: f64, TowLen: f64, TowNum: f64 }
}

routine! {
    /// CamPoint: a point of the virtual spin axis.
    CamPoint { RMax: f64, X: f64, Y: f64, Z: f64 }
}

routine! {
    /// LinkHeader: the initial entry (-1), a link (0) or the final exit (+1).
    LinkHeader { LinkType: f64, Rotation: f64, TowWidth: Option<f64> }
}

routine! {
    /// MoveTo (material laying): a point of a link's head path.
    LinkPoint {
        DTwist: f64, DX: f64, DY: f64, DZ: f64, ETwist: f64, EX: f64, EY: f64, EZ: f64,
        I: f64, J: f64, K: f64, ToLeadIn: f64, VirtDX: f64, VirtDY: f64, VirtDZ: f64,
        X: f64, Y: f64, Z: f64,
    }
}

routine! {
    /// TraverseTo: a point of a link's off-part traverse.
    TraversePoint {
        DTwist: f64, DX: f64, DY: f64, DZ: f64, ETwist: f64, EX: f64, EY: f64, EZ: f64,
        I: f64, J: f64, K: f64, VirtDX: f64, VirtDY: f64, VirtDZ: f64, X: f64, Y: f64, Z: f64,
    }
}

routine! {
    /// RestartBuffer: the safe restart's add point, or an original add or cut point after it.
    RestartPoint {
        AddCutA: String, AddCutB: String, AddCutI: f64, AddCutJ: f64, DX: f64, DY: f64, DZ: f64,
        I: f64, J: f64, K: f64, LParam: f64, SumThick: Option<f64>, VirtDX: f64, VirtDY: f64,
        VirtDZ: f64, X: f64, Y: f64, Z: f64, getNthAddCut: Option<Vec<f64>>,
    }
}

routine! {
    /// GoTo: a point of a tow-packet's head path.
    PacketPoint {
        AddCutA: String, AddCutB: String, AddCutI: f64, AddCutJ: f64, Cached: f64, DTwist: f64,
        DX: f64, DY: f64, DZ: f64, I: f64, J: f64, K: f64, LParam: f64, SumThick: Option<f64>,
        ToLastCut: f64, ToNextAdd: f64, ToNextCut: f64, ToRunOut: f64, TowsInPacket: f64,
        VirtDX: f64, VirtDY: f64, VirtDZ: f64, X: f64, Y: f64, Z: f64,
        getNthLength1: Option<Vec<f64>>, getNthLength2: Option<Vec<f64>>, getNthLength3: Option<Vec<f64>>,
    }
}

routine! {
    /// An option on a link or tow-packet: `name` is its Sub; only the
    /// parameters given are set.
    OptionCall {
        name: SubName, OptNumber1: Option<f64>, OptNumber2: Option<f64>, OptNumber3: Option<f64>,
        OptNumber4: Option<f64>, OptString1: Option<String>, OptString2: Option<String>,
        OptSwitch1: Option<f64>, OptSwitch2: Option<f64>,
    }
}

routine! {
    /// Modals (composite probing).
    ProbeModals {
        FileName: String, Header: String, Part: String, Post: String, Product: String,
        Stamp: String, UnitPerMm: f64, User: String, Version: String,
    }
}

routine! {
    /// SetAngle: before positioning to each probe point.
    SetAngle { Rotisserie: f64 }
}

routine! {
    /// MoveTo (composite probing): a probe point.
    ProbePoint { I: Option<f64>, J: Option<f64>, K: Option<f64>, X: f64, Y: f64, Z: f64 }
}

routine! {
    /// A probe Sub after each probe point: `name` is the Sub.
    ProbeCall { name: SubName, OptNumber1: Option<f64> }
}

/// One line of a material-laying event file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum LayingCall {
    Modals(Box<Modals>),
    Extent(Extent),
    Length(Length),
    CamHeader,
    CamPoint(CamPoint),
    CamTrailer,
    PlyHeader,
    LinkHeader(LinkHeader),
    PulloutHeader,
    PulloutTrailer,
    MoveTo(Box<LinkPoint>),
    OffForm,
    OnForm,
    TraverseHeader,
    TraverseTo(Box<TraversePoint>),
    TraverseTrailer,
    LinkTrailer,
    PacketHeader,
    RestartHeader,
    RestartBuffer(Box<RestartPoint>),
    RestartTrailer,
    GoTo(Box<PacketPoint>),
    Option(Box<OptionCall>),
    PacketTrailer,
    PlyTrailer,
}

/// One line of a composite-probing event file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum ProbingCall {
    Modals(Box<ProbeModals>),
    ProgramHeader,
    SetAngle(SetAngle),
    MoveTo(ProbePoint),
    Probe(ProbeCall),
    ProgramTrailer,
}

/// The two sequences of Vericut's post-processor notes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Application {
    /// Material laying (VCP's Roller Post card).
    Laying,
    /// Composite probing (VCP's Probe card).
    Probing,
}

/// The first line of every event file: which sequence it follows, and the
/// #Primer Subs requested on VCP's Post card (run first, before those of
/// `--primer`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VcpFile {
    pub kind: Application,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub primers: Vec<String>,
}

/// The header line as read.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum HeaderLine {
    VcpFile(VcpFile),
}

/// A call of either application: its routine name (or the Sub an option or
/// probe names) and its variables.
pub trait Call {
    /// The routine, as the seed names it.
    fn routine(&self) -> &'static str;
    /// The Sub to call: the routine, or the named option/probe Sub.
    fn sub(&self) -> &str;
    fn vars(&self) -> Vec<(String, CallValue)>;
}

macro_rules! calls {
    ($ty:ident { units: [$($unit:ident),*], data: [$($data:ident),*], named: [$($named:ident),*] }) => {
        impl Call for $ty {
            fn routine(&self) -> &'static str {
                match self {
                    $($ty::$unit => stringify!($unit),)*
                    $($ty::$data(_) => stringify!($data),)*
                    $($ty::$named(_) => stringify!($named),)*
                }
            }

            fn sub(&self) -> &str {
                match self {
                    $($ty::$named(c) => &c.name.0,)*
                    other => other.routine(),
                }
            }

            fn vars(&self) -> Vec<(String, CallValue)> {
                match self {
                    $($ty::$unit => Vec::new(),)*
                    $($ty::$data(c) => c.vars(),)*
                    $($ty::$named(c) => c.vars(),)*
                }
            }
        }
    };
}

calls!(LayingCall {
    units: [
        CamHeader,
        CamTrailer,
        PlyHeader,
        PulloutHeader,
        PulloutTrailer,
        OffForm,
        OnForm,
        TraverseHeader,
        TraverseTrailer,
        LinkTrailer,
        PacketHeader,
        RestartHeader,
        RestartTrailer,
        PacketTrailer,
        PlyTrailer
    ],
    data: [Modals, Extent, Length, CamPoint, LinkHeader, MoveTo, TraverseTo, RestartBuffer, GoTo],
    named: [Option]
});

calls!(ProbingCall { units: [ProgramHeader, ProgramTrailer], data: [Modals, SetAngle, MoveTo], named: [Probe] });
