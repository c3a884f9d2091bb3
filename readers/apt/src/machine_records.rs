//! Records that set machine state rather than move the tool: FEDRAT,
//! SPINDL, COOLNT, CUTCOM, DELAY/DWELL, the tool records (LOADTL,
//! LOAD/TOOL, CUTTER, TLDATA) and UNITS. Each is read into plain data here;
//! the reader decides which events they become.

use postc_ir::event::{CompSide, Coolant, CoolantAt, CoolantChange, CutterComp, Dwell, FeedUnit, Spindle};
use postc_ir::units::Units;

use crate::words::{Arg, Problem, Rec};

/// A feed rate as written: value, per minute or per revolution, and the
/// unit when the record names one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct FeedSpec {
    pub value: f64,
    pub per_rev: bool,
    pub units: Option<Units>,
    /// The unit word as written, if any.
    pub unit: Option<FeedUnit>,
}

impl FeedSpec {
    /// The feed unit a word names (`MMPM`, `IPM`, `MMPR`, `IPR`), value 0.
    pub fn unit_word(word: &[u8]) -> Option<FeedSpec> {
        let is = |name: &str| word.eq_ignore_ascii_case(name.as_bytes());
        let unit = if is("MMPM") {
            FeedUnit::Mmpm
        } else if is("IPM") {
            FeedUnit::Ipm
        } else if is("MMPR") {
            FeedUnit::Mmpr
        } else if is("IPR") {
            FeedUnit::Ipr
        } else if is("PERMIN") || is("UPM") {
            FeedUnit::PerMinute
        } else if is("PERREV") || is("UPR") {
            FeedUnit::PerRev
        } else {
            return None;
        };
        Some(FeedSpec { value: 0.0, per_rev: unit.per_rev(), units: unit.units(), unit: Some(unit) })
    }

    /// The feed in `job` units per minute, given the spindle speed for feeds
    /// per revolution (`None` when unknown: the value passes unchanged).
    pub fn per_minute(&self, job: Units, rpm: Option<f64>) -> f64 {
        let factor = self.units.map_or(1.0, |u| u.factor_to(job));
        let per_rev = if self.per_rev { rpm.unwrap_or(1.0) } else { 1.0 };
        self.value * factor * per_rev
    }
}

/// `FEDRAT/f[,unit]` or `FEDRAT/unit,f`.
pub(crate) fn parse_fedrat(rec: &Rec<'_>, ignored: &mut dyn FnMut(usize)) -> Result<FeedSpec, Problem> {
    let mut feed = FeedSpec { value: f64::NAN, per_rev: false, units: None, unit: None };
    for (i, arg) in rec.args().enumerate() {
        match arg {
            Arg::Num(v) if feed.value.is_nan() => feed.value = v,
            Arg::Word(w) => match FeedSpec::unit_word(w) {
                Some(unit) => {
                    feed.per_rev = unit.per_rev;
                    feed.units = unit.units;
                    feed.unit = unit.unit;
                }
                None => ignored(i),
            },
            _ => ignored(i),
        }
    }
    if feed.value.is_nan() {
        return Err(Problem::new("FEDRAT needs a feed rate: FEDRAT/500,MMPM", None));
    }
    if feed.value < 0.0 {
        return Err(Problem::new("a feed rate cannot be negative", rec.args().position(|a| a.num().is_some())));
    }
    Ok(feed)
}

/// What a SPINDL record does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum SpindleRecord {
    On(Spindle),
    /// `SPINDL/ON`: restart with the last speed and direction.
    Restart,
    Off,
}

