"""Errors: refused posts, toolpaths and arguments raise PostError (with the
diagnostics) or the iterable's own exception."""

import pytest

import postc
from conftest import POST
from test_check_convert import BAD
from toolpaths import pocket


def test_a_post_with_errors_is_refused_with_its_diagnostics():
    with pytest.raises(postc.PostError) as e:
        postc.post(BAD, pocket(), dialect="vectric")
    assert e.value.diagnostics and all(isinstance(d, postc.Diagnostic) for d in e.value.diagnostics)
    assert any(d.severity == "error" and d.code.startswith("PP") for d in e.value.diagnostics)
    assert "nothing was posted" in str(e.value)


def test_a_missing_post_or_toolpath(tmp_path):
    with pytest.raises(postc.PostError) as e:
        postc.post(tmp_path / "none.pp", pocket())
    assert [d.code for d in e.value.diagnostics] == ["IO001"]
    with pytest.raises(postc.PostError) as e:
        postc.post(POST, tmp_path / "none.jsonl")
    assert [d.code for d in e.value.diagnostics] == ["IO001"]


def test_an_item_that_is_not_an_event():
    events = list(pocket())
    events[5] = {"Feed": {"x": 1, "y": 2, "z": 3, "speed": 9}}
    with pytest.raises(postc.PostError) as e:
        postc.post(POST, events)
    d = e.value.diagnostics[0]
    assert (d.code, d.severity, d.file) == ("TP006", "error", "<toolpath iterable>")
    assert "event 6" in d.message and "speed" in d.message


def test_an_event_out_of_range():
    events = list(pocket())
    events[5] = {"Feed": {"x": 1e12, "y": 2, "z": 3}}
    with pytest.raises(postc.PostError) as e:
        postc.post(POST, events)
    assert "TP004" in [d.code for d in e.value.diagnostics]
    assert "event 6" in str(e.value)


def test_the_iterables_exception_is_raised_again():
    def failing():
        yield from list(pocket())[:10]
        raise KeyError("the CAM system failed")

    with pytest.raises(KeyError, match="CAM system"):
        postc.post(POST, failing())


def test_bad_arguments_are_value_errors():
    with pytest.raises(ValueError):
        postc.post(POST, pocket(), dialect="mazak")
    with pytest.raises(ValueError):
        postc.convert(POST, "heidenhain")
    with pytest.raises(ValueError):
        postc.verify("G0 X0\n", pocket(), tolerance=-1)
    with pytest.raises(postc.PostError) as e:
        postc.post(POST, pocket(), set={"speed": 3})
    assert [d.code for d in e.value.diagnostics] == ["IO007"]


def test_a_refused_conversion_carries_the_commands_reasons(cli):
    """A CIMCO post with code is no Vectric post: refused with CV002 at the
    line `postc convert` names."""
    from conftest import REPO
    js = REPO / "corpus" / "posts" / "cimco" / "fanuc_mill.js"
    refused = cli("convert", js, "--to", "vectric", check=False)
    assert refused.returncode == 1 and b"CV002" in refused.stderr
    with pytest.raises(postc.PostError) as e:
        postc.convert(js, "vectric")
    d = e.value.diagnostics[0]
    assert (d.code, d.severity, d.file, d.line) == ("CV002", "error", str(js), 63)
    assert "cannot be converted" in str(e.value)
