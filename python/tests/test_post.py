"""postc.post against the postc command: the same events posted from a
Python iterable and from a file the command reads give the same bytes."""

import pathlib
import warnings

import pytest

import postc
from conftest import POST, REPO, field_posts, read_jsonl, same_bytes, write_jsonl
from toolpaths import pocket


def test_a_file_toolpath_posts_as_the_command_posts_it(cli):
    toolpath = REPO / "corpus" / "toolpaths" / "standard.ron"
    expected = cli("post", "--no-verify", POST, toolpath).stdout
    assert postc.post(str(POST), str(toolpath)).encode() == expected
    # os.PathLike works as well as str.
    assert postc.post(POST, toolpath).encode() == expected


def test_an_iterable_posts_as_its_jsonl_file(cli, tmp_path):
    events = list(pocket())
    jsonl = write_jsonl(tmp_path / "pocket.jsonl", events)
    expected = cli("post", "--no-verify", POST, jsonl).stdout
    assert postc.post(POST, iter(events)).encode() == expected
    assert postc.post(POST, pocket()).encode() == expected


def test_every_event_of_the_standard_job_reads_from_dicts(cli, tmp_path):
    """The standard job touches every common event (tools, helices, jets,
    dwells, power): read back from JSON Lines as dicts, posted from Python."""
    jsonl = tmp_path / "standard.jsonl"
    cli("toolpath", "gen", "--pattern", "standard", "--moves", "200", "-o", jsonl)
    for post in sorted((REPO / "corpus" / "posts" / "vectric").glob("*.pp")):
        if "tape_split" in post.name:
            continue
        expected = cli("post", "--no-verify", post, jsonl)
        if expected.returncode != 0:
            continue
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            assert same_bytes(postc.post(post, read_jsonl(jsonl), verify=False), expected.stdout), post.name


def test_real_vectric_posts_post_and_verify_the_python_pocket_as_the_command_does(cli, tmp_path):
    """Every field post of the shared corpus: the program posted from the
    generator is the command's, byte for byte, and verifying it (the
    default) refuses it exactly when the command refuses it."""
    posts = field_posts()
    jsonl = write_jsonl(tmp_path / "pocket.jsonl", pocket())
    compared = refused = 0
    for post in posts:
        expected = cli("post", "--no-verify", post, jsonl, check=False)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            if expected.returncode != 0:
                with pytest.raises(postc.PostError):
                    postc.post(post, pocket(), verify=False)
                continue
            program = postc.post(post, pocket(), verify=False)
            assert same_bytes(program, expected.stdout), post
            compared += 1
            verified = cli("post", post, jsonl, check=False)
            try:
                postc.post(post, pocket())
                assert verified.returncode == 0, f"{post}: the command refuses, Python does not"
            except postc.PostError as e:
                refused += 1
                assert verified.returncode == 1, f"{post}: Python refuses, the command does not: {e}"
    print(f"{compared} of {len(posts)} real Vectric posts posted the pocket as the command does; "
          f"verifying refused {refused} of them, as the command does")
    if posts:
        assert compared >= len(posts) // 2, f"only {compared} of {len(posts)} real posts posted"


def test_ints_and_floats_read_the_same():
    """The fast path reads ints as serde does (as floats)."""
    as_floats = [{"Job": {"units": "Mm", "date": "d", "time": "t"}},
                 {"ToolpathStart": {"name": "a"}},
                 {"Rapid": {"x": 1.0, "y": 2.0, "z": 3.0}},
                 {"Feed": {"x": 4.0, "y": 5.0, "z": -1.0, "feed": 800.0}}, "End"]
    as_ints = [{"Job": {"units": "Mm", "date": "d", "time": "t"}},
               {"ToolpathStart": {"name": "a"}},
               {"Rapid": {"x": 1, "y": 2, "z": 3}},
               {"Feed": {"x": 4, "y": 5, "z": -1, "feed": 800}}, "End"]
    assert postc.post(POST, as_floats) == postc.post(POST, as_ints)


def test_out_writes_the_program_whole_as_the_command_writes_it(cli, tmp_path):
    (tmp_path / "py").mkdir()
    (tmp_path / "cli").mkdir()
    out = tmp_path / "py" / "pocket.ngc"
    assert postc.post(POST, pocket(), out=out) is None
    jsonl = write_jsonl(tmp_path / "pocket.jsonl", pocket())
    cli("post", "--no-verify", POST, jsonl, "-o", tmp_path / "cli" / "pocket.ngc")
    assert out.read_bytes() == (tmp_path / "cli" / "pocket.ngc").read_bytes()
    assert [p.name for p in (tmp_path / "py").iterdir()] == ["pocket.ngc"]


