mod ops;

use postc_ir::{BinaryOp, LocalId, UnaryOp};
use postc_runtime::engine::Engine;
use postc_runtime::exec::{Expr, Piece, Stmt, WordsBefore};
use postc_runtime::testing::interp::*;
use postc_runtime::value::{Text, Value};

/// Every move back, short (through the window) or long, is the
/// rotation it stands for.
#[test]
fn move_back_is_the_rotation() {
    for len in 1..48usize {
        let text: Vec<u8> = (0..len as u8).collect();
        for from in 1..=len {
            for to in 0..from {
                let (mut ours, mut want) = (text.clone(), text.clone());
                move_back(&mut ours, to, from);
                want[to..].rotate_right(len - from);
                assert_eq!(ours, want, "len {len}, to {to}, from {from}");
            }
        }
    }
}

/// A run of words answers what its statements answer: the same
/// output, locals, steps and way out, for texts among which some are
/// empty, for no word at all (the block dropped back to its mark), and
/// for a word that is not a text (the statements run), counted and
/// asked of the output alike.
#[test]
fn a_run_of_words_does_what_its_statements_do() {
    use postc_ir::{LocalId, Place, Post};
    use postc_runtime::exec::{Code, WordRun};
    use postc_runtime::output::Output;
    let (post, code) = (Post::default(), Code::default());
    let engine = || {
        let machine = postc_runtime::machine::MachineState::new(
            post.info.units,
            post.options.spindle_speed_range,
            post.options.rotary_wrap,
        );
        let mut engine = Engine::new(&post, &code, machine, Output::memory());
        engine.out.buf.extend_from_slice(b"N1 ");
        engine
    };
    let (counter, block) = (LocalId::new(8), LocalId::new(7));
    let ends = |flow: &Flow| matches!(flow, Flow::Break);
    for before in [WordsBefore::Count(counter), WordsBefore::Written(counter)] {
        let (start, none_printed) = match before {
            WordsBefore::Count(_) => (
                Stmt::Assign(Place::Local(counter), Expr::Number(0.0)),
                Expr::Binary(BinaryOp::JsEq, Box::new(Expr::Local(counter)), Box::new(Expr::Number(0.0))),
            ),
            WordsBefore::Written(_) => {
                (Stmt::Mark(counter), Expr::Unary(UnaryOp::Not, Box::new(Expr::Written(counter))))
            }
        };
        let locals: Vec<LocalId> = (1..4).map(LocalId::new).collect();
        let mut general = vec![start];
        general.extend(locals.iter().map(|&w| Stmt::Word {
            cond: Expr::LocalEmpty { local: w, op: BinaryOp::JsNe },
            word: vec![Piece::Expr(Expr::Local(w))],
            sep: b" ".to_vec(),
            before,
        }));
        general.push(Stmt::If {
            branches: vec![(none_printed, vec![Stmt::Truncate(block), Stmt::Break])],
            otherwise: vec![],
        });
        let run = Stmt::Words(Box::new(WordRun {
            general: general.clone(),
            locals,
            sep: b" ".to_vec(),
            before,
            empty: Some(block),
        }));
        let text = |t: &str| Value::Text(Text::new(t));
        for words in [
            [text("G1"), text(""), text("X1")],
            [text(""), text("Y2"), text("")],
            [text(""), text(""), text("")],
            [text("G1"), Value::Num(7.0), text("")],
            [Value::Num(0.0), text(""), Value::Null],
        ] {
            let mut start = vec![Value::Null; 9];
            start[1..4].clone_from_slice(&words);
            start[block.index()] = Value::Num(0.0);
            let (mut fused, mut plain) = (engine(), engine());
            let (mut fused_frame, mut plain_frame) = (start.clone(), start.clone());
            let fused_flow = fused.exec(std::slice::from_ref(&run), &mut fused_frame).expect("runs");
            let plain_flow = plain.exec(&general, &mut plain_frame).expect("runs");
            let case = format!("{before:?} {words:?}");
            assert_eq!(fused.out.buf, plain.out.buf, "{case}");
            assert_eq!(fused_frame, plain_frame, "{case}");
            assert_eq!(fused.steps, plain.steps, "{case}");
            assert_eq!(ends(&fused_flow), ends(&plain_flow), "{case}");
        }
    }
}

fn add(a: Expr, b: Expr) -> Expr {
    Expr::Binary(BinaryOp::Add, Box::new(a), Box::new(b))
}

#[test]
fn a_chain_of_texts_is_empty_when_every_part_is() {
    let l = |k| Expr::Local(LocalId::new(k));
    let chain = add(add(l(0), l(1)), Expr::text(""));
    let frame = [Value::text(""), Value::text("")];
    assert_eq!(texts_empty(&chain, &frame, &[]), Some(true));
    let frame = [Value::text(""), Value::text("X1")];
    assert_eq!(texts_empty(&chain, &frame, &[]), Some(false));
    // A number makes `+` add: the chain is evaluated as it is.
    let frame = [Value::Num(0.0), Value::text("")];
    assert_eq!(texts_empty(&chain, &frame, &[]), None);
}
