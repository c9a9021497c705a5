"""How results show themselves in Jupyter: the short text ``repr`` and the first rows of
``to_frame()`` as an HTML table (issue 18)."""

from __future__ import annotations

import html

ROWS = 12


class Display:
    """Mixin of the result dataclasses: ``_repr_html_`` from ``repr`` and ``to_frame()``;
    ``save(path)`` and ``load(path)`` (:mod:`rotordyn.results.store`)."""

    def save(self, path):
        """Write this result to ``path`` (a ``.npz`` archive with JSON metadata); read it back
        with ``type(result).load(path)`` or :func:`rotordyn.load_result`. Returns the path."""
        from rotordyn.results.store import save_result

        return save_result(self, path)

    @classmethod
    def load(cls, path):
        """The result of this class saved in ``path`` (another kind: InputError)."""
        from rotordyn.results.store import load_result

        return load_result(path, kind=cls)

    def _repr_html_(self) -> str:
        head = f"<pre>{html.escape(repr(self))}</pre>"
        try:
            df = self.to_frame()
        except Exception:  # noqa: BLE001 - a display never raises
            return head
        more = f"<p>{len(df)} rows; <code>.to_frame()</code> for all</p>" if len(df) > ROWS \
            else ""
        return head + df.head(ROWS).to_html(index=False, float_format=lambda x: f"{x:.6g}") \
            + more
