"""WF Sec. III, the crucial role of aperture velocity: Eqs. (8)-(9) and the prose numbers.

The identities of Eqs. (8)-(9) hold for any geometry and are checked on seeded random
geometries (test fixtures); the prose numbers are evaluated on the Sec. III scenario, a turn
past an emitter at the assumed speed, altitude, range and bearing
(:data:`navcore.papers.wf_inputs.IN`). Models: :mod:`navcore.location.emitter`.
"""

from __future__ import annotations

import numpy as np

from navcore.claims import PROSE_WORDS, Claim, input_cache, printed, prose, with_quotes
from navcore.location.emitter import (
    doppler_gradient_position,
    doppler_gradient_velocity,
    doppler_jacobian_emitter,
    level_turn_track,
    linearized_location_error,
    location_error_covariance,
    position_sensitivity_bound,
    signal_model_error,
    velocity_to_position_sensitivity_ratio,
)
from navcore.papers.wf_inputs import IN
from navcore.papers.wf_location_error import EMITTER, F0, orbit
from navcore.papers.wf_quotes import QUOTES
from navcore.units import FT, C

#: The page that discusses the claims of Sec. III.
PAGE = "wf/02-velocity-sensitivity"


#: Samples along the Sec. III scenario track: a numerical resolution, not an input (the claims
#: take the minimum or the mean over the continuous track; at this density a 10 % change of it
#: moves them by round-off only).
SCENARIO_SAMPLES = 2001


def scenario_track(M: int = SCENARIO_SAMPLES) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The Sec. III scenario track: a turn at the assumed rate, speed and altitude, for the assumed
    aperture duration."""
    return level_turn_track(IN.speed_mps, IN.altitude_m, M, IN.turn_rate_deg_s, IN.aperture_duration_s)


def scenario_emitter() -> np.ndarray:
    """The emitter at the assumed horizontal distance and bearing from the start of the track."""
    b = np.deg2rad(IN.emitter_bearing_deg)
    return IN.emitter_distance_m * np.array([np.cos(b), np.sin(b), 0.0])


def mean_range() -> float:
    """Mean aperture-to-emitter range over the Sec. III scenario (assumed inputs), m."""
    _, pos, _ = scenario_track()
    return float(np.mean(np.linalg.norm(scenario_emitter() - pos, axis=1)))


@input_cache
def _random_geometries(n: int = 2000) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(11)
    p = rng.normal(0, 5000, (n, 3))
    e = p + rng.normal(0, 30000, (n, 3))
    v = rng.normal(0, 200, (n, 3))
    return p, e, v


def _eq8_identity() -> bool:
    p, e, _ = _random_geometries()
    # only the difference of the positions enters: put the emitter at the origin, vectorised
    norms = np.linalg.norm(doppler_gradient_velocity(F0, np.zeros(3), p - e), axis=1)
    return bool(np.max(np.abs(norms / (F0 / C) - 1)) < 1e-12)


def position_bound_ratios() -> np.ndarray:
    """||df/dp|| divided by the printed bound of WF Eq. (9), over random geometries."""
    p, e, v = _random_geometries()
    g = np.linalg.norm(doppler_gradient_position(F0, np.zeros(3), p - e, v), axis=1)
    return g / position_sensitivity_bound(F0, np.linalg.norm(v, axis=1), np.linalg.norm(e - p, axis=1))


def _eq9_bound_holds() -> bool:
    return bool(np.max(position_bound_ratios()) <= 1.0)


def wingtip_velocity_amplitude() -> float:
    """Velocity amplitude 2 pi f A of the assumed first wing mode, m/s."""
    return float(2 * np.pi * IN.vib_hz * IN.vib_amplitude_m)


def sensitivity_ratios() -> np.ndarray:
    """||df/dv|| / ||df/dp|| at each sample of the book geometry (exact WF Eqs. (8)-(9)), s.

    The frequency change caused by a 1 m/s aperture-velocity error divided by that of a 1 m
    aperture-position error, each in its worst direction. Sec. III scenario (assumed speed,
    altitude and emitter distance; the carrier cancels).
    """
    _, pos, vel = scenario_track()
    emitter = scenario_emitter()
    gv = np.linalg.norm(doppler_gradient_velocity(F0, emitter, pos), axis=1)
    gp = np.linalg.norm(doppler_gradient_position(F0, emitter, pos, vel), axis=1)
    return gv / gp


@input_cache
def location_error_leverage() -> dict[str, np.ndarray]:
    """Emitter-position error per unit aperture error through WF Eq. (6), book geometry.

    ``"bias_v"`` / ``"bias_p"``: norm of the emitter-position error (m) caused by a constant
    1 m/s velocity error / 1 m position error along x, y, z of every sample (exact signal-model
    error of Eq. (6), propagated to first order). ``"white_v"`` / ``"white_p"``: RMS of the
    emitter-position error (m) for independent errors of 1 m/s / 1 m per axis and sample.
    """
    _, pos, vel = orbit()
    H = doppler_jacobian_emitter(F0, EMITTER, pos, vel)
    out: dict[str, np.ndarray] = {"bias_v": np.empty(3), "bias_p": np.empty(3)}
    for axis, d in enumerate(np.eye(3)):
        ft_v = signal_model_error(F0, EMITTER, pos, vel, pos, vel + d)
        ft_p = signal_model_error(F0, EMITTER, pos, vel, pos + d, vel)
        out["bias_v"][axis] = np.linalg.norm(linearized_location_error(H, ft_v)[:3])
        out["bias_p"][axis] = np.linalg.norm(linearized_location_error(H, ft_p)[:3])
    for key, g in (
        ("white_v", doppler_gradient_velocity(F0, EMITTER, pos)),
        ("white_p", doppler_gradient_position(F0, EMITTER, pos, vel)),
    ):
        cov = location_error_covariance(H, np.diag(np.sum(g**2, axis=1)))
        out[key] = np.array(np.sqrt(np.trace(cov[:3, :3])))
    return out


def flexible_mode_is_several() -> bool:
    """'An adverse velocity component of several meters/second': the assumed first mode's velocity
    amplitude within the prose table's 'several' (3 to 9 m/s)."""
    word = PROSE_WORDS["several"]
    v = wingtip_velocity_amplitude()
    return bool(word["centre"] - word["abs"] <= v <= word["centre"] + word["abs"])


