use postc_front_vcpost::registers::*;

#[test]
fn formats() {
    assert_eq!(parse_format("4.3"), Some((false, 4, 3)));
    assert_eq!(parse_format("+5"), Some((true, 5, 0)));
    assert_eq!(parse_format(".3"), Some((false, 0, 3)));
    assert_eq!(parse_format("4.x"), None);
    assert_eq!(parse_format(""), None);
    assert_eq!(parse_format("1.10"), None);
}
