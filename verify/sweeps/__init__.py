"""twoball.verify.sweeps -- parameter sweeps on a pool or Dask."""

__all__ = ["cost", "parallel", "sweeps"]
