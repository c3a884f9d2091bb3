use postc_fuzz::testing::root::*;
use postc_fuzz::*;

#[test]
fn mutants_are_reproducible_and_differ_from_their_seed() {
    let seed = b"VAR X = [X|C|X|1.3]\nbegin HEADER\n\"G0 [X]\"\n";
    let a = mutate(&mut fastrand::Rng::with_seed(7), seed, &[]);
    let b = mutate(&mut fastrand::Rng::with_seed(7), seed, &[]);
    assert_eq!(a, b);
    let differ = (0..50).filter(|s| mutate(&mut fastrand::Rng::with_seed(*s), seed, &[]) != seed).count();
    assert!(differ > 40, "{differ} of 50 mutants differ");
}

#[test]
fn human_output_without_a_code_is_found() {
    assert_eq!(uncoded(b"error[PP001]: x\nwarning[RT010]: y\n"), None);
    assert!(uncoded(b"error: something\n").is_some());
}

#[test]
fn json_items_need_a_code_and_a_position() {
    assert_eq!(json_problem(br#"[{"file":"a.pp","code":"PP001","line":1,"column":2}]"#), None);
    assert!(matches!(json_problem(br#"[{"file":"a.pp","code":"","line":1,"column":2}]"#), Some(Problem::NoCode(_))));
    assert!(matches!(
        json_problem(br#"[{"file":"a.pp","code":"PP001","line":null,"column":null}]"#),
        Some(Problem::NoPosition(_))
    ));
}
