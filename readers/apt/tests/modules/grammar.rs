use chumsky::inspector::TruncateState;
use chumsky::prelude::*;
use postc_reader_apt::testing::grammar::*;

type Parsed = (Shape, Vec<(ItemKind, String, f64)>);

fn parse(text: &str) -> Result<Parsed, usize> {
    let mut items = TruncateState(Vec::new());
    let result = record().parse_with_state(text.as_bytes(), &mut items);
    match result.into_result() {
        Ok(shape) => Ok((
            shape,
            items.iter().map(|i| (i.kind, text[i.start as usize..i.end as usize].to_string(), i.value)).collect(),
        )),
        Err(errors) => Err(errors.first().map_or(0, |e| e.span().start)),
    }
}

#[test]
fn records_of_every_shape() {
    let (shape, items) = parse("GOTO / 1.5, -2,3.").unwrap();
    assert_eq!(shape, Shape::Slash);
    assert_eq!(items.len(), 4);
    assert_eq!(items[3].2, 3.0);
    assert_eq!(parse("RAPID").unwrap().0, Shape::Bare);
    assert_eq!(parse("RAPID/").unwrap().1.len(), 1);
    let (_, items) = parse("TOOL PATH/8_KONTUR,TOOL,FACE_MILL_1").unwrap();
    assert_eq!(items[1].0, ItemKind::Head);
    assert_eq!(items[2].0, ItemKind::Word);
    let (_, items) = parse("TLON,GOFWD/ (CIRCLE/ 1, 2, 3, 5), ON, (LINE/ 1,2,3,4,5,6)").unwrap();
    assert_eq!(items.iter().filter(|i| i.0 == ItemKind::Open).count(), 2);
    assert_eq!(items.iter().filter(|i| i.0 == ItemKind::Close).count(), 2);
    let (_, items) = parse("THREAD/.05,(.5-2*.05*.6),-1.2").unwrap();
    assert!((items[2].2 - 0.44).abs() < 1e-12);
    let (_, items) = parse("CYCLE/ DRILL,3.0,46.9 46.9 DWELL,0").unwrap();
    assert_eq!(items.iter().filter(|i| i.0 == ItemKind::MissingComma).count(), 2);
    assert_eq!(parse("PL1=PLANE/0,0,1,0").unwrap().0, Shape::Assignment);
    assert_eq!(parse("CUTTER/ 6.0,0.0,").unwrap().1.len(), 3);
}

#[test]
fn errors_point_at_the_bad_byte() {
    assert_eq!(parse("GOTO/1,,2"), Err(7));
    assert!(parse("1,2,3").is_err());
    assert!(parse("GOTO/(1/0)").is_err());
}
