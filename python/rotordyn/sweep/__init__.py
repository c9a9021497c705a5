"""Sweeps over any model field and the operating variables, on threads, local worker
processes or a dask cluster, into a parquet dataset that pandas, pyarrow, polars and duckdb
read as a directory (bookkeeping under ``_`` names): :func:`run_sweep`, :func:`open`."""

from rotordyn.sweep.dataset import SweepDataset, open_dataset
from rotordyn.sweep.runner import SweepInterrupted, SweepResult, read_dataset, run_sweep
from rotordyn.sweep.spec import SweepSpec

open = open_dataset  # noqa: A001 - rotordyn.sweep.open(OUT), as the issue asks

__all__ = ["SweepSpec", "SweepResult", "SweepDataset", "SweepInterrupted", "run_sweep",
           "read_dataset", "open", "open_dataset"]
