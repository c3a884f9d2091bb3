//! The `lathe` option (`OutputOptions::lathe`): a turning toolpath in the
//! runtime's terms. Every event is turned before it is dispatched (and
//! before a script host observes it), whatever the post's dialect.

use postc_ir::event::{ArcMove, Event, Plane};

/// A lathe toolpath in the runtime's terms: (x, y, z) becomes (z, x, y),
/// so the turning plane ZX (X the radius, Z along the spindle) lies in
/// the runtime's XY plane with the same sense of rotation, and G18 arcs
/// reach the arc sections. Handlers read the lathe's X from Y and its Z
/// from X.
pub fn turn_event(event: Event) -> Event {
    let p = |x: f64, y: f64, z: f64| (z, x, y);
    match event {
        Event::Rapid(mut m) => {
            (m.x, m.y, m.z) = p(m.x, m.y, m.z);
            Event::Rapid(m)
        }
        Event::Feed(mut m) => {
            (m.x, m.y, m.z) = p(m.x, m.y, m.z);
            Event::Feed(m)
        }
        Event::Arc(a) => Event::Arc(turn_arc(a)),
        Event::DrillPoint(mut d) => {
            (d.x, d.y, d.z) = p(d.x, d.y, d.z);
            Event::DrillPoint(d)
        }
        Event::Job(mut job) => {
            if let Some(h) = &mut job.home {
                (h.x, h.y, h.z) = p(h.x, h.y, h.z);
            }
            if let Some(m) = &mut job.material {
                for q in [&mut m.min, &mut m.max] {
                    (q.x, q.y, q.z) = p(q.x, q.y, q.z);
                }
            }
            Event::Job(job)
        }
        other => other,
    }
}

fn turn_arc(mut a: ArcMove) -> ArcMove {
    (a.x, a.y, a.z) = (a.z, a.x, a.y);
    (a.cx, a.cy, a.cz) = (a.cz, a.cx, a.cy);
    a.plane = match a.plane {
        Plane::Zx => Plane::Xy,
        Plane::Xy => Plane::Yz,
        Plane::Yz => Plane::Zx,
    };
    a
}
