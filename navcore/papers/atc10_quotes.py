"""The paper's words behind every ATC-10 claim (issue 27, item 5): its ``printed`` quote.

Each quote is the text of the transcription (whitespace collapsed; table rows as their cells joined
by single spaces; LaTeX as transcribed); pieces of one passage are joined by " [...] ". The
tolerance policy of each claim follows its quote by the ledger's rule, and a number claim's quote
prints its published number. The independent audit of issue 27 verified each piece against the
transcription; ``tests/test_atc10_quotes.py`` checks them again wherever the transcription is present.
Claims that give ``printed=`` themselves keep it; :func:`navcore.claims.quotes.with_quotes` fills the others.
"""

from __future__ import annotations

__all__ = ["QUOTES"]

#: Claim id -> the paper's words or formula as quoted.
QUOTES: dict[str, str] = {
    "ATC10-appA-any-pd-reachable": (
        "(A.17) can be made to hold by taking t sufficiently small and $p_d$ sufficiently large"
    ),
    "ATC10-appA-limit": "if $t < p_d^4$ then $P_D$ will approach 1 as K gets larger and larger",
    "ATC10-appE-cumulants": (
        "$$\\lambda_2 = \\frac{2\\tau}{\\alpha} \\int_{-\\infty}^{\\infty} x^2 C(x) dx \\quad (\\text{E.9})$$"
    ),
    "ATC10-appE-expansion": "Collecting like powers of v (E.11) becomes",
    "ATC10-appE-gaussian-order": "The first term in (E.15) is $O(N^{-1/2})$.",
    "ATC10-appE-lambda3-order": "The second term is $O(N^{-3/2})$.",
    "ATC10-appE-n-minus-one": "we can replace the coefficient $(N-1)$ with N , without any error in our work",
    "ATC10-appF-identity": (
        "$$\\int_{-\\infty}^{\\infty} x^2 C_{ij}(x) dx = \\frac{1}{4\\tau} \\int_{-\\infty}^{\\infty} "
        "R_{jj}(q) R_{ii}(q) dq \\quad (F.5)$$"
    ),
    "ATC10-appG-V0-closed-form": "$$\\text{Var}[x_3(t)] = \\beta^2 V_0 t^{2\\rho}$$",
    "ATC10-appG-V0-printed": (
        "$$V_0 = \\frac{\\frac{1}{2\\rho} + \\int_0^{\\infty} [s^\\rho - \\frac{1}{2} - (s+1)^\\rho - "
        "\\frac{1}{2}] ds}{[\\Gamma(\\rho + \\frac{1}{2})]^2}$$"
    ),
    "ATC10-appG-counter-linearisation": (
        "$$(nN + K)^{2\\rho} - (nN)^{2\\rho} \\approx 2\\rho(nN)^{2\\rho - 1} k$$"
    ),
    "ATC10-appG-half-is-wiener": (
        "(Note that when $\\rho = \\frac{1}{2}$, $x_3(t)$ is just the integral of $v(t)$)"
    ),
    "ATC10-appG-newton-error": "the error in $t_k^{(1)}$ is only on the order of $\\frac{k}{f_0} \\lambda^2$",
    "ATC10-appG-offset-like-flicker": (
        'the effects of the "1/f" noise are quite similar to those of the unknown frequency offset'
    ),
    "ATC10-appG-spectrum": "would behave as $|f|^{-2\\rho-1}$",
    "ATC10-appH-H16-H21": (
        "$$P_{\\xi_x} = [P_x^{-1} + F'P_n^{-1}F - F'P_n^{-1}G(G'P_n^{-1}G)^{-1}G'P_n^{-1}F]^{-1} \\quad "
        "(\\text{H.21})$$"
    ),
    "ATC10-appH-H27-gls": "$$\\hat{y} = (G'G)^{-1}G'(z - Fx - \\mu_n) \\quad (H.27)$$",
    "ATC10-appH-H8-H22": (
        "$$P_{\\xi_y} = (G'P_n^{-1}G)^{-1} + "
        "(G'P_n^{-1}G)^{-1}G'P_n^{-1}FP_{\\xi_x}F'P_n^{-1}G(G'P_n^{-1}G)^{-1} \\quad (\\text{H.22})$$"
    ),
    "ATC10-appH-orthogonal-best": "to obtain the best estimator performances",
    "ATC10-appH-proposition": (
        "Proposition: $M'_0 (M_0 P_\\epsilon M'_0)^{-1} M_0 = P_\\epsilon^{-1} (I - GK)$"
    ),
    "ATC10-appH-rank-r-prior-mean": (
        "the best estimate for τ_n is just the mean of τ_n given $\\hat{\\tau}_N$"
    ),
    "ATC10-appH-scalar-gain-corrected": (
        "$$\\gamma = \\frac{\\sigma^2}{\\sigma^2 + \\sigma_x^2 [F'F - F'G(G'G)^{-1}G'F]}$$"
    ),
    "ATC10-appH-scalar-gain-printed": (
        "$$\\gamma = \\frac{\\sigma^2}{\\sigma^2 + \\sigma_x^2 [F'F - F'G(G'G)^{-1}G'F]}$$"
    ),
    "ATC10-eq2.4.1": "$$P_D \\geq p_d^4 \\quad \\text{when } K = 1 \\quad (2.4.1)$$",
    "ATC10-eq2.4.2-nu-max": "ν is the nonnegative number which maximizes",
    "ATC10-eq2.5.10-random-pick": "with probability greater than 0.5, an incorrect position will be picked",
    "ATC10-eq2.5.12-composition": (
        "$$\\bar{N}_{AD} \\geq 0.5 N p_d^4 (1 - (1-p_f)^{2B\\alpha}) (1 - (1-p_f)^{4B\\beta})^3 \\quad "
        "\\text{when } K = 1$$"
    ),
    "ATC10-eq2.5.5-composition": (
        "$$\\bar{N}_f \\geq \\bar{N}_{FL} = (N_T - N) \\exp \\left[(K t + 1) \\ln \\left((1 - (1 - "
        "p_f)^{2B\\alpha}) (1 - (1 - p_f)^{4B\\beta})^3 \\right) \\right] \\quad (2.5.5)$$"
    ),
    "ATC10-eq2.8.1-erf-coefficient": (
        "$$p_f = \\frac{1}{2} - \\frac{1}{2} \\operatorname{erf} \\left(\\frac{1}{2} \\sqrt{\\frac{P_0 B "
        "\\tau}{J}} - \\phi \\right) \\quad (2.8.1)$$"
    ),
    "ATC10-eq3.4.10-second-moment": (
        "$$E(n^2) = \\sum_{\\substack{j=1 \\\\ j \\neq i}}^N \\frac{2\\tau}{\\alpha} "
        "\\int_{-\\infty}^{\\infty} x^2 C_{ij}(x) dx \\quad (3.4.10)$$"
    ),
    "ATC10-eq3.4.6-cumulants": "which is the desired result.",
    "ATC10-eq3.5.5-chernoff-dominates": "Using Chernoff Bounds we can upper bound (3.5.4) as",
    "ATC10-eq3.7.23-closed-form": "Which can be solved directly yielding,",
    "ATC10-eq3.7.26-approx": "in which case (3.7.24) and (3.7.25) can be approximated by",
    "ATC10-eq3.7.5-cosh-inequality": "By Jensen's Inequality we have",
    "ATC10-eq3.8.12-series": (
        "$\\frac{1}{16} \\left(\\frac{\\text{Expfg}}{N\\tau/\\alpha}\\right)^3 + \\dots \\quad (3.8.12)$"
    ),
    "ATC10-eq3.8.16-equals-closed-form": (
        "It will be convenient to express; Expf in terms of Expfg, and Expd in terms of Expdg. This is "
        "quite easy to do and we obtain"
    ),
    "ATC10-eq3.8.3-gaussian-roc": "Combining (3.8.1) and (3.8.2) we have the ROCg",
    "ATC10-eq3.8.6-printed": "$$E(e^{\\mu n}) = \\exp\\left(\\frac{\\mu^2}{2}\\right) \\tag{3.8.6}$$",
    "ATC10-eq3.8.7-bound": "$$p_f \\leq \\exp\\left(-\\frac{\\theta^2}{2p}\\right)$$",
    "ATC10-eq4.5.1-least-squares": (
        "$$\\sigma_{\\xi\\tau_0}^2 = \\frac{\\sigma^2}{K-1'F_0(F_0'F_0)^{-1}F_0'1} = \\sigma^2 \\gamma_0 "
        "\\quad (4.5.5)$$"
    ),
    "ATC10-eq4.5.16-recursion-mc": "The resulting error statistics are just",
    "ATC10-eq4.5.27-extrapolation-mc": (
        "$\\sigma_{\\varepsilon_{\\tau_n}}^2 &= \\sigma_\\gamma^2 + \\sigma_0^2 "
        "\\left[\\frac{2-\\gamma\\beta}{\\gamma\\beta} (n-N) + (n-N)^2 \\right] \\tag{4.5.27}$"
    ),
    "ATC10-eq4.5.10-printed": (
        "$$\\hat{\\tau}_1 = \\gamma_1^{-1} (I - F_1 (F_1' F_1)^{-1} F_1') [\\hat{T}_1 - k_1 - "
        "(\\hat{\\tau}_0 + \\bar{\\tau}) 1] + \\hat{\\tau}_0 + \\bar{\\tau} \\quad (4.5.10)$$"
    ),
    "ATC10-eq4.5.21-printed": (
        "$&= 2\\sigma_0^2 + \\sigma_{\\gamma_{n-1}}^2 - 2E[\\Delta_n \\xi_{\\tau_{n-1}}] \\tag{4.5.21}$"
    ),
    "ATC10-eq4.5.23-increment-covariance": (
        "$$E[\\Delta_n \\Delta_{n-i}] = \\begin{cases} 2\\sigma_0^2, & i=0 \\\\ \\sigma_0^2, & 1 \\leq i "
        "\\leq n-1 \\end{cases} \\quad (4.5.23)$$"
    ),
    "ATC10-eq4.5.31-printed": (
        "$\\gamma_n &= \\frac{\\sigma_{\\tau_n}^2}{\\sigma_o^2 + \\sigma_{\\tau_n}^2 \\beta_n}$"
    ),
    "ATC10-eq4.5.37-gain-limit": (
        "$$\\gamma_n \\rightarrow \\gamma = \\frac{1}{\\beta} \\psi(\\alpha) \\quad (4.5.37)$$"
    ),
    "ATC10-eq4.5.35-printed": (
        "$\\sigma^2 [\\text{tr}\\{(F_n' F_n)^{-1}\\} + \\gamma_n^2 F_n' (F_n' F_n)^{-2} F_n] \\quad (4.5.35)$"
    ),
    "ATC10-eq4.5.38-coefficient": (
        "$&\\cong 1.89 [\\alpha^{1/3} - (\\frac{\\alpha}{2})^{2/3}], \\text{ for } \\alpha \\leq 0.3$"
    ),
    "ATC10-eqA.13-chernoff-below-exact": (
        "$$P_D \\geq 1 - \\exp -K (v(1-t) - \\ln ((1-p_d^4) e^v + p_d^4)) \\quad (A.17)$$"
    ),
    "ATC10-eqA.15-printed": (
        "$$P_D \\geq 1 \\exp -K (v(1-t) - \\ln (P(\\rho(i,1) = 0 | H_1(i)) e^v + P(\\rho(i,1) = 1 | "
        "H_1(i)))) \\quad (A.15)$$"
    ),
    "ATC10-eqA.16-bound-stays-valid": (
        "When the approximation doesn't hold exactly, the lower bound of (A.15) will still be true if "
        "the approximation is used."
    ),
    "ATC10-eqA.6-majority-test": "The coefficient of the left hand side of (A.7) is positive.",
    "ATC10-eqA.7-printed": (
        "$\\leq K \\left(\\text{Ln} \\lambda_1 \\left(\\frac{\\text{Prob} (\\rho(i,1) = 1 | "
        "H_0(i))}{\\text{Prob} (\\rho(i,1) = 1 | H_1(i))} \\right) \\right) \\quad (\\text{A.7})$"
    ),
    "ATC10-eqA.9-rule-at-design": (
        "$$\\text{Decide } H_1(i) \\text{ if } K_0 \\leq t K \\quad (\\text{A.9})$$"
    ),
    "ATC10-eqB.11-monte-carlo": (
        "$$P_F \\geq \\exp \\left[(Kt + 1) \\text{Ln} \\left(\\left(1 - (1-p_f)^{2B\\alpha}\\right) "
        "\\left(1 - (1-p_f)^{4B\\beta}\\right)^3 \\right) \\right] \\quad (\\text{B.11})$$"
    ),
    "ATC10-eqB.6-correlated-samples": (
        "$$\\text{Prob} (\\phi_1 | H_0(i)) = \\left(1 - (1-p_f)^{2B\\alpha}\\right) \\left(1 - "
        "(1-p_f)^{4B\\beta}\\right)^3 \\quad (\\text{B.6})$$"
    ),
    "ATC10-eqB.9-lists-needed": (
        "$\\{ \\text{A false alarm on Seg.}(K) \\} \\supseteq \\bigcap_{j=1}^{Kt+1} \\{ \\rho(i,j) = 1 \\}$"
    ),
    "ATC10-eqC.1-printed": (
        "$$\\text{Prob } [\\gamma_D(i) = 1] \\geq [1 - p_f]^{2B\\alpha} [1 - (1-p_f)^{4B\\beta}]^3 "
        "\\quad (\\text{C.1})$$"
    ),
    "ATC10-eqC.17-monte-carlo": (
        "which, when we compare to (C.1), we see is the desired lower bound when either $K=1$ or $K>1$."
    ),
    "ATC10-eqC.2-printed": "$$|T_1(1) - T_2(1)| \\leq \\frac{v\\alpha}{c} \\text{ seconds}$$",
    "ATC10-eqC.5-track-window": "$$|d_1^1 - d_1^2| \\leq \\frac{2v\\alpha}{c} \\quad (C.5)$$",
    "ATC10-eqD-derivation": (
        "$$p_f = \\frac{1}{2} - \\frac{1}{2} \\operatorname{erf} \\left(\\sqrt{\\frac{E}{2J/B}} - \\phi "
        "\\right) \\quad (D.16)$$"
    ),
    "ATC10-eqD.17-direct": "(D.17) gives the desired dependence of $p_f$ upon the parameters of interest.",
    "ATC10-fig2.3-2.16-curve-sets": "For Various ($p_d$, t) Combinations.",
    "ATC10-fig3.10-linear": "the functional dependence between Exp and $Exp_g$ is practically linear",
    "ATC10-fig3.10-rate": (
        "the rate of this approach is more rapid for lower values of $Exp_g$ than for higher "
        "values of $Exp_g$"
    ),
    "ATC10-fig3.9-exp-below": (
        "Figure 3.9 illustrates Exp as a function of N for $\\text{Exp}_g = 4$ and various values of τ/α "
        ". [...] Exp is less than $Exp_g$ by a non-negligible amount"
    ),
    "ATC10-fig3.9-shortfall": "Exp is less than $Exp_g$ by a non-negligible amount",
    "ATC10-fig4.1-large-alpha": (
        "$$\\psi(\\alpha) \\cong 1 - \\frac{4}{27} \\alpha^{-1}, \\text{ for } \\alpha \\geq 1$$"
    ),
    "ATC10-fig4.1-small-alpha": (
        "$&\\cong 1.89 [\\alpha^{1/3} - (\\frac{\\alpha}{2})^{2/3}], \\text{ for } \\alpha \\leq 0.3$"
    ),
    "ATC10-fig4.2-4.3-shape": (
        "Finally, Figures 4.2 and 4.3 illustrate how $\\sqrt{\\text{Var}[\\|\\xi_{p_n}\\|]}$ varies with n ."
    ),
    "ATC10-sec1.1-K1000-prohibitive": (
        "As K approaches 1000, the cost and complexity of this unsophisticated jammer is such as to "
        "prohibit its use"
    ),
    "ATC10-sec1.1-erp-rises-with-K": "For K less than 100 the required jammer is modest",
    "ATC10-sec1.1-level-10pct-airborne": (
        "at least 10% of the number of airborne aircraft are falsely located [...] we have selected the "
        "threshold values as $(0.9) N_T$ for $\\bar{N}_F$ and $(0.01) N_T$ for $\\bar{N}_{AD}$"
    ),
    "ATC10-sec1.3-oscillator": "requires a short-term oscillator stability better than 5 parts in 10^8",
    "ATC10-sec2.1-threshold-behaviour": (
        "performance parameters exhibit a strong threshold behavior as a function of signal to "
        "interference ratio"
    ),
    "ATC10-sec2.3-coherent-beats-envelope": (
        'The performance of a matched filter detector is always better than a "matched filter-envelope '
        'detector" since phase is assumed known.'
    ),
    "ATC10-sec2.3-segment-holds-signature": "at least once in each such time segment and possibly twice",
    "ATC10-sec2.6-monotone-in-J": (
        "the presence of other sources of interference can only increase $\\bar{N}_{FL}$ and $\\bar{N}_{ADL}$"
    ),
    "ATC10-sec2.7-20deg": (
        "This could be realized with 30 watts of rf power and an antenna with a 20° beamwidth."
    ),
    "ATC10-sec2.7-30W": (
        "This could be realized with 30 watts of rf power and an antenna with a 20° beamwidth."
    ),
    "ATC10-sec2.7-levels-near-threshold": (
        "Since these are close to the threshold, we shall use these values as indicators of total system "
        "performance degeneration."
    ),
    "ATC10-sec2.7-lt2dB-ADL": (
        "the difference between required jamming power for a $P_{DL}$ of 0.9 and 0.999 is less than 2 db"
    ),
    "ATC10-sec2.7-lt2dB-FL": (
        "the difference between required jamming power for a $P_{DL}$ of 0.9 and 0.999 is less than 2 db"
    ),
    "ATC10-sec2.7-nominal-33dBW": (
        "we can determine, from Figs. 2.1 and 2.2, the maximum required jammer ERP [...] we shall thus "
        "take as a nominal jamming level 33 dbw ERP"
    ),
    "ATC10-sec2.7-plateau": "these lower bounds maintain their maximum values over quite a large range",
    "ATC10-sec2.7-pulse-energy": "10 mJoules (e.g. $P_0 = 30$ dbw, $\\tau = 10$ μ sec)",
    "ATC10-sec2.8-10dB-K10to100": (
        "it takes about 10 db more power to disable a $K = 10$ system than a $K = 1$ system and about 10 "
        "db more power to disable a $K = 100$ system"
    ),
    "ATC10-sec2.8-10dB-K1to10": (
        "it takes about 10 db more power to disable a $K = 10$ system than a $K = 1$ system and about 10 "
        "db more power to disable a $K = 100$ system"
    ),
    "ATC10-sec2.8-FL-first": (
        "$\\bar{N}_{FL}$ degrades more rapidly with $\\frac{J}{P_0 B \\tau}$ than does the bound on the "
        "average number of ambiguous detections"
    ),
    "ATC10-sec2.8-FL-less-t-sensitive": (
        'make the $\\bar{N}_{FL}$ vs. $\\frac{J}{P_0 B \\tau}$ curve less sensitive to decreasing " t "'
    ),
    "ATC10-sec2.8-K1000-critical": (
        "For $K = 1000$ the required jamming power depends critically on the desired level of $P_{DL}$ ."
    ),
    "ATC10-sec2.8-adl-falls-with-t": (
        "This implies that $p_f$ is decreasing and thus $\\bar{N}_{ADL}$ is decreasing."
    ),
    "ATC10-sec2.8-first-stage-fa-rises": (
        'As " t " decreases the probability of an aircraft false alarm (on the first stage decision '
        "process) will increase."
    ),
    "ATC10-sec2.8-pd-rises-with-t": (
        "As t decreases $p_d$ must decrease in order to maintain a fixed $P_{DL}$"
    ),
    "ATC10-sec2.8-t0-worst": (
        'by just considering the curves corresponding to " $t=0$ " for a fixed K and $P_{DL}$'
    ),
    "ATC10-sec2.8-threshold-every-curve": "each curve exhibits a strong thresholding property",
    "ATC10-sec3.1.2-coherent-beats-envelope": (
        'Of course a receiver which uses "matched filter-envelope detection" will not perform as well as '
        'one which uses "matched filter detection."'
    ),
    "ATC10-sec3.1.2-peak-optimistic": (
        "our results under this assumption can only be more optimistic than without it"
    ),
    "ATC10-sec3.1.3B-psk": (
        "is not as preferable as the ROC obtained when the detector operates, only in the presence of "
        "additive gaussian noise, with the same signal to interference ratio"
    ),
    "ATC10-sec3.3-overlap-window": "can only be nonzero if the reception time $t_j$ satisfies",
    "ATC10-sec3.3-peak-one": "this has a peak value of 1",
    "ATC10-sec3.4-power": (
        "constrains the average multiple access noise power to equal $\\frac{2(N-1)\\tau}{\\alpha} b$"
    ),
    "ATC10-sec3.4-zero-mean": "$$\\int_{-\\infty}^{\\infty} x C_{ij}(x) dx = 0 \\quad (3.4.12)$$",
    "ATC10-sec3.5-asymptotically-tight": (
        "These bounds are asymptotically tight in the sense that they approach the actual ROC as the "
        "number of aircraft being considered increases."
    ),
    "ATC10-sec3.5-bound-monotone": (
        "As N increases and/or (τ/α) increases the upper bound to $p_f$ increases and the lower bound to "
        "$p_d$ decreases."
    ),
    "ATC10-sec3.5-lower-bound-printed": "$$\\phi_1 = -2\\rho_1 \\sqrt{2 \\frac{\\partial^2}{\\partial r^2}$$",
    "ATC10-sec3.5-lower-bound-valid": "The bounds given by (3.5.14) constitute the lower bound to the ROC.",
    "ATC10-sec3.6-deteriorates": "the performance of the matched filter detector **deteriorates**",
    "ATC10-sec3.6-order": (
        "We can order the common amplitude densities in terms of their preferability as; $C_2(x)$, "
        "$C_1(x)$, $C_3(x)$, $C_4(x)$."
    ),
    "ATC10-sec3.7-convexity-operating": (
        "The function given by (3.7.15) is strictly convex (as can be determined by taking the second "
        "derivative), in $\\{\\sqrt{\\beta_1}, \\dots, \\sqrt{\\beta_N}\\}$."
    ),
    "ATC10-sec3.7-convexity-unconditional": (
        "The function given by (3.7.15) is strictly convex (as can be determined by taking the second "
        "derivative), in $\\{\\sqrt{\\beta_1}, \\dots, \\sqrt{\\beta_N}\\}$. Hence, it must have a "
        "unique minimum"
    ),
    "ATC10-sec3.7-equal-share": (
        "the total multiple access noise is divided equally among all mismatched signatures"
    ),
    "ATC10-sec3.7-smallest-peak": "with the smallest possible peak height",
    "ATC10-sec3.8-example-exp": "we see that $\\text{Exp} \\approx 9$",
    "ATC10-sec3.8-example-expg": "$$\\text{Exp}g = 12.5$$",
    "ATC10-sec3.8-example-n-effective": "This would make N effectively equal to $2(10^5)$.",
    "ATC10-sec3.8-example-optimistic": (
        "yielded a much more optimistic system performance than actually existed"
    ),
    "ATC10-sec3.8-example-p": "$$p = 50$$",
    "ATC10-sec3.8-example-ratio": "the ratio of $Exp_g$ to Exp is approximately 1.4",
    "ATC10-sec3.8-exp-below-exp-g": "Exp approaches $Exp_g$ monotonically from below with increasing N",
    "ATC10-sec3.8-exp-limit": (
        "$$\\text{Expf} \\sim \\text{Expfg} \\quad \\text{as } N \\rightarrow \\infty \\quad (3.8.15)$$"
    ),
    "ATC10-sec3.8-gauss-always-optimistic": (
        "The value of $p_f$ indicated by the ROCg is always lower than the actual $p_f$ ."
    ),
    "ATC10-sec3.8-tail-ratio": (
        "the gaussian approximation to the multiple access noise distribution is a very poor approximation"
    ),
    "ATC10-sec3.9-W-bracket": (
        "$$W = \\left[\\frac{4}{3} \\tau_c \\left(1 + 2 \\frac{\\tau_c}{\\tau} + 2 "
        "\\left(\\frac{\\tau_c}{\\tau} \\right)^2 \\right) \\right]^{-1}$$"
    ),
    "ATC10-sec3.9-W-limit": "$$W \\approx \\frac{3/4}{\\tau_c} \\quad (3.9.3)$$",
    "ATC10-sec3.9-W-real-code": "$$W \\approx \\frac{3/4}{\\tau_c} \\quad (3.9.3)$$",
    "ATC10-sec3.9-peak-sir": "as the peak signal to interference ratio.",
    "ATC10-sec3.9-power": (
        "This is the same average multiple access noise power which would be obtained if the "
        "interference input to the matched filter detector was white gaussian noise having a spectral "
        "height of $\\frac{N}{3\\alpha \\ 1/\\tau_c}$"
    ),
    "ATC10-sec4.1-dilution-range": (
        "typical satellite constellations of from five to eight satellites could be expected to have "
        "geometric dilutions of from one to two orders of magnitude"
    ),
    "ATC10-sec4.1-rank-condition": (
        "k is finite if and only if $\\text{rank}(HF)=3$; a necessary condition for this to be true is "
        "that $K \\geq 4$"
    ),
    "ATC10-sec4.1-tracking-reduces": (
        "by incorporating a suitable model for the sequence $\\{\\tau_i\\}$, the variance of the error "
        "ξ_p can be reduced"
    ),
    "ATC10-sec4.3-fractional-error": (
        "Thus, the rms fractional error in $\\{\\tau_n\\}$ is just $\\sigma_0/\\bar{\\tau}$."
    ),
    "ATC10-sec4.3-std-n-sigma0": (
        "the standard deviation of $(\\tau_n - \\tau_0)$ becomes approximately $n\\sigma_0$"
    ),
    "ATC10-sec4.5.1-equivalent": (
        "are equivalent expressions for $P_{\\xi p_0}$, and (4.5.7) and (4.1.2) are equivalent expressions"
    ),
    "ATC10-sec4.5.1-finite-iff": (
        "is finite if and only if the geometric dilution, as defined in Section 4.1, is finite"
    ),
    "ATC10-sec4.5.2-beta-rotation": "Under this transformation, β_n changes to $\\bar{\\beta}_n$:",
    "ATC10-sec4.5.2-constant-gain-worse": (
        "The only difference would be that the estimates for small values of n would not be quite as good."
    ),
    "ATC10-sec4.5.2-kalman-poor": (
        'after the estimate for " α_0 " has converged, poor estimates of τ_n would result'
    ),
    "ATC10-sec4.5.2-one-real-root": "the above cubic equation has only one real root",
    "ATC10-sec4.5.2-state-model": "will have the second order statistics of (4.3.1) if",
    "ATC10-sec4.5.2-tau-sum-printed": "$$\\tau_n = \\sum_{i=1}^n w_i + \\alpha_0$$",
    "ATC10-sec4.5.3-quadratic-growth": "increases as $(n-N)^2$ for large values of $(n-N)$",
    "ATC10-sec4.5.4-beta-three-satellites": (
        "Thus, it is impossible to estimate τ_0 with less than four satellites."
    ),
    "ATC10-sec4.5.4-convergence-rule": (
        "the number of steps necessary for γ_n to converge to within $(0.1)\\gamma$ of γ is approximately"
    ),
    "ATC10-sec4.5.4-psi-approx-exI-s5": (
        "can be reduced to approximately $\\psi(\\alpha) \\cdot \\text{Var}[\\|\\xi_{p_0}\\|]$"
    ),
    "ATC10-sec4.5.4-psi-approx-exII-s50": (
        "can be reduced to approximately $\\psi(\\alpha) \\cdot \\text{Var}[\\|\\xi_{p_0}\\|]$"
    ),
    "ATC10-sec4.5.4-psi-factor": (
        "the quantity $\\psi(\\alpha)$ in (4.5.37) is just the factor by which the second term in "
        "(4.5.35) is reduced"
    ),
    "ATC10-sec4.5.4-second-term-dominates": (
        "the second term in (4.5.35) always significantly dominates the first term"
    ),
    "ATC10-sec4.5.4-steps-formula-sign": "$$n \\cong \\frac{1}{\\text{Log}(1-\\psi(\\alpha))} - 1$$",
    "ATC10-sec4.6-cone-exI": (
        "all within a 45° half-angle cone with a vertical axis and the vertex at the aircraft"
    ),
    "ATC10-sec4.6-cone-exII": (
        "all within a 45° half-angle cone with a vertical axis and the vertex at the aircraft"
    ),
    "ATC10-sec4.6-dominance-stronger-exII": "This is particularly true in Example II.",
    "ATC10-sec4.6-k-identity": "$&= \\sqrt{\\text{tr}\\{(F'F)^{-1}\\} + \\frac{1}{\\beta} 1'F(F'F)^{-2}F'1}$",
    "ATC10-sec4.6-marginal-gains": (
        "the point at which one begins to obtain only marginal gains by tracking $\\{\\tau_n\\}$ is the "
        "point at which"
    ),
    "ATC10-sec4.6-rule1-exII": "tracking $\\{\\tau_n\\}$ with all satellites can significantly reduce",
    "ATC10-sec4.6-rule2-exI": "but this reduction is significant only when",
    "ATC10-sec4.6-rule3-jump-from-clock-term": (
        "This is due largely to the increases in $\\text{tr}\\{(F'F)^{-1}\\}$ and $1'F(F'F)^{-2}F'1$ "
        "when the number of satellites drops to three (Table 4.2)."
    ),
    "ATC10-sec4.6-rule4-common-threshold": (
        "The interval of time over which the tracking error will be acceptable varies from about 30 to "
        "60 seconds."
    ),
    "ATC10-sec4.6-rule4-outage-exI": (
        "The interval of time over which the tracking error will be acceptable varies from about 30 to "
        "60 seconds."
    ),
    "ATC10-sec4.6-rule4-outage-exII": (
        "The interval of time over which the tracking error will be acceptable varies from about 30 to "
        "60 seconds."
    ),
    "ATC10-sec4.6-s-increases-invariant": (
        "the quantities $\\text{tr}\\{(F_n' F_n)^{-1}\\}$ and $1' F_n (F_n' F_n)^{-2} F_n' 1$ both increase"
    ),
    "ATC10-sec4.6-s-increases-printed": (
        "the quantities $\\text{tr}\\{(F'F)^{-1}\\}$ and $1'F(F'F)^{-2}F'1$ both increase; this increase "
        "is substantial in Example II"
    ),
    "ATC10-sec4.6-satellite-count": "there are initially seven or eight satellites",
    "ATC10-sec4.6-second-term-dominates-p0": "the second term obviously dominates",
    "ATC10-sec4.6-tr-increases": (
        "the quantities $\\text{tr}\\{(F'F)^{-1}\\}$ and $1'F(F'F)^{-2}F'1$ both increase"
    ),
    "ATC10-sec4.6-triplet-exI": (
        "these satellites were the most widely spaced triplet of satellites within the constraint cone"
    ),
    "ATC10-sec4.6-triplet-exII": (
        "these satellites were the most widely spaced triplet of satellites within the constraint cone"
    ),
    "ATC10-sec4.7-crossover-100": (
        "it could be that the value of n , where these two components are comparable, is much larger, "
        "say, $n=100$"
    ),
    "ATC10-sec4.7-gains-only-below-sigma": (
        "are significant only when the accuracy of the aircraft clock is greater than or equal to the "
        "accuracy with which the pulse times of arrival are measured"
    ),
    "ATC10-sec4.7-markov-order": "is not a Markov process of finite order when $\\frac{1}{2} < \\rho < 1$",
    "ATC10-sec4.7-three-sat-sigma": (
        "it is only when $\\sigma_0 \\cong .1 \\sigma$ that one can estimate aircraft positions, with "
        "acceptable error, over several tens of seconds"
    ),
    "ATC10-tab1.1-K1-beamwidth": "Beamwidth (degrees) [...] 1 33 15 2 15",
    "ATC10-tab1.1-K1-diameter": "Antenna Diameter (feet) [...] 1 33 15 2 15",
    "ATC10-tab1.1-K1-erp": "ERP (dbw) [...] 1 33 15 2 15",
    "ATC10-tab1.1-K1-rf": "rf Power (dbw) [...] 1 33 15 2 15",
    "ATC10-tab1.1-K10-beamwidth": "Beamwidth (degrees) [...] 10 43 20 4 12",
    "ATC10-tab1.1-K10-diameter": "Antenna Diameter (feet) [...] 10 43 20 4 12",
    "ATC10-tab1.1-K10-erp": "ERP (dbw) [...] 10 43 20 4 12",
    "ATC10-tab1.1-K10-rf": "rf Power (dbw) [...] 10 43 20 4 12",
    "ATC10-tab1.1-K100-beamwidth": "Beamwidth (degrees) [...] 100 53 23 8 5",
    "ATC10-tab1.1-K100-diameter": "Antenna Diameter (feet) [...] 100 53 23 8 5",
    "ATC10-tab1.1-K100-erp": "ERP (dbw) [...] 100 53 23 8 5",
    "ATC10-tab1.1-K100-rf": "rf Power (dbw) [...] 100 53 23 8 5",
    "ATC10-tab1.1-K1000-beamwidth": "Beamwidth (degrees) [...] 1000 77 40 18 2",
    "ATC10-tab1.1-K1000-diameter": "Antenna Diameter (feet) [...] 1000 77 40 18 2",
    "ATC10-tab1.1-K1000-erp": "ERP (dbw) [...] 1000 77 40 18 2",
    "ATC10-tab1.1-K1000-rf": "rf Power (dbw) [...] 1000 77 40 18 2",
    "ATC10-tab1.1-caption-pdl": (
        "with a processor designed to achieve a detection probability of at least 0.88"
    ),
    "ATC10-tab2.1-K10-pdl0.88": "10 0.88 46",
    "ATC10-tab2.1-K10-pdl0.999": "10 0.999 43",
    "ATC10-tab2.1-K100-pdl0.88": "100 0.88 56",
    "ATC10-tab2.1-K100-pdl0.999": "100 0.999 51",
    "ATC10-tab2.1-K1000-pdl0.98": "1000 0.98 > 130",
    "ATC10-tab2.1-K1000-pdl0.999": "1000 0.999 77",
    "ATC10-tab4.2-exI-beta-fitted": "I .0543 7.84 9.39 1.30 5.76",
    "ATC10-tab4.2-exI-beta-physical": "I .0543 7.84 9.39 1.30 5.76",
    "ATC10-tab4.2-exI-s_123-fitted": "I .0543 7.84 9.39 1.30 5.76",
    "ATC10-tab4.2-exI-s_123-physical": "I .0543 7.84 9.39 1.30 5.76",
    "ATC10-tab4.2-exI-s_all-fitted": "I .0543 7.84 9.39 1.30 5.76",
    "ATC10-tab4.2-exI-s_all-physical": "I .0543 7.84 9.39 1.30 5.76",
    "ATC10-tab4.2-exI-trace_123-fitted": "I .0543 7.84 9.39 1.30 5.76",
    "ATC10-tab4.2-exI-trace_123-physical": "I .0543 7.84 9.39 1.30 5.76",
    "ATC10-tab4.2-exI-trace_all-fitted": "I .0543 7.84 9.39 1.30 5.76",
    "ATC10-tab4.2-exI-trace_all-physical": "I .0543 7.84 9.39 1.30 5.76",
    "ATC10-tab4.2-exII-beta-fitted": "II .00355 3.99 14.9 1.16 14.3",
    "ATC10-tab4.2-exII-beta-physical": "II .00355 3.99 14.9 1.16 14.3",
    "ATC10-tab4.2-exII-s_123-fitted": "II .00355 3.99 14.9 1.16 14.3",
    "ATC10-tab4.2-exII-s_123-physical": "II .00355 3.99 14.9 1.16 14.3",
    "ATC10-tab4.2-exII-s_all-fitted": "II .00355 3.99 14.9 1.16 14.3",
    "ATC10-tab4.2-exII-s_all-physical": "II .00355 3.99 14.9 1.16 14.3",
    "ATC10-tab4.2-exII-trace_123-fitted": "II .00355 3.99 14.9 1.16 14.3",
    "ATC10-tab4.2-exII-trace_123-physical": "II .00355 3.99 14.9 1.16 14.3",
    "ATC10-tab4.2-exII-trace_all-fitted": "II .00355 3.99 14.9 1.16 14.3",
    "ATC10-tab4.2-exII-trace_all-physical": "II .00355 3.99 14.9 1.16 14.3",
    "ATC10-tab4.3-exI-s5-alpha": "I 50 nsec 5 nsec $1.61×10^{-4}$ .10 282 ft 160 ft 230 ft",
    "ATC10-tab4.3-exI-s5-psi": "I 50 nsec 5 nsec $1.61×10^{-4}$ .10 282 ft 160 ft 230 ft",
    "ATC10-tab4.3-exI-s5-sd0": "I 50 nsec 5 nsec $1.61×10^{-4}$ .10 282 ft 160 ft 230 ft",
    "ATC10-tab4.3-exI-s5-sdN": "I 50 nsec 5 nsec $1.61×10^{-4}$ .10 282 ft 160 ft 230 ft",
    "ATC10-tab4.3-exI-s5-sdN1": "I 50 nsec 5 nsec $1.61×10^{-4}$ .10 282 ft 160 ft 230 ft",
    "ATC10-tab4.3-exI-s5-sdN1-corrected": "I 50 nsec 5 nsec $1.61×10^{-4}$ .10 282 ft 160 ft 230 ft",
    "ATC10-tab4.3-exI-s50-alpha": "50 nsec 50 nsec $1.61×10^{-2}$ .40 282 ft 209 ft 450 ft",
    "ATC10-tab4.3-exI-s50-psi": "50 nsec 50 nsec $1.61×10^{-2}$ .40 282 ft 209 ft 450 ft",
    "ATC10-tab4.3-exI-s50-sd0": "50 nsec 50 nsec $1.61×10^{-2}$ .40 282 ft 209 ft 450 ft",
    "ATC10-tab4.3-exI-s50-sdN": "50 nsec 50 nsec $1.61×10^{-2}$ .40 282 ft 209 ft 450 ft",
    "ATC10-tab4.3-exI-s50-sdN1": "50 nsec 50 nsec $1.61×10^{-2}$ .40 282 ft 209 ft 450 ft",
    "ATC10-tab4.3-exI-s50-sdN1-corrected": "50 nsec 50 nsec $1.61×10^{-2}$ .40 282 ft 209 ft 450 ft",
    "ATC10-tab4.3-exI-s500-alpha": "50 nsec 500 nsec 1.61 .925 282 ft 274 ft 1840 ft",
    "ATC10-tab4.3-exI-s500-psi": "50 nsec 500 nsec 1.61 .925 282 ft 274 ft 1840 ft",
    "ATC10-tab4.3-exI-s500-sd0": "50 nsec 500 nsec 1.61 .925 282 ft 274 ft 1840 ft",
    "ATC10-tab4.3-exI-s500-sdN": "50 nsec 500 nsec 1.61 .925 282 ft 274 ft 1840 ft",
    "ATC10-tab4.3-exI-s500-sdN1": "50 nsec 500 nsec 1.61 .925 282 ft 274 ft 1840 ft",
    "ATC10-tab4.3-exI-s500-sdN1-corrected": "50 nsec 500 nsec 1.61 .925 282 ft 274 ft 1840 ft",
    "ATC10-tab4.3-exI-sd0-norm-variance": "I 50 nsec 5 nsec $1.61×10^{-4}$ .10 282 ft 160 ft 230 ft",
    "ATC10-tab4.3-exII-s5-alpha": "II 50 nsec 5 nsec $1.05×10^{-5}$ .04 910 ft 205 ft 677 ft",
    "ATC10-tab4.3-exII-s5-psi": "II 50 nsec 5 nsec $1.05×10^{-5}$ .04 910 ft 205 ft 677 ft",
    "ATC10-tab4.3-exII-s5-sd0": "II 50 nsec 5 nsec $1.05×10^{-5}$ .04 910 ft 205 ft 677 ft",
    "ATC10-tab4.3-exII-s5-sdN": "II 50 nsec 5 nsec $1.05×10^{-5}$ .04 910 ft 205 ft 677 ft",
    "ATC10-tab4.3-exII-s5-sdN1": "II 50 nsec 5 nsec $1.05×10^{-5}$ .04 910 ft 205 ft 677 ft",
    "ATC10-tab4.3-exII-s5-sdN1-corrected": "II 50 nsec 5 nsec $1.05×10^{-5}$ .04 910 ft 205 ft 677 ft",
    "ATC10-tab4.3-exII-s50-alpha": "50 nsec 50 nsec $1.05×10^{-3}$ .18 910 ft 396 ft 1500 ft",
    "ATC10-tab4.3-exII-s50-psi": "50 nsec 50 nsec $1.05×10^{-3}$ .18 910 ft 396 ft 1500 ft",
    "ATC10-tab4.3-exII-s50-sd0": "50 nsec 50 nsec $1.05×10^{-3}$ .18 910 ft 396 ft 1500 ft",
    "ATC10-tab4.3-exII-s50-sdN": "50 nsec 50 nsec $1.05×10^{-3}$ .18 910 ft 396 ft 1500 ft",
    "ATC10-tab4.3-exII-s50-sdN1": "50 nsec 50 nsec $1.05×10^{-3}$ .18 910 ft 396 ft 1500 ft",
    "ATC10-tab4.3-exII-s50-sdN1-corrected": "50 nsec 50 nsec $1.05×10^{-3}$ .18 910 ft 396 ft 1500 ft",
    "ATC10-tab4.3-exII-s500-alpha": "50 nsec 500 nsec $1.05×10^{-1}$ .635 910 ft 727 ft 4200 ft",
    "ATC10-tab4.3-exII-s500-psi": "50 nsec 500 nsec $1.05×10^{-1}$ .635 910 ft 727 ft 4200 ft",
    "ATC10-tab4.3-exII-s500-sd0": "50 nsec 500 nsec $1.05×10^{-1}$ .635 910 ft 727 ft 4200 ft",
    "ATC10-tab4.3-exII-s500-sdN": "50 nsec 500 nsec $1.05×10^{-1}$ .635 910 ft 727 ft 4200 ft",
    "ATC10-tab4.3-exII-s500-sdN1": "50 nsec 500 nsec $1.05×10^{-1}$ .635 910 ft 727 ft 4200 ft",
    "ATC10-tab4.3-exII-s500-sdN1-corrected": "50 nsec 500 nsec $1.05×10^{-1}$ .635 910 ft 727 ft 4200 ft",
    "ATC10-thm3.1-gaussian-limit": (
        "then $M_i(v)$ is asymptotically (with N) the characteristic function of a gaussian random variable"
    ),
    "ATC10-thm3.2-optimum": "(thereby giving the most preferable upper bound to the ROC), is e^*",
    "ATC10-thm3.3-bound": (
        "$$E(n)^2 \\leq \\sum_{\\substack{j=1 \\\\ j \\neq i}}^N \\frac{1}{4\\alpha \\sqrt{W_i W_j}}$$"
    ),
    "ATC10-thm3.3-equality": (
        "The bound holds with equality iff $R_{jj}(\\cdot) = R_{ii}(\\cdot)$ for all $j \\neq i$."
    ),
    "ATC10-thm3.3-printed": (
        "$$E(n^2) \\leq \\sum_{\\substack{j=1 \\\\ j \\neq i}}^N \\frac{1}{4\\alpha \\sqrt{W_j} W_j}$$"
    ),
}