def test_out_through_a_link_writes_where_it_points_and_a_pipe_stays_a_pipe(tmp_path):
    # A link to a machine's program folder gets the program and stays a
    # link; a named pipe a sender reads gets the program and stays a pipe.
    import os, stat, threading
    (tmp_path / "machine").mkdir()
    (tmp_path / "machine" / "O1001.ngc").write_text("old\n")
    link = tmp_path / "O1001.ngc"
    link.symlink_to(tmp_path / "machine" / "O1001.ngc")
    assert postc.post(POST, pocket(), out=link) is None
    assert link.is_symlink()
    assert "G1" in (tmp_path / "machine" / "O1001.ngc").read_text()
    fifo = tmp_path / "sender.fifo"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_bytes()), daemon=True)
    reader.start()
    assert postc.post(POST, pocket(), out=fifo) is None
    reader.join(20)
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    assert got and b"G1" in got[0]


def test_out_may_not_be_an_input(tmp_path):
    toolpath = write_jsonl(tmp_path / "t.jsonl", pocket())
    before = toolpath.read_bytes()
    with pytest.raises(postc.PostError) as e:
        postc.post(POST, toolpath, out=toolpath)
    assert [d.code for d in e.value.diagnostics] == ["IO012"]
    assert toolpath.read_bytes() == before


def test_set_gives_date_and_time_as_the_command(cli, tmp_path):
    events = [e for e in pocket() if not (isinstance(e, dict) and "Job" in e)]
    jsonl = write_jsonl(tmp_path / "p.jsonl", events)
    expected = cli("post", "--no-verify", "--set", "date=1999-12-31", "--set", "time=23:59", POST, jsonl).stdout
    assert postc.post(POST, events, set={"date": "1999-12-31", "time": "23:59"}).encode() == expected
    assert postc.post(POST, events, set=["date=1999-12-31", "time=23:59"]).encode() == expected


def test_a_post_given_as_text_with_its_dialect():
    text = POST.read_text()
    assert postc.post(text, pocket(), dialect="vectric") == postc.post(POST, pocket())
    # Without dialect=, the content says it is a Vectric post.
    assert postc.post(text, pocket()) == postc.post(POST, pocket())


def test_exact_arcs_as_the_command(cli, tmp_path):
    jsonl = write_jsonl(tmp_path / "p.jsonl", pocket())
    expected = cli("post", "--no-verify", "--exact-arcs", POST, jsonl).stdout
    assert postc.post(POST, pocket(), exact_arcs=True).encode() == expected


def test_warnings_are_python_warnings():
    events = [e for e in pocket() if e != "End"]
    with pytest.warns(postc.PostWarning, match="TP005"):
        postc.post(POST, events)


def test_the_fast_path_reads_what_serde_reads(cli, tmp_path):
    """Every move of the standard job (arcs both ways, helices, intents,
    rotary words) read by the fast path, and read by serde (a `"feed": None`
    sends a move there): the same program."""
    jsonl = tmp_path / "standard.jsonl"
    cli("toolpath", "gen", "--pattern", "standard", "--moves", "300", "-o", jsonl)
    events = read_jsonl(jsonl)
    moves = [e for e in events if isinstance(e, dict) and set(e) & {"Rapid", "Feed", "Arc"}]
    assert {next(iter(e)) for e in moves} == {"Rapid", "Feed", "Arc"}

    def through_serde(e):
        if isinstance(e, dict) and set(e) & {"Feed", "Arc"}:
            (name, fields), = e.items()
            if fields.get("feed") is None:
                return {name: dict(fields, feed=None)}
        if isinstance(e, dict) and "Rapid" in e:
            return {"Rapid": dict(e["Rapid"], a=None)} if "a" not in e["Rapid"] else e
        return e

    for post in ("gcode_mm.pp", "gcode_arcs_inch.pp", "rotary_wrap_mm.pp"):
        path = POST.parent / post
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            fast = postc.post(path, events, verify=False)
            slow = postc.post(path, [through_serde(e) for e in events], verify=False)
        assert fast == slow, post


def test_check_product_as_the_command(cli):
    import json
    for product in ("cut2d", "aspire"):
        expected = json.loads(cli("check", "--format", "json", "--product", product, POST, check=False).stdout)
        assert [d.to_dict() for d in postc.check(POST, product=product)] == expected
