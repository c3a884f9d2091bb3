//! A CL file of many bad records, for `tests/check_scaling.rs` and
//! `benches/check_errors.rs`.

/// A CL file of about `bytes` bytes where every other GOTO is bad (a stray
/// word among its numbers: one error and one warning each).
pub fn bad_cl(bytes: usize) -> String {
    let mut text = String::from("PARTNO/MANY ERRORS\nUNITS/MM\nLOADTL/1\nCUTTER/6.\nRAPID\nGOTO/0,0,25.\n");
    let mut i = 0u32;
    while text.len() < bytes {
        let x = f64::from(i) * 0.01;
        if i.is_multiple_of(2) {
            text.push_str(&format!("GOTO  /   {x:.4},Q    1.7270,    3.1466, 0.0000000, 0.0000000, 1.0000000\n"));
        } else {
            text.push_str(&format!("GOTO  /   {x:.4},    0.7247,    2.2967, 0.0085511,-0.0050286, 0.9999508\n"));
        }
        i += 1;
    }
    text.push_str("FINI\n");
    text
}
