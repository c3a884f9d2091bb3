use postc_reader_apt::{Content, sniff};

#[test]
fn heads_are_told_apart() {
    assert_eq!(sniff(b"$$* Pro/CLfile\nPARTNO / X\nGOTO / 1,2,3\n"), Content::ClText);
    assert_eq!(sniff(b"TOOL PATH/A,TOOL,B\n"), Content::ClText);
    assert_eq!(sniff(b"REMARK x\nCUTTER/1\n"), Content::ClText);
    assert!(matches!(sniff(b"PARTNO TEST\nPL1 = PLANE/0,0,1,0\nGO/TO,PL1\n"), Content::PartProgram(12, 31)));
    assert!(matches!(sniff(b"P(1)=POINT/1,2,3\n"), Content::PartProgram(..)));
    assert_eq!(sniff(b"POST_NAME = \"Mach3\"\n+ comment\n"), Content::Other);
    assert_eq!(sniff(b"G0 X1 Y2\nG1 Z-1\n"), Content::Other);
    assert!(
        matches!(sniff(&[1, 0, 0, 0, 2, 0, 0, 0, 0xe8, 3, 0, 0, 1, 0, 0, 0]), Content::Binary(k) if k.contains("APT360"))
    );
}
