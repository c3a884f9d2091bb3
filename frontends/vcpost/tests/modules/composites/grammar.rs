use postc_front_vcpost::composites::grammar::*;

fn run(f: fn(State, Step<'_>) -> Result<State, Misplaced>, calls: &[(&str, f64)]) -> Result<State, usize> {
    let mut s = State::Start;
    for (i, (routine, number)) in calls.iter().enumerate() {
        s = f(s, Step { routine, number: *number }).map_err(|_| i)?;
    }
    Ok(s)
}

#[test]
fn a_ply_with_two_packets() {
    let ply = [
        ("Modals", 0.0),
        ("Extent", 0.0),
        ("Length", 1.0),
        ("Length", 2.0),
        ("Length", 0.0),
        ("CamHeader", 0.0),
        ("CamPoint", 0.0),
        ("CamTrailer", 0.0),
        ("PlyHeader", 0.0),
        ("LinkHeader", -1.0),
        ("MoveTo", 0.0),
        ("OnForm", 0.0),
        ("LinkTrailer", 0.0),
        ("Extent", 0.0),
        ("Length", 0.0),
        ("PacketHeader", 0.0),
        ("GoTo", 0.0),
        ("Option", 0.0),
        ("RestartHeader", 0.0),
        ("RestartBuffer", 0.0),
        ("RestartTrailer", 0.0),
        ("GoTo", 0.0),
        ("PacketTrailer", 0.0),
        ("LinkHeader", 0.0),
        ("PulloutHeader", 0.0),
        ("MoveTo", 0.0),
        ("PulloutTrailer", 0.0),
        ("TraverseHeader", 0.0),
        ("TraverseTo", 0.0),
        ("TraverseTrailer", 0.0),
        ("MoveTo", 0.0),
        ("LinkTrailer", 0.0),
        ("PacketHeader", 0.0),
        ("GoTo", 0.0),
        ("PacketTrailer", 0.0),
        ("LinkHeader", 1.0),
        ("OffForm", 0.0),
        ("MoveTo", 0.0),
        ("LinkTrailer", 0.0),
        ("PlyTrailer", 0.0),
    ];
    assert_eq!(run(laying, &ply), Ok(State::Done));
}

#[test]
fn misplaced_calls() {
    assert_eq!(run(laying, &[("Extent", 0.0)]), Err(0));
    let base = [("Modals", 0.0), ("Extent", 0.0), ("Length", 0.0), ("PlyHeader", 0.0)];
    let mut first_link_not_entry = base.to_vec();
    first_link_not_entry.push(("LinkHeader", 0.0));
    assert_eq!(run(laying, &first_link_not_entry), Err(4));
    let mut lengths_open = base[..2].to_vec();
    lengths_open.extend([("Length", 3.0), ("PlyHeader", 0.0)]);
    assert_eq!(run(laying, &lengths_open), Err(3));
    assert_eq!(run(probing, &[("Modals", 0.0), ("ProgramHeader", 0.0), ("MoveTo", 0.0)]), Err(2));
    let points = [
        ("Modals", 0.0),
        ("ProgramHeader", 0.0),
        ("SetAngle", 0.0),
        ("MoveTo", 0.0),
        ("Probe", 0.0),
        ("ProgramTrailer", 0.0),
    ];
    assert_eq!(run(probing, &points), Ok(State::Done));
}
