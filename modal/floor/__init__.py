"""The lower ball dropped on a rigid floor (dimensionless: R, 1/c, m2).

The ball comes as a modal description (:mod:`twoball.modal.balls`: the
Legendre membrane, and the finite elements in :mod:`twoball.fem_membrane.floor`);
:mod:`~twoball.modal.floor.system` assembles the contact problem with the
floor's points and a body's row, :mod:`~twoball.modal.floor.drop` runs
one drop on the contact core and :mod:`~twoball.modal.floor.measure` defines its
measures; :mod:`~twoball.modal.floor.options`, :mod:`~twoball.modal.floor.inputs` and
:mod:`~twoball.modal.floor.references` are its SI edge.  Names load on first use.
"""

from twoball._common.lazy import attach

_NAMES = {
    "DropResult": "twoball.modal.floor.drop",
    "DropSettings": "twoball.modal.floor.drop",
    "FloorEvent": "twoball.modal.floor.drop",
    "run_drop": "twoball.modal.floor.drop",
    "FloorSystem": "twoball.modal.floor.system",
    "floor_system": "twoball.modal.floor.system",
    "Drop": "twoball.modal.floor.options",
    "pressure_area": "twoball.modal.floor.references",
    "RestResult": "twoball.modal.floor.settle",
    "settle": "twoball.modal.floor.settle",
    "restitution_only": "twoball.modal.floor.restitution",
}
__getattr__, __dir__ = attach(__name__, _NAMES)
__all__ = sorted(_NAMES)
