use postc_front_vectric::looks_like_vectric;

#[test]
fn vectric_posts_are_recognised() {
    let post = b"POST_NAME = \"x\"\r\nbegin HEADER\r\n\"G21\"\r\n";
    assert!(looks_like_vectric(post));
    assert!(looks_like_vectric(b"var X_POSITION = [X|A|X|1.3]\nBEGIN feed_move\n"));
}

#[test]
fn other_dialects_are_not() {
    assert!(!looks_like_vectric(b"function onOpen() {\n  writeBlock(\"G21\");\n}\n"));
    assert!(!looks_like_vectric(b"Sub GOTO\n  Out \"<N><X><Y>\"\nEnd Sub\n"));
    assert!(!looks_like_vectric(&[0xff, 0xfe, 0x00, 0x01]));
    assert!(!looks_like_vectric(b""));
}
