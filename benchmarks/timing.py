"""The timing of the benchmark scripts: wall and CPU times of repeated runs after a warm-up.

Imported by the scripts beside it (``python benchmarks/bench_*.py`` puts this folder
first on ``sys.path``).
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np


def timed(task: Callable[[], object], repeats: int) -> tuple[np.ndarray, np.ndarray]:
    """Wall and CPU times [s] of ``repeats`` runs after one untimed warm-up."""
    task()
    wall, cpu = [], []
    for _ in range(repeats):
        start, start_cpu = time.perf_counter(), time.process_time()
        task()
        wall.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    return np.array(wall), np.array(cpu)
