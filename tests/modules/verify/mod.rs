mod geometry;
mod grammar;
mod interp;
mod plot;

use postc_verify::*;

/// The LinuxCNC limit as LinuxCNC's `rs274` applies it (measured: a G2
/// from X0 to X10 with I5.014 is read, I5.0145 refused; from X0 to X2000
/// I1000.5 is read, I1001 refused).
#[test]
fn the_linuxcnc_radius_limit_agrees_with_rs274() {
    let check = |i: f64, end: f64| Controller::LinuxCnc.radius_error(i, end - i, false).is_some();
    assert!(!check(5.014, 10.0));
    assert!(check(5.0145, 10.0));
    assert!(!check(1000.5, 2000.0));
    assert!(check(1001.0, 2000.0));
}

#[test]
fn the_grbl_radius_limit() {
    assert!(Controller::Grbl.radius_error(5.0, 5.004, false).is_none());
    assert!(Controller::Grbl.radius_error(5.0, 5.006, false).is_some());
    assert!(Controller::Grbl.radius_error(1000.0, 1000.4, false).is_none());
    assert!(Controller::Grbl.radius_error(1000.0, 1000.6, false).is_some());
}

pub mod family_tests {
    use postc_verify::*;

    #[test]
    fn families_by_their_first_lines() {
        assert_eq!(foreign_family(b"IN;\nSP1;\nPU0,0;\n"), Some("HPGL"));
        assert_eq!(foreign_family(b"'job\nSA\nMS,1,0.5\nJ3,1,2,3\n"), Some("ShopBot"));
        assert_eq!(foreign_family(b"0 BEGIN PGM 1 MM\n1 BLK FORM\n"), Some("Heidenhain conversational"));
        // Decimal commas are G-code too.
        assert_eq!(foreign_family(b"%\nG90G17G71\nG00X10,000Y10,000\nX5,000Y2,5\n"), None);
        assert_eq!(foreign_family(b"G21 G90\nG0 X1 Y2\n"), None);
        // Sinumerik is read (docs/verify.md): not a foreign family.
        assert_eq!(foreign_family(b"N10 G17 G90 G71\nN20 MCALL CYCLE81(10, 0, 2, -3, )\n"), None);
        assert_eq!(foreign_family(b"N430 G0 SUPA Z0\n"), None);
        assert_eq!(foreign_family(b"\nPRINT \"1001\"\n;date\n"), Some("Kawasaki AS (robot language)"));
        assert_eq!(foreign_family(b".PROGRAM job()\nLMOVE p1\n.END\n"), Some("Kawasaki AS (robot language)"));
        assert_eq!(foreign_family(b"[ 1001\nG90\nG0 X1\n"), Some("Selca"));
        assert_eq!(foreign_family(b": (PGM, NAME=\"1001\")\n: G90\n"), Some("Acramatic"));
        assert_eq!(foreign_family(b"\x11\n:1001;\n'job';\nN10G90;\n"), Some("Bridgeport DNC tape"));
        assert_eq!(foreign_family(b"Tool;Diameter;Length;Comment\n1;6;30;end mill\n"), Some("a CSV sheet"));
        // A Boxford header and Fanuc's `[` expressions are not Selca's remarks.
        assert_eq!(foreign_family(b"[GM HEADER]\ntype=mill\n[PROGRAM]\nG0 X1\n"), None);
        assert_eq!(foreign_family(b"#1=[2+3]\nG0 X[#1]\n"), None);
    }
}
