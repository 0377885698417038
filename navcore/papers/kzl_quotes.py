"""The paper's words behind the KZL claims (issue 27, item 5): each claim's ``printed`` quote.

Each quote is the text of the transcription (LaTeX as transcribed, table rows with their tabs);
pieces of one passage are joined by " [...] ". The independent audit of issue 27 verified every
piece against the transcription, and ``tests/test_paper_quotes.py`` checks them again wherever the
transcription is present. The tolerance policy of each claim follows its quote by the ledger's
rule, and a number claim's quote prints its published number. A claim that gives ``printed=``
itself keeps it; :func:`navcore.claims.quotes.with_quotes` fills the others.
"""

from __future__ import annotations

__all__ = ["QUOTES"]

#: Claim id -> the paper's words or formula as quoted.
QUOTES: dict[str, str] = {
    "KZL-dim13": (
        "The matrix has the dimension $(3 + \\nu \\cdot 2) \\times 17$, where ν is the number "
        "of satellites in view."
    ),
    "KZL-dim17": (
        "In case of $\\nu > 1$ satellites in view, we obtain obviously a $(2 + (\\nu - 1) "
        "\\cdot 4) \\times 17$ matrix"
    ),
    "KZL-eq1-states": "That is, the state vector comprises 17 states.",
    "KZL-eq10-11-fd": (
        "the sub-matrix $F_{23}$ is a skew-symmetric matrix that contains the specific force "
        "components transformed to the n-frame"
    ),
    "KZL-eq11-bracket": (
        "$$F_{23} = F_{a \\times \\psi} = [\\hat{\\mathbf{a}}_{ib}^{n} \\times] = "
        "\\begin{bmatrix} 0 & \\hat{a}_{ib,d}^{n} & -\\hat{a}_{ib,e}^{n} \\\\ "
        "-\\hat{a}_{ib,d}^{n} & 0 & \\hat{a}_{ib,n}^{n} \\\\ \\hat{a}_{ib,e}^{n} & "
        "-\\hat{a}_{ib,n}^{n} & 0 \\end{bmatrix}$$"
    ),
    "KZL-eq13-R": (
        "where R is a frame rotation matrix for the transformation from body-axes angular rates "
        "to the Euler angle angular rates."
    ),
    "KZL-eq15-orderings": (
        "$$= \\frac{2\\pi}{\\lambda} \\left[\\left(\\rho_{A1}^{(n)} - \\rho_{A0}^{(n)} \\right) - "
        "\\left(\\rho_{A1}^{(m)} - \\rho_{A0}^{(m)} \\right) \\right]$$"
    ),
    "KZL-eq17-printed-rank": (
        "$\\frac{2\\pi}{\\lambda}\\left(\\mathbf{l}_{t}^{(m),n} - "
        "\\mathbf{l}_{t}^{(n),n}\\right)^{T} \\left[\\hat{R}_{b}^{n} \\mathbf{l}_{02}^{b} "
        "\\times\\right] & \\mathbf{0}^{T} & \\mathbf{0}^{T} & \\mathbf{0} & \\mathbf{0} \\\\ "
        "\\mathbf{0}^{T} & \\mathbf{0}^{T} & "
        "\\frac{2\\pi}{\\lambda}\\left(\\mathbf{l}_{t}^{(m),n} - "
        "\\mathbf{l}_{t}^{(n),n}\\right)^{T} \\left[\\hat{R}_{b}^{n} \\mathbf{l}_{02}^{b} "
        "\\times\\right]$"
    ),
    "KZL-eq17-rank": (
        "$\\mathbf{l}_{0i}^{b}$ is the lever arm (baseline) between the phase centers of master "
        "antenna (A0) and antenna number i, known in the b-frame."
    ),
    "KZL-eq2-3-levelling": (
        "$$\\varphi = \\arctan_2 \\left(a_{ib,y}^b / a_{ib,z}^b \\right) \\tag{3}$$"
        " [...] Angles (φ, θ, ψ) [°] $\\mathbf{\\psi} = \\begin{bmatrix} 0 & 0 & 90 \\end{bmatrix}^T$"
    ),
    "KZL-eq4-heading": (
        "$$\\psi = \\arctan_2(v_E / v_N) \\tag{4}$$ [...] A straight and level flight with a "
        "nominally constant velocity of 110 m/s in east has been modelled."
        " [...] Angles (φ, θ, ψ) [°] $\\mathbf{\\psi} = \\begin{bmatrix} 0 & 0 & 90 \\end{bmatrix}^T$"
    ),
    "KZL-eq5-series": (
        "$$= \\mathcal{L}^{-1} \\left\\{ [sI - F]^{-1} \\right\\}_{t=T} = I + F \\cdot T + "
        "\\frac{(F \\cdot T)^2}{2} + \\text{h.o.t.}$$"
    ),
    "KZL-eq6-first-order": "one can approximate $$A(k) \\approx I + F \\cdot T$$",
    "KZL-eq9-quaternion": (
        "$$\\dot{\\mathbf{x}}^n = \\mathbf{v}^n \\tag{7}$$ [...] Note that the products in Eq. "
        "(9) are quaternion products as defined by Hamilton."
    ),
    "KZL-fig4-dd-phases-robust": (
        "the results are comparable in case of four or more satellites in view, but if only two "
        "or three satellites are in view still a robust and accurate attitude information is "
        "obtained."
    ),
    "KZL-fig4-redundant-attitude": (
        "A much more accurate attitude estimation result is obtained using additional redundant "
        "attitude information (shown by blue dotted lines in Figure 4). [...] In case of less "
        "than 4 satellites in view, the system can not provide attitude information. Hence, the "
        "errors become much larger during such periods."
    ),
    "KZL-fig4-tight-improves-heading": (
        "It is therefore no surprise that the attitude estimation results using a tightly "
        "coupled GPS/INS integration (represented by the black, dashed curves in Figure 4) are "
        "better than using a similar INS alone."
    ),
    "KZL-fig4-tight-improves-roll-pitch": (
        "It is therefore no surprise that the attitude estimation results using a tightly "
        "coupled GPS/INS integration (represented by the black, dashed curves in Figure 4) are "
        "better than using a similar INS alone."
    ),
    "KZL-fig5-dd-best": (
        "Again, the incorporation of the double-difference carrier phase measurements into the "
        "integration approach yields the best results."
    ),
    "KZL-fig5-ins-position": (
        "The large stand-alone IMU related position and velocity errors (about 1 km and 15 m/s "
        "after 3 minutes, respectively) are not included in the figure."
    ),
    "KZL-fig5-ins-position-covariance": (
        "The large stand-alone IMU related position and velocity errors (about 1 km and 15 m/s "
        "after 3 minutes, respectively) are not included in the figure."
    ),
    "KZL-fig5-ins-velocity": (
        "The large stand-alone IMU related position and velocity errors (about 1 km and 15 m/s "
        "after 3 minutes, respectively) are not included in the figure."
    ),
    "KZL-fig5-ins-velocity-covariance": (
        "The large stand-alone IMU related position and velocity errors (about 1 km and 15 m/s "
        "after 3 minutes, respectively) are not included in the figure."
    ),
    "KZL-fig5-loose-three-unbounded": (
        "During the period where only three satellites are in view, the position and velocity "
        "errors are bounded (which is not the case in a loosely coupled GPS/INS integration)."
    ),
    "KZL-fig5-tight-three-bounded": (
        "In general, if only two satellites are in view, the position and velocity errors grow "
        "remarkably. During the period where only three satellites are in view, the position "
        "and velocity errors are bounded"
    ),
    "KZL-qcorr": (
        "the correction of the *a priori* attitude quaternion is done by computing the "
        "quaternion product $\\hat{q}_{b,k}^{n,+} = \\hat{q}_{b,k}^{n,-} q_k^n$, where the "
        "*n*-frame rotation quaternion is computed"
    ),
    "KZL-sec1-baseline-length-accuracy": (
        "the baseline has to be estimated very accurately (e.g., with mm/cm (length) and arcsec "
        "(angle) accuracy, respectively) to obtain height errors smaller than 1 m."
    ),
    "KZL-sec1-baseline-tilt-accuracy": (
        "the baseline has to be estimated very accurately (e.g., with mm/cm (length) and arcsec "
        "(angle) accuracy, respectively) to obtain height errors smaller than 1 m."
    ),
    "KZL-sec1-footprint-overlap": "The overlap of the antenna footprints will be a few seconds in maximum",
    "KZL-sec1-pointing-half-degree": (
        "footprint chasing in such hybrid bistatic SAR experiments an antenna pointing error of "
        "about 0.5° in all the three angles is acceptable."
    ),
    "KZL-sec1-positioning-less-strict": "The positioning requirements are even less strict.",
    "KZL-sec1-satellite-aircraft-speed-ratio": (
        "In the hybrid experiments, the magnitude of the satellite velocity is about 76 times "
        "higher than that of the airplane."
    ),
    "KZL-sec2.1-four-measurements": (
        "Typically, four or more simultaneous measurements are required to solve for the 3D "
        "receiver position and clock bias."
    ),
    "KZL-sec2.1-gnss-output-rate": "The output rate is relatively low (e.g., 1 Hz)",
    "KZL-sec2.1-ins-data-rate": (
        "With an INS autonomous navigation (almost independent of the environment) at a high "
        "data rate (e.g., 100 Hz) can be realized."
    ),
    "KZL-sec2.1-ins-drift-per-hour": (
        "That is, even if expensive systems (e.g., with a price tag of 50.000\\$–100.000\\$) "
        "are used, position errors of about 1 km/h result if no calibration and external aiding "
        "is applied."
    ),
    "KZL-sec2.2-cascaded-nearly-uncorrelated": (
        "time correlated estimates of position and velocity are the input for the fusion filter "
        "(there are cascaded filters) which has to be accounted for (e.g., by considering this "
        "information only every >10 s or by using a federated filter with high computational "
        "load)."
    ),
    "KZL-sec3.1-gyro-bias-swamps-earth-rate": (
        "The MEMS-based IMU with a typical bias instability between several 100°/h and several "
        "10000°/h can not sense Earth's rotation. Hence, gyro-compassing for alignment in "
        "azimuth can not be performed."
    ),
    "KZL-sec3.1-observability-needs-attitude": (
        "It can be shown by an observability analysis that only with additional redundant "
        "attitude information the states are completely observable (independent of the "
        "manoeuvre of the platform, dependent on the number of satellites in view)."
    ),
    "KZL-sec3.2-earth-transport-rates-negligible": (
        "Moreover, in some cases, depending on the application (gyroscope bias instability, "
        "velocity of the platform), these terms can be neglected."
    ),
    "KZL-sec3.4-sequential-update": (
        "Sequential processing has to be performed to avoid inversion of a huge matrix."
    ),
    "KZL-sec3.5-small-rotation-euler-angles": (
        "In case of small rotations there is approximately no difference between the components "
        "of the rotation vector and the Euler angles. That is, the estimated attitude error can "
        "be interpreted as rotation vector"
    ),
    "KZL-sec3.6-heading-largest-attitude-error": (
        "As expected, in case of the stand-alone IMU, the largest error can be observed in heading."
    ),
    "KZL-sec3.6-heading-with-init": (
        "after 3 minutes (180 s) the heading error is in case of the stand-alone IMU still smaller than 3°."
    ),
    "KZL-sec3.6-heading-with-init-covariance": (
        "after 3 minutes (180 s) the heading error is in case of the stand-alone IMU still smaller than 3°."
    ),
    "KZL-sec3.6-heading-without-init": (
        "Without initialization and calibration the error would be larger than 20°."
    ),
    "KZL-sec3.6-heading-without-init-covariance": (
        "Without initialization and calibration the error would be larger than 20°."
    ),
    "KZL-sec3.7-baseline-tradeoff": (
        "It is easier if shorter baselines are used (because of a reduced search space), "
        "however, the longer the baselines the better the expected attitude accuracy."
    ),
}
