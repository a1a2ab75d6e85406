"""The ground floor of twoball: helpers that know nothing of the physics.

Errors, the resource guard, atomic output (staging), signals, progress lines,
provenance, value lists and lazy attributes.  Every module here imports the
standard library only (and, lazily, nothing above this package), so every
part of twoball can use them.
"""

__all__: list[str] = []
