//! Record dispatch: which events each statement and text record becomes,
//! for the records that are not moves (those are in `motion.rs`) and that
//! need no more than a parse and a state change.

use postc_ir::diagnostic::{Diagnostic, Span};
use postc_ir::event::{Command, Event, FeedRate, Text};

use crate::circle::unit;
use crate::cycle::{CycleRecord, parse_cycle};
use crate::diagnostics as diag;
use crate::lexer::TextWord;
use crate::machine_records::{self, SpindleRecord};
use crate::state::{ActiveCycle, Core, Flow, text_event};
use crate::words::{Arg, Major, Problem, Rec};

impl Core {
    /// Handles one parsed statement record.
    pub fn dispatch(&mut self, major: Major, rec: &Rec<'_>, diags: &mut Vec<Diagnostic>) -> Flow {
        let span = rec.span();
        let word = || rec.word();
        let result: Result<(), Problem> = match major {
            Major::Goto => return self.goto(rec, diags),
            Major::Circle => self.circle_record(rec, diags),
            Major::Rapid => {
                self.rapid = true;
                Ok(())
            }
            Major::From => self.from(rec),
            Major::Godlta => self.godlta(rec, diags),
            Major::Gohome => self.gohome(rec, diags),
            Major::DriveMotion => return self.drive_motion(rec, diags),
            Major::SourceMotion if matches!(rec.arg(0), Some(Arg::Open(_))) => return self.drive_motion(rec, diags),
            Major::SourceMotion => {
                return Flow::PartProgram("a motion statement that drives along named geometry", span);
            }
            Major::Indirv => {
                let mut v = [0.0; 3];
                if rec.numbers(&mut v) == 3 {
                    self.indirv = unit(v);
                    Ok(())
                } else {
                    Err(Problem::new("INDIRV needs a direction: INDIRV/i,j,k", None))
                }
            }
            Major::Fedrat => {
                let mut ignored = |i| diags.push(diag::ignored_word(rec.arg_span(i), &rec.arg_text(i), "FEDRAT"));
                machine_records::parse_fedrat(rec, &mut ignored).map(|feed| {
                    self.note_units(feed.units, true);
                    self.feed = Some(feed);
                    self.note(Event::FeedRate(FeedRate { value: feed.value, unit: feed.unit }), span);
                })
            }
            Major::Spindl => {
                let mut ignored = |i| diags.push(diag::ignored_word(rec.arg_span(i), &rec.arg_text(i), "SPINDL"));
                machine_records::parse_spindl(rec, &mut ignored).map(|s| match s {
                    SpindleRecord::On(spindle) => {
                        if !spindle.css {
                            self.window_speed.get_or_insert(spindle.speed.unwrap_or(0.0));
                        }
                        self.spindle = spindle;
                        self.emit(Event::SpindleOn(spindle), span);
                    }
                    SpindleRecord::Restart => self.emit(Event::SpindleOn(self.spindle), span),
                    SpindleRecord::Off => self.emit(Event::SpindleOff, span),
                })
            }
            Major::Coolnt => {
                let mut ignored = |i| diags.push(diag::ignored_word(rec.arg_span(i), &rec.arg_text(i), "COOLNT"));
                machine_records::parse_coolnt(rec, &mut ignored).map(|c| self.emit(Event::Coolant(c), span))
            }
            Major::Cutcom => {
                let mut ignored = |i| diags.push(diag::ignored_word(rec.arg_span(i), &rec.arg_text(i), "CUTCOM"));
                machine_records::parse_cutcom(rec, &mut ignored).map(|c| {
                    if let Some(c) = c {
                        self.emit(Event::CutterComp(c), span);
                    }
                })
            }
            Major::Delay => {
                let mut ignored = |i| diags.push(diag::ignored_word(rec.arg_span(i), &rec.arg_text(i), "DELAY"));
                machine_records::parse_delay(rec, &mut ignored).map(|d| self.emit(Event::Dwell(d), span))
            }
            Major::Cycle => self.cycle_record(rec, diags),
            Major::Loadtl => self.tool_load(rec, 0, diags),
            Major::Load if rec.arg(0).is_some_and(|a| a.is("TOOL")) => self.tool_load(rec, 1, diags),
            Major::Cutter | Major::Tldata => {
                if let Some(d) = machine_records::cutter_diameter(rec) {
                    self.set_cutter(d, span);
                }
                Ok(())
            }
            Major::Units => machine_records::parse_units(rec).map(|u| self.units_record(u, span, diags)),
            Major::ToolPath => {
                let name = rec.arg(0).map(|_| rec.arg_text(0)).unwrap_or_default();
                let tool =
                    (0..rec.len()).find(|&i| rec.arg(i).is_some_and(|a| a.is("TOOL"))).filter(|&i| i + 1 < rec.len());
                if let Some(i) = tool {
                    let name = rec.arg_text(i + 1);
                    if name != self.tool_name {
                        self.tool_name = name;
                        self.cutter_changed.get_or_insert((self.window.len(), span));
                    }
                }
                self.start_toolpath(name, span, diags);
                Ok(())
            }
            Major::EndOfPath => {
                self.end_toolpath(span, diags);
                Ok(())
            }
            Major::Fini => {
                self.finish(Some(span), span, diags);
                self.emit(Event::End, span);
                self.flush();
                self.ended = true;
                Ok(())
            }
            Major::Multax | Major::Tlaxis | Major::Csys | Major::Nurbs | Major::Pass | Major::Load => {
                match major {
                    Major::Multax if rec.arg(0).is_some_and(|a| a.is("OFF")) => self.axis = None,
                    Major::Tlaxis => {
                        let mut v = [0.0; 3];
                        if rec.numbers(&mut v) == 3 {
                            self.axis = unit(v);
                        }
                    }
                    Major::Csys => self.axis = None,
                    Major::Nurbs if !self.warned_nurbs => {
                        self.warned_nurbs = true;
                        diags.push(diag::nurbs(span));
                    }
                    _ => {}
                }
                self.emit(Event::Command(Command { word: word(), args: rec.command_args() }), span);
                Ok(())
            }
            Major::Unknown => {
                diags.push(diag::unknown_word(span, &word()));
                Ok(())
            }
        };
        if let Err(problem) = result {
            let at = problem.arg.map_or(span, |i| rec.arg_span(i));
            diags.push(diag::bad_args(
                at,
                format!("{}: {}", word(), problem.message),
                "see the record's forms in docs/apt.md",
            ));
        }
        Flow::Continue
    }

