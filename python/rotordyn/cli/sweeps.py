"""Sweeps on the command line: ``rotordyn sweep SPEC --out DIR`` and ``rotordyn plot DIR``."""

from __future__ import annotations

import argparse
import sys

from rotordyn.cli.common import add_dpi, check_dpi, figure_path
from rotordyn.errors import InputError


def register(sub) -> None:
    """``sweep`` and ``plot`` on the ``rotordyn`` parser's subparsers ``sub``."""
    s = sub.add_parser("sweep", help="run a sweep spec on dask into a parquet dataset")
    s.add_argument("spec", help="sweep specification: a TOML file, or a built-in spec's "
                                "name (fig9_stability_map, sweeps/<name>.toml)")
    s.add_argument("--out", required=True, metavar="DIR",
                   help="output dataset directory: new or empty, or this sweep's own to "
                        "resume")
    s.add_argument("--scheduler", default=None, metavar="ADDR",
                   help="tcp://host:port or tls://host:port of an existing dask cluster "
                        "(default: a LocalCluster); the cluster is trusted completely")
    s.add_argument("--tls-ca-file", default=None, metavar="PEM",
                   help="tls:// scheduler: the CA certificate that signed the cluster's "
                        "certificates")
    s.add_argument("--tls-cert", default=None, metavar="PEM",
                   help="tls:// scheduler: this client's certificate")
    s.add_argument("--tls-key", default=None, metavar="PEM",
                   help="tls:// scheduler: this client's private key")
    s.add_argument("--workers", type=int, default=None, metavar="N",
                   help="LocalCluster worker processes, started only when the driver's "
                        "first chunks show the map is worth it (default: one per core, at "
                        "most one per chunk left)")
    s.add_argument("--threads", type=int, default=None, metavar="N",
                   help="compute on N threads in this process, no dask (default: off)")
    s.add_argument("--resume", action=argparse.BooleanOptionalAction, default=True,
                   help="continue an interrupted sweep in --out; --no-resume restarts the "
                        "same sweep from scratch")
    s.add_argument("--json", action="store_true", help="one JSON summary line, no progress")
    s.set_defaults(func=_cmd_sweep)

    s = sub.add_parser("plot", help="figure from a sweep directory")
    s.add_argument("dir", help="sweep dataset directory (written by `rotordyn sweep`)")
    s.add_argument("--kind", required=True,
                   choices=["stability-map", "equilibrium", "campbell", "waterfall",
                            "hopf-map"],
                   help="figure kind; it must match the sweep's analysis")
    s.add_argument("--out", required=True, metavar="FIG", help="FIG.png or FIG.svg")
    s.add_argument("--style", choices=["cascade", "map"], default="cascade",
                   help="waterfall: 3-D cascade or colour map (speed × frequency)")
    s.add_argument("--scale", choices=["linear", "log"], default="linear",
                   help="waterfall: amplitude scale")
    s.add_argument("--axis", choices=["x", "y"], default="x",
                   help="waterfall: journal motion component")
    s.add_argument("--where", action="append", default=[], metavar="AXIS=VALUE",
                   help="fix an axis of the sweep at its grid value nearest VALUE (SI), e.g. "
                        "--where bearing[0].clearance_m=1e-4; repeatable (a third varying axis "
                        "is refused, never averaged)")
    s.add_argument("--facet", default=None, metavar="AXIS",
                   help="stability-map: one map per value of this third varying axis (small "
                        "multiples sharing the colour scale), instead of fixing it with --where")
    add_dpi(s)
    # its libraries load before the 'still running' clock starts (main): the clock then times
    # the reading and drawing, and a dataset refused at once stays one stderr line on a
    # loaded machine, as when pandas and pyarrow loaded with the package
    s.set_defaults(func=_cmd_plot, preload=("pandas", "pyarrow.parquet", "matplotlib"))


def _cmd_sweep(args) -> int:
    from rotordyn.sweep import SweepInterrupted, run_sweep  # (dask, pyarrow: only when used)
    from rotordyn.sweep.runner import manifest_json

    try:
        res = run_sweep(args.spec, args.out, scheduler=args.scheduler, workers=args.workers,
                        threads=args.threads, resume=args.resume,
                        tls_ca_file=args.tls_ca_file, tls_cert=args.tls_cert,
                        tls_key=args.tls_key,
                        progress=False if args.json else None)
    except SweepInterrupted as exc:
        print(f"rotordyn: {exc}", file=sys.stderr)
        return 130
    if res.dropped:
        print(f"rotordyn: resume: {len(res.dropped)} file(s) of {args.out} did not match the "
              "log and were removed, their chunks computed again: " + "; ".join(
                  f"{n} ({why})" for n, why in res.dropped), file=sys.stderr)
    if args.json:
        print(manifest_json(res))
    else:
        c = res.counts
        print(f"{res.manifest['sweep_id']}: {res.done}/{res.n_chunks} chunks, "
              f"{res.manifest['n_points']} points (ok {c['ok']}, failed {c['failed']}, "
              f"unstable {c['unstable']}) -> {args.out}")
    return 0 if res.complete else 1


def _cmd_plot(args) -> int:
    from rotordyn.plot import plot_dataset
    from rotordyn.sweep import read_dataset

    figure_path("--out", args.out)
    kw = ({"style": args.style, "scale": args.scale, "axis": args.axis}
          if args.kind == "waterfall" else {})
    kw["where"] = _where(args.where)
    if args.facet is not None:
        if args.kind != "stability-map":
            raise InputError(f"--facet: only --kind stability-map draws small multiples, got "
                             f"--kind {args.kind}")
        kw["facet"] = args.facet
    kw["dpi"] = check_dpi(args.dpi)
    plot_dataset(read_dataset(args.dir), args.kind, args.out, **kw)
    print(f"wrote {args.out}", file=sys.stderr)
    return 0


def _where(items) -> dict:
    """``["AXIS=VALUE", ...]`` → {axis: value}; InputError naming the flag otherwise."""
    out = {}
    for text in items:
        axis, sep, val = text.partition("=")
        try:
            out[axis.strip()] = float(val)
        except ValueError:
            sep = ""
        if not sep or not axis.strip():
            raise InputError(f"--where: expected AXIS=VALUE (a number, SI), got {text!r}")
    return out
