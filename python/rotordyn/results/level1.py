"""API 617 Level I stability analysis: the log decrement of the judged forward rotor mode
against an applied cross-coupled stiffness Q, the Q_0 that zeroes it, the anticipated
cross-coupling Q_A of the stages, δ_A at Q_A and the Level I criteria.

Source: API Standard 617, 8th ed. (2014), Part 1 §4.8.5; API Standard 684, 2nd ed. (2005),
§2.9 (the same procedure). A Level II analysis is required when Q_0/Q_A < 2, or δ_A < 0.1, or
2 ≤ Q_0/Q_A < 10 and the critical speed ratio CSR lies in Region B of the standard's screening
figure (CSR against the average gas density). The figure's boundary is not reproduced here:
pass the boundary CSR read from it (``csr_limit``) to have that criterion judged."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from rotordyn._common.status import CONVERGED
from rotordyn.results._display import Display

if TYPE_CHECKING:
    import pandas as pd

LEVEL1_RATIO = 2.0      # API 617: Q_0/Q_A ≥ 2
LEVEL1_LOG_DEC = 0.1    # API 617: δ_A ≥ 0.1
LEVEL1_CSR_RATIO = 10.0  # API 617: for 2 ≤ Q_0/Q_A < 10 the screening figure decides
NOT_RESOLVED = "not resolved"
NO_STAGE_DATA = "not evaluated (no stage data)"
MODE_TEXT = {"first_forward": "first forward rotor mode",
             "least_damped": "least damped forward rotor mode"}


@dataclass(frozen=True)
class Level1Result(Display):
    """Level I at one speed.

    q_n_per_m, log_dec, freq_hz: (n,) the applied cross-coupling Q (N/m, increasing, Q_A and
    Q_0 among them), the judged mode's log decrement and damped frequency (Hz) at each Q.
    q_a_n_per_m: Q_A (NaN without stage data); q0_n_per_m: Q_0 (inf when δ stays positive up to
    ``q_max_n_per_m``); log_dec_a: δ at Q_A (NaN without stage data). placement: where Q acts,
    ``[(station, share, position_m)]`` (shares sum to 1); placement_why: how it was chosen.
    stages: the stage data used, one dict per stage (with its q_A). mode: the judging rule
    (``"first_forward"`` or ``"least_damped"``). csr: maximum continuous speed over the first
    critical speed on rigid supports (NaN when not computed); gas_density_kg_m3: the average gas
    density (NaN when not given); csr_limit: the Region B boundary CSR read from the standard's
    figure (NaN when not given).
    """

    speed_hz: float
    q_n_per_m: np.ndarray
    log_dec: np.ndarray
    freq_hz: np.ndarray
    q_a_n_per_m: float
    q0_n_per_m: float
    log_dec_a: float
    q_max_n_per_m: float
    placement: tuple
    placement_why: str
    stages: tuple = ()
    mode: str = "first_forward"
    csr: float = float("nan")
    first_critical_hz: float = float("nan")
    gas_density_kg_m3: float = float("nan")
    csr_limit: float = float("nan")
    status: str = "ok"
    message: str = ""
    log_dec_0: float = float("nan")
    freq_0_hz: float = float("nan")

    @property
    def mode_text(self) -> str:
        """The judged mode in words ("first forward rotor mode")."""
        return MODE_TEXT[self.mode]

    @property
    def has_stage_data(self) -> bool:
        return bool(np.isfinite(self.q_a_n_per_m))

    @property
    def ratio(self) -> float:
        """Q_0/Q_A (inf when Q_0 is not reached; NaN without stage data)."""
        if not self.has_stage_data or self.q_a_n_per_m <= 0:
            return float("nan")
        return float(self.q0_n_per_m / self.q_a_n_per_m)

    def checks(self) -> list[tuple[str, str, str, object]]:
        """(name, criterion, value, verdict): True PASS, False FAIL (Level II required), None
        no criterion applies, ``NOT_RESOLVED`` or ``NO_STAGE_DATA`` a value not computed."""
        name = "API 617 Level I"
        if self.status not in CONVERGED:
            return [(name, "Q_0/Q_A ≥ 2 and δ_A ≥ 0.1", f"no equilibrium ({self.status}): "
                     f"{self.message}", NOT_RESOLVED)]
        if not self.has_stage_data:
            return [(name, "Q_0/Q_A ≥ 2 and δ_A ≥ 0.1", NO_STAGE_DATA, NO_STAGE_DATA)]
        r = self.ratio
        q0 = (f"Q_0 = {self.q0_n_per_m:.4g} N/m" if np.isfinite(self.q0_n_per_m) else
              f"δ > 0 up to Q = {self.q_max_n_per_m:.4g} N/m")
        out = [(f"{name}: Q_0/Q_A", f"Q_0/Q_A ≥ {LEVEL1_RATIO:g}",
                f"{q0}, Q_A = {self.q_a_n_per_m:.4g} N/m, ratio "
                + (f"{r:.3g}" if np.isfinite(r)
                   else f"> {self.q_max_n_per_m / self.q_a_n_per_m:.3g}"),
                bool(r >= LEVEL1_RATIO)),
               (f"{name}: δ_A", f"δ at Q_A ≥ {LEVEL1_LOG_DEC:g}",
                f"δ_A = {self.log_dec_a:.3g} (mode at {self._freq_at_a():.4g} Hz)",
                bool(self.log_dec_a >= LEVEL1_LOG_DEC))]
        crit = (f"for {LEVEL1_RATIO:g} ≤ Q_0/Q_A < {LEVEL1_CSR_RATIO:g}: CSR in Region A of the "
                "standard's screening figure (CSR against the average gas density)")
        if LEVEL1_RATIO <= r < LEVEL1_CSR_RATIO:
            val = (f"CSR = {self.csr:.3g}" if np.isfinite(self.csr) else "CSR not computed")
            if np.isfinite(self.gas_density_kg_m3):
                val += f", average gas density {self.gas_density_kg_m3:.4g} kg/m³"
            if np.isfinite(self.csr) and np.isfinite(self.csr_limit):
                out.append((f"{name}: screening", crit,
                            val + f", Region B above CSR {self.csr_limit:.3g} (as given)",
                            bool(self.csr <= self.csr_limit)))
            else:
                out.append((f"{name}: screening", crit, val + "; the Region B boundary at this "
                            "density was not given (csr_limit, read from the standard's figure)",
                            NOT_RESOLVED))
        return out

    def _freq_at_a(self) -> float:
        i = np.flatnonzero(self.q_n_per_m == self.q_a_n_per_m)
        return float(self.freq_hz[i[0]]) if i.size else float("nan")

    @property
    def level2_required(self):
        """True (a criterion fails), False (Level I passed), None (not evaluated/resolved)."""
        vs = [c[3] for c in self.checks()]
        if any(x is False for x in vs):
            return True
        if any(isinstance(x, str) for x in vs):
            return None
        return False

    def verdict(self) -> str:
        """"PASS", "FAIL (Level II required)", "NOT RESOLVED" or NO_STAGE_DATA."""
        if self.status in CONVERGED and not self.has_stage_data:
            return NO_STAGE_DATA
        lv = self.level2_required
        return {True: "FAIL (Level II required)", False: "PASS", None: "NOT RESOLVED"}[lv]

    def __repr__(self) -> str:
        if self.status not in CONVERGED:
            return f"<Level1Result {self.status} at {self.speed_hz:g} Hz: {self.message}>"
        q0 = (f"Q_0 = {self.q0_n_per_m:.4g} N/m" if np.isfinite(self.q0_n_per_m)
              else f"Q_0 > {self.q_max_n_per_m:.4g} N/m")
        qa = (f"Q_A = {self.q_a_n_per_m:.4g} N/m, Q_0/Q_A = {self.ratio:.3g}, δ_A = "
              f"{self.log_dec_a:.3g}" if self.has_stage_data else "no stage data")
        return (f"<Level1Result {self.verdict()} at {self.speed_hz:g} Hz: {q0}, {qa}; δ(Q=0) = "
                f"{self.log_dec_0:.3g} ({MODE_TEXT[self.mode]}, {self.freq_0_hz:.4g} Hz)>")

    def to_frame(self) -> pd.DataFrame:
        """One row per applied Q: ``applied_q_n_per_m``, ``log_dec``, ``freq_hz``, and flags
        ``is_q_a`` / ``is_q0`` for the rows at Q_A and Q_0; then ``speed_hz``, ``status``."""
        import pandas as pd
        n = self.q_n_per_m.size
        return pd.DataFrame({
            "speed_hz": np.full(n, self.speed_hz),
            "applied_q_n_per_m": self.q_n_per_m,
            "log_dec": self.log_dec,
            "freq_hz": self.freq_hz,
            "is_q_a": self.q_n_per_m == self.q_a_n_per_m,
            "is_q0": self.q_n_per_m == self.q0_n_per_m,
            "status": pd.Categorical([self.status] * n),
        })

    def plot(self, ax=None):
        """Log decrement against the applied cross-coupling with Q_A, Q_0 and δ = 0.1 marked
        (:func:`rotordyn.plot.level1.level1_curve`)."""
        from rotordyn.plot.level1 import level1_curve

        return level1_curve(self, ax=ax)
