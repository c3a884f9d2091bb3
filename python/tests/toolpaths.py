"""Toolpaths the tests make in Python."""

import math


def pocket(width=60.0, height=40.0, depth=6.0, step_down=2.0, tool=6.0):
    """A rectangular pocket cleared by rectangles, with a helical entry arc
    and a dwell: moves of every kind, as a CAM program streams them."""
    yield {"Job": {"units": "Mm", "safe_z": 5.0,
                   "material": {"min": {"x": 0, "y": 0, "z": -depth - 2},
                                "max": {"x": width, "y": height, "z": 0}},
                   "date": "2026-01-01", "time": "12:00:00"}}
    yield {"Tool": {"number": 3, "name": "6 mm End Mill", "diameter": tool,
                    "spindle_speed": 18000, "cut_feed": 1500, "plunge_feed": 400}}
    yield {"ToolpathStart": {"name": "Pocket", "notes": "made in Python"}}
    r = tool / 2
    z = 0.0
    while z > -depth:
        z = max(z - step_down, -depth)
        yield {"Rapid": {"x": r, "y": r, "z": 5}}
        yield {"Feed": {"x": r, "y": r, "z": z, "intent": "Plunge"}}
        inset = r
        while inset <= min(width, height) / 2:
            for x, y in ((inset, inset), (width - inset, inset), (width - inset, height - inset),
                         (inset, height - inset), (inset, inset)):
                yield {"Feed": {"x": x, "y": y, "z": z, "feed": 1400.5}}
            inset += tool * 0.4
        yield {"Feed": {"x": r, "y": r, "z": z}}
        yield {"Dwell": {"seconds": 0.5}}
        yield {"Arc": {"dir": "Ccw", "x": r + 4, "y": r + 4, "z": z, "cx": r + 2, "cy": r + 2}}
        yield {"Arc": {"dir": "Cw", "x": r, "y": r, "z": z, "cx": r + 2, "cy": r + 2, "feed": 900}}
        yield {"Feed": {"x": r, "y": r, "z": 5, "intent": "Retract"}}
    yield "ToolpathEnd"
    yield "End"


def zigzag(moves):
    """`moves` feed moves over a 100 x 100 mm square (the performance test's
    toolpath, docs/performance.md)."""
    yield {"Job": {"units": "Mm", "date": "2026-01-01", "time": "12:00:00"}}
    yield {"Tool": {"number": 1, "name": "6 mm End Mill", "diameter": 6.0,
                    "spindle_speed": 18000, "cut_feed": 1500, "plunge_feed": 400}}
    yield {"ToolpathStart": {"name": "Zigzag"}}
    yield {"Rapid": {"x": 0.0, "y": 0.0, "z": 5.0}}
    for i in range(moves):
        yield {"Feed": {"x": (i * 0.37) % 100.0, "y": (i * 0.011) % 100.0, "z": -1.0 - math.sin(i) * 0.5}}
    yield "ToolpathEnd"
    yield "End"
