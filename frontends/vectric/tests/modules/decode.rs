use postc_front_vectric::decode::*;

#[test]
fn utf8_stays_utf8() {
    let (text, enc) = decode("Länge".as_bytes());
    assert_eq!((text.as_str(), enc), ("Länge", Encoding::Utf8));
    assert_eq!(enc.encode(&text).as_ref(), "Länge".as_bytes());
}

#[test]
fn every_windows_1252_byte_round_trips() {
    let bytes: Vec<u8> = (0..=255u8).collect();
    let (text, enc) = decode(&bytes);
    assert_eq!(enc, Encoding::Windows1252);
    assert_eq!(enc.encode(&text).as_ref(), bytes.as_slice());
}