/// `SPINDL/ON|OFF`, `SPINDL/s[,RPM|SFM|SMM][,CLW|CCLW][,MAXRPM,n]`, `SPINDL/RPM,s,CLW`.
pub(crate) fn parse_spindl(rec: &Rec<'_>, ignored: &mut dyn FnMut(usize)) -> Result<SpindleRecord, Problem> {
    let mut spindle = Spindle::default();
    let mut skip_next = false;
    let mut max_next = false;
    let mut on = false;
    for (i, arg) in rec.args().enumerate() {
        if skip_next {
            skip_next = false;
            continue;
        }
        match arg {
            Arg::Num(v) if max_next => {
                spindle.max_rpm = Some(v);
                max_next = false;
            }
            Arg::Num(v) if spindle.speed.is_none() => spindle.speed = Some(v),
            Arg::Word(w) => {
                let is = |name: &str| w.eq_ignore_ascii_case(name.as_bytes());
                if is("OFF") {
                    return Ok(SpindleRecord::Off);
                } else if is("ON") {
                    on = true;
                } else if is("CLW") || is("CW") {
                    spindle.ccw = false;
                } else if is("CCLW") || is("CCW") {
                    spindle.ccw = true;
                } else if is("SFM") || is("SMM") {
                    spindle.css = true;
                } else if is("MAXRPM") {
                    max_next = true;
                } else if is("RANGE") {
                    skip_next = true;
                } else if !(is("RPM") || is("LOW") || is("MEDIUM") || is("HIGH") || is("NOW") || is("NEXT")) {
                    ignored(i);
                }
            }
            _ => ignored(i),
        }
    }
    match spindle.speed {
        Some(s) if s < 0.0 => Err(Problem::new("a spindle speed cannot be negative", None)),
        Some(_) => Ok(SpindleRecord::On(spindle)),
        None if on => Ok(SpindleRecord::Restart),
        None => Err(Problem::new("SPINDL needs a speed, ON or OFF: SPINDL/12000,RPM,CLW", None)),
    }
}

/// `COOLNT/ON|FLOOD|MIST|THRU|AIR|OFF[,NOW|NEXT]`: the coolant, and its
/// placement as written (`NOW` wins when both are given).
pub(crate) fn parse_coolnt(rec: &Rec<'_>, ignored: &mut dyn FnMut(usize)) -> Result<CoolantChange, Problem> {
    let mut coolant = None;
    let mut at = None;
    for (i, arg) in rec.args().enumerate() {
        let Some(w) = arg.word() else {
            ignored(i);
            continue;
        };
        let is = |name: &str| w.eq_ignore_ascii_case(name.as_bytes());
        let c = if is("ON") || is("FLOOD") {
            Coolant::Flood
        } else if is("MIST") {
            Coolant::Mist
        } else if is("THRU") || is("THRUST") || is("THROUGH") || is("TAPKUL") {
            Coolant::Through
        } else if is("AIR") {
            Coolant::Air
        } else if is("OFF") {
            Coolant::Off
        } else {
            if is("NOW") {
                at = Some(CoolantAt::Now);
            } else if is("NEXT") {
                at = at.or(Some(CoolantAt::Next));
            } else {
                ignored(i);
            }
            continue;
        };
        coolant.get_or_insert(c);
    }
    coolant
        .map(|coolant| CoolantChange { coolant, at })
        .ok_or_else(|| Problem::new("COOLNT needs ON, FLOOD, MIST, THRU, AIR or OFF", None))
}

/// `CUTCOM/LEFT|RIGHT[,n][,XYPLAN]`, `CUTCOM/OFF`; `CUTCOM/ON` alone gives
/// `None` (the side follows in the next CUTCOM).
pub(crate) fn parse_cutcom(rec: &Rec<'_>, ignored: &mut dyn FnMut(usize)) -> Result<Option<CutterComp>, Problem> {
    let mut comp: Option<CutterComp> = None;
    let mut register = None;
    let mut on = false;
    for (i, arg) in rec.args().enumerate() {
        match arg {
            Arg::Num(v) => register = Some(v),
            Arg::Word(w) => {
                let is = |name: &str| w.eq_ignore_ascii_case(name.as_bytes());
                let side = if is("LEFT") {
                    CompSide::Left
                } else if is("RIGHT") {
                    CompSide::Right
                } else if is("OFF") {
                    CompSide::Off
                } else {
                    if is("ON") {
                        on = true;
                    } else if !(is("XYPLAN") || is("YZPLAN") || is("ZXPLAN") || is("NOW") || is("NEXT") || is("ADJUST"))
                    {
                        ignored(i);
                    }
                    continue;
                };
                comp.get_or_insert(CutterComp { side, register: None });
            }
            _ => ignored(i),
        }
    }
    match (comp, register) {
        (Some(mut c), Some(r)) => {
            c.register = Some(
                register_number(r)
                    .ok_or_else(|| Problem::new("a compensation register is a whole number from 0", None))?,
            );
            Ok(Some(c))
        }
        (Some(c), None) => Ok(Some(c)),
        (None, _) if on => Ok(None),
        (None, _) => Err(Problem::new("CUTCOM needs LEFT, RIGHT or OFF", None)),
    }
}

