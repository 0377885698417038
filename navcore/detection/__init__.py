r"""Detection theory.

Modules
-------
pulse_detection
    threshold from :math:`P_{fa}`, :math:`P_d` from SNR for :math:`N` pulses, coherent and
    noncoherent, Swerling 0-IV, and the required SNR; the SNR convention of navcore
    (:math:`E/N_0` per pulse) is stated there.
neyman_pearson
    detection of a known signal in white Gaussian noise, in the log domain (ATC-10's
    detection index :math:`d`, which is :math:`\sqrt{2 E/N_0}` in navcore's convention).

jamming
    lower bounds on false and ambiguous aircraft locations under barrage jamming.
jamming_monte_carlo
    a seeded Monte Carlo of the first stage (lists, the K-list rule, false tracks) against
    those bounds.
antenna
    parabolic-dish antenna relations for jammer hardware.
multiple_access
    multiple-access noise at a matched filter: characteristic function, cumulants,
    Edgeworth terms, amplitude densities, Monte Carlo.
roc_bounds
    Chernoff and corrected Gallager-type ROC bounds, the quasi-optimal density, the
    Gaussian ROC.
zakai
    Zakai bandwidth and the multiple-access noise power of PSK signatures.
"""
