"""twoball.modal.lumped -- the lumped two-ball models of §1(b), as baselines.

Every model takes the same drop (impact speed ``|v0|`` or drop height, gap
``dx``, gravity) and returns a :class:`LumpedResult`:

* :class:`ICMBaseline` -- the independent collision model, eqs. (2.1)-(2.5)
  (:mod:`twoball.modal.icm`);
* :class:`TwoSpringDashpot` -- a linear spring and dashpot per contact, fitted
  to each contact's duration and restitution (Cross 2007; Müller & Pöschel 2011);
* :class:`Bartz2020` -- damped-oscillator contacts in dimensionless form
  (Bartz 2020, delayed rebounds);
* :class:`HertzViscoelastic` -- Hertz contacts with a Tsuji or Kuwabara-Kono dashpot.

The contact models share one event-driven solver (:func:`simulate`).  Presets of
the six Table 1 pairs: :data:`twoball.modal.pairs.PAIRS`; :data:`MODELS` builds
each model from a pair.

Examples
--------
>>> from twoball.modal.pairs import PAIRS
>>> from twoball.modal.lumped import MODELS
>>> pair = PAIRS["basketball-tennis"]
>>> {name: round(build(pair).run(v0=4.1, dx=0.05).v1_ratio, 1) for name, build in MODELS.items()}
{'icm': 2.1, 'two-spring-dashpot': 2.1, 'bartz2020': 2.1, 'hertz-viscoelastic': 2.1}
"""

from __future__ import annotations

from collections.abc import Callable

from twoball.modal.lumped.bartz import Bartz2020
from twoball.modal.lumped.hertz import HertzViscoelastic
from twoball.modal.lumped.icm_baseline import ICMBaseline
from twoball.modal.lumped.result import ContactEvent, EnergyBudget, LumpedResult
from twoball.modal.lumped.solver import simulate
from twoball.modal.lumped.spring_dashpot import TwoSpringDashpot
from twoball.modal.pairs import Pair

#: Each lumped model built from a Table 1 pair, by name.
MODELS: dict[
    str, Callable[[Pair], ICMBaseline | TwoSpringDashpot | Bartz2020 | HertzViscoelastic]
] = {
    "icm": ICMBaseline.from_pair,
    "two-spring-dashpot": TwoSpringDashpot.from_pair,
    "bartz2020": Bartz2020.from_pair,
    "hertz-viscoelastic": HertzViscoelastic.from_pair,
}

__all__ = [
    "MODELS",
    "Bartz2020",
    "ContactEvent",
    "EnergyBudget",
    "HertzViscoelastic",
    "ICMBaseline",
    "LumpedResult",
    "TwoSpringDashpot",
    "simulate",
]
