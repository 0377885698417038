r"""Multiple-access noise at the output of a matched filter (ATC-10 Section 3.4, Appendix E).

:math:`N` aircraft transmit unit-energy signatures of duration :math:`\tau` once every
:math:`\alpha` seconds, at independent, uniformly distributed arrival times. At a sampling
instant, interferer :math:`j` overlaps the matched filter of aircraft :math:`i` with
probability :math:`q = 2 \tau / \alpha` and then contributes an amplitude drawn from its
*amplitude density* :math:`C(x)`. The noise sample is the sum of the :math:`N - 1` gated
contributions, so its cumulant generating function is

.. math::

    \mu(s) = (N - 1) \ln\left((1 - q) + q M_C(s)\right),

the logarithm of ATC-10 Eq. (3.4.6) with :math:`v = s / j`. Everything here works with
:math:`\mu` and its first two derivatives in the log domain; the ROC bounds of
:mod:`navcore.detection.roc_bounds` only need those.

Amplitude densities are objects with ``log_mgf(s)``, ``dlog_mgf(s)`` (:math:`= M'/M`),
``d2_ratio(s)`` (:math:`= M''/M`), ``moment(r)``, ``char_fn(v)`` and ``sample(rng, size)``.
Four closed forms of equal second moment :math:`b` are provided (two-point, uniform, triangular,
Gaussian), a general point-mass density (which also represents a tabulated continuous
density or an empirical sample), and a density given only by its log-MGF.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache
from math import comb
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import special, stats
from scipy.interpolate import BSpline

from navcore._validate import (
    COUNT,
    COUNT0,
    POSITIVE,
    PROBABILITY,
    Range,
    as_finite_array,
    check_public,
    require_integer,
    require_positive,
    require_probability,
)
from navcore.trace import implements

__all__ = [
    "GaussianDensity",
    "LogMGFDensity",
    "MultipleAccessNoise",
    "PointMassDensity",
    "StratifiedSums",
    "TriangularDensity",
    "UniformDensity",
    "carrier_phase_density",
    "cumulants_from_raw_moments",
    "edgeworth_density",
    "edgeworth_tail",
    "gaussian_mixture_exact_tail",
    "irwin_hall_cdf",
    "psk_amplitude_samples",
    "sample_noise",
    "stratified_sums",
    "stratified_tail",
    "tabulated_density",
    "triangular_exact_tail",
    "two_point_density",
    "two_point_exact_tail",
    "uniform_exact_tail",
]

FloatArray = NDArray[np.float64]


def _log_sinhc(x: FloatArray) -> FloatArray:
    """ln(sinh(x)/x), stable for small and large |x|."""
    x = np.abs(np.asarray(x, dtype=float))
    small = x < 1e-3
    xs = np.where(small, 1.0, x)
    big = xs + np.log1p(-np.exp(-2.0 * xs)) - np.log(2.0) - np.log(xs)
    series = x**2 / 6.0 - x**4 / 180.0
    return np.where(small, series, big)


def _langevin(x: FloatArray) -> FloatArray:
    """L(x) = coth x - 1/x, with its series near 0."""
    x = np.asarray(x, dtype=float)
    small = np.abs(x) < 1e-3
    xs = np.where(small, 1.0, x)
    return np.where(small, x / 3.0 - x**3 / 45.0, 1.0 / np.tanh(xs) - 1.0 / xs)


def _langevin_over_x(x: FloatArray) -> FloatArray:
    """L(x)/x, with its series near 0."""
    x = np.asarray(x, dtype=float)
    small = np.abs(x) < 1e-3
    xs = np.where(small, 1.0, x)
    return np.where(small, 1.0 / 3.0 - x**2 / 45.0, (1.0 / np.tanh(xs) - 1.0 / xs) / xs)


@dataclass(frozen=True)
class PointMassDensity:
    """Amplitude density made of point masses ``weights`` at ``values`` (ATC-10 Eq. 3.3.8).

    Also represents a tabulated continuous density (quadrature nodes, see
    :func:`tabulated_density`) or an empirical sample (equal weights).

    Attributes
    ----------
    values : tuple of float
        Atom positions (relative to the unit peak).
    weights : tuple of float
        Atom probabilities (sum 1).
    name : str
        Label.
    """

    values: tuple[float, ...]
    weights: tuple[float, ...]
    name: str = "point masses"
    _x: FloatArray = field(init=False, repr=False, compare=False)
    _logw: FloatArray = field(init=False, repr=False, compare=False)
    _cdf: FloatArray = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        x = as_finite_array("values", self.values).ravel()
        w = as_finite_array("weights", self.weights).ravel()
        if x.size == 0 or x.shape != w.shape:
            raise ValueError("values and weights must be non-empty and of equal length")
        if np.any(w < 0) or not np.isfinite(w).all() or not np.isfinite(x).all():
            raise ValueError("weights must be finite and >= 0, values finite")
        total = w.sum()
        if not total > 0:
            raise ValueError("weights must have a positive sum")
        w = w / total
        with np.errstate(divide="ignore"):
            object.__setattr__(self, "_x", x)
            object.__setattr__(self, "_logw", np.log(w))
        cdf = np.cumsum(w)
        cdf[-1] = 1.0
        object.__setattr__(self, "_cdf", cdf)

    @property
    def second_moment(self) -> float:
        return self.moment(2)

    def _tilted(self, s: ArrayLike) -> tuple[FloatArray, FloatArray]:
        s = np.asarray(s, dtype=float)
        a = s[..., None] * self._x + self._logw
        lm = special.logsumexp(a, axis=-1)
        return lm, np.exp(a - lm[..., None])

    def log_mgf(self, s: ArrayLike) -> FloatArray:
        """ln E exp(s x)."""
        return self._tilted(s)[0]

    def dlog_mgf(self, s: ArrayLike) -> FloatArray:
        """M'(s)/M(s): the mean of the exponentially tilted density."""
        return self._tilted(s)[1] @ self._x

    def d2_ratio(self, s: ArrayLike) -> FloatArray:
        """M''(s)/M(s): the second moment of the tilted density."""
        return self._tilted(s)[1] @ self._x**2

    def moment(self, r: int) -> float:
        return float(np.exp(self._logw) @ self._x**r)

    def char_fn(self, v: ArrayLike) -> NDArray[np.complex128]:
        v = np.asarray(v, dtype=float)
        return np.exp(1j * v[..., None] * self._x) @ np.exp(self._logw)

    def sample(self, rng: np.random.Generator, size: int) -> FloatArray:
        idx = np.searchsorted(self._cdf, rng.random(size), side="right")
        return self._x[np.minimum(idx, self._x.size - 1)]


