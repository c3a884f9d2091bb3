use postc_ir::*;
use postc_ir::event::*;
use postc_runtime::{Output, RunOptions, run};

struct Gen { n: u64, i: u64, pos: [f64;3] }
impl EventSource for Gen {
    fn next_event(&mut self, _: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
        let s = Span::default();
        match self.i {
            0 => { self.i += 1; Some((Event::Tool(Tool { number: 1, cut_feed: 1500.0, plunge_feed: 500.0, spindle_speed: 18000.0, ..Tool::default() }), s)) }
            1 => { self.i += 1; Some((Event::ToolpathStart(ToolpathStart::default()), s)) }
            i if i < self.n + 2 => {
                self.i += 1;
                let k = i as f64;
                self.pos = [self.pos[0] + 0.4935, self.pos[1] + 0.0013, -1.0 - 0.25 * ((k * 0.05) % 2.0 - 1.0).abs()];
                Some((Event::Feed(FeedMove { x: self.pos[0], y: self.pos[1], z: self.pos[2], ..FeedMove::default() }), s))
            }
            _ => None,
        }
    }
}

fn main() {
    let mut post = Post::default();
    post.options.line_ending = b"\n".to_vec();
    let mut var = |q: Quantity, m: Modality, p: &str, d: u8| {
        post.formats.push(NumberFormat { decimals: d, ..NumberFormat::default() });
        post.variables.push(Variable { name: q.label().into(), source: ValueSource::Quantity(q), prefix: p.as_bytes().to_vec(), format: post.formats.len() as u16 - 1, modality: m });
        post.variables.len() as u16 - 1
    };
    let x = var(Quantity::X, Modality::OnChange, "X", 3);
    let y = var(Quantity::Y, Modality::OnChange, "Y", 3);
    let z = var(Quantity::Z, Modality::OnChange, "Z", 3);
    let f = var(Quantity::Feed, Modality::OnChange, "F", 1);
    let line = |v: &[u16], g: &str| Stmt::Line(std::iter::once(Piece::Text(g.as_bytes().to_vec())).chain(v.iter().map(|&i| Piece::Var(i))).collect());
    post.handlers.push(Handler { key: HandlerKey::Section(Section::FeedMove), body: vec![line(&[x, y, z], "G1")], span: None });
    post.handlers.push(Handler { key: HandlerKey::Section(Section::FirstFeedMove), body: vec![line(&[x, y, z, f], "G1")], span: None });
    let n: u64 = std::env::var("N").ok().and_then(|v| v.parse().ok()).unwrap_or(5_000_000);
    let t = std::time::Instant::now();
    let r = run(&post, &mut Gen { n, i: 0, pos: [0.0; 3] }, Output::discard(), RunOptions::default()).ok().unwrap();
    let s = t.elapsed().as_secs_f64();
    println!("{} events, {} bytes, {:.3}s, {:.1} M moves/s, {:.0} MB/s", r.events, r.bytes, s, n as f64 / s / 1e6, r.bytes as f64 / s / 1e6);
}
