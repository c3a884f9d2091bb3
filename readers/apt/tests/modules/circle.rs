use postc_ir::event::{ArcDir, Plane};
use postc_reader_apt::testing::circle::*;

fn spec(axis: V3, ccw: bool) -> CircleSpec {
    CircleSpec { centre: [0.0, 0.0, 0.0], axis, ccw, convention: Convention::Apt }
}

#[test]
fn direction_follows_the_axis() {
    let arc = |axis, ccw| match build_arc(&spec(axis, ccw), Some([1.0, 0.0, 0.0]), [0.0, 1.0, 0.0], None, 0.01) {
        ArcOutcome::Arc { arc, .. } => (arc.dir, arc.plane),
        other => panic!("{other:?}"),
    };
    assert_eq!(arc([0.0, 0.0, 1.0], true), (ArcDir::Ccw, Plane::Xy));
    assert_eq!(arc([0.0, 0.0, -1.0], true), (ArcDir::Cw, Plane::Xy));
    assert_eq!(arc([0.0, 0.0, -1.0], false), (ArcDir::Ccw, Plane::Xy));
    assert_eq!(arc([-1.0, 0.0, 0.0], true), (ArcDir::Cw, Plane::Yz));
    assert_eq!(arc([0.0, 1.0, 0.0], true), (ArcDir::Ccw, Plane::Zx));
}

#[test]
fn tilted_arcs_are_cut_into_points_on_the_circle() {
    let axis = unit([0.0, 1.0, 1.0]).unwrap();
    let start = [1.0, 0.0, 0.0];
    let end = rotate(start, axis, std::f64::consts::FRAC_PI_2);
    let ArcOutcome::Linear(points) = build_arc(&spec(axis, true), Some(start), end, None, 0.001) else {
        panic!("not linearized")
    };
    assert!(points.len() > 5);
    for p in &points {
        assert!((norm(*p) - 1.0).abs() < 1e-9);
    }
    assert_eq!(*points.last().unwrap(), end);
}
