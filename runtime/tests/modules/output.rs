use postc_ir::post::TapeSplitting;
use postc_runtime::output::*;
use std::path::{Path, PathBuf};

fn tape(first: bool) -> TapeSplitting {
    TapeSplitting {
        max_lines: 1000,
        tolerance: 100,
        name_format: "%s_%d.tap".into(),
        start_index: 1,
        index_on_first_file: first,
    }
}

#[test]
fn names_follow_the_format() {
    let t = tape(true);
    let names = part_names(Path::new("out/toolpath.tap"), 3, Some(&t));
    assert_eq!(names, ["out/toolpath_1.tap", "out/toolpath_2.tap", "out/toolpath_3.tap"].map(PathBuf::from));
    let t = tape(false);
    let names = part_names(Path::new("toolpath.tap"), 2, Some(&t));
    assert_eq!(names, ["toolpath.tap", "toolpath_1.tap"].map(PathBuf::from));
    assert_eq!(part_names(Path::new("a.tap"), 1, Some(&t)), [PathBuf::from("a.tap")]);
    assert_eq!(c_format("P%03d_%s.nc", "x", 7), "P007_x.nc");
}

#[test]
fn memory_parts_and_discard() {
    let mut out = Output::memory();
    out.buf.extend_from_slice(b"G0X1\n");
    out.end_block();
    out.new_part();
    out.buf.extend_from_slice(b"G0X2\n");
    out.end_block();
    assert_eq!((out.blocks(), out.bytes()), (2, 10));
    let Ok(Finished::Memory(parts)) = out.finish(None) else { panic!("memory parts") };
    assert_eq!(parts, [b"G0X1\n".to_vec(), b"G0X2\n".to_vec()]);
    let mut out = Output::discard();
    out.buf.extend_from_slice(b"G0X1\n");
    out.end_block();
    assert!(matches!(out.finish(None), Ok(Finished::Streamed)));
}
