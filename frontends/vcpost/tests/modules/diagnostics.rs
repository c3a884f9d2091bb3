use postc_front_vcpost::diagnostics::*;

#[test]
fn codes_are_numbered_in_order() {
    for (i, code) in ALL.iter().enumerate() {
        assert_eq!(*code, format!("VC{:03}", i + 1));
    }
}

#[test]
fn suggestions() {
    assert_eq!(suggest("Fromat", ["Format", "Prefix"]), Some("Format"));
    assert_eq!(suggest("Clearnce", ["Clearance", "X"]), Some("Clearance"));
    assert_eq!(suggest("Q", ["X", "Y"]), None);
}
