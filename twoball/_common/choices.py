"""The choices and defaults of the options, in one place, with the standard library only.

The option objects that act on them (:class:`~twoball.MeshOptions`, the solvers,
:class:`~twoball.Body`, the damping and gas laws, the outputs) and the command
line's ``--help`` both read them from here, so ``twoball SUBCOMMAND --help``
imports no numerical library and no value is written twice.
"""

from __future__ import annotations

__all__ = [
    "DEFAULT_ANIMATION_FRAMES",
    "DEFAULT_ELEMENTS",
    "DEFAULT_FRAMES",
    "DEFAULT_LEVEL",
    "DEFAULT_ORDER",
    "DEFAULT_SIZE",
    "DPI",
    "ENERGY_OPTIONS",
    "FIT_MODELS",
    "FIT_MODEL_COLUMNS",
    "FIT_PARAMETERS",
    "FIELD_BACKENDS",
    "FILTER_KINDS",
    "FORMATS",
    "GAS_MODELS",
    "HORIZONS",
    "LEVEL_RANGE",
    "MAX_MASS_RATIO",
    "MEASURED_COLUMNS",
    "MESH_KINDS",
    "REPRODUCTION_DIR",
    "REPRODUCTION_PARTS",
    "REPRODUCTION_REPORT",
    "ROUTES",
    "SIGMA_PREFIX",
    "SPHERE_KINDS",
    "STANDARD_GRAVITY",
    "STUDIES",
    "SWEEP_PARAMETERS",
    "WATERFALL_INSTANTS",
]

# --- the case and the model --------------------------------------------------------------
#: Gravitational acceleration [m/s^2], the value used in the paper (§2).
STANDARD_GRAVITY = 9.81
#: Spectral filters of eq. (3.16) (:class:`twoball.modal.filters.SpectralFilter`).
FILTER_KINDS: tuple[str, ...] = ("lanczos", "printed", "none")
#: Re-contact horizons of criterion (ii), §3(a) (:func:`twoball.modal.liftoff.find_liftoff`).
HORIZONS: tuple[str, ...] = ("window", "paper")
#: The enclosed gas (:mod:`twoball.modal.stiffness`).
GAS_MODELS: tuple[str, ...] = ("none", "isothermal", "adiabatic")

# --- finite elements and time ------------------------------------------------------------
#: Generated meshes: icosphere, sphere with a ring along phi_a, the axisymmetric line.
MESH_KINDS: tuple[str, ...] = ("sphere", "ring", "axisym")
#: Kinds on a sphere (the field outputs draw a sphere, not the axisymmetric line).
SPHERE_KINDS: tuple[str, ...] = ("sphere", "ring")
#: Icosphere refinement level (1280 triangles), the lift-off's default.
DEFAULT_LEVEL = 3
#: Elements of the axisymmetric line, the lift-off's default (the drop's: 96 at P2).
DEFAULT_ELEMENTS = 400
#: Element and geometry order (isoparametric P2).
DEFAULT_ORDER = 2
#: Icosphere levels any budget allows.
LEVEL_RANGE: tuple[int, int] = (0, 10)
#: Eigen routes of modal superposition on finite elements: every pair below the cutoff,
#: the rational Krylov route, or Krylov from 2000 unknowns on.
ROUTES: tuple[str, ...] = ("full", "krylov", "auto")

# --- the upper body ----------------------------------------------------------------------
#: What starts with the impact's energy: the ball alone, or both bodies.
ENERGY_OPTIONS: tuple[str, ...] = ("ball", "both")
#: Largest mass ratio mu = m1 / m2 of an upper body.
MAX_MASS_RATIO = 100.0

