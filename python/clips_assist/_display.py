"""How a Session shows itself in Jupyter: the scene (PNG) and the goal posterior (HTML).

IPython calls ``_repr_html_`` (the scene and a bar per goal, in one cell output)
and ``_repr_png_`` (the scene alone) when a session is a cell's value; a text
scene, which has no picture, is shown as its lines.
"""
import base64
import html

from ._core import InputError, Session

_BAR = ("<div style='background:#4477aa;height:0.8em;width:{w:.1f}%;min-width:1px'></div>")


def _png_or_none(session):
    try:
        return session.scene_png()
    except InputError:  # a text scene has no picture
        return None


def _repr_png_(self):
    """The current state as PNG bytes (None for a text scene)."""
    return _png_or_none(self)


def _posterior_table(posterior):
    rows = "".join(
        f"<tr><td style='text-align:left'>{html.escape(g['goal'])}</td><td>{g['p']:.3f}</td>"
        f"<td style='width:12em'>{_BAR.format(w=100 * g['p'])}</td></tr>"
        for g in posterior["goals"])
    return (f"<table><thead><tr><th style='text-align:left'>goal</th><th>P</th><th></th></tr></thead>"
            f"<tbody>{rows}</tbody></table>")


def _repr_html_(self):
    """The scene beside the goal posterior, with the domain, t and who is to move."""
    posterior = self.posterior()
    png = _png_or_none(self)
    scene = (f"<img alt='the current state' src='data:image/png;base64,{base64.b64encode(png).decode()}'/>"
             if png is not None else f"<pre>{html.escape(str(self))}</pre>")
    head = (f"<b>{html.escape(self.domain)}</b>, t = {self.t}, {html.escape(self.active_agent)} to move; "
            f"posterior by {html.escape(posterior['method'])} ({html.escape(posterior['modality'])})")
    return (f"<div class='clips-assist-session'><div>{head}</div>"
            f"<div style='display:flex;gap:1.5em;align-items:flex-start'><div>{scene}</div>"
            f"<div>{_posterior_table(posterior)}</div></div></div>")


Session._repr_png_ = _repr_png_
Session._repr_html_ = _repr_html_
