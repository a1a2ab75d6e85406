"""Start-up: what each command imports (a fresh process each), and the scipy-free paths.

Wall times are measured in benchmarks/bench_startup.py, never asserted here.  These
tests pin the cause instead: which heavy libraries a command loads.  Each command
runs through ``twoball.cli.main.main`` in a child ``python -c`` started in
the repository root, so the checkout's code is the one imported; the child reports
``sys.modules`` after the command has finished.
"""

import json
import math
import subprocess
import sys
from pathlib import Path

import mpmath
import numpy as np
import pytest
import scipy
from scipy.linalg import eigvalsh_tridiagonal
from scipy.optimize import brentq
from twoball.modal.initial import _energy_shape, phi_a_from_v0, v0_from_phi_a
from twoball.modal.legendre import _DENSE_JACOBI_MAX, _gauss_legendre
from twoball.modal.parameters import preset
from twoball.modal.report import legendre_liftoff

from twoball._common.errors import ParameterError

ROOT = Path(__file__).resolve().parent.parent

HEAVY = ("scipy", "skfem", "matplotlib", "pyvista", "vtk", "dask", "distributed", "meshio", "rich")

CHILD = r"""
import contextlib, io, json, sys
argv = json.loads(sys.argv[1])
stdout, status = io.StringIO(), None
with contextlib.redirect_stdout(stdout):
    if argv is None:
        import twoball
    else:
        from twoball.cli.main import main
        try:
            status = main(argv)
        except SystemExit as exit:
            status = exit.code
import twoball
print(json.dumps({"modules": sorted(sys.modules), "status": status,
                  "stdout": stdout.getvalue(), "twoball": twoball.__file__}))
"""


