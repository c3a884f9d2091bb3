use postc_front_cimco::looks_like_cimco;

#[test]
fn recognises_cimco_posts() {
    assert!(looks_like_cimco(b"function onLinear(vx, vy, vz, movement) {}"));
    assert!(looks_like_cimco(b"xyzFormat = createFormat({decimals: 3});"));
    assert!(looks_like_cimco(b"var MillDrillingFields = [];"));
    assert!(looks_like_cimco(b"function  onCircular  (cx) {}"));
}

#[test]
fn rejects_other_dialects() {
    assert!(!looks_like_cimco(b"+ Vectric post\nPOST_NAME = \"x\"\nbegin HEADER\n\"G21\"\n"));
    assert!(!looks_like_cimco(b"Sub GOTO\n  Out \"<N><X><Y>\"\nEnd Sub\n"));
    assert!(!looks_like_cimco(b"function foo() { return onLinear; }"));
    assert!(!looks_like_cimco(&[0xff, 0xfe, 0x00]));
}
