"""twoball.verify.studies -- convergence studies and observed orders."""
