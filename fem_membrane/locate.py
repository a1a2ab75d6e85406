"""Where the pole lies in a curved triangle: Lagrange shape functions and point location.

The pole of the ball need not be a mesh node (a user's mesh, a ``pole``
direction): :func:`locate_pole` finds the element the positive z-axis meets and
the reference coordinates of the meeting point on the curved (order-p) surface,
and :func:`shape_functions` gives the values there (dimensionless, unit R).
"""

from __future__ import annotations

import numpy as np

from twoball._common.errors import NumericalError
from twoball.fem_membrane.mesh import NODES_PER_TRIANGLE, SphereMesh


def shape_functions(order: int, xi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Lagrange shape functions of the geometry at a reference point.

    The reference triangle is scikit-fem's, with vertices (0, 0), (1, 0), (0, 1);
    local nodes follow :attr:`SphereMesh.cells` (scikit-fem's ``ElementTriP{p}``
    order).  Orders 1 and 2 are written out; 3 and 4 are scikit-fem's
    ``ElementTriP3``/``ElementTriP4`` basis.

    Parameters
    ----------
    order : {1, 2, 3, 4}
        Geometric order.
    xi : ndarray, shape (2,)
        Reference coordinates.

    Returns
    -------
    values : ndarray, shape (n,)
    gradients : ndarray, shape (n, 2)
        Derivatives with respect to the two reference coordinates; n = 3, 6,
        10 or 15 nodes.
    """
    x, y = float(xi[0]), float(xi[1])
    w = 1.0 - x - y
    if order == 1:
        return np.array([w, x, y]), np.array([[-1.0, -1.0], [1.0, 0.0], [0.0, 1.0]])
    if order > 2:
        from skfem import ElementTriP3, ElementTriP4

        element = ElementTriP3() if order == 3 else ElementTriP4()
        point = np.array([[x], [y]])
        pairs = [element.lbasis(point, i) for i in range(NODES_PER_TRIANGLE[order])]
        values = np.array([float(np.ravel(phi)[0]) for phi, _ in pairs])
        gradients = np.array([[float(np.ravel(d)[0]) for d in dphi] for _, dphi in pairs])
        return values, gradients
    values = np.array(
        [w * (2 * w - 1), x * (2 * x - 1), y * (2 * y - 1), 4 * w * x, 4 * x * y, 4 * y * w]
    )
    gradients = np.array(
        [
            [1 - 4 * w, 1 - 4 * w],
            [4 * x - 1, 0.0],
            [0.0, 4 * y - 1],
            [4 * (w - x), -4 * x],
            [4 * y, 4 * x],
            [-4 * y, 4 * (w - y)],
        ]
    )
    return values, gradients


_LOCATE_MARGIN = 0.25  # candidate triangles: flat barycentric coordinates >= -margin
_INSIDE = 1e-12  # a reference point this far outside the triangle still counts as inside


def _axis_barycentric(corners: np.ndarray) -> np.ndarray:
    """Barycentric coordinates (T, 3) of the z-axis in the xy-projection of triangles."""
    a, b, c = corners[:, 0, :2], corners[:, 1, :2], corners[:, 2, :2]
    e1, e2 = b - a, c - a
    det = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        l1 = (-a[:, 0] * e2[:, 1] + a[:, 1] * e2[:, 0]) / det
        l2 = (-e1[:, 0] * a[:, 1] + e1[:, 1] * a[:, 0]) / det
    out = np.column_stack([1.0 - l1 - l2, l1, l2])
    out[~np.isfinite(out).all(axis=1)] = -np.inf
    return out


def _newton_on_axis(nodes: np.ndarray, order: int, xi: np.ndarray) -> np.ndarray | None:
    """Reference point where the element's surface meets the z-axis (x = y = 0), by Newton."""
    for _ in range(50):
        values, gradients = shape_functions(order, xi)
        residual = values @ nodes[:, :2]
        jacobian = nodes[:, :2].T @ gradients  # d(x, y) / d(xi, eta)
        try:
            step = np.linalg.solve(jacobian, residual)
        except np.linalg.LinAlgError:
            return None
        xi = xi - step
        if np.abs(step).max() < 1e-15:
            return xi
    return xi if np.abs(residual).max() < 1e-13 else None


def locate_pole(mesh: SphereMesh) -> tuple[int, np.ndarray]:
    """The element holding the north pole of the discrete surface, and the pole's place in it.

    The pole of a discrete sphere is the point of its surface on the positive
    z-axis (the radial projection of (0, 0, 1)).  On flat triangles (order 1) it
    is found from the barycentric coordinates of the axis, on curved triangles
    (orders 2 to 4) by Newton's method on the element map, started from the
    flat estimate.  Dimensionless.

    Returns
    -------
    element : int
        Triangle index.
    xi : ndarray, shape (2,)
        Reference coordinates of the pole in that triangle (see :func:`shape_functions`).
    """
    corners = mesh.points[mesh.triangles]
    normal = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    upper = (corners[:, :, 2].sum(axis=1) > 0.0) & (np.abs(normal[:, 2]) > 0.0)
    bary = _axis_barycentric(corners)
    bary[~upper] = -np.inf
    worst = bary.min(axis=1)
    candidates = np.flatnonzero(worst >= -_LOCATE_MARGIN)
    candidates = candidates[np.argsort(-worst[candidates])]
    for element in candidates:
        if mesh.order == 1:
            xi = bary[element, 1:]
        else:
            start = np.clip(bary[element, 1:], 0.0, 1.0)
            xi = _newton_on_axis(mesh.points[mesh.cells[element]], mesh.order, start)
            if xi is None:
                continue
        if min(xi[0], xi[1], 1.0 - xi[0] - xi[1]) >= -_INSIDE:
            return int(element), np.asarray(xi, dtype=float)
    raise NumericalError(f"{mesh.name}: no element meets the positive z-axis (the pole)")
