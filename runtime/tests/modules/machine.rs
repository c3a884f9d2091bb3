use postc_ir::event::{Job, Tool};
use postc_ir::{Quantity, Units};
use postc_runtime::machine::*;

#[test]
fn the_feed_is_the_new_tools_cut_feed_until_a_move_sets_it() {
    let mut m = MachineState::new(Some(Units::Mm), None, None);
    m.set_job(Job { units: Units::Mm, ..Job::default() });
    // No tool, no move: the feed has no value and prints nothing.
    assert!(m.number(Quantity::Feed).is_nan());
    m.set_tool(Tool { number: 1, cut_feed: 254.0, plunge_feed: 127.0, ..Tool::default() });
    assert_eq!(m.number(Quantity::Feed), 254.0);
    assert_eq!(m.number(Quantity::PlungeFeed), 127.0);
}

#[test]
fn power_belongs_to_jet_tools() {
    let mut m = MachineState::new(Some(Units::Mm), None, None);
    assert!(m.number(Quantity::Power).is_nan());
    m.set_tool(Tool { number: 1, spindle_speed: 18000.0, ..Tool::default() });
    assert!(m.number(Quantity::Power).is_nan(), "a spindle tool has no power");
    m.set_tool(Tool { number: 3, jet: true, ..Tool::default() });
    assert_eq!(m.number(Quantity::Power), 0.0, "a jet tool before its power is off");
    m.power = Some(40.0);
    m.set_tool(Tool { number: 3, jet: true, ..Tool::default() });
    assert_eq!(m.number(Quantity::Power), 40.0, "the same jet tool keeps its power");
    m.set_tool(Tool { number: 4, jet: true, power: Some(70.0), ..Tool::default() });
    assert_eq!(m.number(Quantity::Power), 70.0);
    m.set_tool(Tool { number: 1, spindle_speed: 18000.0, ..Tool::default() });
    assert!(m.number(Quantity::Power).is_nan(), "power is forgotten with the jet tool");
}

#[test]
fn values_without_a_source_have_none() {
    let mut m = MachineState::new(Some(Units::Mm), None, None);
    for q in [
        Quantity::A,
        Quantity::B,
        Quantity::C,
        Quantity::Tool,
        Quantity::PreviousTool,
        Quantity::X,
        Quantity::HomeZ,
        Quantity::SafeZ,
        Quantity::DwellTime,
        Quantity::XLength,
        Quantity::WrapDiameter,
    ] {
        assert!(m.number(q).is_nan(), "{q:?}");
    }
    m.set_job(Job { home: Some(postc_ir::event::Point { x: 0.0, y: 0.0, z: 20.0 }), ..Job::default() });
    m.set_tool(Tool { number: 2, ..Tool::default() });
    assert_eq!(m.number(Quantity::Z), 20.0, "the tool starts at home");
    assert_eq!(m.number(Quantity::SafeZ), 20.0, "safe Z falls back to home Z");
    assert_eq!(m.number(Quantity::Tool), 2.0);
    assert!(m.number(Quantity::PreviousTool).is_nan(), "the first tool has no previous one");
    assert_eq!(m.number(Quantity::SpindleSpeed), 0.0, "a speed of 0 prints: the spindle is not turning");
    m.set_tool(Tool { number: 5, ..Tool::default() });
    assert_eq!(m.number(Quantity::PreviousTool), 2.0);
}
