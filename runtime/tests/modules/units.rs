use postc_ir::Units;
use postc_ir::event::Event;
use postc_ir::event::{FeedMove, Job, Spindle, Tool};
use postc_runtime::units::*;

#[test]
fn inch_toolpaths_come_out_in_millimetres() {
    let mut c = Conversion::new(Some(Units::Mm));
    let mut job = Event::Job(Box::new(Job { units: Units::Inch, safe_z: Some(1.0), ..Job::default() }));
    c.convert(&mut job);
    let Event::Job(j) = &job else { panic!() };
    assert_eq!((j.units, j.safe_z), (Units::Mm, Some(25.4)));
    let mut feed = Event::Feed(FeedMove { x: 7.0, y: -1.0, z: 0.5, feed: Some(10.0), ..FeedMove::default() });
    c.convert(&mut feed);
    let Event::Feed(m) = &feed else { panic!() };
    let near = |a: f64, b: f64| (a - b).abs() < 1e-9;
    assert!(near(m.x, 177.8) && near(m.y, -25.4) && near(m.z, 12.7) && near(m.feed.unwrap(), 254.0), "{m:?}");
    let mut tool = Event::Tool(Tool { diameter: 0.25, spindle_speed: 12000.0, cut_feed: 40.0, ..Tool::default() });
    c.convert(&mut tool);
    let Event::Tool(t) = &tool else { panic!() };
    assert!(near(t.diameter, 6.35) && t.spindle_speed == 12000.0 && near(t.cut_feed, 1016.0), "{t:?}");
    let mut css = Event::SpindleOn(Spindle { speed: Some(1000.0), css: true, ..Spindle::default() });
    c.convert(&mut css);
    let Event::SpindleOn(s) = &css else { panic!() };
    assert!((s.speed.unwrap() - 304.8).abs() < 1e-9, "1000 ft/min is 304.8 m/min");
}

#[test]
fn without_post_units_the_toolpath_units_stay() {
    let mut c = Conversion::new(None);
    let mut job = Event::Job(Box::new(Job { units: Units::Inch, ..Job::default() }));
    c.convert(&mut job);
    let mut feed = Event::Feed(FeedMove { x: 7.0, ..FeedMove::default() });
    c.convert(&mut feed);
    assert_eq!(c.output(), Units::Inch);
    assert_eq!(feed, Event::Feed(FeedMove { x: 7.0, ..FeedMove::default() }));
}
