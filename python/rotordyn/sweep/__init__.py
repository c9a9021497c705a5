"""Sweeps over the configuration and speed domains, distributed with dask, collected as a
parquet dataset (one file per chunk) with a manifest."""

from rotordyn.sweep.runner import SweepResult, read_dataset, run_sweep
from rotordyn.sweep.spec import SweepSpec

__all__ = ["SweepSpec", "SweepResult", "run_sweep", "read_dataset"]
