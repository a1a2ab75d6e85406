"""twoball.verify.checks -- the checks of twoball verify."""
