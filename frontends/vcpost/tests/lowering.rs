//! Lowering: small posts and the exact IR they become.

use postc_report::Render as _;
use std::path::Path;

use postc_front_vcpost::{compile, looks_like_vcpost, signatures};
use postc_ir::{
    BinaryOp, Body, Builtin, Dialect, Dispatch, Expr, HandlerKey, Modality, Piece, Place, Post, Quantity, Stmt,
    UnaryOp, ValueSource,
};
use postc_ir::{FunctionId, GlobalId, LocalId, VarId};

/// The post a text compiles to, with its spans (where things are in the
/// text) dropped so that statements compare by what they do.
fn post(text: &str) -> Post {
    let mut post = post_with_spans(text);
    post.drop_spans();
    post
}

fn post_with_spans(text: &str) -> Post {
    let mut sources = postc_report::source_map();
    let (post, diagnostics) = compile(Path::new("t.VcPost"), text.as_bytes(), &mut sources);
    assert!(diagnostics.is_empty(), "{}", sources.render(&diagnostics, false));
    post
}

fn line(pieces: Vec<Piece>) -> Stmt {
    Stmt::Line { pieces, span: None }
}

fn body<'a>(post: &'a Post, name: &str) -> &'a [Stmt] {
    let f = post.functions.iter().find(|f| f.name == name).unwrap_or_else(|| panic!("no function {name}"));
    match &f.body {
        Body::Native(stmts) => stmts,
        Body::Script(_) => panic!("script body"),
    }
}

fn var(post: &Post, name: &str) -> u16 {
    post.variables.iter().position(|v| v.name == name).unwrap_or_else(|| panic!("no register {name}")) as u16
}

fn global(post: &Post, name: &str) -> u16 {
    post.globals.iter().position(|g| g.name == name).unwrap_or_else(|| panic!("no global {name}")) as u16
}

fn text(s: &str) -> Piece {
    Piece::Text(s.as_bytes().to_vec())
}

fn bin(op: BinaryOp, a: Expr, b: Expr) -> Expr {
    Expr::Binary(op, Box::new(a), Box::new(b))
}

#[test]
fn out_templates_become_lines_of_pieces() {
    let p = post("Sub GOTO\n  Out \"<N> G0<X><Y>\"\n  Out \"<N>(\" & OptString1 & \")\"\n  Out\nEnd Sub\n");
    let (n, x, y) = (var(&p, "N"), var(&p, "X"), var(&p, "Y"));
    let opt = global(&p, "OptString1");
    assert_eq!(
        body(&p, "GOTO"),
        &[
            line(vec![Piece::Var(VarId::new(n)), text(" G0"), Piece::Var(VarId::new(x)), Piece::Var(VarId::new(y))]),
            line(vec![Piece::Var(VarId::new(n)), text("("), Piece::Expr(Expr::Global(GlobalId::new(opt))), text(")")]),
            line(vec![]),
        ]
    );
    assert_eq!(p.variables[n as usize].source, ValueSource::Quantity(Quantity::BlockNumber));
    assert_eq!(p.variables[x as usize].source, ValueSource::Assigned);
    assert_eq!(p.variables[x as usize].prefix, b"X");
    assert_eq!(p.globals[opt as usize].initial, Expr::Text(String::new()));
    assert_eq!(p.info.dialect, Dialect::VcPost);
    assert_eq!(p.info.dispatch, Dispatch::AptWords);
}

#[test]
fn register_properties_and_defaults() {
    let p = post(
        "N.Start = 100\nN.Increment = 5\nX.Prefix = \" X\"\nX.Format = \"+4.3\"\nX.Modal = True\nX.DecimalPoint = True\nT.LeadingZeros = 2\nOut \"<N><X><Y><T>\"\n",
    );
    assert_eq!(p.options.block_numbers.start, 100.0);
    assert_eq!(p.options.block_numbers.increment, 5.0);
    let x = &p.variables[var(&p, "X") as usize];
    assert_eq!(x.prefix, b" X");
    assert_eq!(x.modality, Modality::OnChange);
    let fx = &p.formats[x.format.index()];
    assert_eq!(
        (fx.decimals, fx.sign, fx.point, fx.trim_zeros),
        (3, postc_ir::SignStyle::Always, postc_ir::PointStyle::Always, true)
    );
    let y = &p.variables[var(&p, "Y") as usize];
    let fy = &p.formats[y.format.index()];
    assert_eq!((y.prefix.as_slice(), y.modality, fy.decimals, fy.trim_zeros), (&b"Y"[..], Modality::Always, 4, true));
    let t = &p.variables[var(&p, "T") as usize];
    let ft = &p.formats[t.format.index()];
    assert_eq!((ft.width, ft.width_of, ft.padding), (2, postc_ir::WidthOf::IntegerDigits, postc_ir::Padding::Zero));
    assert_eq!(p.init.len(), 1, "properties are not runtime statements");
}