# --- the verbs ---------------------------------------------------------------------------
#: The field outputs' backends.
FIELD_BACKENDS: tuple[str, ...] = ("fem", "legendre")
#: Instants of an exported time series.
DEFAULT_FRAMES = 25
#: Formats of an exported time series.
FORMATS: tuple[str, ...] = ("xdmf", "vtu", "pvd")
#: Size of a rendered picture [pixels].
DEFAULT_SIZE: tuple[int, int] = (640, 480)
#: Frames of a rendered animation.
DEFAULT_ANIMATION_FRAMES = 60
#: Resolution of a figure [dots per inch].
DPI = 300
#: Curves of the waterfall figure (as in Fig. 6).
WATERFALL_INSTANTS = 24
#: Swept parameter (command-line name) -> the Case field it sets; v0, c and R
#: re-derive phi_a from eq. (3.7) (Case.derive).
SWEEP_PARAMETERS: dict[str, str] = {
    "damping": "damping",
    "v0": "v0",
    "wave-speed": "wave_speed",
    "radius": "radius",
    "modes": "modes",
    "mass-ratio": "mass_ratio",  # not a Case field: the points become ContactCase
    "bending": "bending",
}
#: Convergence studies of ``twoball converge``.
STUDIES: tuple[str, ...] = ("h", "order", "modes", "dt")
#: Parts of ``twoball reproduce``, in report order.
REPRODUCTION_PARTS: tuple[str, ...] = (
    "table2",
    "fig6",
    "fig10",
    "fig11",
    "fig12",
    "thresholds",
    "table1",
    "icm",
    "contact",
    "whole_table1",
    "whole_gap",
    "whole_timing",
    "kinds_table1",
    "kinds_gap",
)
#: The reproduction's folder and report.
REPRODUCTION_DIR = "twoball-reproduction"
REPRODUCTION_REPORT = "reproduction.md"

# --- measured data: twoball fit, --measured overlays ------------------------------------
#: The columns of a measured CSV file (SI; the unit is in the name) and what each holds.
MEASURED_COLUMNS: dict[str, str] = {
    "v0_m_s": "input: the impact speed |v0| [m/s] (blank or absent: the case's)",
    "phi_a_rad": "input, closed form: the contact angle phi_a [rad] (blank or absent: the "
    "case's rule)",
    "gap_m": "input, whole bounce: the gap Delta x [m] between the body and the ball's top "
    "(blank or absent: the drop's)",
    "v1_m_s": "measured: the body's speed v1 [m/s] on leaving the ball, upwards (the closed "
    "form: the lift-off velocity v_l)",
    "v2_m_s": "measured, bounce: the ball's rebound speed v2 [m/s], upwards",
    "t_liftoff_s": "measured: the body's lift-off time [s] after the ball's first touch of "
    "the floor",
}
#: Prefix of an uncertainty column: ``sigma_v1_m_s`` holds the standard uncertainty of
#: ``v1_m_s`` (same unit, > 0); with one, residuals are weighted by 1/sigma.
SIGMA_PREFIX = "sigma_"
#: The models of ``twoball fit``: the closed-form lift-off (eqs. (3.12)-(3.16)) or the
#: whole bounce (Moreau-Jean on a Legendre ball).
FIT_MODELS: tuple[str, ...] = ("closed", "bounce")
#: The input and the measured columns each model can use.
FIT_MODEL_COLUMNS: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "closed": (("v0_m_s", "phi_a_rad"), ("v1_m_s", "t_liftoff_s")),
    "bounce": (("v0_m_s", "gap_m"), ("v1_m_s", "v2_m_s", "t_liftoff_s")),
}
#: Fittable parameters (command-line names), what they are and the models that fit them.
FIT_PARAMETERS: dict[str, str] = {
    "damping": "the modal damping ratio D, eq. (3.14) (closed, bounce)",
    "wave-speed": "the angular wave speed c [1/s], eq. (3.8) (closed, bounce)",
    "restitution": "Newton's e12 at the body's impacts on the ball (bounce, with a body)",
    "floor-restitution": "Newton's e at the floor points (bounce)",
}
