"""Tests of twoball.modal.shell (the thin spherical shell in closed form)."""
