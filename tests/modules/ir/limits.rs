use postc_ir::event::Event;
use postc_ir::event::{FeedMove, Job, Move};
use postc_ir::limits::*;
use postc_ir::units::Units;

#[test]
fn ranges_hold_in_the_job_units() {
    let far = |x: f64| Event::Rapid(Move { x, ..Move::default() });
    let mut check = RangeCheck::new();
    assert_eq!(check.check(&far(1e6)), Verdict::Fine);
    let Verdict::Refuse(bad) = check.check(&far(1e308)) else { panic!() };
    assert_eq!(bad.message("Rapid"), "Rapid x is 1e308: a coordinate or length must be within ±1000000 mm");
    assert_eq!(check.check(&far(1e308)), Verdict::RefuseAgain);
    assert!(matches!(check.check(&far(f64::NAN)), Verdict::Refuse(_)));
    let mut inch = RangeCheck::new();
    inch.check(&Event::Job(Box::new(Job { units: Units::Inch, ..Job::default() })));
    assert_eq!(inch.check(&far(39_000.0)), Verdict::Fine);
    let Verdict::Refuse(bad) = inch.check(&far(40_000.0)) else { panic!() };
    assert_eq!(bad.message("Rapid"), "Rapid x is 40000: a coordinate or length must be within ±39370.08 in");
}

/// Moves with rotary and tool axes take the fast path when they are
/// in range and the slow one, which reports, when they are not.
#[test]
fn rotary_and_tool_axes_are_checked() {
    let with = |a: Option<f64>, axis: Option<[f64; 3]>| {
        Event::Feed(FeedMove { x: 1.0, a, tool_axis: axis, ..FeedMove::default() })
    };
    let mut check = RangeCheck::new();
    assert_eq!(check.check(&with(Some(720.0), Some([0.0, 0.0, 1.0]))), Verdict::Fine);
    let Verdict::Refuse(bad) = check.check(&with(Some(2e6), None)) else { panic!() };
    assert_eq!(bad.field, "a");
    let Verdict::Refuse(bad) = check.check(&with(None, Some([f64::NAN, 0.0, 1.0]))) else { panic!() };
    assert_eq!(bad.field, "tool_axis");
}

#[test]
fn feeds_are_not_negative() {
    let feed = |f: f64| Event::Feed(FeedMove { feed: Some(f), ..FeedMove::default() });
    let mut check = RangeCheck::new();
    assert_eq!(check.check(&feed(0.0)), Verdict::Fine);
    let Verdict::Refuse(bad) = check.check(&feed(-5.0)) else { panic!() };
    assert_eq!(bad.message("Feed"), "Feed feed is -5: a feed must be from 0 to 1000000 mm/min");
    let Verdict::Refuse(bad) = check.check(&feed(f64::INFINITY)) else { panic!() };
    assert_eq!(bad.message("Feed"), "Feed feed is not a finite number: a feed must be from 0 to 1000000 mm/min");
}
