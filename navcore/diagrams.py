"""Block diagrams drawn as code (schemdraw, rendered through matplotlib).

The papers' structural figures are redrawn from the models they describe. Where a diagram
shows a quantity (a state count, a rate), the caller passes it in from navcore, so that a
diagram cannot drift from the model it illustrates; :mod:`navcore.figures.diagrams` wires
each diagram to its numbers.

Functions
---------
ins_block_diagram
    inertial navigation system: IMU, strapdown processing, gravity model (KZL Fig. 1).
gnss_receiver_block_diagram
    correlators, carrier and code tracking loops, navigation processor (KZL Fig. 2).
tightly_coupled_feedback_diagram
    GNSS/INS tightly coupled indirect feedback integration (KZL Fig. 3).
matched_filter_receiver_diagram
    receiver matched to one aircraft's signature (ATC-10 Fig. 3.1).
integration_architectures_diagram
    loosely, tightly and deeply coupled INS/GPS side by side (SP Secs. 2.1-2.2 and 3).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import schemdraw
from matplotlib.figure import Figure
from schemdraw import dsp, flow

__all__ = [
    "gnss_receiver_block_diagram",
    "ins_block_diagram",
    "integration_architectures_diagram",
    "matched_filter_receiver_diagram",
    "tightly_coupled_feedback_diagram",
]

FONT = 9
FILL_SENSOR = "#e8f0fa"
FILL_PROC = "#fdf3e3"
FILL_FILTER = "#e6f4e6"

Point = tuple[float, float]


@dataclass
class _Canvas:
    """A schemdraw drawing plus free text placed in drawing coordinates."""

    d: schemdraw.Drawing
    notes: list[tuple[float, float, str, str, str]] = field(default_factory=list)

    def box(self, xy: Point, text: str, w: float = 3.0, h: float = 1.3, fill: str = FILL_PROC):
        return self.d.add(flow.Box(w=w, h=h).at(xy).anchor("center").label(text, fontsize=FONT).fill(fill))

    def arrow(self, start: Point, end: Point, shape: str = "-", k: float | None = None):
        if shape == "-":
            return self.d.add(flow.Arrow().at(start).to(end))
        wire = flow.Wire(shape, k=k, arrow="->") if k is not None else flow.Wire(shape, arrow="->")
        return self.d.add(wire.at(start).to(end))

    def text(self, xy: Point, s: str, ha: str = "center", va: str = "center") -> None:
        self.notes.append((xy[0], xy[1], s, ha, va))

    def figure(self, width_in: float) -> Figure:
        fig = self.d.draw(show=False).fig
        ax = fig.axes[0]
        for x, y, s, ha, va in self.notes:
            ax.text(x, y, s, ha=ha, va=va, fontsize=FONT - 1, zorder=5)
        ax.set_axis_off()
        # include the free text in the limits
        xs = [x for x, *_ in self.notes]
        ys = [y for _, y, *_ in self.notes]
        if xs:
            x0, x1 = ax.get_xlim()
            y0, y1 = ax.get_ylim()
            ax.set_xlim(min(x0, min(xs) - 1.5), max(x1, max(xs) + 1.5))
            ax.set_ylim(min(y0, min(ys) - 0.6), max(y1, max(ys) + 0.6))
        x0, x1 = ax.get_xlim()
        y0, y1 = ax.get_ylim()
        fig.set_size_inches(width_in, width_in * (y1 - y0) / (x1 - x0))
        return fig


def _canvas() -> _Canvas:
    schemdraw.use("matplotlib")
    d = schemdraw.Drawing(show=False)
    d.config(fontsize=FONT, lw=1.2, unit=2.0)
    return _Canvas(d)


def ins_block_diagram(imu_rate_hz: float) -> Figure:
    """Inertial navigation system: IMU outputs, strapdown processing and its feedbacks.

    Parameters
    ----------
    imu_rate_hz : float
        Rate of the IMU increments (shown on the diagram).

    Returns
    -------
    matplotlib.figure.Figure
        The diagram, 9 inches wide, its axes hidden; the caller shows or saves it and
        closes it.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = ins_block_diagram(imu_rate_hz=100.0)
    >>> round(float(fig.get_size_inches()[0]), 1)
    9.0
    >>> plt.close(fig)
    """
    c = _canvas()
    imu = c.box((0, 0), "IMU\ngyroscopes and\naccelerometers", w=4.2, h=2.0, fill=FILL_SENSOR)
    att = c.box(
        (7.5, 2.2), "attitude update\n" + r"$\dot q = \frac{1}{2}\, q \otimes \omega_{nb}^b$", w=4.4, h=1.6
    )
    rot = c.box((7.5, -2.2), "resolve specific force\n" + r"$f^n = C_b^n f_{ib}^b$", w=5.2, h=1.6)
    vel = c.box((14.5, -2.2), "velocity\n" + r"$\dot v^n = f^n + g^n -$ Coriolis", w=5.4, h=1.6)
    pos = c.box((21.0, -2.2), "position\n" + r"$\dot\varphi,\ \dot\lambda,\ \dot h$", w=3.4, h=1.6)
    env = c.box((14.5, 2.2), "gravity model,\nEarth rate,\ntransport rate", w=4.6, h=1.6, fill=FILL_SENSOR)
    split = (imu.E[0] + 1.2, imu.E[1])
    c.d.add(flow.Line().at(imu.E).to(split))
    c.arrow(split, att.W, "|-")
    c.arrow(split, rot.W, "|-")
    c.text((split[0] + 0.3, att.W[1] + 0.45), r"$\omega_{ib}^b$", ha="left")
    c.text((split[0] + 0.3, rot.W[1] - 0.45), r"$f_{ib}^b$", ha="left")
    c.arrow(att.S, rot.N)
    c.text((att.S[0] + 0.2, 0.0), r"$C_b^n$", ha="left")
    c.arrow(rot.E, vel.W)
    c.arrow(vel.E, pos.W)
    c.arrow(env.S, vel.N)
    c.text((env.S[0] + 0.2, 0.0), r"$g^n,\ \omega_{ie}^n,\ \omega_{en}^n$", ha="left")
    c.arrow(env.W, att.E)
    c.text(((env.W[0] + att.E[0]) / 2, env.W[1] + 0.4), r"$\omega_{in}^n$")
    c.arrow(pos.N, env.E, "|-")
    c.text((pos.N[0] + 0.2, 1.0), "position,\nvelocity", ha="left")
    c.d.add(flow.Arrow().at(pos.E).right(1.8))  # type: ignore[call-arg]  # schemdraw accepts a length
    c.text((pos.E[0] + 2.0, pos.E[1]), "position,\nvelocity,\nattitude", ha="left")
    c.text((imu.S[0], imu.S[1] - 0.5), f"increments at {imu_rate_hz:g} Hz", va="top")
    return c.figure(9.0)


def gnss_receiver_block_diagram(nav_rate_hz: float) -> Figure:
    """GNSS receiver: correlators, carrier and code tracking loops, navigation processor.

    Parameters
    ----------
    nav_rate_hz : float
        Output rate of the navigation processor (shown on the diagram).

    Returns
    -------
    matplotlib.figure.Figure
        The diagram, 9.5 inches wide, its axes hidden; the caller shows or saves it and
        closes it.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = gnss_receiver_block_diagram(nav_rate_hz=1.0)
    >>> round(float(fig.get_size_inches()[0]), 1)
    9.5
    >>> plt.close(fig)
    """
    c = _canvas()
    ant = c.d.add(dsp.Antenna().at((-1.5, 1.2)))
    fe = c.box((1.0, -1.0), "RF front end,\ndown-conversion,\nA/D", w=4.4, h=1.8, fill=FILL_SENSOR)
    c.arrow(ant.end, fe.W, "|-")
    cor = c.box((8.0, -1.0), "correlators\nI and Q: early,\nprompt, late", w=4.0, h=1.8)
    c.arrow(fe.E, cor.W)
    c.text(((fe.E[0] + cor.W[0]) / 2, fe.E[1] + 0.35), "IF samples")
    iad = c.box((13.5, -1.0), "integrate\nand dump", w=2.8, h=1.8)
    c.arrow(cor.E, iad.W)
    cdisc = c.box((19.0, 2.2), "carrier\ndiscriminator", w=3.8, h=1.3)
    kdisc = c.box((19.0, -4.2), "code\ndiscriminator", w=3.8, h=1.3)
    c.arrow(iad.N, cdisc.W, "|-")
    c.arrow(iad.S, kdisc.W, "|-")
    c.text((iad.N[0] + 0.2, 1.5), "I, Q", ha="left")
    c.text((iad.S[0] + 0.2, -3.5), "I, Q", ha="left")
    clf = c.box((13.5, 5.0), "carrier loop filter", w=4.4, h=1.2)
    klf = c.box((13.5, -7.0), "code loop filter", w=4.4, h=1.2)
    c.arrow(cdisc.N, clf.E, "|-")
    c.arrow(kdisc.S, klf.E, "|-")
    cnco = c.box((8.0, 5.0), "carrier NCO", w=3.6, h=1.2)
    knco = c.box((8.0, -7.0), "code NCO and\ncode generator", w=3.8, h=1.4)
    c.arrow(clf.W, cnco.E)
    c.arrow(klf.W, knco.E)
    c.arrow(cnco.S, cor.N)
    c.arrow(knco.N, cor.S)
    c.text((cnco.S[0] - 0.2, 2.5), "replica\ncarrier", ha="right")
    c.text((knco.N[0] - 0.2, -4.7), "replica\ncode", ha="right")
    nav = c.box(
        (25.5, -1.0),
        f"navigation\nprocessor\n(Kalman filter)\n{nav_rate_hz:g} Hz",
        w=4.2,
        h=2.4,
        fill=FILL_FILTER,
    )
    top = (cnco.N[0], cnco.N[1] + 1.2)
    c.d.add(flow.Line().at(cnco.N).to(top))
    c.arrow(top, nav.N, "-|")
    c.text((17.0, top[1] + 0.45), "carrier phase and Doppler (delta range, accumulated delta range)")
    bottom = (knco.S[0], knco.S[1] - 1.2)
    c.d.add(flow.Line().at(knco.S).to(bottom))
    c.arrow(bottom, nav.S, "-|")
    c.text((17.0, bottom[1] - 0.45), "code phase (pseudorange)")
    c.d.add(flow.Arrow().at(nav.E).right(1.8))  # type: ignore[call-arg]  # schemdraw accepts a length
    c.text((nav.E[0] + 2.0, nav.E[1]), "position,\nvelocity,\ntime", ha="left")
    return c.figure(9.5)


def tightly_coupled_feedback_diagram(n_states: int, imu_rate_hz: float, gnss_rate_hz: float) -> Figure:
    """GNSS/INS tightly coupled indirect feedback integration.

    Parameters
    ----------
    n_states : int
        Number of error states of the integration filter.
    imu_rate_hz, gnss_rate_hz : float
        Strapdown and measurement-update rates.

    Returns
    -------
    matplotlib.figure.Figure
        The diagram, 9.5 inches wide, its axes hidden; the caller shows or saves it and
        closes it.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = tightly_coupled_feedback_diagram(n_states=17, imu_rate_hz=100.0, gnss_rate_hz=1.0)
    >>> round(float(fig.get_size_inches()[0]), 1)
    9.5
    >>> plt.close(fig)
    """
    c = _canvas()
    imu = c.box((0, 3.0), "IMU", w=2.2, h=1.3, fill=FILL_SENSOR)
    comp = c.box((5.0, 3.0), "sensor error\ncompensation", w=3.2, h=1.6)
    sd = c.box((11.0, 3.0), f"strapdown\nmechanization\n{imu_rate_hz:g} Hz", w=3.4, h=1.9)
    pred = c.box((17.5, 3.0), "predicted\npseudorange and\ndelta range", w=3.6, h=1.9)
    rx = c.box((17.5, -3.5), "GNSS receiver\n(code and carrier\ntracking)", w=3.6, h=1.9, fill=FILL_SENSOR)
    kf = c.box(
        (11.0, -3.5),
        f"error-state\nKalman filter\n{n_states} states, {gnss_rate_hz:g} Hz",
        w=3.8,
        h=2.0,
        fill=FILL_FILTER,
    )
    summ = c.d.add(dsp.SumSigma().at((22.5, -0.25)).anchor("center"))
    c.arrow(imu.E, comp.W)
    c.text(((imu.E[0] + comp.W[0]) / 2, imu.E[1] + 0.4), r"$\omega_{ib}^b, f_{ib}^b$")
    c.arrow(comp.E, sd.W)
    c.arrow(sd.E, pred.W)
    c.text(((sd.E[0] + pred.W[0]) / 2, sd.E[1] + 0.4), "PVA")
    c.arrow(pred.E, summ.N, "-|")
    c.arrow(rx.E, summ.S, "-|")
    c.text((summ.N[0] + 0.3, summ.N[1] + 0.5), "+", ha="left")
    c.text((summ.S[0] + 0.3, summ.S[1] - 0.5), "−", ha="left")
    mid = (summ.W[0] - 1.0, summ.W[1])
    c.d.add(flow.Line().at(summ.W).to(mid))
    c.arrow(mid, kf.N, "-|")
    c.text((mid[0] - 0.2, mid[1] + 0.4), "measurement residuals", ha="right")
    c.arrow(kf.W, comp.S, "-|")
    c.text((comp.S[0] - 0.2, -2.4), "bias and\nscale-factor\nestimates", ha="right")
    c.arrow((kf.N[0] - 1.2, kf.N[1]), (sd.S[0] - 1.2, sd.S[1]))
    c.text((sd.S[0] - 1.4, 0.1), "position, velocity,\nattitude corrections", ha="right")
    c.d.add(flow.Arrow().at(sd.N).up(1.2))  # type: ignore[call-arg]  # schemdraw accepts a length
    c.text((sd.N[0], sd.N[1] + 1.5), "corrected position, velocity, attitude", va="bottom")
    return c.figure(9.5)


def matched_filter_receiver_diagram(signature_label: str = "i") -> Figure:
    """Receiver matched to one aircraft's signature: mixer, low-pass, matched filter, threshold.

    Parameters
    ----------
    signature_label : str
        Label of the aircraft whose signature the filter is matched to.

    Returns
    -------
    matplotlib.figure.Figure
        The diagram, 9.5 inches wide, its axes hidden; the caller shows or saves it and
        closes it.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = matched_filter_receiver_diagram("i")
    >>> round(float(fig.get_size_inches()[0]), 1)
    9.5
    >>> plt.close(fig)
    """
    c = _canvas()
    i = signature_label
    start = (0.0, 0.0)
    mix = c.d.add(dsp.Mixer().at((2.5, 0.0)).anchor("W"))
    c.arrow(start, mix.W)
    c.text((0.2, 0.45), "$Z(t)$", ha="left")
    osc = c.d.add(dsp.Oscillator().at((mix.S[0], mix.S[1] - 1.6)).anchor("N"))
    c.arrow(osc.N, mix.S)
    c.text((osc.S[0], osc.S[1] - 0.3), rf"$2\cos 2\pi f_0 (t - t_{i})$", va="top")
    lp = c.box((mix.E[0] + 1.5 + 1.6, 0.0), "low-pass\nfilter", w=3.2, h=1.4)
    c.arrow(mix.E, lp.W)
    mf = c.box(
        (lp.E[0] + 1.5 + 2.3, 0.0), f'matched filter "{i}"\n' + rf"$h(t) = S_{i}(\tau - t)$", w=4.6, h=1.7
    )
    c.arrow(lp.E, mf.W)
    smp = (mf.E[0] + 2.2, 0.0)
    c.arrow(mf.E, smp)
    c.text(((mf.E[0] + smp[0]) / 2, 0.4), rf"$y_{i}(t)$")
    dec = c.d.add(
        flow.Decision(w=3.8, h=2.0).at(smp).anchor("W").fill(FILL_FILTER).label(rf"$y_{i}(t) \geq \theta$ ?")
    )
    c.d.add(flow.Arrow().at(dec.E).right(1.6))  # type: ignore[call-arg]  # schemdraw accepts a length
    c.text((dec.E[0] + 1.8, 0.0), f"signature ${i}$ received\n" + r"at $t - \tau$", ha="left")
    c.d.add(flow.Arrow().at(dec.S).down(1.2))  # type: ignore[call-arg]  # schemdraw accepts a length
    c.text((dec.S[0], dec.S[1] - 1.4), "not received", va="top")
    c.text((dec.N[0], dec.N[1] + 0.3), "sample at $t$", va="bottom")
    return c.figure(9.5)


def integration_architectures_diagram(
    receiver_states: int,
    loose_states: int,
    tight_states: int,
    loose_update_s: float,
    ehe_limit_m: float,
    tight_rate_hz: float,
    min_satellites: int,
) -> Figure:
    """Loosely, tightly and deeply coupled INS/GPS data flows side by side.

    Parameters
    ----------
    receiver_states, loose_states, tight_states : int
        Filter state counts (from the state layouts).
    loose_update_s : float
        Interval between receiver position updates in the loosely coupled filter (s).
    ehe_limit_m : float
        Expected horizontal error below which a receiver solution is used (m).
    tight_rate_hz : float
        Rate of pseudorange and range-rate updates in the tightly coupled filter.
    min_satellites : int
        Satellites the receiver needs for its own solution.

    Returns
    -------
    matplotlib.figure.Figure
        The diagram, 10 inches wide, its axes hidden; the caller shows or saves it and
        closes it.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = integration_architectures_diagram(8, 17, 19, 1.0, 25.0, 1.0, 4)
    >>> round(float(fig.get_size_inches()[0]), 1)
    10.0
    >>> plt.close(fig)
    """
    c = _canvas()
    cols = {"loose": 0.0, "tight": 13.0, "deep": 26.0}
    titles = {"loose": "loosely coupled", "tight": "tightly coupled", "deep": "deeply integrated"}
    for key, x in cols.items():
        c.text((x + 1.0, 8.3), titles[key])
    # loosely coupled: tracking -> receiver PVA filter -> integration filter <- INS
    x = cols["loose"]
    trk = c.box((x, 6.6), "tracking loops", w=4.0, h=1.1, fill=FILL_SENSOR)
    rx = c.box((x, 3.4), f"receiver PVA filter\n{receiver_states} states", w=4.4, h=1.4)
    ins = c.box((x + 5.0, -0.2), "INS", w=2.0, h=1.1, fill=FILL_SENSOR)
    kf = c.box((x, -0.2), f"integration filter\n{loose_states} error states", w=4.6, h=1.4, fill=FILL_FILTER)
    c.arrow(trk.S, rx.N)
    c.text((trk.S[0] + 0.2, 5.4), f"pseudoranges\n(solution needs\n≥ {min_satellites} satellites)", ha="left")
    c.arrow(rx.S, kf.N)
    c.text(
        (rx.S[0] + 0.2, 1.6), f"position every {loose_update_s:g} s\nif EHE < {ehe_limit_m:g} m", ha="left"
    )
    c.arrow(ins.W, kf.E)
    # tightly coupled
    x = cols["tight"]
    trk = c.box((x, 6.6), "tracking loops", w=4.0, h=1.1, fill=FILL_SENSOR)
    ins = c.box((x + 5.0, -0.2), "INS", w=2.0, h=1.1, fill=FILL_SENSOR)
    kf = c.box((x, -0.2), f"integration filter\n{tight_states} error states", w=4.6, h=1.4, fill=FILL_FILTER)
    c.arrow(trk.S, kf.N)
    c.text(
        (trk.S[0] + 0.2, 3.2), f"pseudorange and\nrange rate per\nsatellite, {tight_rate_hz:g} Hz", ha="left"
    )
    c.arrow(kf.W, trk.W, "c", k=-1.2)
    c.text((x - 3.7, 3.2), "aiding", ha="right")
    c.arrow(ins.W, kf.E)
    # deeply integrated
    x = cols["deep"]
    cor = c.box((x, 6.6), "correlators", w=3.4, h=1.1, fill=FILL_SENSOR)
    ins = c.box((x + 5.0, -0.2), "INS", w=2.0, h=1.1, fill=FILL_SENSOR)
    kf = c.box((x, -0.2), "one filter for\ntracking and\nnavigation", w=3.8, h=1.8, fill=FILL_FILTER)
    c.arrow(cor.S, kf.N)
    c.text((cor.S[0] + 0.2, 3.2), "correlator\nI and Q", ha="left")
    c.arrow(kf.W, cor.W, "c", k=-1.2)
    c.text((x - 3.4, 3.2), "NCO\ncommands", ha="right")
    c.arrow(ins.W, kf.E)
    return c.figure(10.0)
