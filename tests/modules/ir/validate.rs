use postc_ir::code::{Expr, Piece, Stmt};
use postc_ir::post::Post;
use postc_ir::post::{Handler, HandlerKey, Section, ValueSource, Variable};
use postc_ir::validate::*;
use postc_ir::{Modality, NumberFormat};

fn post() -> Post {
    Post {
        formats: vec![NumberFormat::default()],
        variables: vec![Variable {
            name: "X".into(),
            source: ValueSource::Quantity(postc_ir::Quantity::X),
            prefix: b"X".to_vec(),
            format: postc_ir::FormatId::new(0),
            modality: Modality::OnChange,
            span: None,
        }],
        handlers: vec![Handler {
            key: HandlerKey::Section(Section::RapidMove),
            body: vec![Stmt::Line {
                pieces: vec![Piece::Text(b"G0".to_vec()), Piece::Var(postc_ir::VarId::new(0))],
                span: None,
            }],
            span: None,
        }],
        ..Post::default()
    }
}

#[test]
fn a_consistent_post_is_valid() {
    assert_eq!(validate(&post()), Vec::new());
}

#[test]
fn ids_out_of_range_are_found_where_they_are() {
    let mut p = post();
    p.handlers[0].body.push(Stmt::Line { pieces: vec![Piece::Var(postc_ir::VarId::new(9))], span: None });
    p.variables[0].format = postc_ir::FormatId::new(3);
    p.handlers[0]
        .body
        .push(Stmt::Eval(Expr::Call(postc_ir::FunctionId::new(2), vec![Expr::Global(postc_ir::GlobalId::new(1))])));
    let found = validate(&p);
    let at: Vec<Item> = found.iter().map(|i| i.at).collect();
    assert_eq!(at, [Item::Variable(0), Item::Handler(0), Item::Handler(0), Item::Handler(0)], "{found:?}");
    assert!(found[1].message.contains("variable 9 does not exist (the post has 1)"));
}

#[test]
fn options_that_steer_output_are_checked() {
    let mut p = post();
    p.options.arc_tolerance = 0.0;
    p.options.step_budget = 0;
    p.formats[0].multiplier = f64::NAN;
    let found = validate(&p);
    assert_eq!(found.len(), 3, "{found:?}");
}

#[test]
fn regular_expression_flags_are_checked() {
    let mut p = post();
    let regex = |flags: &str| Expr::Regex { pattern: "x".into(), flags: flags.into(), span: None };
    p.handlers[0].body.push(Stmt::Eval(regex("gim")));
    assert_eq!(validate(&p), Vec::new());
    p.handlers[0].body.push(Stmt::Eval(regex("gg")));
    p.handlers[0].body.push(Stmt::Eval(regex("y")));
    let found = validate(&p);
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(found[0].message.contains("`gg`"), "{found:?}");
}
