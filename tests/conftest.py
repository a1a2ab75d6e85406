"""Test-session setup: one BLAS thread, headless plotting and rendering.

The matrices in these tests are small; on a 2-core machine BLAS threads only
contend with each other (measured 10-100x slower dense solves under load).
"""

import os

os.environ.setdefault("MPLBACKEND", "Agg")
os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")

from threadpoolctl import threadpool_limits  # noqa: E402

threadpool_limits(limits=1, user_api="blas")