def imported_by(argv: list[str] | None) -> tuple[set[str], dict]:
    """Top-level packages in ``sys.modules`` of a fresh child after ``twoball argv``.

    ``argv`` None: only ``import twoball``.  Also returns the child's report.
    """
    done = subprocess.run(
        [sys.executable, "-c", CHILD, json.dumps(argv)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stderr
    report = json.loads(done.stdout)
    # the checkout under test, not an installed copy
    assert Path(report["twoball"]).resolve() == ROOT / "twoball" / "__init__.py"
    return {name.split(".")[0] for name in report["modules"]}, report


def test_import_twoball_loads_no_numerical_library():
    packages, _ = imported_by(None)
    assert not packages & {"numpy", *HEAVY}, sorted(packages & {"numpy", *HEAVY})


@pytest.mark.parametrize("argv", [["--help"], [], ["--version"]])
def test_help_loads_no_numerical_library(argv):
    packages, report = imported_by(argv)
    assert report["status"] == 0
    assert "liftoff" in report["stdout"] or "twoball" in report["stdout"]
    assert not packages & {"numpy", *HEAVY}, sorted(packages & {"numpy", *HEAVY})


def test_closed_form_liftoff_json_loads_numpy_only():
    packages, report = imported_by(["liftoff", "--json"])
    assert report["status"] == 0
    assert "numpy" in packages  # it did compute
    assert not packages & set(HEAVY), sorted(packages & set(HEAVY))
    # the child's answer is the API's, bit for bit (JSON floats round-trip exactly)
    data = json.loads(report["stdout"])
    api = legendre_liftoff(preset("basketball"))
    assert data["t_liftoff_s"] == api.t_liftoff_s
    assert data["v_liftoff_m_s"] == api.v_liftoff_m_s
    assert data["t_liftoff_s"] == pytest.approx(9.8825e-3, abs=5e-8)  # §4(b), 9.8825 ms
    # the provenance names libraries it did not import (importlib.metadata)
    versions = data["provenance"]["versions"]
    assert versions["numpy"] == np.__version__ and versions["scipy"] == scipy.__version__
    assert data["provenance"]["command"] == "twoball liftoff --json"


def test_liftoff_json_with_derived_phi_a_loads_no_scipy():
    packages, report = imported_by(["liftoff", "--v0", "3.0", "--json"])
    assert report["status"] == 0
    assert not packages & set(HEAVY), sorted(packages & set(HEAVY))
    assert json.loads(report["stdout"])["phi_a_rad"] == phi_a_from_v0(3.0, 0.12, 320.0)


def test_fem_liftoff_json_loads_no_plotting_rendering_or_dask():
    packages, report = imported_by(["liftoff", "--backend", "fem", "--mesh", "axisym", "--json"])
    assert report["status"] == 0
    assert {"numpy", "scipy", "skfem"} <= packages  # the finite elements did run
    assert not packages & {"matplotlib", "pyvista", "vtk", "dask", "distributed", "meshio", "rich"}
    assert json.loads(report["stdout"])["backend"] == "fem"


# --- the scipy-free paths against scipy and numpy ------------------------------------------


@pytest.mark.parametrize("points", [2, 9, 46, 101, _DENSE_JACOBI_MAX, _DENSE_JACOBI_MAX + 1])
def test_gauss_rule_dense_and_tridiagonal_eigensolvers_agree(points):
    x_dense, w_dense = _gauss_legendre(points, "dense")
    x_tri, w_tri = _gauss_legendre(points, "tridiagonal")
    np.testing.assert_allclose(x_dense, x_tri, rtol=0, atol=4e-16)
    np.testing.assert_allclose(w_dense, w_tri, rtol=4e-15, atol=0)
    # the nodes against numpy's independent rule (companion matrix + one Newton step);
    # its weights are less accurate near the ends (1e-11 relative), so check ours by
    # exactness instead: sum w P_k(x) = int P_k = 2 delta_k0 for every k < 2 m
    np.testing.assert_allclose(x_dense, np.polynomial.legendre.leggauss(points)[0], atol=1e-15)
    moments = np.polynomial.legendre.legvander(x_dense, 2 * points - 1).T @ w_dense
    np.testing.assert_allclose(moments, np.eye(2 * points)[0] * 2.0, rtol=0, atol=2e-14)


def test_gauss_rule_auto_switches_at_the_documented_size():
    for points in (_DENSE_JACOBI_MAX, _DENSE_JACOBI_MAX + 1):
        solver = "dense" if points <= _DENSE_JACOBI_MAX else "tridiagonal"
        (x_auto, w_auto), (x, w) = _gauss_legendre(points), _gauss_legendre(points, solver)
        assert np.array_equal(x_auto, x) and np.array_equal(w_auto, w)
    with pytest.raises(ValueError, match="eigensolver"):
        _gauss_legendre(10, "qr")


def test_gauss_rule_nodes_are_the_jacobi_eigenvalues():
    # Golub-Welsch: the nodes are the eigenvalues of the Jacobi matrix of P_n (a third check)
    k = np.arange(1, 60)
    x = eigvalsh_tridiagonal(np.zeros(60), k / np.sqrt(4.0 * k * k - 1.0))
    np.testing.assert_allclose(_gauss_legendre(60, "dense")[0], x, rtol=0, atol=2e-15)


V0 = np.geomspace(1e-10, 1e4, 241)


def brentq_phi_a(v0: float) -> float:
    """phi_a of eq. (3.7) by scipy's Brent solver in s = pi - phi_a (the former method)."""
    target = math.log((v0 / (0.12 * 320.0)) ** 2)

    def residual(s: float) -> float:
        return math.log(_energy_shape(math.pi - s)) - target

    eps = np.finfo(float).eps
    s = brentq(residual, 1e-6, math.pi / 2 * (1 - 1e-15), xtol=1e-300, rtol=4 * eps, maxiter=500)
    return math.pi - s


def test_phi_a_from_v0_matches_brent_within_round_off():
    ours = np.array([phi_a_from_v0(v, 0.12, 320.0) for v in V0])
    brent = np.array([brentq_phi_a(v) for v in V0])
    # both find the sign change of the same floating-point residual: a few ulp apart
    assert (np.abs(ours - brent) / np.spacing(brent)).max() <= 4
    # and the speed comes back where it is well conditioned: away from phi_a -> pi,
    # where 1 + cos phi_a cancels, and from phi_a -> pi/2, where v0 ~ (-cos phi_a)^-1/2
    resolved = (ours < 3.0) & (V0 <= 100.0)
    back = np.array([v0_from_phi_a(p, 0.12, 320.0) for p in ours[resolved]])
    np.testing.assert_allclose(back, V0[resolved], rtol=1e-13)


def test_phi_a_from_v0_against_eq_3_7_in_high_precision():
    mpmath.mp.dps = 40
    for v0 in V0[165::8]:  # phi_a from 2.96 down to pi/2 + 3e-6
        log_t = 2 * mpmath.log(mpmath.mpf(v0) / (mpmath.mpf("0.12") * 320))

        def residual(y, log_t=log_t):  # log of (3.7) minus log (v0 / R c)^2, y = log(pi - phi_a)
            c = -mpmath.cos(mpmath.exp(y))
            return mpmath.log((1 + c) ** 2 * (2 * c - 1) / (6 * c)) - log_t

        bracket = (mpmath.log(1e-7), mpmath.log(mpmath.pi / 2) - mpmath.mpf(10) ** -30)
        exact = float(mpmath.pi - mpmath.exp(mpmath.findroot(residual, bracket, "illinois")))
        # (3.7) in double precision has round-off amplified by 1 / (1 + cos phi_a) <= 100 here
        assert abs(phi_a_from_v0(v0, 0.12, 320.0) - exact) <= 4 * np.spacing(exact)


@pytest.mark.parametrize("v0", [1e-12, 1e-30, 1e-300])
def test_phi_a_from_v0_refuses_speeds_it_cannot_resolve(v0):
    with pytest.raises(ParameterError, match=r"^v0 must be at least .* m/s"):
        phi_a_from_v0(v0, 0.12, 320.0)


def test_cli_refuses_unresolvable_speed_in_one_line():
    done = subprocess.run(
        [sys.executable, "-m", "twoball", "liftoff", "--v0", "1e-30", "--json"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 2
    assert done.stderr.count("\n") == 1 and "--v0 must be at least" in done.stderr
