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
$RD modes paper-rig --without-bearings --reduction none --n-modes 6 --speed-hz 50 --plot $FIG/paper_rig_mode_shapes.png
$RD modes paper-rig --without-bearings --reduction none --n-modes 6 --speed-hz 50 --mode 3 --plot $FIG/paper_rig_mode3_orbits.png
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
$RD sweep sweeps/fig13_waterfall.toml --out "$TMP/fig13_waterfall" --workers 2   # resumes: no recompute
$RD plot "$TMP/fig13_waterfall" --kind waterfall --style map --scale log \
    --out $FIG/fig13_waterfall_map.png
$RD report paper-rig --out "$TMP/report" --html "$TMP/report.html"
# A machine of the user's own (tests/data/models: the three-impeller compressor rotor): the
# report's mode shape at a critical speed (on linear supports, which have one in range), the
# bearing coefficients over speed (tilting pads condensed at synchronous whirl), and a
# three-axis stability sweep drawn as small multiples (--facet).
M=tests/data/models
$RD report $M/compressor_linear.toml --out "$TMP/r_lin" --html "$TMP/r_lin.html" \
    --operating-speed-hz 140 170
cp "$TMP/r_lin/critical_mode_1.png" $FIG/compressor_critical_mode_1.png
$RD report $M/compressor_tilting_pad.toml --out "$TMP/r_tp" --html "$TMP/r_tp.html" \
    --operating-speed-hz 140 170
cp "$TMP/r_tp/bearing_coefficients.png" $FIG/compressor_tp_bearing_coefficients.png
cat > "$TMP/facets.toml" <<EOF
schema = "rotordyn/sweep/1"
name = "compressor-speed-clearance-viscosity"
model = "$PWD/$M/compressor_plain.toml"
analysis = "stability"
chunk_size = 35

[grid]
"bearings.*.viscosity_pa_s" = [0.012, 0.018, 0.028]
"bearings.*.clearance_m" = [7.0e-5, 8.5e-5, 1.0e-4, 1.15e-4, 1.3e-4]
speed_hz = [60.0, 80.0, 100.0, 120.0, 140.0, 160.0, 180.0]
EOF
$RD sweep "$TMP/facets.toml" --out "$TMP/facets" --workers 2
$RD plot "$TMP/facets" --kind stability-map --facet "bearings.*.viscosity_pa_s" \
    --out $FIG/compressor_stability_facets.png
