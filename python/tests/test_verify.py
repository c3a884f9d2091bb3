"""postc.verify against `postc verify --format json`, and over programs
posted from Python."""

import json

import pytest

import postc
from conftest import POST, write_jsonl
from toolpaths import pocket


def test_a_program_posted_from_python_verifies():
    program = postc.post(POST, pocket())
    assert [d for d in postc.verify(program, pocket(), post=POST) if d.severity == "error"] == []


def test_a_program_that_misses_a_move_is_found_as_the_command_finds_it(cli, tmp_path):
    program = postc.post(POST, pocket())
    lines = program.splitlines(keepends=True)
    # The first cutting move of the pocket goes elsewhere.
    at = next(i for i, line in enumerate(lines) if line.startswith("G1") and "X" in line and "Z" not in line)
    lines[at] = lines[at].replace("X", "X1", 1)
    broken = tmp_path / "broken.ngc"
    broken.write_text("".join(lines))
    toolpath = write_jsonl(tmp_path / "pocket.jsonl", pocket())
    expected = json.loads(cli("verify", broken, "--toolpath", toolpath, "--post", POST,
                              "--format", "json", check=False).stdout)
    assert any(d["severity"] == "error" for d in expected)
    found = postc.verify(broken, toolpath, post=POST)
    assert [d.to_dict() for d in found] == expected
    # The same from the program's text and the toolpath's iterable: the
    # same findings, at the same lines.
    from_memory = postc.verify("".join(lines), pocket(), post=POST)
    assert [(d.code, d.line, d.column) for d in from_memory] == [(d["code"], d["line"], d["column"]) for d in expected]


def test_a_program_of_another_family_is_refused(tmp_path):
    hpgl = tmp_path / "job.plt"
    hpgl.write_text("IN;\nPU0,0;\nPD100,100;\n")
    with pytest.raises(postc.PostError) as e:
        postc.verify(hpgl, pocket())
    assert [d.code for d in e.value.diagnostics] == ["VF001"]


def test_post_verifies_what_it_posts_as_the_command_does(cli, tmp_path):
    """A post whose X is printed twice too large: `postc post` refuses the
    program, and so does postc.post, with the same findings."""
    doubled = tmp_path / "doubled.pp"
    doubled.write_text(POST.read_text().replace("VAR X_POSITION = [X|C|X|1.3]", "VAR X_POSITION = [X|C|X|1.3|2]"))
    toolpath = write_jsonl(tmp_path / "pocket.jsonl", pocket())
    refused = cli("post", doubled, toolpath, "-o", tmp_path / "cli.ngc", check=False)
    assert refused.returncode == 1 and not (tmp_path / "cli.ngc").exists()
    with pytest.raises(postc.PostError) as e:
        postc.post(doubled, pocket(), out=tmp_path / "py.ngc")
    assert not (tmp_path / "py.ngc").exists()
    codes = sorted({d.code for d in e.value.diagnostics if d.severity == "error"})
    assert codes and all(c.startswith("VF") for c in codes)
    assert all(c.encode() in refused.stderr for c in codes)
    assert "verifying the program found errors" in str(e.value)
    # verify=False writes it as posted, as --no-verify does.
    (tmp_path / "cli").mkdir()
    (tmp_path / "py").mkdir()
    cli("post", "--no-verify", doubled, toolpath, "-o", tmp_path / "cli" / "job.ngc")
    postc.post(doubled, pocket(), out=tmp_path / "py" / "job.ngc", verify=False)
    assert (tmp_path / "py" / "job.ngc").read_bytes() == (tmp_path / "cli" / "job.ngc").read_bytes()


def test_a_program_verify_does_not_read_is_posted_with_a_note():
    hpgl = POST.parent / "hpgl_arcs.pp"
    with pytest.warns(postc.PostWarning, match="VF044"):
        program = postc.post(hpgl, pocket())
    assert program
