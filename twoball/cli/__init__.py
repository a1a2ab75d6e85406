"""twoball.cli -- the command line."""
