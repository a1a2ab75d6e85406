"""A render whose drawing cannot get the address space it needs (run by test_render_limits).

Everything before the drawing is done first; then the address-space limit is set a
little above what this process maps, so the renderer's child (which inherits it)
fails inside VTK.  Prints the exception the call raised, and its message.
"""

from __future__ import annotations

import resource
import sys
from pathlib import Path

import numpy as np

import twoball
from twoball._common.watch import Watch
from twoball.modal.parameters import preset
from twoball.verify.output.fields import ball_model, ball_scene, field_mesh
from twoball.verify.output.render import render_scene


def mapped() -> int:
    """Bytes this process maps now."""
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[0]) * resource.getpagesize()


def main(out: Path) -> None:
    case = preset("basketball").derive(modes=10)
    model = ball_model(case, field_mesh(twoball.MeshOptions("sphere", level=1, order=1)))
    scene = ball_scene(model, np.linspace(0.0, model.t_end_s, 3), "legendre")
    limit = mapped() + (300 << 20)
    resource.setrlimit(resource.RLIMIT_AS, (limit, resource.getrlimit(resource.RLIMIT_AS)[1]))
    try:
        render_scene(out, scene, size=(160, 120), monitor=Watch())
    except BaseException as error:  # noqa: BLE001 -- the test reads what it was
        print(type(error).__name__, error)
        return
    print("rendered")


if __name__ == "__main__":
    main(Path(sys.argv[1]))
