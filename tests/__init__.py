"""The tests of twoball; the folders mirror the package (see tests/project/test_layout.py).

``ROOT`` is the repository's root folder, for tests that read its files or start
child processes in it.
"""

from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