#[test]
fn for_loops_keep_bounds_and_pick_the_test_by_the_step() {
    let text = "Sub A\n  Dim i\n  Count = 3\n  For i = 10 To 1 Step -2\n    Out \"x\"\n  Next\n  For i = 1 To Count Step S\n  Next i\nEnd Sub\n";
    let with_spans = post_with_spans(text);
    assert!(matches!(body(&with_spans, "A")[3], Stmt::While { span: Some(_), .. }), "a loop keeps its place");
    let p = post(text);
    let b = body(&p, "A");
    assert_eq!(b[2], Stmt::Assign(Place::Local(LocalId::new(0)), Expr::Number(10.0)));
    let Stmt::While { cond, body: inner, .. } = &b[3] else { panic!("{:?}", b[3]) };
    assert_eq!(*cond, bin(BinaryOp::Ge, Expr::Local(LocalId::new(0)), Expr::Number(1.0)));
    assert_eq!(
        inner.last(),
        Some(&Stmt::Assign(
            Place::Local(LocalId::new(0)),
            bin(BinaryOp::Add, Expr::Local(LocalId::new(0)), Expr::Unary(UnaryOp::Neg, Box::new(Expr::Number(2.0))))
        ))
    );
    assert_eq!(b[5], Stmt::Assign(Place::Local(LocalId::new(1)), Expr::Global(GlobalId::new(global(&p, "Count")))));
    let Stmt::While { cond, .. } = &b[7] else { panic!("{:?}", b[7]) };
    assert!(matches!(cond, Expr::Choose(..)), "{cond:?}");
}

#[test]
fn do_loops_select_case_xor_and_exits() {
    let p = post(
        "Sub A\n  Do\n    If X > 3 Then Exit Do\n  Loop Until X Xor Y\n  Select Case T\n    Case 1, 2 To 3, Is > 4\n      Out \"a\"\n    Case Else\n      Out \"b\"\n  End Select\nEnd Sub\n",
    );
    let b = body(&p, "A");
    let (x, y, t) = (
        Expr::Global(GlobalId::new(global(&p, "X"))),
        Expr::Global(GlobalId::new(global(&p, "Y"))),
        Expr::Global(GlobalId::new(global(&p, "T"))),
    );
    let Stmt::While { cond, body: inner, .. } = &b[0] else { panic!() };
    assert_eq!(*cond, Expr::Bool(true));
    assert_eq!(
        inner[0],
        Stmt::If {
            branches: vec![(bin(BinaryOp::Gt, x.clone(), Expr::Number(3.0)), vec![Stmt::Break])],
            otherwise: vec![]
        }
    );
    let xor = bin(BinaryOp::Ne, Expr::Unary(UnaryOp::Not, Box::new(x)), Expr::Unary(UnaryOp::Not, Box::new(y)));
    assert_eq!(inner[1], Stmt::If { branches: vec![(xor, vec![Stmt::Break])], otherwise: vec![] });
    let Stmt::If { branches, otherwise } = &b[1] else { panic!() };
    let one = bin(BinaryOp::Eq, t.clone(), Expr::Number(1.0));
    let range = bin(
        BinaryOp::And,
        bin(BinaryOp::Ge, t.clone(), Expr::Number(2.0)),
        bin(BinaryOp::Le, t.clone(), Expr::Number(3.0)),
    );
    let is = bin(BinaryOp::Gt, t, Expr::Number(4.0));
    assert_eq!(branches[0].0, bin(BinaryOp::Or, bin(BinaryOp::Or, one, range), is));
    assert_eq!(otherwise, &vec![line(vec![text("b")])]);
}

