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
    # SP
    "sp_acquisition",
    "sp_antijam",
    "sp_architectures",
    "sp_coverage",
    "sp_flyby",
    "sp_missions",
    "sp_missions_scenarios",
    "sp_quotes",
    "sp_residual_acceleration",
    "sp_tables",
    "sp_tracking",
    # ATC-10
    "atc10_coverage_jamming",
    "atc10_coverage_ma",
    "atc10_coverage_tracking",
    "atc10_jamming",
    "atc10_multiple_access",
    "atc10_quotes",
    "atc10_tracking",
    # KZL: Secs. 1-2, 3.1-3.2, 3.3-3.5, 3.6 (covariance, then the simulation) and 3.7
    "kzl_requirements",
    "kzl_mechanization",
    "kzl_tightly_coupled_filter",
    "kzl_covariance",
    "kzl_simulation",
    "kzl_scenario",
    "kzl_quotes",
)
