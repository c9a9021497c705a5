#!/usr/bin/env bash
# Regenerates the figures in docs/figures/ with the shipped commands only, so that what the
# docs show is what a user gets. Run from the repository root after `make install`:
#     bash docs/figures/regenerate.sh            (a few minutes on 2 cores; the waterfall
#                                                 sweep is most of it)
# fig11_orbits.png (transient orbits) is still drawn by docs/calibration/paper_rig_transient.py.
set -euo pipefail
RD=${ROTORDYN:-.venv/bin/rotordyn}
FIG=docs/figures
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
set -x
$RD validate paper-rig --plot $FIG/paper_rig_rotor.png
$RD modes paper-rig --reduction none --n-modes 6 --speed-hz 50 --plot $FIG/paper_rig_mode_shapes.png
$RD modes paper-rig --reduction none --n-modes 6 --speed-hz 50 --mode 3 --plot $FIG/paper_rig_mode3_orbits.png
$RD campbell paper-rig --chamber-pressure-pa 4e5 --config-ay-m 0 --speeds-hz 5:120:1 \
    --plot $FIG/paper_rig_fig12_campbell.png
$RD unbalance paper-rig --unbalance 6,1e-4,0 --station 4 --chamber-pressure-pa 4e5 \
    --config-ay-m 0 --operating-speed-hz 45 55 --plot $FIG/paper_rig_unbalance_bode.png
$RD unbalance paper-rig --unbalance 6,1e-4,0 --station 4 --chamber-pressure-pa 4e5 \
    --config-ay-m 0 --plot $FIG/paper_rig_unbalance_polar.png --plot-kind polar
for f in fig7_equilibrium:paper_rig_fig7:equilibrium fig8_equilibrium_speed:paper_rig_fig8:equilibrium \
         fig9_stability_map:paper_rig_fig9_boundary:stability-map \
         fig10_stability_map_speed:paper_rig_fig10_boundary:stability-map \
         fig13_waterfall:fig13_waterfall:waterfall; do
    IFS=: read -r spec out kind <<< "$f"
    $RD sweep sweeps/$spec.toml --out "$TMP/$spec" --workers 2
    $RD plot "$TMP/$spec" --kind "$kind" --out $FIG/$out.png
done
$RD report paper-rig --out "$TMP/report" --html "$TMP/report.html"
