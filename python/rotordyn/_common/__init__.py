"""The package's lowest room, below every other (docs/architecture.md): field validation
(:mod:`.validate`), unit-slip warnings (:mod:`.plausibility`), BLAS threads (:mod:`.threads`),
the status vocabulary of every result (:mod:`.status`), whirl classification of orbits
(:mod:`.whirl`) and the package version (:mod:`.info`). It imports only ``rotordyn._core``,
``rotordyn.errors`` and ``rotordyn.units``."""
