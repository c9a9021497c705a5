"""Figures (matplotlib), one module per family, sized for a paper's column, units on every axis
and colour bar, legends that explain every line style.

* :mod:`~rotordyn.plot.frequency` Campbell diagrams (tracked modes, log dec colour, critical
  speeds, order lines)
* :mod:`~rotordyn.plot.response` unbalance response: Bode and polar, API 684 AF and margins
* :mod:`~rotordyn.plot.maps` stability maps, threshold curves, equilibrium loci
* :mod:`~rotordyn.plot.shapes` 3-D mode shapes and deflected shapes (whirl orbits)
* :mod:`~rotordyn.plot.drawing` the rotor drawn from the model
* :mod:`~rotordyn.plot.cascade` waterfalls (3-D cascade or colour map, run-ups)
* :mod:`~rotordyn.plot.level1` API 617 Level I: log decrement against the applied
  cross-coupling
* :mod:`~rotordyn.plot.dataset` figures from sweep datasets (``rotordyn plot``)
"""

from rotordyn.plot._style import COLUMN_IN, PAGE_IN, RC
from rotordyn.plot.cascade import runup_spectra, waterfall
from rotordyn.plot.dataset import KINDS, campbell, plot_dataset
from rotordyn.plot.drawing import rotor_drawing
from rotordyn.plot.frequency import campbell_arrays, campbell_diagram
from rotordyn.plot.level1 import level1_curve
from rotordyn.plot.maps import (AXIS_LABEL, AXIS_SCALE, axis_label, boundary_curve, equilibrium_loci,
                                stability_map, stability_map_grid)
from rotordyn.plot.response import bode, polar
from rotordyn.plot.shapes import deflected_shape, mode_shape, mode_shapes_2d, orbits_3d

__all__ = ["KINDS", "AXIS_LABEL", "AXIS_SCALE", "axis_label", "COLUMN_IN", "PAGE_IN", "RC", "plot_dataset",
           "stability_map", "stability_map_grid", "equilibrium_loci", "boundary_curve",
           "campbell", "campbell_arrays", "campbell_diagram", "waterfall", "runup_spectra",
           "bode", "polar", "rotor_drawing", "mode_shape", "mode_shapes_2d", "orbits_3d",
           "deflected_shape", "level1_curve"]
