"""Tests of twoball.fem_shell (the shell in finite elements on the meridian)."""
