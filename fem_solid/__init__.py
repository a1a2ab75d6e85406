"""twoball.fem_solid -- finite elements of the elastic ball on scikit-fem.

Axisymmetric (r, z) linear elasticity on the half disc (solid ball) and the half
annulus (hollow ball), and 3-D elasticity on a tetrahedral ball, all in P2 with
curved (isoparametric) boundaries; eigenpairs classified by degree and radial
order.  Dimensionless: lengths in R, density and shear modulus 1, eigenvalues
(omega R / c_s)^2.
"""

from twoball._common.lazy import attach

__getattr__, __dir__ = attach(
    __name__,
    {
        "SolidEigen": ".eigen",
        "axisymmetric_eigen": ".eigen",
        "axisymmetric_elasticity": ".forms",
        "axisymmetric_mass": ".forms",
        "ball": ".mesh",
        "ball_eigen": ".eigen",
        "ball_gmsh": ".mesh",
        "elasticity_matrices": ".assembly",
        "circle_error": ".mesh",
        "elasticity": ".forms",
        "half_annulus": ".mesh",
        "half_disc": ".mesh",
        "half_disc_gmsh": ".mesh",
        "lame": ".forms",
        "legendre_content": ".eigen",
        "linear": ".mesh",
        "mass": ".forms",
        "vsh_content": ".eigen",
    },
)

__all__ = sorted(__dir__())
