"""The paper's words behind the SP claims (issue 27, item 5): each claim's ``printed`` quote.

Each quote is the text of the transcription (LaTeX as transcribed, table rows with their tabs);
pieces of one passage are joined by " [...] ". The independent audit of issue 27 verified every
piece against the transcription, and ``tests/test_paper_quotes.py`` checks them again wherever the
transcription is present. The tolerance policy of each claim follows its quote by the ledger's
rule, and a number claim's quote prints its published number. A claim that gives ``printed=``
itself keeps it; :func:`navcore.claims.quotes.with_quotes` fills the others.
The claims of the flyby and mission modules (and Table 2.7's cells, which the flyby model
computes) are quoted where they are made.
"""

from __future__ import annotations

__all__ = ["QUOTES"]

#: Claim id -> the paper's words or formula as quoted.
QUOTES: dict[str, str] = {
    "SP-eq2.1-keeps-peak": (
        "To maintain a 90-deg peak error, the natural frequency can be scaled by the square "
        "root of the ratio of aided to unaided step magnitude."
    ),
    "SP-eq2.u1-closed-form": (
        "$$\\Delta \\Phi = \\frac{R}{\\omega_0^2} \\left[e^{-\\omega_0 t} + "
        "\\frac{e^{-\\omega_0 t^2}}{\\sqrt{3}} \\left(\\sin \\omega_0 t \\frac{\\sqrt{3}}{2} - "
        "\\sqrt{3} \\cos \\omega_0 t \\frac{\\sqrt{3}}{2} \\right) \\right]$$"
    ),
    "SP-eq2.u7-worked-example": (
        "$$\\omega_{0,aided} = \\sqrt{\\frac{0.011\\,g}{6\\,g}} \\, 18 \\, rad/s = 0.77 \\, rad/s$$"
    ),
    "SP-fig2.1-omega0": (
        "The graph in Figure 2.1 shows the response, $\\Delta \\Phi$, for a natural frequency "
        "of 17.67 rad/s, the maximum error is 90 deg."
    ),
    "SP-fig2.1-peak": (
        "The graph in Figure 2.1 shows the response, $\\Delta \\Phi$, for a natural frequency "
        "of 17.67 rad/s, the maximum error is 90 deg."
    ),
    "SP-fig2.1-peak-L1": (
        "The graph in Figure 2.1 shows the response, $\\Delta \\Phi$, for a natural frequency "
        "of 17.67 rad/s, the maximum error is 90 deg."
    ),
    "SP-fig2.1-peak-code300": (
        "(Note that distance has been converted to phase error in degrees using the code length "
        "of 300 m.) [...] The graph in Figure 2.1 shows the response, $\\Delta \\Phi$, for a "
        "natural frequency of 17.67 rad/s, the maximum error is 90 deg."
    ),
    "SP-fig2.9-heli-1nmi": (
        "As seen in an earlier scenario, the ratio of the errors between the 10 nmi/h and the 1 "
        "nmi/h navigation system, 2750:192 in this case, is greater than the characterization "
        "ratio, 10:1."
    ),
    "SP-fig3.1-di-lower-initial-rss": (
        "Note also that the deeply integrated system achieves lower rss error during the 60-s "
        "initialization phase."
    ),
    "SP-fig3.2-di-better-second": (
        "The results again indicate a significant improvement in loss-of-lock capability due to "
        "deep integration."
    ),
    "SP-fig3.3-aj-15dB-above-35m": (
        "A/J improvement is in excess of 10 dB at all values of rss error and exceeds 15 dB for "
        "rss error greater than 35 m."
    ),
    "SP-fig3.3-aj-above-10dB": (
        "A/J improvement is in excess of 10 dB at all values of rss error and exceeds 15 dB for "
        "rss error greater than 35 m."
    ),
    "SP-fig3.8-aj-15dB": (
        "The resulting improvement in A/J capability due to deep integration can be seen in "
        "Figure 3.8. For wideband jamming, improvements of at least 15 dB are seen for CEP "
        "values ranging from 6 to 120 m."
    ),
    "SP-fig3.8-narrowband-15dB": (
        "For narrowband jamming, improvements of at least 15 dB are seen for CEP values ranging "
        "from 4 to 80 m."
    ),
    "SP-sec2.1-fixes-decorrelated": (
        "The process noise is of such a magnitude that position solutions separated by 10-s "
        "intervals are not significantly correlated."
    ),
    "SP-sec2.2-same-states": (
        "These same states appear in the cascaded filters of the loosely coupled system."
    ),
    "SP-sec2.5-H-sign": (
        "$$\\delta a = \\begin{bmatrix} 1 & 0 & 0 & 0 & -1 & 1 \\\\ 0 & 1 & 0 & 1 & 0 & -1 \\\\ "
        "0 & 0 & 1 & -1 & 1 & 0 \\end{bmatrix}$$"
    ),
    "SP-sec2.5-doppler-cell-hz": (
        "At the given signal level, a 20-ms integration period should be adequate for "
        "accumulating signal energy. [...] The size of the frequency bandwidth was 50 Hz "
        "corresponding to 10 m/s."
    ),
    "SP-sec2.5-doppler-cell-mps": "The size of the frequency bandwidth was 50 Hz corresponding to 10 m/s.",
    "SP-sec2.5-half-chip-ns": (
        "Loss of lock for the code phase was declared if the tracking error was greater then 1/2 chip (50 ns)"
    ),
    "SP-sec2.5-jerk-6g": (
        "These bandwidths are determined by the requirement that the loops stay in lock for a "
        "10-g/s jerk, which lasts for 0.6 s. (The carrier tracking bandwidth was actually set "
        "for this study by requiring that the phase error be less than 90 deg for a 6-g "
        "acceleration step."
    ),
    "SP-sec2.5-loose-carrier-5.83Hz": "The carrier was a third-order loop with bandwidth of 5.83 Hz.",
    "SP-sec2.5-phase-step-deg": (
        "The size of the phase shift between 20-ms search intervals was 36 deg corresponding to 30 m."
    ),
    "SP-sec2.5-right-factor": (
        "$\\begin{bmatrix} 1 & 0 & 0 \\\\ 0 & 1 & 0 \\\\ 0 & 0 & 1 \\\\ 0 & 1 & -1 \\\\ -1 & 0 & "
        "1 \\\\ 1 & -1 & 0 \\end{bmatrix}$"
    ),
    "SP-sec2.5-step-vs-jerk": "This is a slightly more stringent requirement, but is easier to analyze.",
    "SP-sec2.6.1-code-after-fourth-carrier": (
        "Loss of code lock began after the fourth carrier tracking loop lost lock."
    ),
    "SP-sec2.6.1-reacquisition-2760s": (
        "The first loss of carrier tracking occurs at 360 s. The first loss of code at 1020 s. "
        "[...] The sequence of code reacquisition begins at 2760 s."
    ),
    "SP-sec2.6.2-outside-1sigma": (
        "Sometimes the signal will be found sooner, and of course, 32% of the time, it will be "
        "outside the 1σ bounds and require a longer search."
    ),
    "SP-sec2.6.2-search-10-max": "The 10-nmi/h inertial system holds the search time to about 0.8 to 1.6 s.",
    "SP-sec2.6.2-search-10-min": "The 10-nmi/h inertial system holds the search time to about 0.8 to 1.6 s.",
    "SP-sec2.6.2-search-better": (
        "For a search time of 20 ms/chip (code phase interval), the better IMUs hold the search "
        "time to 0.2 s."
    ),
    "SP-sec2.6.3-6s-longer": (
        "Another contributor to the difference is that the tightly coupled systems resisted the "
        "jamming for about 6 s longer than did the loosely coupled system."
    ),
    "SP-sec2.6.4-pointing-gyrocompass": (
        "The pointing error is negligible compared with the position error so that the target "
        "location errors and the aircraft position errors are essentially the same."
    ),
    "SP-sec2.8-gps-aided-not-dramatic": (
        "Improvement of steady-state error with improving inertial quality is not as dramatic."
    ),
    "SP-sec3.0-tc-loss-54dB": "Code loop loss-of-lock was assumed to occur at J/S = 54 dB.",
    "SP-sec3.1-aj-grows-with-imu": (
        "Note that the A/J improvement also increases when higher quality inertial sensors are employed."
    ),
    "SP-sec3.1-improvement-15dB": (
        "The deeply integrated system was able to maintain code lock up to 65 dB J/S, an "
        "improvement of approximately 15 dB over the tightly coupled system."
    ),
    "SP-sec3.3-aj-falls-beyond-100m": (
        "The improvement is also seen to decrease as the CEP increases beyond 100 m."
    ),
    "SP-sec3.3-aj-rule-100x": (
        "As shown in Reference 5, every 20 dB increase in A/J improvement in the INS/GPS system "
        "requires that the jammer increase its power by a factor of 100 to maintain the same "
        "effectiveness as a jammer."
    ),
    "SP-sec3.3-aj-rule-distance": (
        "As shown in Reference 5, every 20 dB increase in A/J improvement in the INS/GPS system "
        "requires that the jammer increase its power by a factor of 100 to maintain the same "
        "effectiveness as a jammer."
    ),
    "SP-sec3.3-cep-di-100W": (
        "As an example, a 100-W wideband jammer results in a CEP of 11 m for the deeply "
        "integrated system, compared with a CEP of 120 m for the tightly coupled system."
    ),
    "SP-sec3.3-cep-di-10W": (
        "If the jammer power is reduced to 10 W, the CEP values are 2.6 m for the deeply "
        "integrated system and 71 m for the tightly coupled system."
    ),
    "SP-sec3.3-cep-tc-100W": (
        "As an example, a 100-W wideband jammer results in a CEP of 11 m for the deeply "
        "integrated system, compared with a CEP of 120 m for the tightly coupled system."
    ),
    "SP-sec3.3-cep-tc-10W": (
        "If the jammer power is reduced to 10 W, the CEP values are 2.6 m for the deeply "
        "integrated system and 71 m for the tightly coupled system."
    ),
    "SP-sec3.3-di-better": (
        "it can be seen that the deeply integrated system offers significant improvement over "
        "the traditional tightly coupled system for both wideband and narrowband jamming."
    ),
    "SP-sec3.3-low-power-comparable": (
        "In the limit as the jammer power approaches zero, the tightly coupled system "
        "approaches efficient operation, and both systems give comparable performance."
    ),
    "SP-tab2.1-acceleration": "Acceleration\t3",
    "SP-tab2.1-altimeter-bias": "Altimeter bias\t1",
    "SP-tab2.1-position": "Position\t3",
    "SP-tab2.1-total": "Total\t12",
    "SP-tab2.1-user-clock-bias": "User clock bias\t1",
    "SP-tab2.1-user-clock-drift": "User clock drift\t1",
    "SP-tab2.1-velocity": "Velocity\t3",
    "SP-tab2.2-accel-bias": "Accel. bias\t3",
    "SP-tab2.2-accel-scale-factor": "Accel. scale factor\t3",
    "SP-tab2.2-altimeter-bias": "Altimeter bias\t1",
    "SP-tab2.2-gyro-drift": "Gyro drift\t3",
    "SP-tab2.2-gyro-scale-factor": "Gyro scale factor\t3",
    "SP-tab2.2-misalignment": "Misalignment\t3",
    "SP-tab2.2-position": "Position\t3",
    "SP-tab2.2-total": "Total\t22",
    "SP-tab2.2-velocity": "Velocity\t3",
    "SP-tab2.3-accel-bias": "Accel. bias\t3",
    "SP-tab2.3-accel-scale-factor": "Accel. scale factor\t3",
    "SP-tab2.3-altimeter-bias": "Altimeter bias\t1",
    "SP-tab2.3-gyro-drift": "Gyro drift\t3",
    "SP-tab2.3-gyro-scale-factor": "Gyro scale factor\t3",
    "SP-tab2.3-misalignment": "Misalignment\t3",
    "SP-tab2.3-position": "Position\t3",
    "SP-tab2.3-total": "Total\t24",
    "SP-tab2.3-user-clock-bias": "User clock bias\t1",
    "SP-tab2.3-user-clock-drift": "User clock drift\t1",
    "SP-tab2.3-velocity": "Velocity\t3",
    "SP-tab2.5-half-column": "Accel. bias\t223 μg\t37 μg\t19 µg\t4.2 μg",
    "SP-tab2.6-col2-0.2": "0.2 nmi/h\t225\t0.0014 g\t0.27",
    "SP-tab2.6-col2-0.5": "0.5 nmi/h\t311\t0.0019 g\t0.32",
    "SP-tab2.6-col2-1": "1 nmi/h\t431\t0.0026 g\t0.37",
    "SP-tab2.6-col2-10": "10 nmi/h\t1880\t0.011 g\t0.77",
    "SP-tab2.6-col3-0.2": "0.2 nmi/h\t225\t0.0014 g\t0.27",
    "SP-tab2.6-col3-0.5": "0.5 nmi/h\t311\t0.0019 g\t0.32",
    "SP-tab2.6-col3-1": "1 nmi/h\t431\t0.0026 g\t0.37",
    "SP-tab2.6-col3-10": "10 nmi/h\t1880\t0.011 g\t0.77",
    "SP-tab2.6-col4-0.2": "0.2 nmi/h\t225\t0.0014 g\t0.27",
    "SP-tab2.6-col4-0.5": "0.5 nmi/h\t311\t0.0019 g\t0.32",
    "SP-tab2.6-col4-1": "1 nmi/h\t431\t0.0026 g\t0.37",
    "SP-tab2.6-col4-10": "10 nmi/h\t1880\t0.011 g\t0.77",
    "SP-tab2.6-unaided": "No inertial aiding\tNot applicable\t6 g\t18 rad/s",
    "SP-tab2.7-ordering": "Table 2.7: Search for Range Phase as a Function of IMU Quality",
}
