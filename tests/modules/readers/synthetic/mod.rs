use postc_ir::EventSource;
use postc_ir::event::*;
use postc_reader_synthetic::*;

#[test]
fn generators_make_the_moves_asked_for() {
    for p in ["zigzag", "arcs", "mixed"] {
        let mut s = Synthetic::new(p, 1000).unwrap();
        let mut moves = 0;
        let mut diags = Vec::new();
        while let Some((e, _)) = s.next_event(&mut diags) {
            if matches!(e, Event::Rapid(_) | Event::Feed(_) | Event::Arc(_)) {
                moves += 1;
            }
        }
        // The preamble's rapid and plunge and the final retract come on top.
        assert!((1000..=1003).contains(&moves), "{p}: {moves}");
    }
    assert!(Synthetic::new("nope", 1).is_none());
}
