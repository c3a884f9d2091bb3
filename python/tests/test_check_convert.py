"""postc.check and postc.convert against `postc check --format json` and
`postc convert`."""

import json

import pytest

import postc
from conftest import POST, REPO

BAD = """POST_NAME = "bad (*.nc)"
FILE_EXTENSION = "nc"
UNITS = "MM"
VAR X_POSITION = [X|A|X|1.3
begin HEADER
"G21"
begin RAPID_MOVE
"G0 [X] [Y] [Z]"
begin FEED_MOVE
"G1 [X] [Y] [Z] [F]"
begin FOOTER
"M30"
"""


def test_check_gives_what_check_format_json_gives(cli, tmp_path):
    bad = tmp_path / "bad.pp"
    bad.write_text(BAD)
    expected = json.loads(cli("check", "--format", "json", bad, check=False).stdout)
    found = postc.check(bad)
    assert [d.to_dict() for d in found] == expected
    assert any(d.severity == "error" for d in found)
    first = found[0]
    assert (first.code, first.file, first.line, first.column) == (
        expected[0]["code"], str(bad), expected[0]["line"], expected[0]["column"])
    assert first.end == (expected[0]["end_line"], expected[0]["end_column"])


def test_check_of_a_clean_post_and_of_text():
    assert [d for d in postc.check(POST) if d.severity == "error"] == []
    found = postc.check(BAD, dialect="vectric")
    assert found and found[0].file == "<post text>"
    assert [d.code for d in found] == [d.code for d in postc.check(BAD)]


def test_check_of_a_toolpath_file(cli):
    toolpath = REPO / "corpus" / "toolpaths" / "standard.ron"
    expected = json.loads(cli("check", "--format", "json", toolpath, check=False).stdout)
    assert [d.to_dict() for d in postc.check(toolpath)] == expected


@pytest.mark.parametrize("to", ["vectric", "fusion", "ron"])
def test_convert_gives_what_the_command_gives(cli, to):
    expected = cli("convert", POST, "--to", to).stdout
    assert postc.convert(POST, to).encode() == expected


@pytest.mark.parametrize("to", ["cimco", "vcpost"])
def test_a_section_post_only_when_asked(cli, to):
    expected = cli("convert", POST, "--to", to, "--postc-extension").stdout
    assert postc.convert(POST, to, postc_extension=True).encode() == expected


def test_a_vectric_post_is_no_vcpost_milling_post_yet(cli):
    said = cli("convert", POST, "--to", "vcpost", check=False)
    assert said.returncode == 1 and b"error[CV001]" in said.stderr
    with pytest.raises(postc.PostError) as refused:
        postc.convert(POST, "vcpost")
    assert [d.code for d in refused.value.diagnostics] == ["CV001"]


@pytest.mark.parametrize("to", ["cimco", "fusion"])
def test_a_target_engine_that_cannot_hold_the_post_refuses_as_the_command_does(cli, to):
    # rotary_wrap_mm.pp wraps Y onto a rotary axis, whose angle needs the
    # job's wrap diameter, which neither CNC-Calc nor Fusion hands a post
    # (CV004).
    wrap = str(REPO / "corpus/posts/vectric/rotary_wrap_mm.pp")
    said = cli("convert", wrap, "--to", to, check=False)
    assert said.returncode == 1
    with pytest.raises(postc.PostError) as refused:
        postc.convert(wrap, to)
    codes = sorted({d.code for d in refused.value.diagnostics})
    assert codes == sorted({line[6:11] for line in said.stderr.decode().splitlines() if line.startswith("error[")})
    assert codes and codes[0].startswith("CV")


def test_a_converted_post_posts_the_same(tmp_path):
    from toolpaths import pocket
    converted = postc.convert(POST, "ron")
    assert postc.post(converted, pocket(), dialect="ir") == postc.post(POST, pocket())
