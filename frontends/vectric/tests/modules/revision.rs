use postc_front_vectric::revision::*;

/// The test suite of RFC 1321, appendix A.5.
#[test]
fn rfc_1321_vectors() {
    let cases: [(&[u8], &str); 7] = [
        (b"", "D41D8CD98F00B204E9800998ECF8427E"),
        (b"a", "0CC175B9C0F1B6A831C399E269772661"),
        (b"abc", "900150983CD24FB0D6963F7D28E17F72"),
        (b"message digest", "F96B697D7CB7938D525A2F31AAF161D0"),
        (b"abcdefghijklmnopqrstuvwxyz", "C3FCD3D76192E4007DFB496CCA67E13B"),
        (b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789", "D174AB98D277D9F5A5611C2C9F419D9F"),
        (
            b"12345678901234567890123456789012345678901234567890123456789012345678901234567890",
            "57EDF4A22BE3C955AC49DA2E2107B67A",
        ),
    ];
    for (message, hash) in cases {
        assert_eq!(revision(message), hash, "{}", String::from_utf8_lossy(message));
    }
}
