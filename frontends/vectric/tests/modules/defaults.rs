use postc_front_vectric::defaults::*;
use postc_front_vectric::format_spec::parse_format;
use postc_front_vectric::testing::default_text;
use postc_ir::{Modality, Quantity};

#[test]
fn seed_defaults() {
    let x = default_format(Quantity::X);
    assert_eq!((x.modality, x.prefix, x.format.decimals), (Modality::Always, "", 3));
    let length = default_format(Quantity::XLength);
    assert_eq!((length.modality, length.prefix, length.format.decimals), (Modality::Always, "", 3));
    let fc = default_format(Quantity::CutFeed);
    assert_eq!((fc.modality, fc.prefix, fc.format.decimals), (Modality::OnChange, "", 0));
    let n = default_format(Quantity::BlockNumber);
    assert_eq!((n.prefix, n.format.decimals), ("", 0));
}

#[test]
fn every_format_parses() {
    for &q in Quantity::ALL {
        let (_, _, text) = default_text(q);
        assert!(parse_format(text).is_ok(), "{q:?}: {text}");
    }
    assert_eq!(default_format(Quantity::DwellTime).format.decimals, 2);
}
