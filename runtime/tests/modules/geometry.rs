use postc_ir::event::{ArcDir, Plane};
use postc_runtime::geometry::*;
use std::f64::consts::TAU;

#[test]
fn quarter_arcs_turn_the_right_way() {
    let ccw = ArcGeometry::new([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0; 3], ArcDir::Ccw, Plane::Xy);
    assert!((ccw.sweep - TAU / 4.0).abs() < 1e-12);
    let cw = ArcGeometry::new([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0; 3], ArcDir::Cw, Plane::Xy);
    assert!((cw.sweep + 3.0 * TAU / 4.0).abs() < 1e-12);
    let mid = ccw.mid;
    assert!((mid[0] - 0.5f64.sqrt()).abs() < 1e-12 && (mid[1] - 0.5f64.sqrt()).abs() < 1e-12);
}

#[test]
fn closed_arcs_are_full_circles() {
    let full = ArcGeometry::new([1.0, 0.0, 0.0], [1.0, 0.0, -1.0], [0.0; 3], ArcDir::Cw, Plane::Xy);
    assert!((full.sweep + TAU).abs() < 1e-12);
    assert!(full.is_helical());
    assert!((full.length() - TAU.hypot(1.0)).abs() < 1e-12);
}

#[test]
fn segment_count_follows_the_chord_formula() {
    let arc = ArcGeometry::new([10.0, 0.0, 0.0], [-10.0, 0.0, 0.0], [0.0; 3], ArcDir::Ccw, Plane::Xy);
    let n = arc.segments(0.01);
    let step = 2.0 * (1.0f64 - 0.001).acos();
    assert_eq!(n, (std::f64::consts::PI / step).ceil() as u32);
    assert_eq!(arc.segments(100.0), 1);
}

#[test]
fn exact_centre_is_equidistant() {
    let arc = ArcGeometry::new([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0; 3], ArcDir::Ccw, Plane::Xy);
    let e = arc.exact([1.0004, 0.0, 0.0], [0.0, 0.9996, 0.0], ArcDir::Ccw);
    let r0 = (e.start[0] - e.centre[0]).hypot(e.start[1] - e.centre[1]);
    let r1 = (e.end[0] - e.centre[0]).hypot(e.end[1] - e.centre[1]);
    assert!((r0 - r1).abs() < 1e-12);
}

#[test]
fn zx_arcs_use_plane_coordinates() {
    let arc = ArcGeometry::new([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0; 3], ArcDir::Ccw, Plane::Zx);
    assert!((arc.sweep - TAU / 4.0).abs() < 1e-12);
}
