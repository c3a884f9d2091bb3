use postc_ir::event::{ArcDir, Plane};
use postc_verify::geometry::*;

#[test]
fn r_centres_pick_the_short_or_long_arc() {
    let c = r_centre([0.0, 0.0, 0.0], [10.0, 0.0, 0.0], 5.0, ArcDir::Cw, Plane::Xy, 1e-6).unwrap();
    assert!((c[0] - 5.0).abs() < 1e-9 && c[1].abs() < 1e-9);
    // Counter-clockwise from (0,0) to (10,10): the quarter circle about (0,10).
    let c = r_centre([0.0, 0.0, 0.0], [10.0, 10.0, 0.0], 10.0, ArcDir::Ccw, Plane::Xy, 1e-6).unwrap();
    assert!(c[0].abs() < 1e-9 && (c[1] - 10.0).abs() < 1e-9, "{c:?}");
    let c = r_centre([0.0, 0.0, 0.0], [10.0, 10.0, 0.0], 10.0, ArcDir::Cw, Plane::Xy, 1e-6).unwrap();
    assert!((c[0] - 10.0).abs() < 1e-9 && c[1].abs() < 1e-9, "{c:?}");
    let c = r_centre([0.0, 0.0, 0.0], [10.0, 10.0, 0.0], -10.0, ArcDir::Cw, Plane::Xy, 1e-6).unwrap();
    assert!(c[0].abs() < 1e-9 && (c[1] - 10.0).abs() < 1e-9, "{c:?}");
    let arc = Arc { start: [0.0; 3], end: [10.0, 10.0, 0.0], centre: c, dir: ArcDir::Cw, plane: Plane::Xy };
    assert!((arc.sweep(1e-6) - 1.5 * std::f64::consts::PI).abs() < 1e-9);
}

#[test]
fn points_on_an_arc() {
    let arc = Arc {
        start: [10.0, 0.0, 0.0],
        end: [0.0, 10.0, -1.0],
        centre: [0.0, 0.0, 0.0],
        dir: ArcDir::Ccw,
        plane: Plane::Xy,
    };
    let h = std::f64::consts::FRAC_1_SQRT_2 * 10.0;
    let (d, t) = arc.deviation([h, h, -0.5], 1e-3);
    assert!(d < 1e-9 && (t - 0.5).abs() < 1e-9);
    let (d, _) = arc.deviation([-h, -h, -0.5], 1e-3);
    assert!(d.is_infinite());
    assert!((arc.sweep(1e-3) - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
}
