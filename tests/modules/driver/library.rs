use postc_driver::library::{Lookup, lookup};

const NAMES: &[&str] = &["LinuxCNC (mm) (*.ngc)", "grbl (mm) (*.nc)", "Haas VF mill (mm)", "Fanuc 0i/30i mill (mm)"];

#[test]
fn names_match_ignoring_case_and_blanks() {
    assert_eq!(lookup("LinuxCNC (mm) (*.ngc)", NAMES), Lookup::One(0));
    assert_eq!(lookup("  linuxcnc   (MM) (*.NGC) ", NAMES), Lookup::One(0));
    assert_eq!(lookup("haas vf mill (mm)", NAMES), Lookup::One(2));
}

#[test]
fn a_vectric_name_matches_without_its_file_pattern() {
    assert_eq!(lookup("LinuxCNC (mm)", NAMES), Lookup::One(0));
    assert_eq!(lookup("grbl (mm)", NAMES), Lookup::One(1));
    // Only a trailing `(*.ext)` is a file pattern: `(mm)` is part of the name.
    assert!(matches!(lookup("Haas VF mill", NAMES), Lookup::NotFound(_)));
}

#[test]
fn a_near_miss_suggests_the_nearest_names_then_those_that_hold_it() {
    assert_eq!(lookup("LinuxCNC (nm)", NAMES), Lookup::NotFound(vec![0]));
    assert_eq!(lookup("Fanuc 0i/30i mil (mm)", NAMES), Lookup::NotFound(vec![3]));
    assert_eq!(lookup("grbl", NAMES), Lookup::NotFound(vec![1]));
    // A word of the name mistyped.
    assert_eq!(lookup("grbel", NAMES), Lookup::NotFound(vec![1]));
    assert_eq!(lookup("hass", NAMES), Lookup::NotFound(vec![2]));
    assert_eq!(lookup("mill", NAMES), Lookup::NotFound(vec![2, 3]));
    assert_eq!(lookup("Heidenhain", NAMES), Lookup::NotFound(vec![]));
}

#[test]
fn two_posts_of_one_name_are_ambiguous() {
    let names = ["Shop (mm) (*.nc)", "Other", "shop  (MM) (*.nc)"];
    assert_eq!(lookup("Shop (mm) (*.nc)", &names), Lookup::Ambiguous(vec![0, 2]));
    assert_eq!(lookup("shop (mm)", &names), Lookup::Ambiguous(vec![0, 2]));
}
