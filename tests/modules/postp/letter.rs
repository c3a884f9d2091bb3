use postc_postp::letter::*;

#[test]
fn an_l_is_two_feeds_between_a_plunge_and_a_retract() {
    let l = Letter::from_numbers(&[1.0, 2.0, -0.01, 0.0, 0.0, 1.0, 1.0, 0.5, 0.1, 10.0, 5.0]).unwrap();
    let (m, missing) = l.motions("L", Some([0.0, 0.0, 1.0]), 1.0);
    assert!(missing.is_empty());
    assert_eq!(m[0], Motion::Rapid([0.0, 0.0, 0.5]));
    assert_eq!(m[1], Motion::Rapid([1.0, 3.0, 0.5]));
    assert_eq!(m[2], Motion::Rapid([1.0, 3.0, 0.1]));
    assert_eq!(m[3], Motion::Feed([1.0, 3.0, -0.01], 5.0));
    assert_eq!(m[4], Motion::Feed([1.0, 2.0, -0.01], 10.0));
    let Motion::Feed(p, _) = m[5] else { panic!() };
    assert!((p[0] - (1.0 + 4.0 / 6.0)).abs() < 1e-12);
    assert_eq!(m[6], Motion::Rapid([p[0], p[1], 0.5]));
}

#[test]
fn rotation_turns_about_the_start() {
    let l = Letter::from_numbers(&[0.0, 0.0, 0.0, 2.0, 90.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0]).unwrap();
    let (m, missing) = l.motions("\u{e9}.", None, 6.0);
    assert_eq!(missing, vec!['\u{e9}']);
    // The dot of the second character sits 2 units along the turned baseline.
    let dot = m.iter().rev().find_map(|m| if let Motion::Feed(p, _) = m { Some(*p) } else { None }).unwrap();
    assert!(dot[0].abs() < 1e-9 && (dot[1] - 2.0 - 2.0).abs() < 1e-9, "{dot:?}");
}
