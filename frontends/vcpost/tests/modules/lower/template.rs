use postc_front_vcpost::testing::lower_template::TemplatePart::{Register as R, Text as T};
use postc_front_vcpost::testing::lower_template::*;

#[test]
fn splits_registers_from_text() {
    assert_eq!(split("<N> G0<X><Y>"), vec![R("N"), T(" G0"), R("X"), R("Y")]);
    assert_eq!(split("(X<0) <> <A_1>"), vec![T("(X<0) <> "), R("A_1")]);
    assert_eq!(split("<<X>>"), vec![T("<"), R("X"), T(">")]);
    assert_eq!(split("a < b"), vec![T("a < b")]);
    assert_eq!(split(""), vec![]);
}

#[test]
fn finds_unclosed_registers() {
    assert_eq!(unclosed("<N><X"), vec![3..5]);
    assert_eq!(unclosed("<N> G0<X<Y>"), vec![6..8]);
    assert_eq!(unclosed("<FeedRate"), vec![0..9]);
    for closed in ["<N> G0<X><Y>", "(X<0)", "a < b", "(DIST<MAX)", "<<X>>", "<>", "x<", ""] {
        assert_eq!(unclosed(closed), Vec::<std::ops::Range<usize>>::new(), "{closed}");
    }
}
