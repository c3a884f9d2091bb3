use postc_ir::event::{ArcDir, Plane};
use postc_verify::expect::Kind;
use postc_verify::plot::*;
use postc_verify::{Move, Observer};

fn mv(kind: Kind, start: [f64; 3], end: [f64; 3], centre: [f64; 3], dir: ArcDir) -> Move {
    Move { kind, start, end, centre, dir, plane: Plane::Xy, span: postc_ir::Span::new(postc_ir::FileId(0), 0, 0) }
}

#[test]
fn collinear_segments_merge() {
    let mut p = Plot::new();
    for i in 0..1000 {
        let x = f64::from(i);
        p.motion(&mv(Kind::Feed, [x, 0.0, -1.0], [x + 1.0, 0.0, -1.0], [0.0; 3], ArcDir::Cw));
    }
    assert_eq!(p.layers[0][1][1].cmds.len(), 2, "{:?}", &p.layers[0][1][1].cmds[..4]);
}

#[test]
fn arcs_are_svg_arcs_with_their_sweep() {
    // G3 from (10,0) to (0,10) about the origin: counterclockwise, so SVG sweep 0 once Y points down.
    let mut p = Plot::new();
    p.motion(&mv(Kind::Arc, [10.0, 0.0, 0.0], [0.0, 10.0, 0.0], [0.0; 3], ArcDir::Ccw));
    p.motion(&mv(Kind::Arc, [0.0, 10.0, 0.0], [10.0, 0.0, 0.0], [0.0; 3], ArcDir::Cw));
    let svg = p.svg();
    assert!(svg.contains(" 0 0 0 "), "{svg}");
    assert!(svg.contains(" 0 0 1 "), "{svg}");
    // A full circle is drawn in pieces of at most half a turn.
    let mut p = Plot::new();
    p.motion(&mv(Kind::Arc, [10.0, 0.0, 0.0], [10.0, 0.0, 0.0], [0.0; 3], ArcDir::Ccw));
    assert_eq!(p.layers[0][1][1].cmds.iter().filter(|c| matches!(c, Cmd::Arc(..))).count(), 3);
    // Seen from the front the circle is a line across its diameter.
    let xs: Vec<f64> = p.layers[1][1][1]
        .cmds
        .iter()
        .map(|c| match *c {
            Cmd::Move(x, _) | Cmd::Line(x, _) | Cmd::Arc(x, ..) | Cmd::Dot(x, _) => x,
        })
        .collect();
    assert!(xs.iter().any(|x| (x + 10.0).abs() < 0.1), "{xs:?}");
}

#[test]
fn an_xz_arc_turns_the_way_g18_says_seen_from_the_front() {
    // G18 G3 turns from Z toward X (counterclockwise seen from +Y): from Z10 to X10 it
    // goes over the top to the right, clockwise seen from the front, SVG sweep 1.
    let mut p = Plot::new();
    let mut m = mv(Kind::Arc, [0.0, 0.0, 10.0], [10.0, 0.0, 0.0], [0.0; 3], ArcDir::Ccw);
    m.plane = Plane::Zx;
    p.motion(&m);
    assert!(
        matches!(p.layers[1][1][1].cmds[..], [Cmd::Move(..), Cmd::Arc(_, _, _, true)]),
        "{:?}",
        p.layers[1][1][1].cmds
    );
    // Seen from the top it is the line from X0 to X10 (drawn through points).
    assert!(p.layers[0][1][1].cmds.iter().all(|c| !matches!(c, Cmd::Arc(..))));
    // Its bounds reach the arc's top: Z10 at X0 and X10 at Z0, nothing beyond.
    assert!((p.bounds.max[2] - 10.0).abs() < 1e-9 && (p.bounds.max[0] - 10.0).abs() < 1e-9);
}

#[test]
fn layers_are_capped() {
    let mut p = Plot::new();
    for i in 0..(MAX_POINTS + 500) {
        let x = i as f64;
        let y = if i % 2 == 0 { 0.0 } else { 100.0 };
        p.motion(&mv(Kind::Feed, [x, 100.0 - y, 0.0], [x + 1.0, y, 0.0], [0.0; 3], ArcDir::Cw));
    }
    assert!(p.layers[0][1][1].cmds.len() <= MAX_POINTS);
    // Over 100 km of zigzag: thinned to about a pixel, and what does not fit then is left out, and said.
    assert!(p.layers[0][1][1].res > MERGE);
    assert!(p.layers[0][1][1].dropped > 0);
    assert!(p.svg().contains("not drawn"));
    // A dense job (many short moves in a small area) fits once thinned: all of it is drawn.
    let mut p = Plot::new();
    // (A shaky line: short moves, no two collinear.)
    let at = |i: usize| [i as f64 * 0.005, if i.is_multiple_of(2) { 0.0 } else { 0.004 }, 0.0];
    for i in 0..(2 * MAX_POINTS) {
        p.motion(&mv(Kind::Feed, at(i), at(i + 1), [0.0; 3], ArcDir::Cw));
    }
    assert_eq!(p.layers[0][1][1].dropped, 0);
    let svg = p.svg();
    assert!(svg.contains("is drawn to"), "{}", &svg[svg.len() - 2000..]);
    assert!(!svg.contains("not drawn"));
}

#[test]
fn wild_coordinates_draw_a_finite_svg() {
    let mut p = Plot::new();
    p.motion(&mv(Kind::Feed, [0.0, 0.0, 0.0], [10.0, 10.0, -1.0], [0.0; 3], ArcDir::Cw));
    p.motion(&mv(Kind::Feed, [10.0, 10.0, -1.0], [1e300, -1e300, f64::MAX], [0.0; 3], ArcDir::Cw));
    p.motion(&mv(Kind::Arc, [1e300, -1e300, f64::MAX], [0.0, 1e20, 0.0], [1e-300, 0.0, 0.0], ArcDir::Cw));
    let svg = p.svg();
    assert!(!svg.contains("NaN") && !svg.contains("inf"), "{svg}");
    assert!(svg.len() < 100_000);
}

#[test]
fn nice_steps() {
    assert_eq!(nice_step(7.0), 10.0);
    assert_eq!(nice_step(1.5), 2.0);
    assert_eq!(nice_step(0.03), 0.05);
}