#[test]
fn functions_return_their_own_name() {
    let p = post(
        "Function Half(V)\n  If V < 0 Then Exit Function\n  Half = V / 2\nEnd Function\nSub A\n  Z = Half(4)\nEnd Sub\n",
    );
    let f = p.functions.iter().find(|f| f.name == "Half").unwrap();
    assert_eq!((f.params.clone(), f.slots), (vec!["V".to_string()], 2));
    let b = body(&p, "Half");
    assert_eq!(b[0], Stmt::Assign(Place::Local(LocalId::new(1)), Expr::Number(0.0)));
    assert_eq!(
        b[1],
        Stmt::If {
            branches: vec![(
                bin(BinaryOp::Lt, Expr::Local(LocalId::new(0)), Expr::Number(0.0)),
                vec![Stmt::Return(Some(Expr::Local(LocalId::new(1))))]
            )],
            otherwise: vec![]
        }
    );
    assert_eq!(
        b[2],
        Stmt::Assign(
            Place::Local(LocalId::new(1)),
            bin(BinaryOp::Div, Expr::Local(LocalId::new(0)), Expr::Number(2.0))
        )
    );
    assert_eq!(b[3], Stmt::Return(Some(Expr::Local(LocalId::new(1)))));
    assert_eq!(
        body(&p, "A")[0],
        Stmt::Assign(
            Place::Global(GlobalId::new(global(&p, "Z"))),
            Expr::Call(FunctionId::new(0), vec![Expr::Number(4.0)])
        )
    );
}

#[test]
fn handlers_for_apt_words_and_composites_routines_only() {
    let p = post(
        "Sub GOTO\nEnd Sub\nsub fedrat\nend sub\nSub Modals\nEnd Sub\nSub GoFeel\nEnd Sub\nSub Rapid()\n' #Rapid !X\nEnd Sub\nSub [End]\nEnd Sub\n",
    );
    let keys: Vec<&HandlerKey> = p.handlers.iter().map(|h| &h.key).collect();
    assert_eq!(
        keys,
        vec![
            &HandlerKey::Word("GOTO".into()),
            &HandlerKey::Word("FEDRAT".into()),
            &HandlerKey::Word("MODALS".into()),
            &HandlerKey::Word("END".into()),
        ]
    );
    assert_eq!(p.handlers[0].body, vec![Stmt::Eval(Expr::Call(FunctionId::new(0), vec![]))]);
    assert_eq!(
        p.info.subs,
        vec![postc_ir::SubSignature {
            name: "Rapid".into(),
            keyword: Some("Rapid".into()),
            params: vec![postc_ir::SubParam { name: "X".into(), required: true }],
            tips: Vec::new(),
        }]
    );
}

#[test]
fn builtins_map_to_the_ir() {
    let p = post(
        "A = Format(X, \"0.00\") & Str(1) & Format(2)\nB = IIf(X > 1, 1, 2)\nC = Sqr(Abs(-4)) + Int(1.5) + Fix(-1.5) + Round(2.5, 1)\nD = Mid(\"abc\", 2) & UCase(Left$(\"ab\", 1))\n",
    );
    let Stmt::Assign(_, a) = &p.init[0] else { panic!() };
    let x = Expr::Global(GlobalId::new(global(&p, "X")));
    let expected = bin(
        BinaryOp::Concat,
        bin(
            BinaryOp::Concat,
            Expr::Builtin(Builtin::FormatPicture, vec![x.clone(), Expr::Text("0.00".into())]),
            Expr::Builtin(Builtin::Str, vec![Expr::Number(1.0)]),
        ),
        Expr::Builtin(Builtin::Str, vec![Expr::Number(2.0)]),
    );
    assert_eq!(*a, expected);
    let Stmt::Assign(_, b) = &p.init[1] else { panic!() };
    assert!(matches!(b, Expr::Choose(..)));
    let Stmt::Assign(_, d) = &p.init[3] else { panic!() };
    assert!(matches!(d, Expr::Binary(BinaryOp::Concat, l, _) if matches!(**l, Expr::Builtin(Builtin::Mid, _))));
}

