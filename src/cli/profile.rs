//! `postc bench --profile`: where the time of a run goes, per handler and
//! per post function — calls, time spent in the function itself and with
//! what it calls, native or script — so a post author sees which function
//! to change, and we see which construct to lower next.
//!
//! The runtime tells a [`Profiler`] when each handler and call starts and
//! ends ([`postc_runtime::profile`]); the profiler reads the clock. The
//! clock costs time of its own, so a profiled run is slower than a plain
//! `postc bench`; the shares are what to read.

use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;
use std::time::{Duration, Instant};

use postc_ir::{Body, HandlerKey, Post};
use postc_runtime::profile::{CallObserver, Frame};

/// Time and calls of one frame kind.
#[derive(Clone, Copy, Default)]
struct Totals {
    calls: u64,
    /// With what it calls.
    total: Duration,
    /// In the frame itself.
    own: Duration,
}

/// The frames running, and the totals so far.
#[derive(Default)]
pub struct Profile {
    stack: Vec<(Frame, Instant, Duration)>,
    totals: HashMap<Frame, Totals>,
}

/// The observer handed to the runtime; the profile stays readable here.
#[derive(Clone, Default)]
pub struct Profiler(pub Rc<RefCell<Profile>>);

impl CallObserver for Profiler {
    fn enter(&mut self, frame: Frame) {
        self.0.borrow_mut().stack.push((frame, Instant::now(), Duration::ZERO));
    }

    fn exit(&mut self) {
        let mut p = self.0.borrow_mut();
        let Some((frame, start, children)) = p.stack.pop() else { return };
        let took = start.elapsed();
        if let Some(parent) = p.stack.last_mut() {
            parent.2 += took;
        }
        // A recursive frame counts its time once, at the outermost call.
        let outermost = !p.stack.iter().any(|(f, _, _)| *f == frame);
        let t = p.totals.entry(frame).or_default();
        t.calls += 1;
        if outermost {
            t.total += took;
        }
        t.own += took.saturating_sub(children);
    }
}

impl Profiler {
    /// The report: one line per handler and function that ran, by time
    /// spent in it, as shares of the whole run.
    pub fn report(&self, post: &Post, run: Duration) -> String {
        let p = self.0.borrow();
        let mut rows: Vec<(Frame, Totals)> = p.totals.iter().map(|(f, t)| (*f, *t)).collect();
        rows.sort_by_key(|r| std::cmp::Reverse(r.1.own));
        let whole = run.as_secs_f64().max(1e-9);
        let in_handlers: Duration =
            rows.iter().filter(|(f, _)| matches!(f, Frame::Handler(_))).map(|(_, t)| t.total).sum();
        let mut out =
            String::from("\nwhere the time goes (own: in the function itself; with calls: and what it calls)\n");
        out.push_str(&format!(
            "{:<34} {:>7} {:>12} {:>7} {:>11}\n",
            "handler / function", "kind", "calls", "own", "with calls"
        ));
        for (frame, t) in &rows {
            let (name, kind) = match frame {
                Frame::Handler(i) => match post.handlers.get(*i).map(|h| &h.key) {
                    Some(HandlerKey::Section(s)) => (s.name().to_string(), "handler"),
                    Some(HandlerKey::Word(w)) => (w.clone(), "handler"),
                    None => ("?".to_string(), "handler"),
                },
                Frame::Function(f) => match post.functions.get(f.index()) {
                    Some(func) => (
                        func.name.clone(),
                        match func.body {
                            Body::Native(_) => "native",
                            Body::Script(_) => "script",
                        },
                    ),
                    None => ("?".to_string(), "?"),
                },
            };
            out.push_str(&format!(
                "{:<34} {:>7} {:>12} {:>6.1}% {:>10.1}%\n",
                name,
                kind,
                t.calls,
                100.0 * t.own.as_secs_f64() / whole,
                100.0 * t.total.as_secs_f64() / whole
            ));
        }
        let outside = run.saturating_sub(in_handlers);
        out.push_str(&format!(
            "{:<34} {:>7} {:>12} {:>6.1}%\n",
            "(outside handlers: reading, dispatch)",
            "",
            "",
            100.0 * outside.as_secs_f64() / whole
        ));
        for (frame, _) in rows.iter().take(3) {
            if let Frame::Function(f) = frame
                && let Some(func) = post.functions.get(f.index())
                && let Some(why) = &func.why_script
            {
                out.push_str(&format!("`{}` runs as a script: {}\n", func.name, why.what));
            }
        }
        out
    }
}
