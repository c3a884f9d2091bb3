use postc::cli::outputs::Batch;
use postc::cli::sink::*;
use postc_ir::post::TapeSplitting;
use postc_runtime::output::Finished;

#[test]
fn files_appear_only_when_finished() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("o.nc");
    let batch = Batch::default();
    let mut out = file(&target, &batch).unwrap();
    out.buf.extend_from_slice(b"G0X1\n");
    out.end_block();
    out.flush();
    assert!(!target.exists());
    let files = out.finish(None).unwrap();
    assert!(matches!(files, Finished::Files(ref f) if f == std::slice::from_ref(&target)));
    assert!(!target.exists());
    batch.commit(&[], None).unwrap();
    assert_eq!(std::fs::read(&target).unwrap(), b"G0X1\n");
    // A dropped (failed) run leaves nothing behind.
    let other = dir.path().join("p.nc");
    let mut out = file(&other, &batch).unwrap();
    out.buf.extend_from_slice(b"G0X1\n");
    out.flush();
    drop(out);
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
}

#[test]
fn tape_split_parts_are_named_at_the_end() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("t.tap");
    let tape = TapeSplitting {
        max_lines: 1,
        tolerance: 0,
        name_format: "%s_%d.tap".into(),
        start_index: 1,
        index_on_first_file: true,
    };
    let batch = Batch::default();
    let mut out = file(&target, &batch).unwrap();
    out.buf.extend_from_slice(b"A\n");
    out.end_block();
    out.new_part();
    out.buf.extend_from_slice(b"B\n");
    out.end_block();
    assert_eq!(
        std::fs::read_dir(dir.path())
            .unwrap()
            .filter_map(Result::ok)
            .filter(|e| !e.file_name().to_string_lossy().starts_with(".postc-"))
            .count(),
        0
    );
    let Finished::Files(files) = out.finish(Some(&tape)).unwrap() else { panic!("files") };
    assert_eq!(files, [dir.path().join("t_1.tap"), dir.path().join("t_2.tap")]);
    batch.commit(&[], None).unwrap();
    assert_eq!(std::fs::read(&files[1]).unwrap(), b"B\n");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
}
