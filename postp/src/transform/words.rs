//! The postp words that reach the transform as `Command`s: each is checked
//! and either handled here (TRANS, CLEARP, CLRSRF, LETTER, ROTABL/LINEAR,
//! RETRCT) or given to the post with fixed, normalized arguments.

use postc_ir::Diagnostic;
use postc_ir::EventSource;
use postc_ir::event::{Arg, Command};

use super::{Kind, Transform, codes, word};
use crate::letter::Letter;

fn num(a: Option<&Arg>) -> Option<f64> {
    match a {
        Some(Arg::Number(n)) => Some(*n),
        _ => None,
    }
}

fn is(a: Option<&Arg>, w: &str) -> bool {
    matches!(a, Some(Arg::Word(x)) if x.eq_ignore_ascii_case(w))
}

fn numbers(args: &[Arg]) -> Vec<f64> {
    args.iter().filter_map(|a| num(Some(a))).collect()
}

/// The NOW or NEXT among the arguments, or `default`; `Err` on another word.
fn placement(args: &[Arg], default: &'static str) -> Result<&'static str, String> {
    let mut place = default;
    for a in args {
        match a {
            Arg::Word(w) if w.eq_ignore_ascii_case("NOW") => place = "NOW",
            Arg::Word(w) if w.eq_ignore_ascii_case("NEXT") => place = "NEXT",
            Arg::Word(w) | Arg::Text(w) => return Err(format!("`{w}` is not NOW or NEXT")),
            Arg::Number(_) => {}
        }
    }
    Ok(place)
}

/// A plane as coefficients a, b, c, d (ax + by + cz = d), from the forms
/// `(PLANE/a,b,c,d)`, `a,b,c,d`, `XYPLAN,d`, `YZPLAN,d`, `ZXPLAN,d`.
fn plane(args: &[Arg]) -> Result<[f64; 4], String> {
    let n = numbers(args);
    let first = args.first();
    let axis = |v: [f64; 3]| match n.as_slice() {
        [d] => Ok([v[0], v[1], v[2], *d]),
        _ => Err("give one distance: XYPLAN,d".to_string()),
    };
    if is(first, "XYPLAN") {
        axis([0.0, 0.0, 1.0])
    } else if is(first, "YZPLAN") {
        axis([1.0, 0.0, 0.0])
    } else if is(first, "ZXPLAN") {
        axis([0.0, 1.0, 0.0])
    } else if let (Some(Arg::Word(w)), true) = (first, args.len() == 1) {
        Err(format!(
            "`{w}` names a plane defined in the part program; CL data does not carry it, so give the plane itself (XYPLAN,d or a,b,c,d)"
        ))
    } else if let ([a, b, c, d], true) =
        (n.as_slice(), first.is_none_or(|f| is(Some(f), "PLANE") || num(Some(f)).is_some()))
    {
        let len = (a * a + b * b + c * c).sqrt();
        if len > 1e-12 {
            Ok([a / len, b / len, c / len, d / len])
        } else {
            Err("the plane's normal a,b,c is zero".into())
        }
    } else {
        Err("a plane is (PLANE/a,b,c,d), a,b,c,d, XYPLAN,d, YZPLAN,d or ZXPLAN,d".into())
    }
}

impl<S: EventSource> Transform<S> {
    fn bad(&self, diags: &mut Vec<Diagnostic>, word: &str, problem: String) {
        self.error(diags, codes::BAD_ARGS, format!("{word}: {problem}"), "these arguments");
    }

    /// A word with one number and an optional NOW or NEXT.
    fn number_word(&mut self, c: &Command, out: &str, default: &'static str, diags: &mut Vec<Diagnostic>) {
        let n = numbers(&c.args);
        match (n.as_slice(), placement(&c.args, default)) {
            ([v], Ok(place)) if *v >= 0.0 => self.command(out, vec![Arg::Number(*v), word(place)]),
            (_, Err(e)) => self.bad(diags, &c.word, e),
            _ => self.bad(diags, &c.word, format!("give one number from 0 and NOW or NEXT: {}/8,NEXT", c.word)),
        }
    }

    /// Handles a postp word.
    pub(super) fn word(&mut self, c: Command, diags: &mut Vec<Diagnostic>) {
        let w = c.word.to_ascii_uppercase();
        let a = &c.args;
        match w.as_str() {
            "PARTNO" => self.push(postc_ir::Event::Command(c)),
            "MACHIN" => {
                if !is(a.first(), self.machine.name) {
                    diags.push(
                        Diagnostic::warning(
                            codes::MACHIN_NOT_FIRST,
                            "a second MACHIN is ignored; the first one chose the controller",
                        )
                        .at(self.span, "ignored"),
                    );
                }
            }
            "AUXFUN" => self.number_word(&c, "AUXFUN", "NOW", diags),
            "PREFUN" => self.number_word(&c, "PREFUN", "NOW", diags),
            "SELCTL" | "TOOLNO" => self.number_word(&c, "TOOLNO", "NOW", diags),
            "END" | "REWIND" | "RESET" | "OPSTOP" | "STOP" => {
                // The startup string puts the machine back in absolute mode.
                if w == "RESET" {
                    self.incremental = false;
                }
                self.command(&w, Vec::new());
            }
            "GOHOME" => {
                self.command("GOHOME", Vec::new());
                self.pos = None;
            }
            "DELETE" | "OPSKIP" => match a.as_slice() {
                [Arg::Word(s)] if s.eq_ignore_ascii_case("ON") || s.eq_ignore_ascii_case("OFF") => {
                    self.command("DELETE", vec![word(&s.to_ascii_uppercase())])
                }
                _ => self.bad(diags, &w, format!("give ON or OFF: {w}/ON")),
            },
            "TMARK" => match numbers(a).as_slice() {
                [] if a.is_empty() => self.command("TMARK", vec![Arg::Number(0.0)]),
                [n] if (1.0..=255.0).contains(n) && n.fract() == 0.0 => self.command("TMARK", vec![Arg::Number(*n)]),
                _ => self.bad(diags, &w, "give a character code from 1 to 255: TMARK/37".into()),
            },
            "MODE" => match (numbers(a).as_slice(), placement(a, "NOW")) {
                ([n], Ok(place)) if *n == 90.0 || *n == 91.0 => {
                    self.incremental = *n == 91.0;
                    self.command("MODE", vec![Arg::Number(*n), word(place)]);
                }
                (_, Err(e)) => self.bad(diags, &w, e),
                _ => self.bad(diags, &w, "give 90 (absolute) or 91 (incremental): MODE/91".into()),
            },
            "ORIGIN" => match (numbers(a).as_slice(), placement(a, "XY")) {
                ([n], Ok(place)) if (54.0..60.0).contains(n) && (*n < 55.0 || n.fract() == 0.0) => {
                    self.command("ORIGIN", vec![Arg::Number(*n), word(place)]);
                }
                (_, Err(e)) => self.bad(diags, &w, e),
                _ => self.bad(diags, &w, "give 54 to 59, or 54.1 to 54.99 for an extended offset: ORIGIN/55".into()),
            },
            "SEQNO" => self.seqno(&c, diags),
            "SPINDL" | "COOLNT" | "CUTCOM" | "DELAY" | "DWELL" | "LOADTL" => {}
            "THREAD" => {
                if self.needs(Kind::Lathe, "THREAD", diags) {
                    match numbers(a).as_slice() {
                        n @ [_, _, _, _, _, _, _, _, _, _] if n[0] > 0.0 => {
                            self.command("THREAD", n.iter().map(|v| Arg::Number(*v)).collect())
                        }
                        _ => self.bad(
                            diags,
                            &w,
                            "give pitch,fd,z,dfc,mdc,dlp,pocd,taper,ia,sp (10 numbers, pitch > 0)".into(),
                        ),
                    }
                }
            }
            "TURRET" => {
                if self.needs(Kind::Lathe, "TURRET", diags) {
                    match numbers(a).as_slice() {
                        [t] if *t >= 0.0 => self.command("TURRET", vec![Arg::Number(*t), Arg::Number(*t)]),
                        [t, o] if *t >= 0.0 && *o >= 0.0 => {
                            self.command("TURRET", vec![Arg::Number(*t), Arg::Number(*o)])
                        }
                        _ => self.bad(diags, &w, "give the position and optionally the offset: TURRET/3,13".into()),
                    }
                }
            }
            "TRANS" => match numbers(a).as_slice() {
                n @ ([_] | [_, _] | [_, _, _]) if n.len() == a.len() => {
                    self.trans = [0.0; 3];
                    self.trans[..n.len()].copy_from_slice(n);
                }
                _ => self.bad(diags, &w, "give dx,dy,dz: TRANS/1,0,0".into()),
            },
            "CLEARP" => {
                if is(a.first(), "OFF") && a.len() == 1 {
                    self.clearp = None;
                } else if is(a.first(), "YZPLAN") || is(a.first(), "ZXPLAN") {
                    self.error(
                        diags,
                        codes::BAD_PLANE,
                        "CLEARP must be parallel to the XY plane (XYPLAN)".into(),
                        "not valid here",
                    );
                } else {
                    match plane(a) {
                        Ok([x, y, z, d]) if x.abs() < 1e-9 && y.abs() < 1e-9 => self.clearp = Some(d / z),
                        Ok(_) => self.error(
                            diags,
                            codes::BAD_PLANE,
                            "CLEARP must be parallel to the XY plane".into(),
                            "a tilted plane",
                        ),
                        Err(e) => self.error(diags, codes::BAD_PLANE, format!("CLEARP: {e}"), "this plane"),
                    }
                }
            }
            "CLRSRF" => {
                if is(a.first(), "NOW") && a.len() == 1 {
                    self.clear_surface(diags);
                } else {
                    match plane(a) {
                        Ok([x, y, z, d]) => self.clrsrf = Some(([x, y, z], d)),
                        Err(e) => self.error(diags, codes::BAD_PLANE, format!("CLRSRF: {e}"), "this plane"),
                    }
                }
            }
            "RETRCT" => {
                if self.needs(Kind::Mill, "RETRCT", diags) {
                    self.retract(diags);
                }
            }
            "LETTER" => {
                if self.needs(Kind::Mill, "LETTER", diags) {
                    match Letter::from_numbers(&numbers(a)) {
                        Some(l) if a.len() == 11 && l.sx > 0.0 && l.sy > 0.0 => self.letter = Some((l, self.span)),
                        _ => {
                            self.bad(diags, &w, "give x,y,z,dx,r,sx,sy,zc,zr,f,zf (11 numbers, scales above 0)".into())
                        }
                    }
                }
            }
            "ROTABL" => {
                if self.needs(Kind::Mill, "ROTABL", diags) {
                    self.rotabl(&c, diags);
                }
            }
            "FROM" => match numbers(a).as_slice() {
                [x, y, z, ..] => {
                    self.pos = Some([*x, *y, *z]);
                    let q = [x + self.trans[0], y + self.trans[1], z + self.trans[2]];
                    self.command("FROM", q.iter().map(|v| Arg::Number(*v)).collect());
                }
                _ => self.bad(diags, &w, "give x,y,z".into()),
            },
            _ => self.warn_once(
                diags,
                &w,
                Diagnostic::warning(codes::IGNORED, format!("postp does not use {w}; those records are ignored")),
            ),
        }
    }

    fn seqno(&mut self, c: &Command, diags: &mut Vec<Diagnostic>) {
        let a = &c.args;
        if is(a.first(), "OFF") && a.len() == 1 {
            self.command("SEQNO", vec![Arg::Number(-1.0), Arg::Number(0.0), Arg::Number(0.0)]);
            return;
        }
        let start = num(a.first());
        let incr = if is(a.get(1), "INCR") { num(a.get(2)) } else { None };
        let program = num(a.get(3));
        match (start, incr, a.len()) {
            (Some(s), Some(i), 3 | 4) if s >= 0.0 && i > 0.0 && (a.len() == 3 || program.is_some_and(|p| p >= 0.0)) => {
                self.command("SEQNO", vec![Arg::Number(s), Arg::Number(i), Arg::Number(program.unwrap_or(0.0))])
            }
            _ => self.bad(
                diags,
                "SEQNO",
                "give start,INCR,increment[,program]: SEQNO/10,INCR,10,1001 (or SEQNO/OFF)".into(),
            ),
        }
    }

    fn rotabl(&mut self, c: &Command, diags: &mut Vec<Diagnostic>) {
        let a = &c.args;
        if is(a.first(), "LINEAR") {
            let radius = if is(a.get(2), "RADIUS") { num(a.get(3)) } else { None };
            let axis = if is(a.get(1), "AAXIS") {
                Some(0)
            } else if is(a.get(1), "BAXIS") {
                Some(1)
            } else if is(a.get(1), "NOMORE") && a.len() == 2 {
                self.mapping = None;
                return;
            } else {
                None
            };
            match axis {
                Some(i) if a.len() == 2 || (a.len() == 4 && radius.is_some()) => {
                    if self.has_axis(if i == 0 { 'A' } else { 'B' }, diags) {
                        self.start_mapping(i, radius, diags);
                    }
                }
                _ => self.bad(diags, "ROTABL", "give ROTABL/LINEAR,AAXIS|BAXIS|NOMORE[,RADIUS,r]".into()),
            }
            return;
        }
        let axis = ["AAXIS", "BAXIS", "CAXIS"].iter().position(|x| is(a.first(), x));
        let incr = is(a.get(1), "INCR");
        let angle = num(a.get(2));
        let mut dir = None;
        let mut place = "NOW";
        let mut ok = axis.is_some() && (incr || is(a.get(1), "ATANGL")) && angle.is_some();
        for x in a.iter().skip(3) {
            match x {
                Arg::Word(w) if w.eq_ignore_ascii_case("CLW") => dir = Some(1.0),
                Arg::Word(w) if w.eq_ignore_ascii_case("CCLW") => dir = Some(-1.0),
                Arg::Word(w) if w.eq_ignore_ascii_case("NOW") => place = "NOW",
                Arg::Word(w) if w.eq_ignore_ascii_case("NEXT") => place = "NEXT",
                _ => ok = false,
            }
        }
        let (Some(i), Some(v), true) = (axis, angle, ok) else {
            self.bad(diags, "ROTABL", "give ROTABL/AAXIS|BAXIS|CAXIS,ATANGL|INCR,a[,CLW|CCLW][,NEXT|NOW]".into());
            return;
        };
        let letter = ['A', 'B', 'C'][i];
        if !self.has_axis(letter, diags) {
            return;
        }
        // Positive is clockwise; CLW or CCLW overrides the sign.
        let v = dir.map_or(v, |d| d * v.abs());
        let target = if incr { self.angles[i] + v } else { v };
        self.angles[i] = target;
        if self.mapping.is_some_and(|m| m.axis == i) {
            self.mapping = None;
        }
        self.command("ROTABL", vec![word(&letter.to_string()), Arg::Number(target), word(place)]);
    }

    /// Whether MACHIN's axis type gives the machine this rotary axis.
    fn has_axis(&self, letter: char, diags: &mut Vec<Diagnostic>) -> bool {
        if self.machine.axes.contains(&letter) {
            return true;
        }
        self.error(
            diags,
            codes::NO_SUCH_AXIS,
            format!("MACHIN/{} declares no {letter} axis", self.machine.name),
            "this rotary axis",
        );
        false
    }
}
