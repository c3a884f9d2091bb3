//! The job's outline (`postc_ir::outline::JobOutline`): what a post that
//! reads ahead learns of each section before it comes.

use postc_ir::event::{Event, FeedMove, Move, Spindle, Tool, ToolpathStart};
use postc_ir::outline::JobOutline;

/// A section's tool keeps its rpm when the spindle starts at constant
/// surface speed before the first move (a lathe's `G96`: the speed is
/// metres a minute, no rpm), and takes the speed of a plain spindle start.
#[test]
fn a_constant_surface_speed_is_not_the_tools_rpm() {
    let section = |spindle: Spindle| {
        vec![
            Event::Tool(Tool { number: 1, spindle_speed: 1500.0, turning: true, ..Tool::default() }),
            Event::ToolpathStart(ToolpathStart { name: "Face".into(), feed_per_rev: true, ..ToolpathStart::default() }),
            Event::SpindleOn(spindle),
            Event::Rapid(Move { x: 27.0, z: 5.0, ..Move::default() }),
            Event::Feed(FeedMove { x: 0.0, z: 0.0, ..FeedMove::default() }),
        ]
    };
    let css = JobOutline::of(section(Spindle { speed: Some(200.0), css: true, max_rpm: Some(3000.0), ccw: false }));
    assert_eq!(css.sections[0].tool.spindle_speed, 1500.0);
    let rpm = JobOutline::of(section(Spindle { speed: Some(800.0), ..Spindle::default() }));
    assert_eq!(rpm.sections[0].tool.spindle_speed, 800.0);
}
