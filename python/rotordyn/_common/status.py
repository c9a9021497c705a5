"""The status vocabulary of every result and sweep row (DESIGN §5): a status is truthful, and
only a converged equilibrium is linearised, classified or integrated from."""

STATUSES = ("ok", "no_equilibrium", "contact", "not_converged", "error", "starved")
# Converged equilibria ("contact": converged with a film thinner than contact_fraction c);
# only these are linearised, classified or integrated from. The others are failures.
CONVERGED = ("ok", "contact")
FAILED = ("no_equilibrium", "not_converged", "error", "starved")
# "starved": a thermal film whose metered oil supply and the hot oil reaching its inlet fall
# short of the flow it draws (docs/film-physics.md "A metered supply below the film's demand")


def point_messages(status, messages):
    """``point_message`` of a result over points (Campbell, unbalance response; one type on
    every path, isothermal or thermal): an (n,) object array, at a failed point why it failed
    (a str: the failed stage's message, ``"<ErrorClass>: <what>"`` where a solve raised, else
    the status itself), None where the point converged (status in :data:`CONVERGED`)."""
    import numpy as np

    out = np.full(len(status), None, dtype=object)
    for i, (st, m) in enumerate(zip(status, messages)):
        if str(st) not in CONVERGED:
            out[i] = str(m) if m else str(st)
    return out
