use postc_reader_apt::testing::lines::*;

#[test]
fn newlines_are_found_in_every_position() {
    for len in 0..40 {
        for at in 0..len {
            let mut hay = vec![b'x'; len];
            hay[at] = b'\n';
            if at + 3 < len {
                hay[at + 3] = b'\n';
            }
            assert_eq!(find_newline(&hay), Some(at));
        }
        assert_eq!(find_newline(&vec![0x8a; len]), None);
    }
}

#[test]
fn lines_strip_crlf_and_keep_offsets() {
    let mut lines = Lines::new(&b"GOTO/1,2,3\r\nFINI\nX"[..]);
    let mut buf = Vec::new();
    let a = lines.read(&mut buf).unwrap().unwrap();
    assert_eq!((a.start, &buf[..]), (0, &b"GOTO/1,2,3"[..]));
    let b = lines.read(&mut buf).unwrap().unwrap();
    assert_eq!((b.start, &buf[..]), (12, &b"FINI"[..]));
    let c = lines.read(&mut buf).unwrap().unwrap();
    assert_eq!((c.start, &buf[..]), (17, &b"X"[..]));
    assert!(lines.read(&mut buf).unwrap().is_none());
}
