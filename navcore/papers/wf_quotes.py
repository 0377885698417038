"""The paper's words behind the WF claims (issue 27, item 5): each claim's ``printed`` quote.

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
    "WF-eq11-covariance": (
        "$$\\mathbf{P}_{DN}(k/*) = "
        "\\boldsymbol{\\tau}(k/*)\\mathbf{P}_N(k/*)\\boldsymbol{\\tau}^T(k/*) + "
        "\\mathbf{Q}_T(k). \\quad (11)$$"
    ),
    "WF-eq11-large-QT": (
        "It can be seen that if the uncertainty introduced by transformation T is large "
        "($\\mathbf{Q}_T$ large), the local state estimate error $\\mathbf{P}_{DN}$ will be large, "
        "regardless of the accuracy of the on-board navigation system ($\\mathbf{P}_N$ small or "
        "large)."
    ),
    "WF-eq13-innovation": (
        "$\\hat{\\mathbf{x}}_{DL}(k/k) &= \\hat{\\mathbf{x}}_{DL}(k/k-1) + "
        "\\mathbf{K}_{DL}(k)[\\mathbf{y}_a(k) - \\hat{\\mathbf{x}}_{DL}(k/k-1)]$"
    ),
    "WF-eq14-three-factors": (
        "three factors contribute to the accuracy of this local velocity estimate: the accuracy "
        "of the local acceleration measurement ($\\mathbf{Q}_a$); the accuracy of the local "
        "velocity measurement ($\\mathbf{R}_L$); and the update rate ($1/T_s$)."
    ),
    "WF-eq16-17-information": (
        "$$\\mathbf{P}_{DG}(k/k) = [\\mathbf{P}_{DL}^{-1}(k/k-1) + "
        "\\mathbf{H}_G^T(k)\\mathbf{R}_G^{-1}(k)\\mathbf{H}_G(k)]^{-1}. \\quad (17)$$"
    ),
    "WF-eq19-outage-infinite-covariance": (
        "Note that $\\mathbf{P}_{DX}(k/k)$, ($X=N, L$, or G) is set to infinity whenever the X "
        "-th sensor outage occurs."
    ),
    "WF-eq19-weighted-least-squares": (
        "Nevertheless, the estimate in (18) can be shown [7] to be the solution derived under a "
        "weighted least squares cost and can also be given a minimum variance interpretation."
    ),
    "WF-eq20-PNG": (
        "$\\mathbf{P} &= \\begin{bmatrix} \\mathbf{P}_{DN} & \\mathbf{P}_{NL} & \\mathbf{P}_{NG} "
        "\\\\ \\mathbf{P}_{LN} & \\mathbf{P}_{DL} & \\mathbf{P}_{NG} \\\\ \\mathbf{P}_{GN} & "
        "\\mathbf{P}_{GL} & \\mathbf{P}_{DG} \\end{bmatrix}$"
    ),
    "WF-eq24-PN": "$\\mathbf{P}_N \\mathbf{P}_N^T = \\sigma_N^2 \\mathbf{I}$",
    "WF-eq25-fL1c": "$f_o^{L1}/c = 5.25 \\text{m}^{-1}$",
    "WF-eq3-normal": (
        "The condition for a least-squares solution is $$\\mathbf{H}^T \\mathbf{W}[\\mathbf{m} "
        "- \\mathbf{f}(\\hat{\\mathbf{p}}^e, \\hat{\\Theta})] = 0, \\quad (3)$$"
    ),
    "WF-eq6-linear": (
        "Using the definition of $\\mathbf{H}$ in (4) as a derivative and assuming that the "
        "location estimate is close to the true value gives"
    ),
    "WF-eq6-model-error-acts-like-noise": (
        "Therefore, (6) shows that the location error is affected as much by the signal model "
        "error $\\tilde{\\mathbf{f}}_\\theta$ as it is by the measurement error $\\mathbf{e}$ ."
    ),
    "WF-eq6-montecarlo": (
        "$$\\hat{\\mathbf{p}}^e - \\mathbf{p}^e = (\\mathbf{H}^T \\mathbf{W} \\mathbf{H})^{-1} "
        "\\mathbf{H}^T \\mathbf{W}[\\mathbf{e} + \\tilde{\\mathbf{f}}_\\theta], \\quad (6)$$"
    ),
    "WF-eq8-norm": (
        "$$\\left\\| \\frac{\\partial f}{\\partial \\mathbf{v}} \\right\\| = \\left\\| "
        "\\frac{f_0}{c} \\mathbf{u}_R \\right\\| = \\frac{f_0}{c}, \\quad (8)$$"
    ),
    "WF-eq9-bound": (
        "$$\\left\\| \\frac{\\partial f}{\\partial \\mathbf{p}} \\right\\| \\leq \\frac{f_0}{c} "
        "\\frac{2\\|\\mathbf{v}\\|}{R}, \\quad (9)$$"
    ),
    "WF-eq9-velocity-error-dominates": (
        "Thus, reducing the uncertainty in $\\mathbf{v}$ is at least 100 times more effective "
        "than reducing the uncertainty in $\\mathbf{p}$ in order to achieve the same relative "
        "accuracy improvement."
    ),
    "WF-eq9-velocity-position-ratio": (
        "for the typical values of R and $\\|\\mathbf{v}\\|$ under consideration, "
        "$R/2\\|\\mathbf{v}\\|$ is on the order of 100 ."
    ),
    "WF-fig1-improvement-at-100ug": (
        "For example, it can be seen from Figure 1 that a $100\\mu\\text{g}$ local "
        "accelerometer would provide at least a 60dB reduction of local velocity estimation "
        "error assuming a 2m/s $1\\text{-}\\sigma$ local velocity uncertainty in the absence of "
        "the accelerometer."
    ),
    "WF-fig1-order": (
        "Figure 1 shows the velocity accuracy improvement bounds for the case of using on-board "
        "navigation data together with local accelerometer measurements but no aperture-local "
        "GPS measurements."
    ),
    "WF-fig1-slope": (
        "The velocity estimation error bound given in (23) is calculated as a function of $σ_a$ "
        "and $T_s$ with $σ_T$ as a parameter"
    ),
    "WF-fig1-update-rate-50hz": (
        "The horizontal axes for these two figures are labeled as local accelerometer "
        "resolution at a 50 Hz measurement update rate."
    ),
    "WF-fig2-gps-adds-little": (
        "Comparing Figure 1 to Figure 2 shows that the benefits gained by acquiring local GPS "
        "measurements on top of the accelerometer measurements are quite limited."
    ),
    "WF-fig2-order": (
        "line plots show the result for 1 GPS satellite while the circle marker plots show the "
        "result for 3 GPS satellite."
    ),
    "WF-fig2-three-vs-one-satellite": (
        "Note that the 3-satellite result is not shown for the $\\sigma_T = 0$ case because it "
        "was virtually identical to the 1-satellite result."
    ),
    "WF-rem1-weights": "Remarks: (i) A particular set of feasible $k_i$ 's in (22) can be, for example,",
    "WF-rem2-generic": (
        "(ii) The upper bound tends to be exact when one sensor error is much smaller than the "
        "others or when the estimation errors of all processors are completely correlated."
    ),
    "WF-rem2-isotropic": (
        "(ii) The upper bound tends to be exact when one sensor error is much smaller than the "
        "others or when the estimation errors of all processors are completely correlated."
    ),
    "WF-rem2-one-small": (
        "(ii) The upper bound tends to be exact when one sensor error is much smaller than the "
        "others or when the estimation errors of all processors are completely correlated."
    ),
    "WF-rem2-weaker-correlation": (
        "The upper bound becomes more conservative when the correlation becomes weaker."
    ),
    "WF-sec3-flexible-mode-velocity": (
        "On the other hand, the frequency of the first flexible mode is in the range of several "
        "Hertz, which can result in an adverse velocity component of several meters/second."
    ),
    "WF-sec3-tip-position-vs-ins": (
        "The position perturbation caused by such wingtip deflections, however, is at most "
        "0.01% relative to the typical range under consideration, and at most 10% relative to "
        "the best position accuracy provided by an INS/GPS system [3]."
    ),
    "WF-sec3-tip-position-vs-range": (
        "The position perturbation caused by such wingtip deflections, however, is at most "
        "0.01% relative to the typical range under consideration, and at most 10% relative to "
        "the best position accuracy provided by an INS/GPS system [3]."
    ),
    "WF-sec3-velocity-vs-ins": (
        "and is $10^4\\%$ at the worst relative to the best velocity accuracy provided by an INS/GPS [3]."
    ),
    "WF-sec3-velocity-vs-nominal": (
        "The velocity perturbation is approximately 1% relative to the nominal velocity under consideration"
    ),
    "WF-sec4d-fused-velocity-accuracy": (
        "giving an improved local velocity accuracy of at least $2 \\times 10^{-3} = 0.002\\text{m/s}$."
    ),
    "WF-sec4d-gps-noticeable-only-when-severe": (
        "The benefits become noticeable only when the uncertainty of the local velocity "
        "estimate based on the lever-arm-adjusted navigation-state estimate is very severe, the "
        "local accelerometer accuracy is very poor, and three satellites are visible."
    ),
    "WF-sec4d-improvement-factor": "This is a factor of 10^3 accuracy improvement",
    "WF-sec4d-mems-ten-times-more-sensitive": (
        "Note that the current MEMS technology can already produce devices an order of "
        "magnitude more sensitive than $100\\mu\\text{g}$ [4]."
    ),
    "WF-sec4d-sigma-g-from-gps-doppler": (
        "$\\sigma_G = 1$ Hz (consistent with the GPS velocity accuracy from Doppler shift measurement)"
    ),
    "WF-sec4d-sigma-l-high-resolution": "$\\sigma_L = 0.002$ m/s [...] $\\sigma_L = 200\\sigma_a$ [3],[5].",
    "WF-sec4d-sigma-l-medium-resolution": (
        "2 m/s (high to medium velocity accuracy (see [5], Table 1)) [...] $\\sigma_L = "
        "200\\sigma_a$ [3],[5]."
    ),
    "WF-sec4d-unfiltered-velocity-accuracy": (
        "On the other hand, without filtering the local measurements, the accelerometer "
        "resolution translates into a local velocity accuracy at around 0.2m/s [3],[5]."
    ),
    "WF-sec5-aperture-errors-negligible": (
        "Aperture-local MEMS accelerometers and aperture-acquired GPS measurements together "
        "with the on-board navigation system's measurements can reduce the impact of the "
        "aperture errors to a negligible level."
    ),
    "WF-thm-bound": "Theorem: An upper bound on $Cov\\{\\mathbf{x}_D - \\hat{\\mathbf{x}}_D\\}$ is given by",
    "WF-thm-montecarlo": (
        "Theorem: An upper bound on $Cov\\{\\mathbf{x}_D - \\hat{\\mathbf{x}}_D\\}$ is given by"
    ),
}
