"""postc: post CNC toolpaths through Vectric, CIMCO, VcPost and Fusion posts,
check and convert posts, and verify G-code programs, from Python.

The same engine as the ``postc`` command (python/README.md). A toolpath is a
path (``.ron``, ``.jsonl``, APT CL) or any iterable of events in the native
schema (docs/toolpath-format.md) as Python writes its JSON form: a dict of
one event name and its fields, ``{"Feed": {"x": 10, "y": 5, "z": -1}}``, or a
unit event's name, ``"End"``.
"""

import os
from typing import Any, Iterable, Literal, Mapping, Optional, Union

__version__: str

Event = Union[Mapping[str, Any], str]
"""One toolpath event: ``{"Rapid": {"x": 0, "y": 0, "z": 5}}`` or ``"End"``."""

PathOrText = Union[str, bytes, "os.PathLike[str]"]
"""A path, or the text itself: a ``str`` with a line break, or ``bytes``."""

Toolpath = Union[str, "os.PathLike[str]", Iterable[Event]]
"""A toolpath file's path, or an iterable of events (a generator works)."""

Dialect = Literal["vectric", "cimco", "vcpost", "fusion", "ir", "ron"]

class Diagnostic:
    """One diagnostic, with the fields of ``postc check --format json``."""

    code: str
    """The stable code, e.g. ``PP012`` (``postc explain CODE`` documents it)."""
    severity: Literal["error", "warning", "note"]
    message: str
    file: str
    """The file it points into: a path, or ``<post text>``, ``<toolpath iterable>``, ``<program text>``."""
    line: Optional[int]
    """1-based line of the start, when the diagnostic has a place."""
    column: Optional[int]
    end_line: Optional[int]
    end_column: Optional[int]
    @property
    def end(self) -> Optional[tuple[int, int]]:
        """``(end_line, end_column)``, or ``None`` when the diagnostic has no place."""
    def to_dict(self) -> dict[str, Any]:
        """The dict ``postc check --format json`` prints for this diagnostic."""

class PostError(Exception):
    """A post, toolpath or program postc refuses; the message renders every reason."""

    diagnostics: list[Diagnostic]
    """Every reason, as diagnostics."""

class PostWarning(UserWarning):
    """A warning of a post or a run, given through Python's ``warnings`` module."""

def post(
    post: PathOrText,
    toolpath: Toolpath,
    *,
    out: Optional[Union[str, "os.PathLike[str]"]] = None,
    set: Optional[Union[Mapping[str, Any], Iterable[str]]] = None,
    dialect: Optional[Dialect] = None,
    exact_arcs: bool = False,
    verify: bool = True,
) -> Optional[str]:
    """Posts ``toolpath`` through ``post`` and returns the program's text, or
    writes it to ``out`` (whole, or not at all; tape-split parts beside it)
    and returns ``None``.

    ``post``'s dialect comes from its extension or its content, as the
    command finds it; ``dialect`` overrides. ``set`` gives job values as
    ``--set`` does: ``{"date": "2026-01-01", "time": "12:00", "tolerance":
    0.005}`` or ``["date=2026-01-01"]``. ``exact_arcs`` computes arc words
    from the printed end points (``--exact-arcs``).

    A program whose bytes are not UTF-8 is returned byte for character
    (Latin-1). Raises ``PostError`` when the post has errors, the toolpath
    does not read or posting fails; an exception the iterable raises is
    raised again. Warnings go to Python's ``warnings`` as ``PostWarning``.

    The program is verified as ``postc post`` verifies it (the generic
    controller, 0.01 mm): an error refuses it (``PostError`` with the
    findings; nothing is written), a program verify does not read (HPGL,
    ShopBot, ...) is said with a VF044 note. ``verify=False`` skips it, as
    ``--no-verify`` does.
    """

def check(
    post: PathOrText,
    *,
    dialect: Optional[Dialect] = None,
    product: Optional[Literal["cut2d", "vcarve", "aspire", "cut3d", "photovcarve"]] = None,
) -> list[Diagnostic]:
    """What ``postc check`` says about a post (or a toolpath file): every
    diagnostic, errors included; an empty list for a clean post.
    ``product`` warns about what that Vectric product's post processor does
    not support (``--product``)."""

def convert(
    post: PathOrText,
    to: Literal["vectric", "vcpost", "cimco", "fusion", "ron"],
    *,
    dialect: Optional[Dialect] = None,
    postc_extension: bool = False,
) -> str:
    """The post as a post of another dialect (``postc convert``).
    ``postc_extension=True`` writes a post of another dialect as a CIMCO
    or VcPost section post, which only postc runs (``--postc-extension``). Raises
    ``PostError`` with every reason when the target cannot hold it."""

def verify(
    program: PathOrText,
    toolpath: Toolpath,
    *,
    post: Optional[PathOrText] = None,
    dialect: Optional[Dialect] = None,
    controller: Literal["linuxcnc", "fanuc", "haas", "grbl", "generic"] = "generic",
    tolerance: float = 0.01,
) -> list[Diagnostic]:
    """Replays a G-code program and compares its motion with the toolpath it
    was posted from, as ``postc verify`` does; returns the findings (no
    error among them: the program makes the toolpath's moves). ``post``
    tells verify the program's units, rounding and block numbering. Raises
    ``PostError`` for a program verify does not read (HPGL, ShopBot,
    Heidenhain conversational, binary) or a toolpath that does not read."""
