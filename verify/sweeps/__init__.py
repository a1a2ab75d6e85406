"""twoball.verify.sweeps -- parameter sweeps on a pool or Dask."""