@implements("ATC10 3.7.1")
def two_point_density(b: float) -> PointMassDensity:
    r"""The quasi-optimal density: masses 1/2 at :math:`\pm\sqrt{b}` (ATC-10 Eq. 3.7.1 with
    :math:`b = p/((N-1)q)`).

    Parameters
    ----------
    b : float
        Variance of one interferer's amplitude (``> 0``).

    Returns
    -------
    PointMassDensity
        The two atoms and their weights.

    Raises
    ------
    ValueError
        If ``b`` is not positive.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (3.7.1).

    Examples
    --------
    >>> d = two_point_density(0.04)
    >>> [round(v, 6) for v in d.values], [round(w, 6) for w in d.weights]
    ([-0.2, 0.2], [0.5, 0.5])
    """
    require_positive("b", b)
    a = float(np.sqrt(b))
    return PointMassDensity((-a, a), (0.5, 0.5), name="two-point")


def tabulated_density(
    pdf: Callable[[FloatArray], FloatArray], lo: float, hi: float, n: int = 200, name: str = "tabulated"
) -> PointMassDensity:
    """A continuous density on [lo, hi] as Gauss-Legendre point masses (exact MGF to quadrature order).

    Parameters
    ----------
    pdf : callable
        Probability density ``pdf(x)`` on [lo, hi]; the weights are ``pdf`` at the nodes
        times the quadrature weights, so pass a density that integrates to 1.
    lo : float
        Lower end of the support.
    hi : float
        Upper end of the support.
    n : int, default 200
        Number of nodes (``>= 2``).
    name : str, default "tabulated"
        Name of the density.

    Returns
    -------
    PointMassDensity
        Nodes and weights.

    Raises
    ------
    ValueError
        If ``n`` is less than 2.

    Examples
    --------
    >>> import numpy as np
    >>> d = tabulated_density(lambda x: np.full_like(x, 0.5), -1.0, 1.0, n=20)
    >>> w, x = np.array(d.weights), np.array(d.values)
    >>> round(float(w.sum()), 12), round(float(np.sum(w * x**2)), 6)
    (1.0, 0.333333)
    """
    if not hi > lo:
        raise ValueError(f"hi must be > lo, got lo={lo}, hi={hi}")
    require_integer("n", n, minimum=2)
    t, w = np.polynomial.legendre.leggauss(n)
    x = 0.5 * (hi - lo) * t + 0.5 * (hi + lo)
    return PointMassDensity(tuple(x), tuple(w * pdf(x) * 0.5 * (hi - lo)), name=name)


@implements("ATC10 3.3.7")
def carrier_phase_density(
    envelope_values: ArrayLike,
    envelope_weights: ArrayLike,
    n_phases: int = 12,
    name: str = "cos(phase) x envelope",
) -> PointMassDensity:
    r"""Amplitude density of :math:`n_{ij} = \cos(2\pi f_0 (t_i - t_j))\, X` with a uniform carrier
    phase and a point-mass envelope :math:`X` (ATC-10 Sec. 3.4, the overlap integral of Eq. 3.3.7).

    Sec. 3.4 takes the arrival time :math:`t_j` uniform over :math:`\alpha` with
    :math:`f_0 \alpha` an integer, so the carrier phase is uniform over :math:`[0, 2\pi)`
    whatever the envelope. The phase is represented by ``n_phases`` equally spaced values
    :math:`2\pi k / n`, :math:`k = 0, \ldots, n - 1`, each of probability :math:`1/n`, which
    give every moment :math:`E \cos^r` of order :math:`r < n` exactly (odd ones zero, so the
    density is symmetric and :math:`\lambda_3 = 0` of Appendix E's Eq. E.15). The atoms are the
    products :math:`\cos(\phi_k)\, x_m`, phase-major, with weights :math:`w_m / n`.

    Parameters
    ----------
    envelope_values : array_like
        Atom positions :math:`x_m` of the envelope :math:`X` (1-D, finite).
    envelope_weights : array_like
        Their probabilities :math:`w_m` (``> 0``; 1-D, the length of ``envelope_values``).
    n_phases : int, default 12
        Number of equally spaced carrier phases (``>= 1``).
    name : str, default "cos(phase) x envelope"
        Label of the density.

    Returns
    -------
    PointMassDensity
        ``n_phases * len(envelope_values)`` point masses.

    Raises
    ------
    ValueError
        If ``n_phases`` is not a positive integer, or ``envelope_values`` and
        ``envelope_weights`` are not 1-D, empty, of different lengths or not finite, or a
        weight is not positive.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 3.4 and Eq. (3.3.7).

    Examples
    --------
    >>> d = carrier_phase_density((0.5, 2.0), (0.8, 0.2), n_phases=4)
    >>> len(d.values), round(d.moment(2), 12)  # E cos^2 = 1/2 times E X^2 = 1.0
    (8, 0.5)
    """
    require_integer("n_phases", n_phases, minimum=1)
    x = as_finite_array("envelope_values", envelope_values, ndim=1)
    w = as_finite_array("envelope_weights", envelope_weights, ndim=1)
    if x.size == 0 or x.shape != w.shape:
        raise ValueError(
            "envelope_values and envelope_weights must be non-empty and of equal length, "
            f"got {x.size} and {w.size}"
        )
    if np.any(w <= 0.0):
        raise ValueError(f"envelope_weights must be > 0 (an atom of zero probability is none), got {w}")
    phases = 2.0 * np.pi * np.arange(n_phases) / n_phases
    vals = [np.cos(ph) * xm for ph in phases for xm in x]
    probs = [wm / phases.size for _ in phases for wm in w]
    return PointMassDensity(tuple(vals), tuple(probs), name=name)


