use postc::cli::outputs::*;

#[test]
fn links_and_hard_links_are_the_same_file() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in.pp");
    std::fs::write(&input, "x").unwrap();
    let new = dir.path().join("new.nc");
    assert!(check_paths(&[&input], &[&new]).is_ok());
    assert!(check_paths(&[&input], &[&input]).is_err());
    let dotted = dir.path().join(".").join("in.pp");
    assert!(check_paths(&[&input], &[&dotted]).is_err());
    assert!(check_paths(&[], &[&new, &dir.path().join("./new.nc")]).is_err());
    #[cfg(unix)]
    {
        let link = dir.path().join("link.nc");
        std::os::unix::fs::symlink(&input, &link).unwrap();
        assert!(check_paths(&[&input], &[&link]).is_err());
        let hard = dir.path().join("hard.nc");
        std::fs::hard_link(&input, &hard).unwrap();
        assert!(check_paths(&[&input], &[&hard]).is_err());
    }
}

#[test]
fn a_batch_commits_all_or_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.nc"), dir.path().join("b.nc"));
    let batch = Batch::default();
    for target in [&a, &b] {
        let temp = Temp::beside(target).unwrap();
        std::io::Write::write_all(&mut temp.file().unwrap(), b"G0\n").unwrap();
        batch.stage(temp, target.clone());
    }
    assert!(!a.exists() && !b.exists());
    batch.commit(&[], None).unwrap();
    assert_eq!(std::fs::read(&a).unwrap(), b"G0\n");
    assert_eq!(std::fs::read(&b).unwrap(), b"G0\n");
    // An uncommitted batch leaves nothing.
    let c = dir.path().join("c.nc");
    let batch = Batch::default();
    batch.stage(Temp::beside(&c).unwrap(), c.clone());
    drop(batch);
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
}
