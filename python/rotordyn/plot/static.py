"""Static diagrams along the rotor: deflection (µm), shear force (N) and bending moment (N·m) in
the vertical and horizontal planes, with the reactions of the supports and bearings marked."""

from __future__ import annotations


from rotordyn.plot._style import PAGE_IN, paper_style


@paper_style
def static_diagram(result, axes=None, system=None):
    """Three stacked Axes of a :class:`rotordyn.results.StaticResult` (z along the rotor, m);
    returns them."""
    import matplotlib.pyplot as plt

    if axes is None:
        fig, axes = plt.subplots(3, 1, sharex=True, figsize=(PAGE_IN * 0.62, PAGE_IN * 0.8),
                                 layout="constrained")
    a1, a2, a3 = axes
    z = result.node_positions_m
    a1.plot(z, result.deflection_y_m * 1e6, color="tab:blue", label="vertical y")
    a1.plot(z, result.deflection_x_m * 1e6, color="tab:orange", ls="--", label="horizontal x")
    zs = result.section_positions_m
    a2.plot(zs, result.shear_y_n, color="tab:blue", label="vertical (y)")
    a2.plot(zs, result.shear_x_n, color="tab:orange", ls="--", label="horizontal (x)")
    a3.plot(zs, result.moment_yz_n_m, color="tab:blue", label="vertical plane (y–z)")
    a3.plot(zs, result.moment_xz_n_m, color="tab:orange", ls="--",
            label="horizontal plane (x–z)")
    if system is not None and len(result.reactions):
        zst = system.rotor.station_positions_m()
        for r in result.reactions.itertuples():
            a2.annotate(f"{r.name or r.kind}\n{r.force_y_n:.3g} N", (zst[r.station], 0.0),
                        xytext=(0, 14), textcoords="offset points", ha="center", fontsize=6,
                        arrowprops=dict(arrowstyle="->", lw=0.6))
    for ax in axes:
        ax.axhline(0, color="0.5", lw=0.5)
    a1.set_ylabel("deflection (µm)")
    a2.set_ylabel("shear force (N)")
    a3.set_ylabel("bending moment (N·m)\nsagging > 0")
    a3.set_xlabel("axial position z (m)")
    a1.set_title(f"static deflection and internal forces at {result.speed_hz:g} Hz "
                 f"(weight {result.weight_n:.4g} N)")
    for ax in axes:
        ax.legend(loc="best", fontsize=6)
    return tuple(axes)