_c8, _c8_tol = printed("100")
_c6, _c6_tol = printed("1e4", why="'$10^{4}$ %', one significant digit")
_c3, _c3_tol = printed("10")
_c2, _c2_tol = printed("0.01")

ORDER = prose("on the order of", why="'R/2|v| is on the order of 100'")
APPROX = prose("approximately", why="'approximately 1 % relative to the nominal velocity'")


# ----------------------------------------------------------------------------- claims
CLAIMS = [
    Claim(
        id="WF-sec3-tip-position-vs-range",
        aliases=("WF-c2-position",),
        locator="Sec. III",
        quantity="wing-tip position perturbation relative to range",
        published=_c2,
        unit="%",
        compute=lambda: 100 * IN.deflection_ft * FT / mean_range(),
        tolerance=_c2_tol,
        expected_status="not-reproducible",
        relation="<=",
        note="'Several feet' (assumed 5 ft, 3-9) over the mean range of the Sec. III scenario (assumed "
        "speed, altitude and emitter distance). 'At most 0.01 %' is read as an upper bound, with half a "
        "unit in its last printed digit.",
        discussed_in=PAGE,
    ),
    Claim(
        id="WF-sec3-tip-position-vs-ins",
        aliases=("WF-c3-position-ins",),
        locator="Sec. III",
        quantity="wing-tip position perturbation relative to the best INS/GPS position accuracy",
        published=_c3,
        unit="%",
        kind="reproduction",
        compute=lambda: 100 * IN.deflection_ft * FT / IN.ins_gps_position_m,
        tolerance=_c3_tol,
        expected_status="not-reproducible",
        relation="<=",
        note="The INS/GPS position accuracy of reference [3] (Graham & Johnston 1986, Table 1) is not "
        "quoted: assumed 10 m (5-30 m). At the nominal 5 ft it gives 15 %; 'at most 10 %' needs an "
        "accuracy of 15 m or worse (or a smaller deflection).",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="WF-sec3-flexible-mode-velocity",
        aliases=("WF-c4-flexible-mode",),
        locator="Sec. III",
        quantity="a first flexible mode of several hertz gives an aperture velocity amplitude of several "
        "m/s (3 to 9 m/s, the reading of 'several' in the ledger's table of prose words)",
        compute=flexible_mode_is_several,
        expected_status="not-reproducible",
        note="The velocity amplitude $2\\pi f A$ of the assumed first wing mode: $f$ = 3 Hz (3-9, "
        "'several Hertz') with a tip amplitude $A$ = 0.1 m (5-30 cm) gives 1.9 m/s, below 'several'. The "
        "paper says the mode 'can result in' several m/s, a "
        "possibility: across the assumed frequency and amplitude the velocity amplitude spans 0.94-17 "
        "m/s and lies in 3-9 m/s over part of that range, not at the nominal mode. The paper prints no "
        "number: 'several' is read as 3-9, as in the ledger's table of prose words.",
        discussed_in=PAGE,
    ),
    Claim(
        id="WF-sec3-velocity-vs-nominal",
        aliases=("WF-c5-velocity-nominal",),
        locator="Sec. III",
        quantity="velocity perturbation relative to the nominal velocity",
        published=1.0,
        unit="%",
        compute=lambda: 100 * IN.sigma_t_large / IN.speed_mps,
        tolerance=APPROX,
        expected_status="consistent",
        note="Perturbation = the large $\\sigma_T$ of Sec. IV.D (2 m/s); nominal speed assumed 200 m/s "
        "(100-300).",
        discussed_in=PAGE,
    ),
    Claim(
        id="WF-sec3-velocity-vs-ins",
        aliases=("WF-c6-velocity-ins",),
        locator="Sec. III",
        quantity="velocity perturbation relative to the best INS/GPS velocity accuracy",
        published=_c6,
        unit="%",
        kind="cross-check",
        compute=lambda: 100 * IN.sigma_t_large / IN.sigma_n,
        tolerance=_c6_tol,
        expected_status="consistent",
        note="$\\sigma_T = 2$ m/s over $\\sigma_N = 0.02$ m/s, both printed in Sec. IV.D: arithmetic on "
        "printed values, a cross-check.",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="WF-eq8-norm",
        locator="Eq. (8)",
        quantity="$\\|\\partial f/\\partial \\mathbf{v}\\| = f_0/c$ for every geometry",
        compute=_eq8_identity,
        note="2000 seeded random geometries; relative deviation < $10^{-12}$.",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="WF-eq9-bound",
        locator="Eq. (9)",
        quantity="$\\|\\partial f/\\partial \\mathbf{p}\\| \\le (f_0/c)\\, 2\\|\\mathbf{v}\\|/R$ for every "
        "geometry",
        compute=_eq9_bound_holds,
        note="2000 seeded random geometries. The exact norm is $(f_0/c)\\|\\mathbf{v}_\\perp\\|/R$, so the "
        "bound is "
        "loose by at least a factor 2.",
        discussed_in=PAGE,
    ),
    Claim(
        id="WF-eq9-velocity-position-ratio",
        aliases=("WF-c7-ratio",),
        locator="Sec. III, after Eq. (9)",
        quantity="$R / (2 \\|\\mathbf{v}\\|)$, velocity-to-position sensitivity ratio",
        published=100.0,
        unit="s",
        compute=lambda: float(velocity_to_position_sensitivity_ratio(IN.speed_mps, mean_range())),
        tolerance=ORDER,
        expected_status="not-reproducible",
        note="Mean range of the Sec. III scenario (assumed speed, altitude and emitter distance). With the "
        "exact Eq. (9) norm the ratio is at least $R/\\|\\mathbf{v}\\|$, twice as large.",
        discussed_in=PAGE,
    ),
    Claim(
        id="WF-eq9-velocity-error-dominates",
        aliases=("WF-c8-effective",),
        locator="Sec. III, after Eq. (9)",
        quantity="a 1 m/s velocity error changes the modelled frequency at least 100 times as much as a "
        "1 m position error (smallest "
        "$\\|\\partial f/\\partial \\mathbf{v}\\| / \\|\\partial f/\\partial \\mathbf{p}\\|$ over the track)",
        published=_c8,
        unit="s",
        compute=lambda: float(np.min(sensitivity_ratios())),
        tolerance=_c8_tol,
        expected_status="not-reproducible",
        relation=">=",
        note="'At least 100 times more effective', read with the exact gradients of Eqs. (8)-(9) over the "
        "Sec. III scenario (assumed speed, altitude and emitter distance: the paper gives none). The "
        "exact ratio is $R/\\|\\mathbf{v}_\\perp\\| \\ge R/\\|\\mathbf{v}\\|$, "
        "so it holds on any track with $R \\ge$ 100 s $\\cdot \\|\\mathbf{v}\\|$. The paper's own "
        "argument, $R/(2\\|\\mathbf{v}\\|)$ "
        "(WF-eq9-velocity-position-ratio), "
        "falls short of 100 on this geometry. Through Eq. (6) the location-error leverage depends on the "
        "error: a constant vertical velocity error is mostly absorbed by the $f_0$ estimate (shown on this "
        "page).",
        discussed_in=PAGE,
    ),
]

CLAIMS = with_quotes(CLAIMS, QUOTES)
