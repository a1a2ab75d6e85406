"""Mesh options (fem_membrane/options.py): what does not apply is refused."""

from __future__ import annotations

import pytest

from twoball._common.errors import ParameterError
from twoball.fem_membrane.build import build_space
from twoball.fem_membrane.mesh import ring_sphere
from twoball.fem_membrane.options import MeshOptions
from twoball.fem_membrane.space import sphere_space


@pytest.mark.parametrize(
    ("kwargs", "text"),
    [
        ({"mesh": "ring", "geometry": "exact"}, "isoparametric with mesh ring"),
        ({"mesh": "axisym", "geometry": "exact"}, "isoparametric with mesh axisym"),
        ({"geometry": "flat"}, "one of isoparametric, exact"),
        ({"order": 5}, "1, 2, 3 or 4"),
    ],
)
def test_options_refuse_what_does_not_apply(kwargs, text):
    with pytest.raises(ParameterError, match=text):
        MeshOptions.resolve(**kwargs)
    if "mesh" in kwargs:
        with pytest.raises(ParameterError, match=text):
            build_space(kwargs["mesh"], level=1, elements=10, geometry="exact")
    with pytest.raises(ParameterError):
        sphere_space(ring_sphere(1, 2.6), geometry="exact")
