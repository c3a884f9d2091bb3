use postc_front_vectric::diagnostics::*;
use postc_ir::codes;

#[test]
fn the_enum_names_every_pp_entry_in_order() {
    let pp: Vec<&str> = codes::ALL.iter().map(|c| c.code).filter(|c| c.starts_with("PP")).collect();
    let named: Vec<&str> = Code::ALL.iter().map(|c| c.id()).collect();
    assert_eq!(named, pp);
}
