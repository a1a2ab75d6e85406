"""twoball.verify.reproduce -- the paper reproduction."""
