"""The status vocabulary of every result and sweep row (DESIGN §5): a status is truthful, and
only a converged equilibrium is linearised, classified or integrated from."""

STATUSES = ("ok", "no_equilibrium", "contact", "not_converged", "error")
# Converged equilibria ("contact": converged with a film thinner than contact_fraction c);
# only these are linearised, classified or integrated from. The others are failures.
CONVERGED = ("ok", "contact")
FAILED = ("no_equilibrium", "not_converged", "error")
