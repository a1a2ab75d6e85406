"""twoball.verify.cli -- the command line."""
