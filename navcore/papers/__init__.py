"""Per-paper modules: published inputs (typed data with units and locators), claims, errata.

Each module defines module-level ``CLAIMS`` (list of :class:`navcore.claims.Claim`) and
``ERRATA`` (list of :class:`navcore.claims.Erratum`). Modules are discovered by
:mod:`navcore.ledger.registry`; name them ``<paper>_<section>.py`` (``sp_architectures``,
``atc10_jamming``). Paper names belong here, not in the model subpackages.
"""

#: The modules in the papers' reading order (by paper, then section): the order of the ledger's
#: rows and of the errata lists (:func:`navcore.ledger.registry.paper_modules`). A new module
#: is listed here; a test checks that every module is, and nothing else.
READING_ORDER = (
    # WF: Secs. II, III, IV.B, IV.C (the Theorem), IV.D and V
    "wf_location_error",
    "wf_aperture_velocity",
    "wf_local_estimators",
    "wf_federated_fusion",
    "wf_assessment",
    "wf_inputs",
    "wf_example",
    "wf_quotes",
    # SP: Secs. 2.1-2.3 (Tables 2.1-2.3), 2.5 (tracking, residual acceleration, acquisition),
    # 2.6.1-2.6.4 (the missions, then the flyby of Sec. 2.6.2 and Table 2.7) and 3
    "sp_architectures",
    "sp_tracking",
    "sp_residual_acceleration",
    "sp_acquisition",
    "sp_missions",
    "sp_flyby",
    "sp_antijam",
    "sp_tables",
    "sp_scenario_wiring",
    "sp_mission_flights",
    "sp_quotes",
    # ATC-10: Ch. 1 (Table 1.1), Ch. 2 (Secs. 2.1-2.5, 2.7, 2.6-2.8 lists), App. A-D; Ch. 3
    # (Secs. 3.1-3.4 with App. E, 3.5-3.7, 3.8, 3.9 with App. F); Ch. 4 (Secs. 4.1-4.2, 4.3-4.5.2,
    # 4.5.3-4.5.4, 4.6 with Tables 4.1-4.2, 4.6 with Table 4.3 and 4.7) and App. G-H
    "atc10_system_tables",
    "atc10_jamming",
    "atc10_single_pulse",
    "atc10_tracking_lists",
    "atc10_jamming_appendices",
    "atc10_multiple_access",
    "atc10_roc_bounds",
    "atc10_gaussian_comparison",
    "atc10_zakai_bandwidth",
    "atc10_tracking_geometry",
    "atc10_clock_tracking",
    "atc10_tracking_procedures",
    "atc10_example_constellations",
    "atc10_tracking_examples",
    "atc10_tracking_appendices",
    "atc10_quotes",
    # KZL: Secs. 1-2, 3.1-3.2, 3.3-3.5, 3.6 (covariance, then the simulation) and 3.7
    "kzl_requirements",
    "kzl_mechanization",
    "kzl_tightly_coupled_filter",
    "kzl_covariance",
    "kzl_simulation",
    "kzl_scenario",
    "kzl_quotes",
)
