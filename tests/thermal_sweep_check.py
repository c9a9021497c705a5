"""A ``thermal`` sweep over one model field against the direct calls (used by
test_film_thd_system.py and test_thd_walls.py): the sweep's rows of each point beside
``rotordyn.system_thermal_equilibrium`` on the model with that field value."""

import rotordyn


def sweep_points(tmp_path, system, field: str, values, speed_hz: float = 150.0):
    """Run the 2-point-chunk ``thermal`` sweep of ``system`` over ``field`` = ``values`` at
    ``speed_hz`` (one thread), check it is complete and every row ok, and return
    [(value, rows of the point, direct result)] in point order."""
    import rotordyn.sweep as sw
    from rotordyn.sweep import run_sweep
    from rotordyn.sweep.paths import set_field

    system.to_toml(tmp_path / "m.toml")
    spec = tmp_path / "s.toml"
    grid = ", ".join(repr(float(x)) for x in values)
    spec.write_text(f'schema = "rotordyn/sweep/1"\nname = "field"\nmodel = "m.toml"\n'
                    f'analysis = "thermal"\nchunk_size = 2\n[grid]\n'
                    f'"{field}" = [{grid}]\nspeed_hz = {speed_hz!r}\n')
    res = run_sweep(spec, tmp_path / "o", threads=1)
    assert res.complete and res.counts["failed"] == 0
    fr = sw.open(tmp_path / "o").frame
    assert len(fr) == len(system.bearings) * len(values) and (fr["status"] == "ok").all()
    out = []
    for _, g in fr.groupby("point_id"):
        x = float(g.iloc[0][field])
        r = rotordyn.system_thermal_equilibrium(set_field(system, field, x), speed_hz=speed_hz)
        out.append((x, g, r))
    return out