/// A register or tool number: a whole number from 0.
pub(crate) fn register_number(v: f64) -> Option<u32> {
    (v >= 0.0 && v <= f64::from(u32::MAX) && v.fract() == 0.0).then_some(v as u32)
}

/// `DELAY/s`, `DELAY/REV,n` (and DWELL).
pub(crate) fn parse_delay(rec: &Rec<'_>, ignored: &mut dyn FnMut(usize)) -> Result<Dwell, Problem> {
    let mut dwell = Dwell { seconds: f64::NAN, revolutions: false };
    for (i, arg) in rec.args().enumerate() {
        match arg {
            Arg::Num(v) if dwell.seconds.is_nan() => dwell.seconds = v,
            Arg::Word(w) if w.eq_ignore_ascii_case(b"REV") => dwell.revolutions = true,
            Arg::Word(w) if w.eq_ignore_ascii_case(b"SEC") => {}
            _ => ignored(i),
        }
    }
    if dwell.seconds.is_nan() || dwell.seconds < 0.0 {
        return Err(Problem::new("DELAY needs a time in seconds (DELAY/2) or revolutions (DELAY/REV,5)", None));
    }
    Ok(dwell)
}

/// A tool load: number and offset registers.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct ToolLoad {
    pub number: u32,
    pub length_offset: Option<u32>,
    pub diameter_offset: Option<u32>,
}

/// `LOADTL/t[,h[,d]]`, `LOADTL/t,ADJUST,h`, `LOAD/TOOL,t[,ADJUST,h]`.
pub(crate) fn parse_tool_load(rec: &Rec<'_>, skip: usize, ignored: &mut dyn FnMut(usize)) -> Result<ToolLoad, Problem> {
    let mut numbers = [None; 3];
    let mut n = 0;
    let mut adjust = None;
    let mut i = skip;
    while let Some(arg) = rec.arg(i) {
        match arg {
            Arg::Num(v) => {
                if n < 3 {
                    numbers[n] = Some(v);
                }
                n += 1;
            }
            Arg::Word(w) if w.eq_ignore_ascii_case(b"ADJUST") || w.eq_ignore_ascii_case(b"LENGTH") => {
                adjust = rec.arg(i + 1).and_then(|a| a.num());
                i += 1;
            }
            _ => ignored(i),
        }
        i += 1;
    }
    let bad = |what: &str| Problem::new(format!("the {what} must be a whole number from 0"), None);
    let number = numbers[0]
        .ok_or_else(|| Problem::new("a tool load needs the tool number: LOADTL/3", None))
        .and_then(|v| register_number(v).ok_or_else(|| bad("tool number")))?;
    let length =
        adjust.or(numbers[1]).map(|v| register_number(v).ok_or_else(|| bad("length offset register"))).transpose()?;
    let diameter = numbers[2].map(|v| register_number(v).ok_or_else(|| bad("diameter offset register"))).transpose()?;
    Ok(ToolLoad { number, length_offset: length, diameter_offset: diameter })
}

/// The cutter diameter of `CUTTER/d,...`, `TLDATA/MILL,d,...` or
/// `TLDATA/DRILL,MILL,d,...`: the first number. `None` when there is none
/// (`CUTTER/OFF`, lathe tools).
pub(crate) fn cutter_diameter(rec: &Rec<'_>) -> Option<f64> {
    rec.args().find_map(|a| a.num()).filter(|d| *d >= 0.0)
}

/// `UNITS/MM|INCHES|...`.
pub(crate) fn parse_units(rec: &Rec<'_>) -> Result<Units, Problem> {
    let word = rec.arg(0).and_then(|a| a.word()).unwrap_or_default();
    let is = |name: &str| word.eq_ignore_ascii_case(name.as_bytes());
    if is("MM") || is("MILLIMETERS") || is("MILLIMETRES") || is("METRIC") {
        Ok(Units::Mm)
    } else if is("INCHES") || is("INCH") || is("IN") || is("ENGLISH") {
        Ok(Units::Inch)
    } else {
        Err(Problem::new("UNITS needs MM or INCHES", Some(0)))
    }
}