#[test]
fn language_is_case_insensitive_and_lines_continue() {
    let p = post(
        "x.PREFIX = \" X\"\nSUB goto\n  LET x = 1 + _\n      2\n  IF x > 2 THEN OUT \"<X>\" ELSE out \"<n>\"\nend SUB\n",
    );
    let x = var(&p, "x");
    let b = body(&p, "goto");
    assert_eq!(b[0], Stmt::Assign(Place::Var(VarId::new(x)), bin(BinaryOp::Add, Expr::Number(1.0), Expr::Number(2.0))));
    let Stmt::If { otherwise, .. } = &b[1] else { panic!() };
    assert_eq!(otherwise[0], line(vec![Piece::Var(VarId::new(var(&p, "N")))]));
}

#[test]
fn previous_and_host_functions() {
    let p = post("Sub GoTo\n  If Z < Z.Previous Then Out \"<Z>\"\n  L = getNthLength1(0)\nEnd Sub\n");
    let z = var(&p, "Z");
    let b = body(&p, "GoTo");
    let Stmt::If { branches, .. } = &b[0] else { panic!() };
    assert_eq!(branches[0].0, bin(BinaryOp::Lt, Expr::Var(VarId::new(z)), Expr::Previous(VarId::new(z))));
    let host = p.functions.iter().position(|f| f.name == "getNthLength1").unwrap() as u16;
    assert_eq!(
        b[1],
        Stmt::Assign(
            Place::Global(GlobalId::new(global(&p, "L"))),
            Expr::Call(FunctionId::new(host), vec![Expr::Number(0.0)])
        )
    );
}

#[test]
fn signatures_are_typed() {
    let text = "Sub WallThick()\n' #Cycle !X !Y !Width\n' #cycle !Correction Offset\nEnd Sub\nSub OpMessage()\n' #Option\n' #C1 Operator message\nEnd Sub\n";
    let (program, diagnostics) = postc_front_vcpost::parse(text, postc_ir::FileId(0));
    assert!(diagnostics.is_empty());
    let sigs = signatures(&program);
    assert_eq!(sigs.len(), 2);
    assert_eq!(sigs[0].keyword, Some(postc_front_vcpost::ast::SubKeyword::Cycle));
    assert_eq!(
        sigs[0].params,
        vec![
            ("X".into(), true),
            ("Y".into(), true),
            ("Width".into(), true),
            ("Correction".into(), true),
            ("Offset".into(), false)
        ]
    );
    assert_eq!(sigs[1].tips, vec![(postc_front_vcpost::ast::TipSlot::C1, "Operator message".to_string())]);
    assert_eq!(postc_front_vcpost::probe_cycles(&program).len(), 2);
}

#[test]
fn sniffing() {
    assert!(looks_like_vcpost(b"Sub GOTO\r\n  Out \"<N><X>\"\r\nEnd Sub\r\n"));
    assert!(looks_like_vcpost(b"' post\nsub Rapid()\nout \"x\"\n"));
    assert!(!looks_like_vcpost(b"+ Vectric post\nPOST_NAME = \"x\"\nbegin HEADER\n\"G90\"\n"));
    assert!(!looks_like_vcpost(b"function onLinear(x, y, z, feed) {\n  writeBlock(\"G1\");\n}\n"));
    assert!(!looks_like_vcpost(b""));
}

/// `<Name` never closed with `>` in an `Out` string is
/// an error at its line and column (it used to print literally, silently).
#[test]
fn an_unclosed_register_in_out_is_an_error_at_its_place() {
    let text = "Sub ToolChange\n  Out \"<N> T1\"\nEnd Sub\n\nSub Linear\n  Out \"<N> G1 \"\"A\"\" <X<Y>\"\n  Out \"<N> G1<FeedRate\"\n  Out \"(X<0) a < b (DIST<MAX)\"\nEnd Sub\n";
    let mut sources = postc_report::source_map();
    let (_, diagnostics) = compile(Path::new("t.VcPost"), text.as_bytes(), &mut sources);
    let found: Vec<_> = diagnostics
        .iter()
        .map(|d| {
            let span = d.primary_span().expect("a span");
            let (line, col) = sources.line_column(span.file, span.start).expect("a position");
            let (end_line, end_col) = sources.line_column(span.file, span.end).expect("a position");
            (d.code, d.severity, line, col, end_line, end_col)
        })
        .collect();
    use postc_ir::Severity::Error;
    assert_eq!(
        found,
        vec![("VC038", Error, 6, 21, 6, 23), ("VC038", Error, 7, 14, 7, 23)],
        "{}",
        sources.render(&diagnostics, false)
    );
}