@dataclass(frozen=True)
class UniformDensity:
    r"""Uniform amplitude density on :math:`[-\sqrt{3b}, \sqrt{3b}]` (second moment :math:`b`).

    Attributes
    ----------
    b : float
        Second moment (relative to the unit peak squared).
    name : str
        Label.
    """

    b: float
    name: str = "uniform"

    def __post_init__(self) -> None:
        require_positive("b", self.b)

    @property
    def half_width(self) -> float:
        return float(np.sqrt(3.0 * self.b))

    @property
    def second_moment(self) -> float:
        return self.b

    def log_mgf(self, s: ArrayLike) -> FloatArray:
        return _log_sinhc(self.half_width * np.asarray(s, dtype=float))

    def dlog_mgf(self, s: ArrayLike) -> FloatArray:
        a = self.half_width
        return a * _langevin(a * np.asarray(s, dtype=float))

    def d2_ratio(self, s: ArrayLike) -> FloatArray:
        a = self.half_width
        return a**2 * (1.0 - 2.0 * _langevin_over_x(a * np.asarray(s, dtype=float)))

    def moment(self, r: int) -> float:
        return 0.0 if r % 2 else self.half_width**r / (r + 1)

    def char_fn(self, v: ArrayLike) -> FloatArray:
        return np.sinc(self.half_width * np.asarray(v, dtype=float) / np.pi)

    def sample(self, rng: np.random.Generator, size: int) -> FloatArray:
        return rng.uniform(-self.half_width, self.half_width, size)


@dataclass(frozen=True)
class TriangularDensity:
    r"""Triangular density on :math:`[-\sqrt{6b}, \sqrt{6b}]`: the sum of two uniforms of second
    moment :math:`b/2`.

    Attributes
    ----------
    b : float
        Second moment (relative to the unit peak squared).
    name : str
        Label.
    """

    b: float
    name: str = "triangular"

    def __post_init__(self) -> None:
        require_positive("b", self.b)

    @property
    def second_moment(self) -> float:
        return self.b

    @property
    def _u(self) -> UniformDensity:
        return UniformDensity(self.b / 2.0)

    def log_mgf(self, s: ArrayLike) -> FloatArray:
        return 2.0 * self._u.log_mgf(s)

    def dlog_mgf(self, s: ArrayLike) -> FloatArray:
        return 2.0 * self._u.dlog_mgf(s)

    def d2_ratio(self, s: ArrayLike) -> FloatArray:
        u = self._u
        return 2.0 * u.d2_ratio(s) + 2.0 * u.dlog_mgf(s) ** 2

    def moment(self, r: int) -> float:
        a = float(np.sqrt(6.0 * self.b))
        return 0.0 if r % 2 else 2.0 * a**r / ((r + 1) * (r + 2))

    def char_fn(self, v: ArrayLike) -> FloatArray:
        return self._u.char_fn(v) ** 2

    def sample(self, rng: np.random.Generator, size: int) -> FloatArray:
        return self._u.sample(rng, size) + self._u.sample(rng, size)


