use postc_lsp::vocab::*;

#[test]
fn every_section_and_label_has_a_description() {
    for name in section_names() {
        assert!(lookup(VECTRIC_SECTIONS, name).is_some(), "section {name} undescribed");
    }
    for (var, label) in postc_front_vectric::names::VAR_NAMES {
        assert!(lookup(VECTRIC_LABELS, label).is_some(), "label {label} of {var} undescribed");
    }
    for (name, _) in VECTRIC_GLOBALS {
        assert!(postc_front_vectric::names::GlobalName::from_name(name).is_some(), "{name}");
    }
}
