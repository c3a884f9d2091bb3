use postc_front_vcpost::testing::composites_check::*;
use postc_ir::Span;

#[test]
fn seed_add_cut_example_agrees() {
    let mut d = Vec::new();
    add_cut("0001111111111100", "0011111111111000", 8188.0, 16376.0, Span::default(), &mut d);
    assert!(d.is_empty(), "{d:?}");
    add_cut("0001111111111100", "0011111111111000", 8189.0, 16376.0, Span::default(), &mut d);
    assert_eq!(d.len(), 1);
}
