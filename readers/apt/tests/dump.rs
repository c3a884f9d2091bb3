//! Prints what the reader makes of a file: `APT_DUMP=path cargo test -p postc-reader-apt --test dump -- --nocapture`.

#[test]
fn dump() {
    let Ok(path) = std::env::var("APT_DUMP") else { return };
    let bytes = std::fs::read(&path).expect("read");
    let read = crate::common::read_bytes(&path, &bytes);
    print!("{}", crate::common::render(&read));
}