    fn cycle_record(&mut self, rec: &Rec<'_>, diags: &mut Vec<Diagnostic>) -> Result<(), Problem> {
        let span = rec.span();
        let mut ignored = |i| diags.push(diag::ignored_word(rec.arg_span(i), &rec.arg_text(i), "CYCLE"));
        let record = parse_cycle(rec, &mut ignored)?;
        match record {
            CycleRecord::Prepare => {}
            CycleRecord::Off => {
                if self.cycle.take().is_some_and(|c| c.header_z.is_some()) {
                    self.emit(Event::DrillEnd, span);
                }
            }
            CycleRecord::Start(spec) => {
                self.drop_circle(Some(span), diags);
                if self.cycle.take().is_some_and(|c| c.header_z.is_some()) {
                    self.emit(Event::DrillEnd, span);
                }
                if let Some(feed) = &spec.feed {
                    self.note_units(feed.units, true);
                }
                let clearance_z = self.pos.map(|p| p[2]);
                self.cycle = Some(ActiveCycle { spec, span, header_z: None, clearance_z });
            }
        }
        Ok(())
    }

    /// A text record.
    pub fn text_record(&mut self, word: TextWord, text: String, span: Span, diags: &mut Vec<Diagnostic>) {
        match word {
            TextWord::Pprint | TextWord::Remark => self.emit(Event::Comment(Text { text }), span),
            TextWord::Insert => self.emit(Event::Insert(Text { text }), span),
            TextWord::Partno => {
                if let Some(job) = &mut self.job {
                    job.part.get_or_insert(text.clone());
                }
                self.emit(text_event("PARTNO", text), span);
            }
            TextWord::OpFeatStart => self.start_toolpath(text, span, diags),
            TextWord::OpFeatEnd => self.end_toolpath(span, diags),
        }
    }
}
