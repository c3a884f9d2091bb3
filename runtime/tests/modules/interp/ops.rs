use postc_ir::{BinaryOp, Builtin};
use postc_runtime::testing::interp_ops::*;
use postc_runtime::value::Value;

#[test]
fn min_max_and_pow_answer_as_javascript() {
    let num = |v: Value| v.num();
    let n = Value::Num;
    assert!(num(builtin(Builtin::Min, &[n(0.0), n(f64::NAN)])).is_nan());
    assert!(num(builtin(Builtin::Max, &[n(1.0), n(f64::NAN), n(3.0)])).is_nan());
    assert_eq!(num(builtin(Builtin::Min, &[n(2.0), n(-1.0)])), -1.0);
    assert!(num(builtin(Builtin::Min, &[n(0.0), n(-0.0)])).is_sign_negative());
    assert!(num(builtin(Builtin::Max, &[n(-0.0), n(0.0)])).is_sign_positive());
    assert_eq!(num(builtin(Builtin::Max, &[])), f64::NEG_INFINITY);
    assert!(num(binary(BinaryOp::Pow, &n(1.0), &n(f64::NAN))).is_nan());
    assert!(num(binary(BinaryOp::Pow, &n(-1.0), &n(f64::INFINITY))).is_nan());
    assert_eq!(num(binary(BinaryOp::Pow, &n(f64::NAN), &n(0.0))), 1.0);
    assert_eq!(num(binary(BinaryOp::Pow, &n(2.0), &n(10.0))), 1024.0);
}

#[test]
fn pictures() {
    assert_eq!(format_picture(12.34567, "0.000"), "12.346");
    assert_eq!(format_picture(2.5, "#.###"), "2.5");
    assert_eq!(format_picture(7.0, "0000"), "0007");
    assert_eq!(format_picture(-0.25, "0.00"), "-0.25");
}

#[test]
fn text_builtins() {
    let t = |s: &str| Value::text(s);
    assert_eq!(builtin(Builtin::Mid, &[t("ABCDEF"), Value::Num(2.0), Value::Num(3.0)]), t("BCD"));
    // JavaScript's substring: clamped, NaN as 0, swapped, a missing end.
    assert_eq!(builtin(Builtin::Substring, &[t("F1500"), Value::Num(1.0)]), t("1500"));
    assert_eq!(builtin(Builtin::Substring, &[t("ABCDEF"), Value::Num(4.0), Value::Num(1.0)]), t("BCD"));
    assert_eq!(builtin(Builtin::Substring, &[t("ABC"), Value::Num(-2.0), Value::Num(9.0)]), t("ABC"));
    assert_eq!(builtin(Builtin::Substring, &[t("ABC"), t("x"), Value::Num(2.0)]), t("AB"));
    assert_eq!(builtin(Builtin::Substring, &[t("été"), Value::Num(1.0)]), t("té"));
    assert_eq!(builtin(Builtin::Right, &[t("ABC"), Value::Num(5.0)]), t("ABC"));
    assert_eq!(builtin(Builtin::Val, &[t(" 12.5mm")]), Value::Num(12.5));
    assert_eq!(binary(BinaryOp::Concat, &Value::Num(3.0), &t("x")), t("3x"));
    assert_eq!(binary(BinaryOp::Add, &Value::Num(3.0), &Value::Num(0.5)), Value::Num(3.5));
}

/// `compare`'s path for two numbers answers what `binary` answers, for
/// every comparison, NaN, signed zeros and infinities included.
#[test]
fn numbers_compare_as_binary_compares_them() {
    use BinaryOp::*;
    let numbers = [f64::NAN, f64::NEG_INFINITY, -1.5, -0.0, 0.0, 1.0, 1.5, f64::INFINITY];
    for op in [Eq, Ne, Lt, Le, Gt, Ge, JsEq, JsNe, JsLt, JsLe, JsGt, JsGe, StrictEq, StrictNe] {
        for x in numbers {
            for y in numbers {
                let (a, b) = (Value::Num(x), Value::Num(y));
                let Value::Bool(full) = binary(op, &a, &b) else { panic!("{op:?} gives no truth value") };
                assert_eq!(compare(op, &a, &b), Some(full), "{x} {op:?} {y}");
            }
        }
    }
}