@dataclass(frozen=True)
class GaussianDensity:
    """Gaussian amplitude density :math:`N(0, b)`.

    Attributes
    ----------
    b : float
        Variance (relative to the unit peak squared).
    name : str
        Label.
    """

    b: float
    name: str = "Gaussian"

    def __post_init__(self) -> None:
        require_positive("b", self.b)

    @property
    def second_moment(self) -> float:
        return self.b

    def log_mgf(self, s: ArrayLike) -> FloatArray:
        return 0.5 * self.b * np.asarray(s, dtype=float) ** 2

    def dlog_mgf(self, s: ArrayLike) -> FloatArray:
        return self.b * np.asarray(s, dtype=float)

    def d2_ratio(self, s: ArrayLike) -> FloatArray:
        s = np.asarray(s, dtype=float)
        return self.b + (self.b * s) ** 2

    def moment(self, r: int) -> float:
        return 0.0 if r % 2 else float(special.factorial2(r - 1, exact=True)) * self.b ** (r // 2)

    def char_fn(self, v: ArrayLike) -> FloatArray:
        return np.exp(-0.5 * self.b * np.asarray(v, dtype=float) ** 2)

    def sample(self, rng: np.random.Generator, size: int) -> FloatArray:
        return rng.normal(0.0, np.sqrt(self.b), size)


@dataclass(frozen=True)
class LogMGFDensity:
    """A density known only through its log-MGF; derivatives by central differences.

    ``moment`` uses finite differences of the MGF at 0 (orders <= 4) and there is no sampler.

    Attributes
    ----------
    log_mgf_fn : callable
        ``s -> ln E[exp(s X)]``.
    name : str
        Label.
    step : float
        Central-difference step in ``s``.
    """

    log_mgf_fn: Callable[[FloatArray], FloatArray]
    name: str = "log-MGF"
    step: float = 1e-4

    def log_mgf(self, s: ArrayLike) -> FloatArray:
        return np.asarray(self.log_mgf_fn(np.asarray(s, dtype=float)), dtype=float)

    def dlog_mgf(self, s: ArrayLike) -> FloatArray:
        s = np.asarray(s, dtype=float)
        h = self.step
        return (self.log_mgf(s + h) - self.log_mgf(s - h)) / (2 * h)

    def d2_ratio(self, s: ArrayLike) -> FloatArray:
        s = np.asarray(s, dtype=float)
        h = self.step
        k2 = (self.log_mgf(s + h) - 2 * self.log_mgf(s) + self.log_mgf(s - h)) / h**2
        return k2 + self.dlog_mgf(s) ** 2

    @property
    def second_moment(self) -> float:
        return float(self.d2_ratio(0.0))

    def moment(self, r: int) -> float:
        if r == 1:
            return float(self.dlog_mgf(0.0))
        if r == 2:
            return self.second_moment
        raise ValueError("LogMGFDensity.moment supports r in {1, 2}")


@dataclass(frozen=True)
class MultipleAccessNoise:
    r"""The multiple-access noise sample :math:`n_i(t)` for a common amplitude density (ATC-10
    Sec. 3.4).

    Parameters
    ----------
    n_aircraft : int
        :math:`N`, the number of aircraft; :math:`N - 1` of them interfere.
    tau_over_alpha : float
        Signature duration over repetition period; an interferer overlaps the sample with
        probability :math:`q = 2 \tau/\alpha` (Eq. 3.4.4).
    density : amplitude density
        The common :math:`C(x)` of Eq. (3.3.8).
    """

    n_aircraft: int
    tau_over_alpha: float
    density: Any

    def __post_init__(self) -> None:
        require_integer("n_aircraft", self.n_aircraft, minimum=2)
        require_probability("2*tau_over_alpha", 2.0 * self.tau_over_alpha)
        require_positive("tau_over_alpha", self.tau_over_alpha)

    @property
    def q(self) -> float:
        r"""Overlap probability :math:`2 \tau/\alpha`."""
        return 2.0 * self.tau_over_alpha

    @property
    def n_interferers(self) -> int:
        return self.n_aircraft - 1

    def _weight(self, s: ArrayLike) -> tuple[FloatArray, FloatArray]:
        lm = self.density.log_mgf(s)
        k1 = np.logaddexp(np.log1p(-self.q), np.log(self.q) + lm)
        return k1, np.exp(np.log(self.q) + lm - k1)

    def cgf(self, s: ArrayLike) -> FloatArray:
        r""":math:`\mu(s) = \ln E e^{s n} = (N-1) \ln((1-q) + q M_C(s))`; ATC-10 Eq. (3.4.6) at
        :math:`v = s/j`."""
        return self.n_interferers * self._weight(s)[0]

    def cgf_d1(self, s: ArrayLike) -> FloatArray:
        r""":math:`\mu'(s)`, the mean of the tilted noise."""
        w = self._weight(s)[1]
        return self.n_interferers * w * self.density.dlog_mgf(s)

    def cgf_d2(self, s: ArrayLike) -> FloatArray:
        r""":math:`\mu''(s) > 0`, the variance of the tilted noise."""
        w = self._weight(s)[1]
        r1 = self.density.dlog_mgf(s)
        return self.n_interferers * (w * self.density.d2_ratio(s) - (w * r1) ** 2)

    def char_fn(self, v: ArrayLike) -> NDArray[np.complex128]:
        """:math:`M_i(v) = E e^{j v n}`, ATC-10 Eq. (3.4.6)."""
        phi = np.asarray(self.density.char_fn(v), dtype=complex)
        return np.exp(self.n_interferers * np.log((1.0 - self.q) + self.q * phi))

    @property
    def mean(self) -> float:
        """:math:`E(n)`, Eq. (3.4.9)."""
        return self.n_interferers * self.q * self.density.moment(1)

    @property
    def power(self) -> float:
        """:math:`E(n^2)`, Eq. (3.4.10); equals :math:`(N-1) q b` for a symmetric :math:`C`
        (Eq. 3.4.13)."""
        m1 = self.density.moment(1)
        m2 = self.density.moment(2)
        k = self.n_interferers
        return k * self.q * m2 + (self.q * k * m1) ** 2 - self.q**2 * k * m1**2

    @property
    def gaussian_limit_variance(self) -> float:
        r""":math:`N (2 \tau/\alpha) b`: the variance of Theorem 3.1's limit (uses :math:`N`, as
        the paper does)."""
        return self.n_aircraft * self.q * self.density.moment(2)

    def cumulants(self, order: int = 6) -> FloatArray:
        r"""Cumulants :math:`\kappa_1, \dots, \kappa_r` of :math:`n`, :math:`r` = ``order``:
        :math:`N-1` times the cumulants of :math:`Q` (Eqs. E.2-E.6)."""
        raw = [self.q * self.density.moment(r) for r in range(1, order + 1)]
        return self.n_interferers * cumulants_from_raw_moments(raw)


def cumulants_from_raw_moments(raw: ArrayLike) -> FloatArray:
    r"""Cumulants from raw moments :math:`m_1, \dots, m_n` by the standard recursion.

    Parameters
    ----------
    raw : array_like
        Raw moments ``m_1, m_2, ...`` (units of the variable to the power of the order).

    Returns
    -------
    ndarray
        Cumulants :math:`\kappa_1, \dots, \kappa_n`.

    Examples
    --------
    >>> cumulants_from_raw_moments([0.0, 1.0, 0.0, 3.0]).round(12).tolist()  # N(0,1)
    [0.0, 1.0, 0.0, 0.0]
    """
    m = np.asarray(raw, dtype=float)
    k = np.zeros_like(m)
    for n in range(1, m.size + 1):
        acc = m[n - 1]
        for j in range(1, n):
            acc -= comb(n - 1, j - 1) * k[j - 1] * m[n - j - 1]
        k[n - 1] = acc
    return k


def _edgeworth_coefficients(noise: MultipleAccessNoise, use_n: bool) -> tuple[float, dict[int, float]]:
    kap = noise.cumulants(6) / noise.n_interferers
    nn = noise.n_aircraft if use_n else noise.n_interferers
    var = nn * kap[1]
    c = {3: nn * kap[2] / 6.0, 4: nn * kap[3] / 24.0, 6: nn * kap[5] / 720.0 + nn**2 * kap[2] ** 2 / 72.0}
    return var, c


def edgeworth_density(
    noise: MultipleAccessNoise, n: ArrayLike, terms: int = 2, use_n: bool = True
) -> FloatArray:
    r"""The expansion (E.15) truncated after ``terms`` correction terms.

    ``terms=0`` is Theorem 3.1's Gaussian limit; 1 adds the :math:`\lambda_3` term, 2 the
    :math:`\lambda_4` term and 3 the :math:`(jv)^6` term (:math:`\lambda_6` and
    :math:`\lambda_3^2`). ``use_n`` replaces :math:`N - 1` by :math:`N` as App. E does.

    Parameters
    ----------
    noise : MultipleAccessNoise
        The multiple-access noise model (N aircraft, overlap probability, amplitude density C).
    n : array_like
        Noise values (relative to the unit signal peak).
    terms : int, default 2
        Number of correction terms, 0..3.
    use_n : bool, default True
        Use N instead of N - 1 interferers, as Appendix E does.

    Returns
    -------
    ndarray
        Approximate probability density of the noise (per unit of ``n``).

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Appendix E, Eq. (E.15), and Theorem 3.1.

    Examples
    --------
    >>> noise = MultipleAccessNoise(100, 0.01, UniformDensity(0.3))
    >>> round(float(edgeworth_density(noise, 0.0, terms=0)), 4)
    0.515
    """
    var, c = _edgeworth_coefficients(noise, use_n)
    sig = np.sqrt(var)
    z = np.asarray(n, dtype=float) / sig
    phi = np.exp(-0.5 * z**2) / np.sqrt(2 * np.pi) / sig
    out = phi.copy()
    orders = (3, 4, 6)[: max(0, terms)]
    for k in orders:
        out = out + c[k] * sig ** (-k) * special.eval_hermitenorm(k, z) * phi
    return out


def edgeworth_tail(
    noise: MultipleAccessNoise, t: ArrayLike, terms: int = 2, use_n: bool = True
) -> FloatArray:
    """``P(n >= t)`` from the expansion (E.15) integrated term by term.

    Parameters
    ----------
    noise : MultipleAccessNoise
        The multiple-access noise model (N aircraft, overlap probability, amplitude density C).
    t : array_like
        Thresholds (relative to the unit signal peak).
    terms : int, default 2
        Number of correction terms, 0..3.
    use_n : bool, default True
        Use N instead of N - 1 interferers, as Appendix E does.

    Returns
    -------
    ndarray
        Approximate tail probability.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Appendix E, Eq. (E.15).

    Examples
    --------
    >>> noise = MultipleAccessNoise(100, 0.01, UniformDensity(0.3))
    >>> round(float(edgeworth_tail(noise, 0.0, terms=0)), 4)
    0.5
    """
    var, c = _edgeworth_coefficients(noise, use_n)
    sig = np.sqrt(var)
    z = np.asarray(t, dtype=float) / sig
    phi = np.exp(-0.5 * z**2) / np.sqrt(2 * np.pi)
    out = special.ndtr(-z)
    orders = (3, 4, 6)[: max(0, terms)]
    for k in orders:
        out = out + c[k] * sig ** (-k) * special.eval_hermitenorm(k - 1, z) * phi
    return out


def sample_noise(noise: MultipleAccessNoise, n_samples: int, rng: np.random.Generator) -> FloatArray:
    """Seeded Monte Carlo of n: ``K ~ Binomial(N-1, q)`` overlapping interferers, each drawn from C.

    Parameters
    ----------
    noise : MultipleAccessNoise
        The multiple-access noise model (N aircraft, overlap probability, amplitude density C).
    n_samples : int
        Number of samples (``>= 1``, bounded).
    rng : numpy.random.Generator
        Seeded generator (``numpy.random.default_rng(seed)``).

    Returns
    -------
    (n_samples,) ndarray
        Noise samples (relative to the unit peak).

    Raises
    ------
    ValueError
        If ``n_samples`` is not a positive integer.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 3.3.

    Examples
    --------
    >>> import numpy as np
    >>> noise = MultipleAccessNoise(100, 0.01, UniformDensity(0.3))
    >>> sample_noise(noise, 5, np.random.default_rng(0)).shape
    (5,)
    """
    require_integer("n_samples", n_samples, minimum=1)
    k = rng.binomial(noise.n_interferers, noise.q, size=n_samples)
    draws = noise.density.sample(rng, int(k.sum()))
    owner = np.repeat(np.arange(n_samples), k)
    return np.bincount(owner, weights=draws, minlength=n_samples).astype(float)


def _k_range(n_interferers: int, q: float, tail: float = 1e-16) -> tuple[NDArray[np.int64], FloatArray]:
    kmax = int(stats.binom.isf(tail, n_interferers, q)) + 2
    ks = np.arange(0, kmax + 1)
    return ks, stats.binom.pmf(ks, n_interferers, q)


@dataclass(frozen=True)
class TailEstimate:
    """Stratified Monte Carlo estimate of P(n >= t) (``upper``) and P(n <= -t) (``lower``)."""

    t: FloatArray
    upper: FloatArray
    upper_se: FloatArray
    lower: FloatArray
    lower_se: FloatArray


@dataclass(frozen=True)
class StratifiedSums:
    """Sorted Monte Carlo sums of K draws from C for each K, with the exact binomial weights of K.

    Build once with :func:`stratified_sums`; :meth:`tail` then estimates P(n >= t) for any
    thresholds (and, since the sums scale, ``scale`` evaluates a density stretched by a factor).

    Attributes
    ----------
    weights : ndarray
        ``P(K = k)``, k = 0..kmax.
    sums : tuple of ndarray
        Sorted sums of k draws, k = 1..kmax.
    n_per_stratum : int
        Sums per value of K.
    """

    weights: FloatArray  # P(K = k), k = 0..kmax
    sums: tuple[FloatArray, ...]  # sorted sums for k = 1..kmax
    n_per_stratum: int

    def tail(self, t: ArrayLike, scale: float = 1.0) -> tuple[FloatArray, FloatArray]:
        """(P(scale * n >= t), standard error)."""
        t = np.atleast_1d(np.asarray(t, dtype=float)) / scale
        est = np.where(t <= 0, self.weights[0], 0.0)
        var = np.zeros_like(t)
        m = self.n_per_stratum
        for wk, s in zip(self.weights[1:], self.sums, strict=True):
            pu = 1.0 - np.searchsorted(s, t, side="left") / m
            est = est + wk * pu
            var = var + wk**2 * pu * (1 - pu) / m
        return est, np.sqrt(var)


def stratified_sums(
    noise: MultipleAccessNoise, n_per_stratum: int, rng: np.random.Generator
) -> StratifiedSums:
    """Seeded Monte Carlo sums stratified on the number K of overlapping interferers.

    The binomial weights of K are exact; for each K >= 1, ``n_per_stratum`` sums of K draws
    from C are stored sorted. Rare events at large K are therefore resolved far below
    1/(total samples).

    Parameters
    ----------
    noise : MultipleAccessNoise
        The multiple-access noise model (N aircraft, overlap probability, amplitude density C).
    n_per_stratum : int
        Sums per value of K (``>= 1``, bounded).
    rng : numpy.random.Generator
        Seeded generator (``numpy.random.default_rng(seed)``).

    Returns
    -------
    StratifiedSums
        Sorted sums per K with their binomial weights; :meth:`StratifiedSums.tail` estimates
        tail probabilities.

    Raises
    ------
    ValueError
        If ``n_per_stratum`` is not a positive integer.

    Examples
    --------
    >>> import numpy as np
    >>> noise = MultipleAccessNoise(100, 0.01, UniformDensity(0.3))
    >>> ss = stratified_sums(noise, 200, np.random.default_rng(0))
    >>> p, se = ss.tail(0.0)
    >>> round(float(np.ravel(p)[0]), 2)
    0.59
    """
    require_integer("n_per_stratum", n_per_stratum, minimum=1)
    ks, w = _k_range(noise.n_interferers, noise.q)
    sums = []
    for k in ks[1:]:
        s = noise.density.sample(rng, n_per_stratum * int(k)).reshape(n_per_stratum, int(k)).sum(axis=1)
        s.sort()
        sums.append(s)
    return StratifiedSums(w, tuple(sums), n_per_stratum)


def stratified_tail(
    noise: MultipleAccessNoise, t: ArrayLike, n_per_stratum: int, rng: np.random.Generator
) -> TailEstimate:
    """Exact ROC by Monte Carlo stratified on the number K of overlapping interferers.

    Parameters
    ----------
    noise : MultipleAccessNoise
        The multiple-access noise model (N aircraft, overlap probability, amplitude density C).
    t : array_like
        Thresholds (``>= 0``, relative to the unit peak).
    n_per_stratum : int
        Sums per value of K.
    rng : numpy.random.Generator
        Seeded generator (``numpy.random.default_rng(seed)``).

    Returns
    -------
    TailEstimate
        ``P(n >= t)`` (``upper``) and ``P(n <= -t)`` (``lower``) with standard errors.

    Raises
    ------
    ValueError
        If ``n_per_stratum`` is not a positive integer.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 3.5 (the exact ROC the bounds bracket).

    Examples
    --------
    >>> import numpy as np
    >>> noise = MultipleAccessNoise(100, 0.01, UniformDensity(0.3))
    >>> est = stratified_tail(noise, [0.5], 2000, np.random.default_rng(0))
    >>> bool(est.upper[0] > 0.0), bool(est.upper_se[0] < est.upper[0])
    (True, True)
    """
    t = np.atleast_1d(np.asarray(t, dtype=float))
    ss = stratified_sums(noise, n_per_stratum, rng)
    up, up_se = ss.tail(t)
    ge, ge_se = ss.tail(np.nextafter(-t, np.inf))  # P(n > -t)
    return TailEstimate(t, up, up_se, 1.0 - ge, ge_se)


def two_point_exact_tail(amplitude: float, n_interferers: int, q: float, t: ArrayLike) -> FloatArray:
    r"""Exact :math:`P(n \ge t)` for the two-point density :math:`\pm a`.

    :math:`\sum_K \mathrm{Bin}(K)\, P(a(2J - K) \ge t)`, ``J ~ Bin(K, 1/2)``.

    Parameters
    ----------
    amplitude : float
        Atom amplitude ``a`` (relative to the unit peak).
    n_interferers : int
        Number of potential interferers ``N - 1``.
    q : float
        Overlap probability, in [0, 1].
    t : array_like
        Thresholds.

    Returns
    -------
    ndarray
        Tail probability.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 3.7 (the quasi-optimal density).

    Examples
    --------
    >>> round(float(two_point_exact_tail(0.2, 1, 1.0, [0.1])[0]), 6)
    0.5
    """
    t = np.atleast_1d(np.asarray(t, dtype=float))
    ks, w = _k_range(n_interferers, q)
    out = np.zeros_like(t)
    for k, wk in zip(ks, w, strict=True):
        # a(2J-K) >= t  <=>  J >= (t/a + K)/2
        jmin = np.ceil((t / amplitude + k) / 2.0 - 1e-12)
        out += wk * stats.binom.sf(jmin - 1, k, 0.5)
    return out


def gaussian_mixture_exact_tail(b: float, n_interferers: int, q: float, t: ArrayLike) -> FloatArray:
    r"""Exact :math:`P(n \ge t)` for Gaussian :math:`C = N(0, b)`:
    :math:`\sum_K \mathrm{Bin}(K)\, Q(t / \sqrt{K b})`.


    Parameters
    ----------
    b : float
        Variance of one interferer's amplitude (relative to the unit peak squared).
    n_interferers : int
        Number of potential interferers ``N - 1``.
    q : float
        Probability that an interferer overlaps, in [0, 1].
    t : array_like
        Thresholds.

    Returns
    -------
    ndarray
        Tail probability.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 3.3 (the binomial mixture of overlaps).

    Examples
    --------
    >>> round(float(gaussian_mixture_exact_tail(0.01, 99, 0.02, [0.0])[0]), 4)
    0.5677
    """
    t = np.atleast_1d(np.asarray(t, dtype=float))
    ks, w = _k_range(n_interferers, q)
    out = w[0] * (t <= 0)
    kk = ks[1:, None].astype(float)
    out = out + (w[1:, None] * special.ndtr(-t[None, :] / np.sqrt(kk * b))).sum(axis=0)
    return out


#: Largest number of uniform summands :func:`irwin_hall_cdf` accepts (the spline's degree is one
#: less; the binomial ranges of ATC-10 Sec. 3.6 need about 60).
MAX_IRWIN_HALL_TERMS = 400


@cache
def _irwin_hall_cdf_spline(n: int) -> BSpline:
    """The Irwin-Hall CDF of ``n`` summands as a B-spline: the antiderivative of the cardinal
    B-spline of degree n - 1 on the knots 0, 1, ..., n (its density)."""
    return BSpline.basis_element(np.arange(n + 1, dtype=float), extrapolate=False).antiderivative()


def irwin_hall_cdf(n: int, x: ArrayLike) -> FloatArray:
    r"""CDF of the Irwin-Hall law: :math:`P(U_1 + \dots + U_n \le x)`, :math:`U_i` i.i.d. U(0, 1).

    The density of the sum is the cardinal B-spline of degree :math:`n - 1` on the knots
    :math:`0, 1, \dots, n`; its CDF is the antiderivative spline, whose B-spline coefficients
    are cumulative sums of positive numbers. De Boor's recursion (scipy's ``BSpline``) evaluates
    it by convex combinations of those non-negative coefficients, so the result has a relative
    error of a few units of round-off everywhere, the far tails included (checked against the
    alternating sum in 80-digit arithmetic: below :math:`10^{-15}` relative for n up to 60 and
    values down to :math:`10^{-260}`). The textbook alternating sum
    :math:`\sum_{j \le x} (-1)^j \binom{n}{j} (x - j)^n / n!` is not used: in double precision
    it cancels catastrophically near the middle of the law for large n.

    Parameters
    ----------
    n : int
        Number of uniform summands, 1 to ``MAX_IRWIN_HALL_TERMS``.
    x : array_like
        Points (any real; 0 below the support, 1 above it).

    Returns
    -------
    ndarray
        :math:`P(S_n \le x)`, the shape of ``x``.

    Raises
    ------
    ValueError
        If ``n`` is not an integer in [1, ``MAX_IRWIN_HALL_TERMS``], or ``x`` is not finite.

    References
    ----------
    Hall, "The distribution of means for samples of size N drawn from a population in which the
    variate takes values between 0 and 1", Biometrika 19 (1927); de Boor, *A Practical Guide to
    Splines* (1978), Ch. IX (cardinal B-splines, the stable evaluation).

    Examples
    --------
    >>> round(float(irwin_hall_cdf(2, 0.5)), 6)  # a triangle: x^2 / 2
    0.125
    >>> round(float(irwin_hall_cdf(3, 1.5)), 12)  # symmetric about n / 2
    0.5
    """
    n = require_integer("n", n, minimum=1)
    if n > MAX_IRWIN_HALL_TERMS:
        raise ValueError(f"n must be an integer <= {MAX_IRWIN_HALL_TERMS}, got {n}")
    xs = as_finite_array("x", x)
    inside = np.asarray(_irwin_hall_cdf_spline(n)(np.clip(xs, 0.0, float(n))), dtype=float)
    return np.where(xs >= n, 1.0, np.where(xs <= 0.0, 0.0, inside))


def _uniform_sum_tail(
    half_width: float, per_interferer: int, n_interferers: int, q: float, t: ArrayLike
) -> FloatArray:
    """Exact P(n >= t) when each overlapping interferer adds ``per_interferer`` independent
    uniforms on [-half_width, half_width]: given K overlaps the noise is half_width (2 V - m)
    with V Irwin-Hall of m = per_interferer K summands, so P(n >= t) = P(m - V <= (m - t /
    half_width) / 2), and m - V is Irwin-Hall again (the argument is formed without a
    difference of nearly equal numbers, so small tails keep their relative accuracy)."""
    tt = np.atleast_1d(np.asarray(t, dtype=float))
    ks, w = _k_range(n_interferers, q)
    out = w[0] * (tt <= 0)
    u = tt / half_width
    for k, wk in zip(ks[1:], w[1:], strict=True):
        m = per_interferer * int(k)
        out = out + wk * irwin_hall_cdf(m, 0.5 * (m - u))
    return out


def uniform_exact_tail(b: float, n_interferers: int, q: float, t: ArrayLike) -> FloatArray:
    r"""Exact :math:`P(n \ge t)` for the uniform :math:`C` of second moment :math:`b`:
    :math:`\sum_K \mathrm{Bin}(K)\, P(S_K \ge t)`, :math:`S_K` a sum of :math:`K` uniforms
    on :math:`[-\sqrt{3b}, \sqrt{3b}]` (an Irwin-Hall law, :func:`irwin_hall_cdf`).

    The binomial weights are those of :func:`gaussian_mixture_exact_tail` (overlap counts whose
    probability is below :math:`10^{-16}` are dropped); each conditional tail has a relative error of a
    few round-off units, so the result is exact to that truncation.

    Parameters
    ----------
    b : float
        Second moment of one interferer's amplitude (relative to the unit peak squared), > 0.
    n_interferers : int
        Number of potential interferers ``N - 1``.
    q : float
        Probability that an interferer overlaps, in [0, 1].
    t : array_like
        Thresholds.

    Returns
    -------
    ndarray
        Tail probability.

    Raises
    ------
    ValueError
        If ``b`` is not positive, ``n_interferers`` not a count, ``q`` not a probability, or the
        overlap count needs more than ``MAX_IRWIN_HALL_TERMS`` summands.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Secs. 3.3 and 3.6 (the binomial
    mixture of overlaps; the uniform amplitude density is the book's choice, Fig. 3.2 being lost).

    Examples
    --------
    >>> float(uniform_exact_tail(1 / 3, 1, 1.0, [0.5])[0])  # one uniform on [-1, 1]
    0.25
    """
    require_positive("b", b)
    return _uniform_sum_tail(float(np.sqrt(3.0 * b)), 1, n_interferers, q, t)


def triangular_exact_tail(b: float, n_interferers: int, q: float, t: ArrayLike) -> FloatArray:
    r"""Exact :math:`P(n \ge t)` for the triangular :math:`C` of second moment :math:`b`.

    A triangular amplitude on :math:`[-\sqrt{6b}, \sqrt{6b}]` is the sum of two uniforms on
    :math:`[-\sqrt{3b/2}, \sqrt{3b/2}]`, so the sum of :math:`K` of them is an Irwin-Hall law
    of :math:`2K` summands, rescaled; the binomial mixture and its accuracy are those of
    :func:`uniform_exact_tail`.

    Parameters
    ----------
    b : float
        Second moment of one interferer's amplitude (relative to the unit peak squared), > 0.
    n_interferers : int
        Number of potential interferers ``N - 1``.
    q : float
        Probability that an interferer overlaps, in [0, 1].
    t : array_like
        Thresholds.

    Returns
    -------
    ndarray
        Tail probability.

    Raises
    ------
    ValueError
        If ``b`` is not positive, ``n_interferers`` not a count, ``q`` not a probability, or the
        overlap count needs more than ``MAX_IRWIN_HALL_TERMS`` summands.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Secs. 3.3 and 3.6 (the triangular
    amplitude density is the book's choice, Fig. 3.2 being lost).

    Examples
    --------
    >>> float(triangular_exact_tail(1 / 6, 1, 1.0, [0.0])[0])  # symmetric about 0
    0.5
    """
    require_positive("b", b)
    return _uniform_sum_tail(float(np.sqrt(1.5 * b)), 2, n_interferers, q, t)


@implements("ATC10 3.3.7")
def psk_amplitude_samples(
    code_i: ArrayLike, n_events: int, rng: np.random.Generator, chunk: int = 20000
) -> FloatArray:
    r"""Samples of :math:`n_{ij}(t)` given overlap (Eq. 3.3.7) for random PSK interferers.

    Each interferer has a fresh random :math:`\pm 1` code of the same length :math:`L` as
    ``code_i``, rectangular chips, unit energy, a delay :math:`d` uniform over
    :math:`(-\tau, \tau)` relative to the matched-filter peak and a uniform carrier phase. The
    cross-correlation at a continuous delay :math:`d = (k + f) \tau_c` is
    :math:`(1-f) c_k + f c_{k+1}`, with :math:`c_k` the aperiodic discrete cross-correlation
    divided by :math:`L`.

    Parameters
    ----------
    code_i : array_like
        Chip sequence of the wanted signature.
    n_events : int
        Number of samples (``>= 1``, bounded).
    rng : numpy.random.Generator
        Seeded generator (``numpy.random.default_rng(seed)``).
    chunk : int, default 20000
        Samples computed per batch (memory bound); the samples do not depend on it.

    Returns
    -------
    (n_events,) ndarray
        Cross-term amplitudes relative to the unit peak.

    Raises
    ------
    ValueError
        If ``n_events`` is not a positive integer.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (3.3.7).

    Examples
    --------
    >>> import numpy as np
    >>> from navcore.detection.zakai import barker_code
    >>> x = psk_amplitude_samples(barker_code(13), 1000, np.random.default_rng(0))
    >>> x.shape, bool(np.abs(x).max() <= 1.0)
    ((1000,), True)
    """
    ci = np.asarray(code_i, dtype=float).ravel()
    L = ci.size
    require_integer("n_events", n_events, minimum=1)
    out = np.empty(n_events)
    m = np.arange(L)
    # delays (in chips) and carrier phases first, then the codes chunk by chunk: the samples do
    # not depend on ``chunk`` (each draw takes the generator's stream in order), only memory does
    delays = rng.uniform(-L, L, n_events)
    phases = rng.uniform(0, 2 * np.pi, n_events)
    for start in range(0, n_events, chunk):
        e = min(chunk, n_events - start)
        d = delays[start : start + e]
        k = np.floor(d).astype(int)
        f = d - k
        cj = rng.choice(np.array([-1.0, 1.0]), size=(e, L))
        pad = np.zeros((e, 3 * L + 2))
        pad[:, L : 2 * L] = cj

        def corr(lag: NDArray[np.int64], cj_pad: FloatArray = pad) -> FloatArray:
            idx = m[None, :] - lag[:, None] + L
            return (np.take_along_axis(cj_pad, idx, axis=1) @ ci) / L

        x = (1.0 - f) * corr(k) + f * corr(k + 1)
        out[start : start + e] = np.cos(phases[start : start + e]) * x
    return out


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "n_aircraft": Range(1.0, None),
        "n_events": COUNT,
        "n_interferers": COUNT0,
        "n_per_stratum": COUNT,
        "n_samples": COUNT,
        "chunk": COUNT,
        "terms": COUNT0,
        "q": PROBABILITY,
        "tau_over_alpha": POSITIVE,
        "step": POSITIVE,
    },
)
