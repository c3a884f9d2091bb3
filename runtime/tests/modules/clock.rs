use postc_runtime::clock::*;

#[test]
fn known_dates() {
    assert_eq!(format_utc(0), ("Thursday, January 1, 1970".into(), "00:00".into()));
    assert_eq!(format_utc(951_782_400), ("Tuesday, February 29, 2000".into(), "00:00".into()));
    assert_eq!(format_utc(1_795_422_900), ("Monday, November 23, 2026".into(), "08:35".into()));
    // The date of the real program the long form comes from.
    assert_eq!(format_utc(1_321_358_400).0, "Tuesday, November 15, 2011");
    assert_eq!(format_utc(-86_400).0, "Wednesday, December 31, 1969");
}
