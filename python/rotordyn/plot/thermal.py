"""Bearing temperatures against speed (issue 20): per bearing the hottest film temperature
(°C) and the total power loss (W) of its films (pads, lobes), from the frame of
:func:`rotordyn.report.thermal.bearing_totals` (columns ``bearing``, ``speed_hz``,
``max_temperature_c``, ``power_loss_w``)."""

from __future__ import annotations

from rotordyn.plot._style import COLUMN_IN, paper_style, require


@paper_style
def bearing_temperatures(totals):
    """Two panels over ``speed_hz``: the hottest film temperature (°C) and the power loss (W),
    one line per bearing; returns the figure."""
    import matplotlib.pyplot as plt

    need = {"bearing", "speed_hz", "max_temperature_c", "power_loss_w"}
    require(need <= set(totals.columns), "bearing_temperatures: expected columns bearing, "
            "speed_hz, max_temperature_c, power_loss_w")
    require(len(totals) > 0, "bearing_temperatures: the frame has no rows")
    fig, (a, b) = plt.subplots(1, 2, figsize=(2 * COLUMN_IN, 0.8 * COLUMN_IN),
                               layout="constrained")
    styles = ("o-", "s--", "^:", "d-.")
    for k, (name, g) in enumerate(totals.groupby("bearing", sort=False)):
        g = g.sort_values("speed_hz")
        a.plot(g["speed_hz"], g["max_temperature_c"], styles[k % 4], label=str(name))
        b.plot(g["speed_hz"], g["power_loss_w"], styles[k % 4], label=str(name))
    a.set(xlabel="speed (Hz)", ylabel="hottest film temperature (°C)")
    b.set(xlabel="speed (Hz)", ylabel="power loss (W)")
    a.legend(fontsize="small")
    return fig
