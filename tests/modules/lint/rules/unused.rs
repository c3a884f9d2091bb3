use crate::modules::lint::{lint_cimco, lint_vcpost, lint_vectric};

#[test]
fn fires_on_an_unused_var() {
    let found = lint_vectric("VAR SAFE_Z = [SAFEZ|A|Z|1.3]\nbegin FEED_MOVE\n\"G1[X][F]\"\n");
    assert!(found.iter().any(|d| d.code == "LN007"), "{found:?}");
}

#[test]
fn quiet_on_a_used_var() {
    let found = lint_vectric("VAR SAFE_Z = [SAFEZ|A|Z|1.3]\nbegin FEED_MOVE\n\"G1[X][SAFEZ][F]\"\n");
    assert!(!found.iter().any(|d| d.code == "LN007"), "{found:?}");
}

const JS: &str = "var xyzFormat = createFormat({decimals:3});\nvar unusedFormat = createFormat({decimals:1});\nvar xOutput = createVariable({prefix:\"X\"}, xyzFormat);\nfunction helper() { return \"(H)\"; }\nfunction unused() { return \"\"; }\nfunction onLinear(x, y, z, movement) { return helper() + xOutput.format(x); }\n";

#[test]
fn cimco_unused_format_and_function_fire() {
    let found = lint_cimco(JS);
    assert!(found.iter().any(|d| d.code == "LN008"), "{found:?}");
    let fns: Vec<_> = found.iter().filter(|d| d.code == "LN009").map(|d| d.message.clone()).collect();
    assert_eq!(fns, ["function `unused` is never called"], "{found:?}");
}

/// A format handed to a helper as a value and a function handed to
/// `filter` are used.
#[test]
fn cimco_formats_and_functions_used_as_values_are_quiet() {
    let found = lint_cimco(
        "var xyzFormat = createFormat({decimals:3});\nfunction word(f, v) { return f.format(v); }\nfunction kept(w) { return w !== \"\"; }\nfunction onLinear(x, y, z, movement) { return [word(xyzFormat, x)].filter(kept).join(\"\"); }\n",
    );
    assert!(!found.iter().any(|d| d.code == "LN008" || d.code == "LN009"), "{found:?}");
}

#[test]
fn vcpost_sub_nothing_can_call_fires() {
    let found = lint_vcpost(
        "Sub GOTO\n  Call Helper\n  Out \"G1 <X>\"\nEnd Sub\nSub Helper\n  Out \"(H)\"\nEnd Sub\nSub Forgotten\n  Out \"(F)\"\nEnd Sub\n",
    );
    let subs: Vec<_> = found.iter().filter(|d| d.code == "LN016").map(|d| d.message.clone()).collect();
    assert_eq!(subs, ["`Forgotten` is never called"], "{found:?}");
}

#[test]
fn vcpost_subs_offered_by_keyword_or_raised_as_events_are_quiet() {
    let found = lint_vcpost(
        "Sub GOTO\n  Out \"G1 <X>\"\nEnd Sub\nSub OpMessage()\n' #Option\n' #C1 Message to the operator\n  Out \"(MSG)\"\nEnd Sub\nSub CamPoint\n  Out \"(P)\"\nEnd Sub\n",
    );
    assert!(!found.iter().any(|d| d.code == "LN016"), "{found:?}");
}
